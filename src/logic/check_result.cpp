#include "logic/check_result.hpp"

namespace sfcv::logic {

std::string_view to_string(Verdict v) {
  switch (v) {
    case Verdict::Holds:
      return "holds";
    case Verdict::Violated:
      return "violated";
    case Verdict::Unknown:
      return "unknown";
    case Verdict::NotChecked:
      return "not checked";
  }
  return "?";
}

int exit_code(const CheckReport& r) {
  bool violated = false, unknown = false;
  for (const auto& p : r.results) {
    violated |= p.verdict == Verdict::Violated;
    unknown |= p.verdict == Verdict::Unknown;
  }
  return violated ? 1 : unknown ? 3 : 0;
}

}  // namespace sfcv::logic
