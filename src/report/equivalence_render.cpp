#include "report/equivalence_render.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>

#include "model/names.hpp"
#include "report/trace_render.hpp"

namespace sfcv::report {

namespace {

bool starts_with_ci(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && model::iequals(s.substr(0, prefix.size()), prefix);
}

/// A compared signal that its side never writes is a free input of the product, not kept in
/// the state: shown as "?".
constexpr std::uint32_t kNotObserved = ~std::uint32_t{0};
constexpr std::int64_t kUnknownValue = std::numeric_limits<std::int64_t>::min();

std::uint32_t observable(const semantics::TransitionSystem& ts, const std::string& name) {
  return semantics::find_observable(ts, name).value_or(kNotObserved);
}

std::int64_t value(const semantics::TransitionSystem& ts, semantics::StateView state,
                   std::uint32_t index) {
  return index == kNotObserved ? kUnknownValue : ts.observe(state, index);
}

std::string value_text(std::int64_t v) {
  return v == kUnknownValue ? "?" : std::to_string(v);
}

/// One cycle of a counterexample as the side-by-side views show it.
struct Row {
  std::vector<std::pair<std::string, std::int64_t>> inputs;  ///< non-zero ones
  std::vector<std::string> old_steps, new_steps;
  std::vector<std::pair<std::int64_t, std::int64_t>> values;  ///< per compared signal
  std::vector<bool> differs;                                  ///< per compared signal
};

std::vector<Row> rows(const logic::Trace& trace, const semantics::EquivalenceProduct& p,
                      const semantics::TransitionSystem& ts) {
  std::vector<std::uint32_t> old_ix, new_ix, flag_ix;
  for (const auto& s : p.compared) {
    old_ix.push_back(observable(ts, s.old_seen));
    new_ix.push_back(observable(ts, s.new_seen));
    flag_ix.push_back(observable(ts, s.differs));
  }
  const std::string old_prefix = semantics::kEquivOldPrefix;
  const std::string new_prefix = semantics::kEquivNewPrefix;
  std::vector<Row> out;
  for (std::size_t k = 0; k < trace.steps.size(); ++k) {
    const auto& step = trace.steps[k];
    Row row;
    if (k > 0)
      for (std::size_t i = 0; i < step.inputs.size() && i < ts.inputs().size(); ++i)
        if (step.inputs[i] != 0) row.inputs.emplace_back(ts.inputs()[i].name, step.inputs[i]);
    const auto& obs = ts.observables();
    for (std::uint32_t i = 0; i < obs.size(); ++i) {
      if (obs[i].kind != semantics::ObservableKind::Step || ts.observe(step.state, i) == 0)
        continue;
      if (starts_with_ci(obs[i].name, old_prefix))
        row.old_steps.push_back(obs[i].name.substr(old_prefix.size()));
      else if (starts_with_ci(obs[i].name, new_prefix))
        row.new_steps.push_back(obs[i].name.substr(new_prefix.size()));
    }
    for (std::size_t s = 0; s < p.compared.size(); ++s) {
      row.values.emplace_back(value(ts, step.state, old_ix[s]), value(ts, step.state, new_ix[s]));
      row.differs.push_back(value(ts, step.state, flag_ix[s]) == 1);
    }
    out.push_back(std::move(row));
  }
  return out;
}

std::string join(const std::vector<std::string>& parts, const char* sep) {
  std::string s;
  for (const auto& p : parts) s += (s.empty() ? "" : sep) + p;
  return s;
}

std::string inputs_text(const Row& row, bool first) {
  if (first) return "(initial)";
  std::vector<std::string> parts;
  for (const auto& [name, value] : row.inputs)
    parts.push_back(value == 1 ? name : name + "=" + std::to_string(value));
  return parts.empty() ? "-" : join(parts, " ");
}

std::string verdict_text(logic::Verdict v) {
  switch (v) {
    case logic::Verdict::Holds:
      return "equivalent";
    case logic::Verdict::Violated:
      return "differ";
    default:
      return "unknown";
  }
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f s", s);
  return buf;
}

/// The signals a result is about: every compared one, or the one of --changed.
std::vector<std::size_t> signals_of(const EquivalenceRun& run,
                                    const semantics::EquivalenceProduct& p, std::size_t result) {
  std::vector<std::size_t> out;
  for (std::size_t s = 0; s < p.compared.size(); ++s)
    if (!run.per_signal || s == result) out.push_back(s);
  return out;
}

}  // namespace

std::string equivalence_verdict(const logic::CheckReport& report) {
  const int code = logic::exit_code(report);
  return code == 0 ? "equivalent" : code == 1 ? "differ" : "unknown";
}

std::string equivalence_trace_table(const logic::Trace& trace,
                                    const semantics::EquivalenceProduct& p,
                                    const semantics::TransitionSystem& ts) {
  const auto table = rows(trace, p, ts);
  std::vector<std::vector<std::string>> cells;
  std::vector<std::string> header = {"cycle", "inputs", "OLD steps", "NEW steps"};
  for (const auto& s : p.compared)
    header.push_back(model::iequals(s.name, s.new_name) ? s.name : s.name + "/" + s.new_name);
  cells.push_back(header);
  for (std::size_t k = 0; k < table.size(); ++k) {
    const auto& r = table[k];
    std::vector<std::string> line = {std::to_string(k), inputs_text(r, k == 0),
                                     r.old_steps.empty() ? "-" : join(r.old_steps, ","),
                                     r.new_steps.empty() ? "-" : join(r.new_steps, ",")};
    for (std::size_t s = 0; s < r.values.size(); ++s)
      line.push_back(value_text(r.values[s].first) + "/" + value_text(r.values[s].second) +
                     (r.differs[s] ? " *" : ""));
    cells.push_back(std::move(line));
  }
  std::vector<std::size_t> width(header.size(), 0);
  for (const auto& line : cells)
    for (std::size_t c = 0; c < line.size(); ++c) width[c] = std::max(width[c], line[c].size());
  std::string out;
  for (const auto& line : cells) {
    std::string text;
    for (std::size_t c = 0; c < line.size(); ++c)
      text +=
          line[c] + (c + 1 < line.size() ? std::string(width[c] - line[c].size() + 2, ' ') : "");
    out += "  " + text + "\n";
  }
  out += "  (signals as OLD/NEW at the end of each cycle; * where they differ";
  out += p.compared.empty() ? ")\n" : "; --within counts the lag)\n";
  return out;
}

nlohmann::json equivalence_trace_json(const logic::Trace& trace,
                                      const semantics::EquivalenceProduct& p,
                                      const semantics::TransitionSystem& ts) {
  const auto table = rows(trace, p, ts);
  auto cycles = nlohmann::json::array();
  for (std::size_t k = 0; k < table.size(); ++k) {
    const auto& r = table[k];
    nlohmann::json inputs = nlohmann::json::object();
    for (const auto& [name, value] : r.inputs) inputs[name] = value;
    nlohmann::json old_side = {{"steps", r.old_steps}}, new_side = {{"steps", r.new_steps}};
    nlohmann::json old_values = nlohmann::json::object(), new_values = nlohmann::json::object();
    auto differs = nlohmann::json::array();
    for (std::size_t s = 0; s < p.compared.size(); ++s) {
      const auto json_value = [](std::int64_t v) {
        return v == kUnknownValue ? nlohmann::json() : nlohmann::json(v);
      };
      old_values[p.compared[s].name] = json_value(r.values[s].first);
      new_values[p.compared[s].new_name] = json_value(r.values[s].second);
      if (r.differs[s]) differs.push_back(p.compared[s].name);
    }
    old_side["signals"] = old_values;
    new_side["signals"] = new_values;
    cycles.push_back({{"cycle", k},
                      {"inputs", inputs},
                      {"old", old_side},
                      {"new", new_side},
                      {"differs", differs}});
  }
  return {{"length", trace.steps.empty() ? 0 : trace.steps.size() - 1}, {"cycles", cycles}};
}

std::string equivalence_trace_vcd(const logic::Trace& trace, const semantics::EquivalenceProduct& p,
                                  const semantics::TransitionSystem& ts, std::int64_t cycle_ms) {
  logic::Trace marked = trace;
  for (const auto& s : p.compared)
    for (const auto* name : {&s.old_seen, &s.new_seen, &s.differs}) {
      const auto ix = observable(ts, *name);
      if (ix != kNotObserved &&
          std::find(marked.marked.begin(), marked.marked.end(), ix) == marked.marked.end())
        marked.marked.push_back(ix);
    }
  return trace_vcd(marked, ts, {cycle_ms});
}

std::string equivalence_text(const EquivalenceRun& run, const semantics::EquivalenceProduct& p,
                             const semantics::TransitionSystem& ts) {
  std::string out = "sfcv equiv " + run.old_path + " " + run.new_path + ": " +
                    equivalence_verdict(run.report) + "\n";
  std::vector<std::string> names;
  for (const auto& s : p.compared)
    names.push_back(model::iequals(s.name, s.new_name) ? s.name : s.name + "=" + s.new_name);
  out += "  compared (" + std::to_string(names.size()) + "): " + join(names, ", ") + "\n";
  out += "  shared inputs (" + std::to_string(p.shared_inputs.size()) +
         "): " + (p.shared_inputs.empty() ? "-" : join(p.shared_inputs, ", ")) + "\n";
  if (run.within) out += "  NEW may lag by up to " + std::to_string(run.within) + " cycles\n";
  for (const auto& n : p.notes) out += "  note: " + n + "\n";
  const auto& r = run.report;
  for (std::size_t i = 0; i < r.results.size(); ++i) {
    const auto& res = r.results[i];
    const auto engine = res.decided_by.empty() ? r.engine : res.decided_by;
    std::string what = run.per_signal && i < p.compared.size() ? p.compared[i].name : "all";
    out += "  " + what + ": " + verdict_text(res.verdict);
    if (res.verdict == logic::Verdict::Violated && res.trace)
      out += " after " + std::to_string(res.trace->steps.size() - 1) + " cycle(s)";
    out += " (" + engine + ", " + seconds_text(res.seconds) + ")";
    if (res.verdict != logic::Verdict::Holds && res.verdict != logic::Verdict::Violated &&
        !res.message.empty())
      out += ": " + res.message;
    out += "\n";
    if (res.verdict == logic::Verdict::Violated && res.trace) {
      std::vector<std::string> differing;
      const auto table = rows(*res.trace, p, ts);
      for (const auto s : signals_of(run, p, i))
        if (!table.empty() && table.back().differs[s]) differing.push_back(p.compared[s].name);
      out += "  first difference: " + join(differing, ", ") + "\n";
      out += equivalence_trace_table(*res.trace, p, ts);
    }
  }
  return out;
}

nlohmann::json equivalence_json(const EquivalenceRun& run, const semantics::EquivalenceProduct& p,
                                const semantics::TransitionSystem& ts) {
  auto compared = nlohmann::json::array();
  for (const auto& s : p.compared)
    compared.push_back({{"old", s.name}, {"new", s.new_name}, {"internal", s.internal}});
  auto results = nlohmann::json::array();
  const auto& r = run.report;
  for (std::size_t i = 0; i < r.results.size(); ++i) {
    const auto& res = r.results[i];
    nlohmann::json j = {
        {"signal", run.per_signal && i < p.compared.size() ? p.compared[i].name : "all"},
        {"verdict", verdict_text(res.verdict)},
        {"engine", res.decided_by.empty() ? r.engine : res.decided_by},
        {"seconds", res.seconds}};
    if (!res.message.empty()) j["message"] = res.message;
    if (res.verdict == logic::Verdict::Violated && res.trace)
      j["trace"] = equivalence_trace_json(*res.trace, p, ts);
    results.push_back(std::move(j));
  }
  return {{"old", run.old_path},  {"new", run.new_path},  {"verdict", equivalence_verdict(r)},
          {"within", run.within}, {"compared", compared}, {"shared_inputs", p.shared_inputs},
          {"notes", p.notes},     {"engine", r.engine},   {"seconds", r.seconds},
          {"results", results}};
}

}  // namespace sfcv::report
