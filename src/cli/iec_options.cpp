#include "cli/iec_options.hpp"

#include <cctype>

#include "cli/exit_code.hpp"
#include "model/literal.hpp"
#include "model/names.hpp"

namespace sfcv::cli {

std::int64_t parse_cycle_ms(const std::string& text) {
  // Digits and a unit (ms when left out), read by the one checked conversion of durations
  // (model/literal.hpp): `9223372036854775807s` once wrapped around to a negative cycle.
  std::size_t digits = 0;
  while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
  const auto unit = model::to_upper(text.substr(digits));
  if (digits == 0)
    throw InputError(text.rfind('-', 0) == 0
                         ? "--cycle must be positive"
                         : "bad --cycle '" + text + "' (expected e.g. 10ms, 1s)");
  if (unit != "S" && unit != "MS" && !unit.empty())
    throw InputError("bad --cycle '" + text + "' (units: ms, s)");
  model::DurationLiteral d("--cycle " + text);
  const auto ms = d.add(text.substr(0, digits), "", unit == "S" ? 1000000000 : 1000000)
                      ? d.milliseconds(false)
                      : model::Converted<std::int64_t>{{}, d.error()};
  if (!ms) throw InputError("bad --cycle '" + text + "': " + ms.error);
  if (*ms <= 0) throw InputError("--cycle must be positive");
  return *ms;
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
