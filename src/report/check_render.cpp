#include "report/check_render.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "report/concise_text.hpp"
#include "report/numbers.hpp"
#include "report/sha256.hpp"
#include "report/text_encoding.hpp"
#include "report/trace_render.hpp"

namespace sfcv::report {

namespace {
std::string run_time_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3fs", s);
  return buf;
}
}  // namespace

/// A chart that never moves (corpus 07 with --unwritten keep: 2 states, every step but the
/// initial ones unreachable, every transition dead): not 110 findings alone, but why and what to
/// do. Empty unless the dead-transitions check found every transition of the system dead.
std::string stuck_diagnosis(const logic::CheckReport& report,
                            const semantics::TransitionSystem& ts) {
  const auto& transitions = ts.transitions();
  if (!report.complete || transitions.empty()) return {};
  const auto dead = std::find_if(report.results.begin(), report.results.end(), [](const auto& r) {
    return r.check == "dead-transitions" && r.verdict == logic::Verdict::Violated;
  });
  if (dead == report.results.end() ||
      std::max(dead->findings_total, dead->findings.size()) < transitions.size())
    return {};
  std::vector<std::string> inputs;
  for (const auto& in : ts.inputs())
    if (!in.pseudo) inputs.push_back(in.name);
  std::string out = "diagnosis: the chart never moves: every one of its " +
                    counted(transitions.size(), "transition") + " is dead";
  if (report.states_known)
    out += " and only " + counted(report.states.str(), "state") +
           (report.states.str() == "1" ? " is" : " are") + " reachable";
  out += ".\n";
  if (inputs.empty()) {
    out +=
        "  why: no input ever changes: the run has no free input (with --unwritten keep the "
        "variables that no POU writes hold their initial values), so no transition condition can "
        "become true.\n";
  } else {
    out += "  why: no transition condition becomes true, whatever the " +
           counted(inputs.size(), "input") + " (" + inputs.front() +
           (inputs.size() > 1 ? ", ..." : "") +
           ") do: the conditions read variables that never change, or the charts belong to "
           "function block instances that the program never calls.\n";
  }
  out +=
      "  what to do: 'sfcv info' lists the inputs and the variables no POU writes; read the "
      "sensors as inputs (--unwritten free, the default), call each function block instance "
      "every cycle in the program (or check its POU alone with --pou), and check that the "
      "conditions of the initial steps' transitions read inputs.\n";
  return out;
}

bool from_command_line(const logic::PropertyResult& r) {
  const auto& f = r.where.file;
  return f.empty() || f == "--ctl" || f == "--ltl" || f == "--pattern";
}

std::string property_id(const logic::PropertyResult& r) {
  if (!r.check.empty()) return "check/" + r.check;
  if (!from_command_line(r)) {
    std::string id;
    for (char c : r.name)
      id +=
          std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ? c : '_';
    return "property/" + id;
  }
  std::string text;
  for (char c : r.name)
    if (!std::isspace(static_cast<unsigned char>(c))) text += c;
  const std::string kind = r.where.file.size() > 2 ? r.where.file.substr(2) : "ctl";
  return "property/" + kind + "-" + sha256_hex(text).substr(0, 12);
}

std::string property_file_stem(const logic::PropertyResult& r) {
  auto id = property_id(r);
  std::replace(id.begin(), id.end(), '/', '-');
  return id;
}

std::string findings_cut_note(const logic::PropertyResult& r) {
  if (r.findings_total <= r.findings.size()) return {};
  return std::to_string(r.findings.size()) + " of " + std::to_string(r.findings_total) +
         " findings shown; --all for every one";
}

