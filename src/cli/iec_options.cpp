#include "cli/iec_options.hpp"

#include "cli/exit_code.hpp"
#include "model/names.hpp"

namespace sfcv::cli {

std::int64_t parse_cycle_ms(const std::string& text) {
  std::size_t pos = 0;
  long long v = 0;
  try {
    v = std::stoll(text, &pos);
  } catch (const std::exception&) {
    throw InputError("bad --cycle '" + text + "' (expected e.g. 10ms, 1s)");
  }
  const auto unit = model::to_upper(text.substr(pos));
  if (unit == "S")
    v *= 1000;
  else if (unit != "MS" && !unit.empty())
    throw InputError("bad --cycle '" + text + "' (units: ms, s)");
  if (v <= 0) throw InputError("--cycle must be positive");
  return v;
}

semantics::PriorityMode parse_priority(const std::string& text) {
  if (text == "standard") return semantics::PriorityMode::Standard;
  if (text == "none") return semantics::PriorityMode::None;
  throw InputError("bad --priority '" + text + "' (expected standard or none)");
}

semantics::TimeMode parse_time_mode(const std::string& text) {
  if (text == "abstract") return semantics::TimeMode::Abstract;
  if (text == "discrete") return semantics::TimeMode::Discrete;
  throw InputError("bad --time '" + text + "' (expected abstract or discrete)");
}

semantics::UnwrittenMode parse_unwritten(const std::string& text) {
  if (text == "free") return semantics::UnwrittenMode::Free;
  if (text == "keep") return semantics::UnwrittenMode::Keep;
  throw InputError("bad --unwritten '" + text + "' (expected free or keep)");
}

}  // namespace sfcv::cli
