#pragma once
// Renders a CheckReport: human text (one line per property: name, verdict, time; findings and
// traces below) or JSON (schema in docs/formats.md, "sfcv check --json").

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "logic/check_result.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::report {

enum class TraceFormat { Table, Json, Vcd, Csv, None };

struct RenderOptions {
  TraceFormat trace = TraceFormat::Table;
  std::string model;          ///< the model file, for the JSON header
  std::string semantics;      ///< "iec61131", "grafcet"
  std::int64_t cycle_ms = 1;  ///< IEC 61131-3 scan cycle, the VCD time step
  /// Text: findings keep their XML element paths and absolute file paths (else relative paths
  /// and line:col only, report/concise_text.hpp).
  bool verbose = false;
};

/// "20 of 137 findings shown; --all for every one" when the engine kept fewer findings than it
/// made, else empty.
std::string findings_cut_note(const logic::PropertyResult& r);

/// "diagnosis: the chart never moves ...": why and what to do, when the dead-transitions check
/// found every transition of the system dead; empty otherwise. check_text ends with it.
std::string stuck_diagnosis(const logic::CheckReport& report,
                            const semantics::TransitionSystem& ts);

std::string check_text(const logic::CheckReport& report, const semantics::TransitionSystem& ts,
                       const RenderOptions& options);
/// A state or edge count as JSON: a number while it fits in 64 bits, else its decimal string.
nlohmann::json count_json(const logic::BigCount& count);

nlohmann::json check_json(const logic::CheckReport& report, const semantics::TransitionSystem& ts,
                          const RenderOptions& options);
nlohmann::json trace_to_json(const logic::Trace& trace, const semantics::TransitionSystem& ts);

}  // namespace sfcv::report
