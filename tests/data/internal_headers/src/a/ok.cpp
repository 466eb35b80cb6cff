#include "a/detail/x.hpp"
#include "a/marked.hpp"

int a_uses_its_own() {
  return detail_x() + marked();
}
