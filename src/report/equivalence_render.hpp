#pragma once
// `sfcv equiv` results (docs/equivalence.md): the verdict per question and the counterexample
// side by side, OLD's and NEW's steps and compared signals per cycle, in text, JSON, VCD and HTML.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "logic/check_result.hpp"
#include "semantics/equivalence.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::report {

struct EquivalenceRun {
  std::string old_path, new_path;
  std::uint32_t within = 0;
  bool per_signal = false;  ///< --changed: one question per compared signal
  /// The check of the product: one result ("equivalent") or one per compared signal, in the
  /// order of EquivalenceProduct::compared.
  logic::CheckReport report;
};

/// "equivalent", "differ" or "unknown" (exit codes 0, 1, 3).
std::string equivalence_verdict(const logic::CheckReport& report);

std::string equivalence_text(const EquivalenceRun& run, const semantics::EquivalenceProduct& p,
                             const semantics::TransitionSystem& ts);
nlohmann::json equivalence_json(const EquivalenceRun& run, const semantics::EquivalenceProduct& p,
                                const semantics::TransitionSystem& ts);
/// `sfcv equiv --html`: one self-contained page from the equivalence_json document: the verdicts
/// and each counterexample side by side (OLD's and NEW's steps and signals per cycle).
std::string equivalence_html(const nlohmann::json& result);

/// One counterexample side by side: a row per cycle with the inputs read, OLD's and NEW's active
/// steps and each compared signal as old/new, `*` where they differ.
std::string equivalence_trace_table(const logic::Trace& trace,
                                    const semantics::EquivalenceProduct& p,
                                    const semantics::TransitionSystem& ts);
nlohmann::json equivalence_trace_json(const logic::Trace& trace,
                                      const semantics::EquivalenceProduct& p,
                                      const semantics::TransitionSystem& ts);
/// The VCD writer of traces (trace_render.hpp) with both sides' compared signals marked, so
/// that they appear next to each other (`Old_Main_q`, `New_Main_q`).
std::string equivalence_trace_vcd(const logic::Trace& trace, const semantics::EquivalenceProduct& p,
                                  const semantics::TransitionSystem& ts, std::int64_t cycle_ms);

}  // namespace sfcv::report
