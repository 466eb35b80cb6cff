#include "report/trace_render.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <nlohmann/json.hpp>

#include "report/check_render.hpp"

namespace sfcv::report {

namespace {

using semantics::ObservableKind;

bool is_bool(const semantics::InputVariable& in) { return in.type.kind == model::TypeKind::Bool; }

bool marked(const logic::Trace& t, std::uint32_t obs) {
  return std::find(t.marked.begin(), t.marked.end(), obs) != t.marked.end();
}

/// Observables a trace shows: steps, outputs and the marked atoms.
std::vector<std::uint32_t> shown_observables(const logic::Trace& t,
                                             const semantics::TransitionSystem& ts) {
  std::vector<std::uint32_t> out;
  const auto& obs = ts.observables();
  for (std::uint32_t i = 0; i < obs.size(); ++i)
    if (obs[i].kind == ObservableKind::Step || obs[i].is_output || marked(t, i)) out.push_back(i);
  return out;
}

std::string input_change(const semantics::InputVariable& in, std::int64_t v) {
  if (is_bool(in)) return (v ? "+" : "-") + in.name;
  return in.name + "=" + std::to_string(v);
}

std::string vcd_id(std::size_t i) {
  std::string id;
  do {
    id += static_cast<char>('!' + i % 94);
    i /= 94;
  } while (i);
  return id;
}

std::string binary(std::int64_t v) {
  std::string s;
  auto u = static_cast<std::uint64_t>(v);
  for (int b = 31; b >= 0; --b) s += ((u >> b) & 1U) ? '1' : '0';
  const auto first = s.find('1');
  return first == std::string::npos ? "0" : s.substr(first);
}

/// The shortest name of each observable that still resolves to it ("s1" for
/// "ChemicalPlant.s1" when unambiguous), to keep tables narrow.
std::vector<std::string> short_names(const semantics::TransitionSystem& ts) {
  const auto& obs = ts.observables();
  std::vector<std::string> out;
  for (std::uint32_t i = 0; i < obs.size(); ++i) {
    std::string best = obs[i].name;
    for (const auto& a : obs[i].aliases) {
      // Bare numbers ("12" for Grafcet step X12) read badly in a table.
      if (a.size() >= best.size() || std::isdigit(static_cast<unsigned char>(a[0]))) continue;
      const auto hit = semantics::find_observable(ts, a);
      if (hit && *hit == i) best = a;
    }
    out.push_back(best);
  }
  return out;
}

}  // namespace

std::string trace_table(const logic::Trace& trace, const semantics::TransitionSystem& ts) {
  const auto& obs = ts.observables();
  const auto& inputs = ts.inputs();
  const auto& trs = ts.transitions();
  const auto names = short_names(ts);
  std::vector<std::array<std::string, 6>> rows;
  rows.push_back({"#", "inputs (changed)", "fired", "active steps", "outputs", "atoms"});
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const auto& st = trace.steps[i];
    std::array<std::string, 6> row;
    row[0] = (trace.loop_start && *trace.loop_start == i ? "->" : "") + std::to_string(i);
    for (std::size_t k = 0; k < inputs.size() && k < st.inputs.size(); ++k) {
      const bool changed = i == 0 ? (st.inputs[k] != (is_bool(inputs[k]) ? 0 : inputs[k].type.lo))
                                  : st.inputs[k] != trace.steps[i - 1].inputs[k];
      if (changed) row[1] += (row[1].empty() ? "" : " ") + input_change(inputs[k], st.inputs[k]);
    }
    for (auto t : st.fired) row[2] += (row[2].empty() ? "" : ", ") + (t < trs.size() ? trs[t].name : "?");
    for (std::uint32_t o = 0; o < obs.size(); ++o) {
      const auto v = ts.observe(st.state, o);
      const std::string mark = marked(trace, o) ? "*" : "";
      if (obs[o].kind == ObservableKind::Step) {
        if (v) row[3] += (row[3].empty() ? "" : " ") + names[o] + mark;
      } else if (obs[o].is_output) {
        if (obs[o].type.kind == model::TypeKind::Bool) {
          if (v) row[4] += (row[4].empty() ? "" : " ") + names[o] + mark;
        } else {
          row[4] += (row[4].empty() ? "" : " ") + names[o] + "=" + std::to_string(v) + mark;
        }
      }
      if (marked(trace, o)) row[5] += (row[5].empty() ? "" : " ") + names[o] + "=" + std::to_string(v);
    }
    rows.push_back(std::move(row));
  }
  std::array<std::size_t, 6> width{};
  for (const auto& r : rows)
    for (std::size_t c = 0; c < 6; ++c) width[c] = std::max(width[c], r[c].size());
  std::string out;
  if (!trace.note.empty()) out += "  " + trace.note + "\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::string line = "  ";
    for (std::size_t c = 0; c < 6; ++c) {
      if (c == 5 && trace.marked.empty()) break;
      auto cell = rows[r][c];
      if (c + 1 < 6) cell.resize(width[c], ' ');
      line += cell + (c + 1 < 6 ? " | " : "");
    }
    while (!line.empty() && (line.back() == ' ' || line.back() == '|')) line.pop_back();
    out += line + "\n";
    if (r == 0) {
      std::string rule = "  ";
      for (std::size_t c = 0; c < 6; ++c) {
        if (c == 5 && trace.marked.empty()) break;
        rule += std::string(width[c], '-') + (c + 1 < 6 ? "-+-" : "");
      }
      out += rule + "\n";
    }
  }
  if (trace.loop_start)
    out += "  (the last row is row " + std::to_string(*trace.loop_start) +
           " again: the run repeats rows " + std::to_string(*trace.loop_start) + ".." +
           std::to_string(trace.steps.size() - 1) + " forever)\n";
  if (trace.ends_in_deadlock) out += "  (the run ends: the last situation has no successor)\n";
  return out;
}