std::string check_text(const logic::CheckReport& report, const semantics::TransitionSystem& ts,
                       const RenderOptions& options) {
  std::string out;
  out += (report.states_known ? counted(report.states.str(), "state") + ", " : std::string()) +
         (report.edges_known ? counted(report.edges.str(), "edge") + ", " : std::string()) +
         "depth " + std::to_string(report.depth) + " (" + report.engine + " engine, " +
         run_time_text(report.seconds) + ")";
  if (!report.complete)
    out += report.limit == "interrupted"
               ? std::string(" -- INCOMPLETE: interrupted (SIGINT or SIGTERM)")
               : " -- INCOMPLETE: the " + report.limit + " limit was reached";
  if (report.stopped_early)
    out +=
        " -- stopped early: every invariant is violated (the counts are those explored up to "
        "the violations)";
  out += "\n";
  if (const auto& c = report.coverage) {
    out += "coverage: " + std::to_string(c->steps_visited) + "/" + std::to_string(c->steps) +
           " steps active, " + std::to_string(c->transitions_fired) + "/" +
           std::to_string(c->transitions) + " transitions fired, " +
           std::to_string(c->actions_active) + "/" + std::to_string(c->actions) +
           " actions active" + (report.complete ? "" : " (so far)") + "\n";
    for (const auto& u : c->unvisited) out += "  never: " + u + "\n";
  }
  std::size_t width = 0;
  for (const auto& r : report.results) width = std::max(width, r.name.size());
  width = std::min<std::size_t>(width, 48);
  for (const auto& r : report.results) {
    std::string name = r.name;
    if (name.size() < width) name.resize(width, ' ');
    std::string verdict(logic::to_string(r.verdict));
    verdict.resize(11, ' ');
    out += name + "  " + verdict + " " + run_time_text(r.seconds);
    // --engine auto past its explicit probe: which engine answered.
    if (!r.decided_by.empty() && r.decided_by != report.engine) out += "  [" + r.decided_by + "]";
    if (!r.message.empty()) out += "  " + r.message;
    out += "\n";
    if (!r.description.empty()) out += "  requirement: " + r.description + "\n";
    if (!r.justification.empty()) out += "  justification: " + r.justification + "\n";
    if (r.check.empty() && r.formula != r.name) out += "  formula: " + r.formula + "\n";
    if (!r.vacuity.empty()) out += "  " + r.vacuity + "\n";
    for (const auto& f : r.findings) out += "  - " + f + "\n";
    if (const auto cut = findings_cut_note(r); !cut.empty()) out += "  (" + cut + ")\n";
    if (r.trace && options.trace != TraceFormat::None) {
      const bool cex = r.trace->kind == logic::TraceKind::Counterexample;
      out += std::string("  ") + (cex ? "counterexample" : "witness") + " (" +
             counted(r.trace->steps.size(), "situation") + ")";
      const bool inline_trace =
          options.trace == TraceFormat::Table || options.trace == TraceFormat::Json;
      const auto file = options.trace_files.find(property_id(r));
      if (file != options.trace_files.end())
        out += ": " + file->second + "\n";
      else
        out += inline_trace ? ":\n" : ": not written\n";
      switch (options.trace) {
        case TraceFormat::Table:
          out += trace_table(*r.trace, ts);
          break;
        case TraceFormat::Json:
          out += trace_json(*r.trace, ts);
          break;
        case TraceFormat::Vcd:
        case TraceFormat::Csv:
          break;  // files of their own (or standard output alone), never inside the text
        case TraceFormat::None:
          break;
      }
    }
  }
  out += stuck_diagnosis(report, ts);
  if (!options.verbose) out = concise_text(out, working_directory());
  if (options.provenance) out += provenance_text(*options.provenance);
  return valid_utf8(out);  // names are bytes; the report is UTF-8
}

nlohmann::json count_json(const logic::BigCount& count) {
  const auto small = count.to_u64();
  return small ? nlohmann::json(*small) : nlohmann::json(count.str());
}

nlohmann::json check_json(const logic::CheckReport& report, const semantics::TransitionSystem& ts,
                          const RenderOptions& options) {
  using nlohmann::json;
  json j;
  j["schema_version"] = kCheckJsonSchemaVersion;
  j["model"] = options.model;
  j["semantics"] = options.semantics;
  j["engine"] = report.engine;
  // A number while it fits in 64 bits (JSON readers take those exactly), else a decimal string.
  j["states"] = report.states_known ? count_json(report.states) : json(nullptr);
  j["edges"] = report.edges_known ? count_json(report.edges) : json(nullptr);
  j["depth"] = report.depth;
  // A search that stopped at the violations did not explore every reachable state: its counts
  // are those explored up to them, not the system's.
  j["complete"] = report.complete && !report.stopped_early;
  j["stopped_early"] = report.stopped_early;
  j["limit"] = report.complete ? json(nullptr) : json(report.limit);
  j["seconds"] = report.seconds;
  j["exit_code"] = logic::exit_code(report);
  if (const auto& c = report.coverage)
    j["coverage"] = {{"steps", c->steps},
                     {"steps_visited", c->steps_visited},
                     {"transitions", c->transitions},
                     {"transitions_fired", c->transitions_fired},
                     {"actions", c->actions},
                     {"actions_active", c->actions_active},
                     {"unvisited", c->unvisited}};
  j["properties"] = json::array();
  for (const auto& r : report.results) {
    json p;
    p["id"] = property_id(r);
    p["name"] = r.name;
    p["kind"] = r.check.empty() ? "property" : "standard-check";
    if (!r.check.empty()) p["check"] = r.check;
    p["formula"] = r.formula;
    if (!r.description.empty()) p["description"] = r.description;
    if (!r.justification.empty()) p["justification"] = r.justification;
    p["verdict"] = std::string(logic::to_string(r.verdict));
    const bool definite =
        r.verdict == logic::Verdict::Holds || r.verdict == logic::Verdict::Violated;
    p["decided_by"] =
        !definite ? json(nullptr) : json(r.decided_by.empty() ? report.engine : r.decided_by);
    p["message"] = r.message;
    p["findings"] = r.findings;
    p["findings_total"] = std::max(r.findings_total, r.findings.size());
    if (r.check.empty()) p["vacuous"] = r.vacuous ? json(*r.vacuous) : json(nullptr);
    if (!r.vacuity.empty()) p["vacuity"] = r.vacuity;
    p["seconds"] = r.seconds;
    if (r.where.known()) p["where"] = r.where.str();
    p["trace"] = r.trace ? trace_to_json(*r.trace, ts) : json(nullptr);
    j["properties"].push_back(std::move(p));
  }
  j["provenance"] = options.provenance ? provenance_json(*options.provenance) : json(nullptr);
  make_valid_utf8(j);  // names are bytes; a JSON document is UTF-8 (dump() throws otherwise)
  return j;
}

}  // namespace sfcv::report
