#include "report/check_render.hpp"

#include <algorithm>
#include <cstdio>

#include "report/text_encoding.hpp"
#include "report/trace_render.hpp"

namespace sfcv::report {

namespace {
std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3fs", s);
  return buf;
}
}  // namespace

std::string findings_cut_note(const logic::PropertyResult& r) {
  if (r.findings_total <= r.findings.size()) return {};
  return std::to_string(r.findings.size()) + " of " + std::to_string(r.findings_total) +
         " findings shown; --all for every one";
}

std::string check_text(const logic::CheckReport& report, const semantics::TransitionSystem& ts,
                       const RenderOptions& options) {
  std::string out;
  out += (report.states_known ? report.states.str() + " states, " : std::string()) +
         (report.edges_known ? report.edges.str() + " edges, " : std::string()) + "depth " +
         std::to_string(report.depth) + " (" + report.engine + " engine, " +
         seconds(report.seconds) + ")";
  if (!report.complete)
    out += report.limit == "interrupted"
               ? std::string(" -- INCOMPLETE: interrupted (SIGINT or SIGTERM)")
               : " -- INCOMPLETE: the " + report.limit + " limit was reached";
  if (report.stopped_early) out += " -- stopped early: every invariant is violated";
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
    out += name + "  " + verdict + " " + seconds(r.seconds);
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
             std::to_string(r.trace->steps.size()) + " situations):\n";
      switch (options.trace) {
        case TraceFormat::Table:
          out += trace_table(*r.trace, ts);
          break;
        case TraceFormat::Json:
          out += trace_json(*r.trace, ts);
          break;
        case TraceFormat::Vcd:
          out += trace_vcd(*r.trace, ts, {options.cycle_ms});
          break;
        case TraceFormat::Csv:
          out += trace_csv(*r.trace, ts);
          break;
        case TraceFormat::None:
          break;
      }
    }
  }
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
  j["model"] = options.model;
  j["semantics"] = options.semantics;
  j["engine"] = report.engine;
  // A number while it fits in 64 bits (JSON readers take those exactly), else a decimal string.
  j["states"] = report.states_known ? count_json(report.states) : json(nullptr);
  j["edges"] = report.edges_known ? count_json(report.edges) : json(nullptr);
  j["depth"] = report.depth;
  j["complete"] = report.complete;
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
  make_valid_utf8(j);  // names are bytes; a JSON document is UTF-8 (dump() throws otherwise)
  return j;
}

}  // namespace sfcv::report
