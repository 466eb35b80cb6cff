#pragma once
// Renders a CheckReport: human text (one line per property: name, verdict, time; findings and
// traces below) or JSON (schema in docs/formats.md, "sfcv check --json").

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "logic/check_result.hpp"
#include "report/provenance.hpp"
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
  /// Who ran what, when, on which files (report/provenance.hpp); every report renders it.
  std::optional<Provenance> provenance;
  /// Where each trace went (--trace-dir, --trace-file: the file; "standard output"), by
  /// property_id: the text names it; a VCD or CSV is never printed inside the text.
  std::map<std::string, std::string> trace_files;
  /// SARIF: artifact URIs relative to this directory (uriBaseId SRCROOT); empty: as given.
  std::string sarif_root;
};

/// The version of the JSON of `sfcv check --json` (share/sfcv/check-result.schema.json):
/// the major number changes when a key is renamed or removed, the minor when one is added.
inline constexpr const char* kCheckJsonSchemaVersion = "1.0";

/// A result's id, the same in every report and every run of the same question: "check/<name>"
/// for a standard check, "property/<name>" for a property named in a spec file, and for one
/// given on the command line (whose name is its text) its kind and 12 hex digits of the text's
/// SHA-256, spaces left out: "property/ctl-3a7bd3e2360a". SARIF rule ids, trace file names.
std::string property_id(const logic::PropertyResult& r);
/// property_id as a file name stem: "check-reachable", "property-ctl-3a7bd3e2360a".
std::string property_file_stem(const logic::PropertyResult& r);
/// Whether the property was given on the command line (--ctl, --ltl, --pattern): it has no
/// source location of its own.
bool from_command_line(const logic::PropertyResult& r);

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
