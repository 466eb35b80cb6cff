#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// --timeout, --max-states, --memory: registered and validated in one place, turned into the one
// model::Budget a run shares across its phases. An invalid value is a usage error (exit 2),
// never "no limit".

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "model/budget.hpp"
#include "report/check_html.hpp"

namespace sfcv::cli {

struct LimitOptions {
  std::string timeout;     ///< seconds, > 0; empty: none
  std::string max_states;  ///< a count, > 0; empty: none
  std::string memory;      ///< e.g. 2G, 512M, 64K; empty: none
};

/// The one group of limit options every subcommand offers (group "Limits" in its help); a
/// subcommand runs under them through run_limited (cli/run_guard.hpp).
void add_limit_options(CLI::App& sub, LimitOptions& options, const std::string& what_stops);

/// The budget of a run starting now; throws UsageError for a bad value.
model::Budget make_budget(const LimitOptions& options);

/// The time a report's pictures may take at the end of a run under `budget`: what is left of
/// its deadline and half a second of the grace the run has to report (docs/reliability.md),
/// at most 60 s; none after that.
report::PictureLimits picture_limits(const model::Budget& budget);

/// "2G", "512M", "64K", "1000000" (bytes) -> bytes; throws UsageError.
std::uint64_t parse_memory(const std::string& text);

}  // namespace sfcv::cli
