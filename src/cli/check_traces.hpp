#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// Where `sfcv check` puts its traces (docs/reports.md, "Traces"):
// - --trace-dir DIR: every trace, one file per property, named by its id
//   (DIR/check-reachable.vcd, DIR/property-ctl-3a7bd3e2360a.vcd);
// - --trace-file F: the trace when there is one; with several, one file per property beside
//   F, its id before the extension (t.vcd -> t.check-reachable.vcd);
// - --trace vcd or csv without them (or --trace-file -): standard output holds the trace alone
//   and the report goes to standard error; with several traces nothing is written there and
//   the run ends with exit 2, asking for --trace-dir (a VCD file holds one run).
// A table or JSON trace without a file stays inside the text report.

#include <map>
#include <string>
#include <vector>

#include "logic/check_result.hpp"
#include "report/check_render.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::cli {

struct TraceRequest {
  report::TraceFormat format = report::TraceFormat::Table;
  std::string file;   ///< --trace-file; "-" is standard output
  std::string dir;    ///< --trace-dir
  bool json = false;  ///< --json: standard output holds the JSON document
  std::int64_t cycle_ms = 1;
};

/// Whether the traces go to standard output on their own (the report then to standard error).
bool traces_on_standard_output(const TraceRequest& request);

/// Throws UsageError for a request that cannot be met (a trace on standard output beside
/// --json); creates --trace-dir. Call before the run.
void check_trace_request(const TraceRequest& request);

/// The trace of one result in the requested format.
std::string trace_text(const logic::Trace& trace, const semantics::TransitionSystem& ts,
                       const TraceRequest& request);

struct WrittenTraces {
  std::map<std::string, std::string> where;  ///< property_id -> file, or "standard output"
  std::string standard_output;               ///< the one trace for standard output
  std::vector<std::string> errors;           ///< files that could not be written; exit 2
};

/// Writes every trace of `result` as requested (files now; standard_output for the caller).
WrittenTraces write_traces(const logic::CheckReport& result, const semantics::TransitionSystem& ts,
                           const TraceRequest& request);

}  // namespace sfcv::cli
