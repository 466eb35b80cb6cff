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
    case Verdict::NotApplicable:
      return "n/a";
  }
  return "?";
}

int exit_code(const CheckReport& r) {
  bool violated = false, unknown = false;
  for (const auto& p : r.results) {
    violated |= p.verdict == Verdict::Violated;
    unknown |= p.verdict == Verdict::Unknown || p.verdict == Verdict::NotChecked;
  }
  return violated ? 1 : unknown ? 3 : 0;
}

bool nothing_decided(const CheckReport& r) {
  bool not_checked = false;
  for (const auto& p : r.results) {
    if (p.verdict != Verdict::NotChecked && p.verdict != Verdict::NotApplicable) return false;
    not_checked |= p.verdict == Verdict::NotChecked;
  }
  return not_checked;
}

}  // namespace sfcv::logic
