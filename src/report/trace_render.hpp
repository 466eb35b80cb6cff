#pragma once
// Renders a trace in the chart's own words: a table (one row per cycle or stable situation:
// inputs that changed, fired transitions, active steps, outputs, the property's atoms marked
// with '*'), JSON, VCD (GTKWave), or CSV (the input file of `sfcv simulate`, to replay it).

#include <cstdint>
#include <string>

#include "logic/trace.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::report {

std::string trace_table(const logic::Trace& trace, const semantics::TransitionSystem& ts);
/// JSON text (schema in docs/formats.md, "sfcv check --json").
std::string trace_json(const logic::Trace& trace, const semantics::TransitionSystem& ts);
struct VcdOptions {
  std::int64_t step_ms = 1;  ///< IEC 61131-3: the scan cycle; Grafcet: 1 per stable situation
};
/// The one VCD writer (`check --trace vcd`, `simulate --vcd`): scopes inputs, steps, actions,
/// outputs, atoms; names as VCD identifiers ('.' and ':' become '_'); time in ms.
std::string trace_vcd(const logic::Trace& trace, const semantics::TransitionSystem& ts,
                      const VcdOptions& options = {});
/// Header of input names, then the inputs of each cycle (IEC 61131-3: steps after the first) or
/// of each stable situation (Grafcet: every step, the first being the initial inputs).
std::string trace_csv(const logic::Trace& trace, const semantics::TransitionSystem& ts);

}  // namespace sfcv::report
