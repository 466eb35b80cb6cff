#include "report/shard_result.hpp"

#include <stdexcept>

namespace sfcv::report {

namespace {

using nlohmann::json;

logic::BigCount count_from_string(const std::string& s) {
  logic::BigCount n;
  for (const char c : s) {
    if (c < '0' || c > '9') throw std::invalid_argument("not a count: " + s);
    logic::BigCount ten = n.shifted_left(3);
    ten += n.shifted_left(1);
    ten += logic::BigCount(static_cast<std::uint64_t>(c - '0'));
    n = ten;
  }
  return n;
}

json trace_raw(const logic::Trace& t) {
  json steps = json::array();
  for (const auto& s : t.steps)
    steps.push_back({{"inputs", s.inputs}, {"state", s.state}, {"fired", s.fired}});
  return {{"kind", t.kind == logic::TraceKind::Witness ? "witness" : "counterexample"},
          {"steps", steps},
          {"loop_start", t.loop_start ? json(*t.loop_start) : json(nullptr)},
          {"ends_in_deadlock", t.ends_in_deadlock},
          {"marked", t.marked},
          {"note", t.note}};
}

logic::Trace trace_from_raw(const json& j) {
  logic::Trace t;
  t.kind = j.at("kind") == "witness" ? logic::TraceKind::Witness : logic::TraceKind::Counterexample;
  for (const auto& s : j.at("steps"))
    t.steps.push_back({s.at("inputs").get<std::vector<std::int64_t>>(),
                       s.at("state").get<std::vector<semantics::StateWord>>(),
                       s.at("fired").get<std::vector<std::uint32_t>>()});
  if (!j.at("loop_start").is_null()) t.loop_start = j.at("loop_start").get<std::size_t>();
  t.ends_in_deadlock = j.at("ends_in_deadlock").get<bool>();
  t.marked = j.at("marked").get<std::vector<std::uint32_t>>();
  t.note = j.at("note").get<std::string>();
  return t;
}

logic::Verdict verdict_from(const std::string& s) {
  for (const auto v : {logic::Verdict::Holds, logic::Verdict::Violated, logic::Verdict::Unknown,
                       logic::Verdict::NotChecked, logic::Verdict::NotApplicable})
    if (logic::to_string(v) == s) return v;
  throw std::invalid_argument("not a verdict: " + s);
}

json result_raw(const logic::PropertyResult& r) {
  return {{"name", r.name},
          {"formula", r.formula},
          {"description", r.description},
          {"justification", r.justification},
          {"check", r.check},
          {"verdict", std::string(logic::to_string(r.verdict))},
          {"message", r.message},
          {"findings", r.findings},
          {"findings_total", r.findings_total},
          {"trace", r.trace ? trace_raw(*r.trace) : json(nullptr)},
          {"certificate", r.certificate},
          {"vacuous", r.vacuous ? json(*r.vacuous) : json(nullptr)},
          {"vacuity", r.vacuity},
          {"seconds", r.seconds},
          {"where",
           {{"file", r.where.file},
            {"line", r.where.line},
            {"column", r.where.column},
            {"element_path", r.where.element_path}}},
          {"decided_by", r.decided_by}};
}

logic::PropertyResult result_from_raw(const json& j) {
  logic::PropertyResult r;
  r.name = j.at("name");
  r.formula = j.at("formula");
  r.description = j.at("description");
  r.justification = j.at("justification");
  r.check = j.at("check");
  r.verdict = verdict_from(j.at("verdict"));
  r.message = j.at("message");
  r.findings = j.at("findings").get<std::vector<std::string>>();
  r.findings_total = j.at("findings_total");
  if (!j.at("trace").is_null()) r.trace = trace_from_raw(j.at("trace"));
  r.certificate = j.at("certificate");
  if (!j.at("vacuous").is_null()) r.vacuous = j.at("vacuous").get<bool>();
  r.vacuity = j.at("vacuity");
  r.seconds = j.at("seconds");
  const auto& w = j.at("where");
  r.where.file = w.at("file");
  r.where.line = w.at("line");
  r.where.column = w.at("column");
  r.where.element_path = w.at("element_path");
  r.decided_by = j.at("decided_by");
  return r;
}

}  // namespace

json report_to_json(const logic::CheckReport& report) {
  json results = json::array();
  for (const auto& r : report.results) results.push_back(result_raw(r));
  json coverage = nullptr;
  if (report.coverage) {
    const auto& c = *report.coverage;
    coverage = {{"steps", c.steps},
                {"steps_visited", c.steps_visited},
                {"transitions", c.transitions},
                {"transitions_fired", c.transitions_fired},
                {"actions", c.actions},
                {"actions_active", c.actions_active},
                {"unvisited", c.unvisited}};
  }
  return {{"engine", report.engine},
          {"states", report.states.str()},
          {"edges", report.edges.str()},
          {"states_known", report.states_known},
          {"edges_known", report.edges_known},
          {"depth", report.depth},
          {"stopped_early", report.stopped_early},
          {"complete", report.complete},
          {"limit", report.limit},
          {"seconds", report.seconds},
          {"results", results},
          {"coverage", coverage}};
}

logic::CheckReport report_from_json(const json& j) {
  logic::CheckReport report;
  report.engine = j.at("engine");
  report.states = count_from_string(j.at("states"));
  report.edges = count_from_string(j.at("edges"));
  report.states_known = j.at("states_known");
  report.edges_known = j.at("edges_known");
  report.depth = j.at("depth");
  report.stopped_early = j.at("stopped_early");
  report.complete = j.at("complete");
  report.limit = j.at("limit");
  report.seconds = j.at("seconds");
  for (const auto& r : j.at("results")) report.results.push_back(result_from_raw(r));
  if (const auto& c = j.at("coverage"); !c.is_null()) {
    logic::Coverage cov;
    cov.steps = c.at("steps");
    cov.steps_visited = c.at("steps_visited");
    cov.transitions = c.at("transitions");
    cov.transitions_fired = c.at("transitions_fired");
    cov.actions = c.at("actions");
    cov.actions_active = c.at("actions_active");
    cov.unvisited = c.at("unvisited").get<std::vector<std::string>>();
    report.coverage = cov;
  }
  return report;
}

json units_json(const std::vector<logic::WorkUnit>& units, std::uint32_t count) {
  const auto shard = logic::assign_shards(units, count);
  json out = json::array();
  for (std::size_t i = 0; i < units.size(); ++i)
    out.push_back({{"id", units[i].id},
                   {"kind", units[i].kind},
                   {"name", units[i].name},
                   {"cost", units[i].cost},
                   {"shard", shard[i] + 1}});
  return out;
}

json shard_json(const logic::ShardSpec& spec, bool diversify,
                const std::vector<logic::WorkUnit>& units,
                const std::vector<logic::WorkUnit>& covered, const logic::CheckReport& report,
                const Provenance& provenance) {
  json ids = json::array();
  for (const auto& u : covered) ids.push_back(u.id);
  return {{"index", spec.index},
          {"count", spec.count},
          {"diversify", diversify},
          {"units", units_json(units, diversify ? 1 : spec.count)},
          {"covers", ids},
          {"result", report_to_json(report)},
          {"settings", provenance.settings},
          {"libraries", provenance.libraries}};
}

}  // namespace sfcv::report
