#include "cli/run_limits.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

#include "cli/exit_code.hpp"

namespace sfcv::cli {

void add_limit_options(CLI::App& sub, LimitOptions& o, const std::string& what_stops) {
  sub.add_option("--max-states", o.max_states,
                 "Stop after N states (N > 0; the bdd engine: reached states): " + what_stops)
      ->group("Limits (exit 3 when reached)");
  sub.add_option("--timeout", o.timeout,
                 "Stop after a duration (seconds, or 500ms, 10s, 2m, 1h), whatever the phase: " +
                     what_stops)
      ->group("Limits (exit 3 when reached)");
  sub.add_option("--memory", o.memory,
                 "Memory budget of the whole process, e.g. 2G (K, M, G): past it, " + what_stops)
      ->group("Limits (exit 3 when reached)");
}

std::uint64_t parse_memory(const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const std::string unit = text.substr(used);
  double factor = 1;
  if (unit == "K" || unit == "k" || unit == "KB" || unit == "KiB")
    factor = 1024.0;
  else if (unit == "M" || unit == "MB" || unit == "MiB")
    factor = 1024.0 * 1024;
  else if (unit == "G" || unit == "GB" || unit == "GiB")
    factor = 1024.0 * 1024 * 1024;
  else if (!unit.empty() && unit != "B")
    used = 0;
  if (used == 0 || !(value > 0) || value * factor > 1e15 || value * factor < 1)
    throw UsageError("bad --memory '" + text + "' (expected a size such as 2G, 512M or 64K)");
  return static_cast<std::uint64_t>(value * factor);
}

namespace {

double parse_timeout(const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  // A unit as --cycle and --memory take one: seconds when left out.
  const std::string unit = used == 0 ? std::string() : text.substr(used);
  double factor = 1;
  if (unit == "ms")
    factor = 0.001;
  else if (unit == "m" || unit == "min")
    factor = 60;
  else if (unit == "h")
    factor = 3600;
  else if (!unit.empty() && unit != "s")
    used = 0;
  value *= factor;
  if (used == 0 || !std::isfinite(value) || !(value > 0) || value > 1e9)
    throw UsageError("bad --timeout '" + text +
                     "' (expected a duration > 0: seconds such as 60 or 0.5, or 10s, 2m, 1h, "
                     "500ms)");
  return value;
}

std::uint64_t parse_count(const std::string& text) {
  std::uint64_t value = 0;
  bool ok = !text.empty() && text.size() <= 19;
  for (char c : text) ok = ok && c >= '0' && c <= '9';
  if (ok) value = std::stoull(text);
  if (!ok || value == 0)
    throw UsageError("bad --max-states '" + text + "' (expected a whole number > 0)");
  return value;
}

}  // namespace

model::Budget make_budget(const LimitOptions& o) {
  model::Budget budget;
  if (!o.timeout.empty()) budget.set_timeout(parse_timeout(o.timeout));
  if (!o.max_states.empty()) budget.max_states = parse_count(o.max_states);
  if (!o.memory.empty()) budget.max_memory_bytes = parse_memory(o.memory);
  return budget;
}

report::PictureLimits picture_limits(const model::Budget& budget) {
  report::PictureLimits limits;
  if (budget.deadline) {
    const double left =
        std::chrono::duration<double>(*budget.deadline - model::Budget::Clock::now()).count();
    limits.seconds = std::min(limits.seconds, left + 0.5);
  }
  return limits;
}

}  // namespace sfcv::cli
