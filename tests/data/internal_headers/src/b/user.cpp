#include "a/detail/x.hpp"
#include "a/marked.hpp"

int b_reaches_into_a() {
  return detail_x() + marked();
}