nlohmann::json trace_to_json(const logic::Trace& trace, const semantics::TransitionSystem& ts) {
  using nlohmann::json;
  const auto& obs = ts.observables();
  const auto& inputs = ts.inputs();
  const auto& trs = ts.transitions();
  json j;
  j["kind"] = trace.kind == logic::TraceKind::Witness ? "witness" : "counterexample";
  j["loop_start"] = trace.loop_start ? json(*trace.loop_start) : json(nullptr);
  j["ends_in_deadlock"] = trace.ends_in_deadlock;
  j["note"] = trace.note;
  j["marked"] = json::array();
  for (auto m : trace.marked) j["marked"].push_back(obs[m].name);
  j["steps"] = json::array();
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const auto& st = trace.steps[i];
    json row;
    row["index"] = i;
    json in = json::object();
    json changed = json::array();
    for (std::size_t k = 0; k < inputs.size() && k < st.inputs.size(); ++k) {
      in[inputs[k].name] = is_bool(inputs[k]) ? json(st.inputs[k] != 0) : json(st.inputs[k]);
      if (i > 0 && st.inputs[k] != trace.steps[i - 1].inputs[k]) changed.push_back(inputs[k].name);
    }
    row["inputs"] = in;
    row["changed"] = changed;
    row["fired"] = json::array();
    for (auto t : st.fired) row["fired"].push_back(t < trs.size() ? trs[t].name : "?");
    row["active_steps"] = json::array();
    json values = json::object();
    for (std::uint32_t o = 0; o < obs.size(); ++o) {
      const auto v = ts.observe(st.state, o);
      if (obs[o].kind == ObservableKind::Step && v) row["active_steps"].push_back(obs[o].name);
      if (obs[o].is_output || marked(trace, o) || obs[o].kind != ObservableKind::Step)
        values[obs[o].name] = obs[o].type.kind == model::TypeKind::Bool ? json(v != 0) : json(v);
    }
    row["values"] = values;
    row["situation"] = ts.describe(st.state);
    j["steps"].push_back(std::move(row));
  }
  return j;
}

std::string trace_json(const logic::Trace& trace, const semantics::TransitionSystem& ts) {
  return trace_to_json(trace, ts).dump(2) + "\n";
}

std::string trace_vcd(const logic::Trace& trace, const semantics::TransitionSystem& ts) {
  const auto& obs = ts.observables();
  const auto& inputs = ts.inputs();
  const auto shown = shown_observables(trace, ts);
  std::string out;
  out += "$comment sfcv trace: one time unit per cycle (IEC 61131-3) or stable situation "
         "(Grafcet) $end\n";
  out += "$timescale 1 ns $end\n$scope module inputs $end\n";
  auto var = [&](std::size_t id, const model::Type& type, const std::string& name) {
    const bool b = type.kind == model::TypeKind::Bool;
    std::string safe = name;
    for (auto& c : safe)
      if (c == ' ' || c == ':') c = '_';
    out += std::string("$var ") + (b ? "wire 1 " : "integer 32 ") + vcd_id(id) + " " + safe +
           " $end\n";
  };
  for (std::size_t k = 0; k < inputs.size(); ++k) var(k, inputs[k].type, inputs[k].name);
  out += "$upscope $end\n$scope module state $end\n";
  for (std::size_t i = 0; i < shown.size(); ++i)
    var(inputs.size() + i, obs[shown[i]].type, obs[shown[i]].name);
  out += "$upscope $end\n$enddefinitions $end\n";
  auto value = [&](std::size_t id, bool b, std::int64_t v) {
    if (b) return std::string(v ? "1" : "0") + vcd_id(id) + "\n";
    return "b" + binary(v) + " " + vcd_id(id) + "\n";
  };
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const auto& st = trace.steps[i];
    out += "#" + std::to_string(i) + "\n";
    if (i == 0) out += "$dumpvars\n";
    for (std::size_t k = 0; k < inputs.size() && k < st.inputs.size(); ++k)
      if (i == 0 || st.inputs[k] != trace.steps[i - 1].inputs[k])
        out += value(k, is_bool(inputs[k]), st.inputs[k]);
    for (std::size_t s = 0; s < shown.size(); ++s) {
      const auto v = ts.observe(st.state, shown[s]);
      if (i == 0 || v != ts.observe(trace.steps[i - 1].state, shown[s]))
        out += value(inputs.size() + s, obs[shown[s]].type.kind == model::TypeKind::Bool, v);
    }
    if (i == 0) out += "$end\n";
  }
  out += "#" + std::to_string(trace.steps.size()) + "\n";
  return out;
}

std::string trace_csv(const logic::Trace& trace, const semantics::TransitionSystem& ts) {
  const auto& inputs = ts.inputs();
  std::string out = "# sfcv check trace: one row per cycle after the initial situation";
  if (trace.loop_start)
    out += "; rows from cycle " + std::to_string(*trace.loop_start + 1) + " on repeat forever";
  out += "\n";
  for (std::size_t k = 0; k < inputs.size(); ++k) out += (k ? "," : "") + inputs[k].name;
  out += "\n";
  for (std::size_t i = 1; i < trace.steps.size(); ++i) {
    for (std::size_t k = 0; k < inputs.size(); ++k)
      out += (k ? "," : "") + std::to_string(k < trace.steps[i].inputs.size() ? trace.steps[i].inputs[k] : 0);
    out += "\n";
  }
  return out;
}

}  // namespace sfcv::report
