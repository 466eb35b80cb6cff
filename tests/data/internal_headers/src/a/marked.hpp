#pragma once
// Internal header of sfcv_a: only src/a includes it.
inline int marked() {
  return 2;
}
