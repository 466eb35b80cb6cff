#pragma once
// Renders a trace in the chart's own words: a table (one row per cycle or stable situation:
// inputs that changed, fired transitions, active steps, outputs, the property's atoms marked
// with '*'), JSON, VCD (GTKWave), or CSV (the input file of `sfcv simulate`, to replay it).

#include <string>

#include "logic/trace.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::report {

std::string trace_table(const logic::Trace& trace, const semantics::TransitionSystem& ts);
/// JSON text (schema in docs/formats.md, "sfcv check --json").
std::string trace_json(const logic::Trace& trace, const semantics::TransitionSystem& ts);
std::string trace_vcd(const logic::Trace& trace, const semantics::TransitionSystem& ts);
/// Header of input names, then one row per step after the first (the inputs of each cycle).
std::string trace_csv(const logic::Trace& trace, const semantics::TransitionSystem& ts);

}  // namespace sfcv::report
