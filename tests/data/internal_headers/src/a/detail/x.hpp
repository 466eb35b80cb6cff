#pragma once
inline int detail_x() {
  return 1;
}
