#include "report/trace_render.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <functional>
#include <nlohmann/json.hpp>

#include "report/check_render.hpp"
#include "report/provenance.hpp"
#include "report/text_encoding.hpp"

namespace sfcv::report {

namespace {

using semantics::ObservableKind;

bool is_bool(const semantics::InputVariable& in) {
  return in.type.kind == model::TypeKind::Bool;
}

bool marked(const logic::Trace& t, std::uint32_t obs) {
  return std::find(t.marked.begin(), t.marked.end(), obs) != t.marked.end();
}

/// An integer as its type names it: the enumerator of an enumeration (`Filling`), else the
/// number (the JSON and CSV traces keep numbers, for replay).
std::string value_text(const model::Type& type, std::int64_t v) {
  for (const auto& [name, value] : type.enumerators)
    if (value == v) return name;
  return std::to_string(v);
}

std::string input_change(const semantics::InputVariable& in, std::int64_t v) {
  if (is_bool(in)) return (v ? "+" : "-") + in.name;
  return in.name + "=" + value_text(in.type, v);
}

std::string vcd_id(std::size_t i) {
  std::string id;
  do {
    id += static_cast<char>('!' + i % 94);
    i /= 94;
  } while (i);
  return id;
}

/// A VCD reference is an identifier: letters, digits and '_' ("ChemicalPlant.s1" becomes
/// "ChemicalPlant_s1", "timeout:T1" becomes "timeout_T1").
std::string vcd_name(const std::string& name) {
  std::string r;
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    r += u < 0x80 && (std::isalnum(u) || c == '_') ? c : '_';
  }
  return r.empty() ? "_" : r;  // "$var wire 1 ! $end" would lack its reference
}

/// A CSV field as RFC 4180 quotes it: in double quotes, `"` doubled, when it holds a separator
/// (',' or the ';' that `sfcv simulate` also accepts), a quote, a line break, a leading '#'
/// (a comment line to the reader) or leading or trailing spaces (which the reader trims), or
/// is empty.
std::string csv_field(const std::string& s) {
  const bool plain = !s.empty() && s.find_first_of(",;\"\r\n") == std::string::npos &&
                     s[0] != '#' && !std::isspace(static_cast<unsigned char>(s.front())) &&
                     !std::isspace(static_cast<unsigned char>(s.back()));
  if (plain) return s;
  std::string r = "\"";
  for (char c : s) r += c == '"' ? std::string("\"\"") : std::string(1, c);
  return r + "\"";
}

/// Two's complement, 64 bits, leading zeros dropped.
std::string binary(std::int64_t v) {
  std::string s;
  auto u = static_cast<std::uint64_t>(v);
  for (int b = 63; b >= 0; --b) s += ((u >> b) & 1U) ? '1' : '0';
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
      // Row 0 shows every integer input (its value matters even if it never changes) and the
      // Boolean inputs that are true; later rows show what changed.
      const bool changed = i == 0 ? (!is_bool(inputs[k]) || st.inputs[k] != 0)
                                  : st.inputs[k] != trace.steps[i - 1].inputs[k];
      if (changed) row[1] += (row[1].empty() ? "" : " ") + input_change(inputs[k], st.inputs[k]);
    }
    for (auto t : st.fired)
      row[2] += (row[2].empty() ? "" : ", ") + (t < trs.size() ? trs[t].name : "?");
    for (std::uint32_t o = 0; o < obs.size(); ++o) {
      const auto v = ts.observe(st.state, o);
      const std::string mark = marked(trace, o) ? "*" : "";
      if (obs[o].kind == ObservableKind::Step) {
        if (v) row[3] += (row[3].empty() ? "" : " ") + names[o] + mark;
      } else if (obs[o].is_output) {
        if (obs[o].type.kind == model::TypeKind::Bool) {
          if (v) row[4] += (row[4].empty() ? "" : " ") + names[o] + mark;
        } else {
          row[4] +=
              (row[4].empty() ? "" : " ") + names[o] + "=" + value_text(obs[o].type, v) + mark;
        }
      }
      if (marked(trace, o))
        row[5] += (row[5].empty() ? "" : " ") + names[o] + "=" + value_text(obs[o].type, v);
    }
    rows.push_back(std::move(row));
  }
  std::array<std::size_t, 6> width{};
  for (const auto& r : rows)
    for (std::size_t c = 0; c < 6; ++c) width[c] = std::max(width[c], r[c].size());
  std::string out;
  if (!trace.note.empty()) out += "  " + trace.note + "\n";
  const std::size_t columns = trace.marked.empty() ? 5 : 6;  // the atoms column when marked
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::string line = "  ";
    for (std::size_t c = 0; c < columns; ++c) {
      auto cell = rows[r][c];
      if (c + 1 < columns) cell.resize(width[c], ' ');
      line += cell + (c + 1 < columns ? " | " : "");
    }
    while (!line.empty() && (line.back() == ' ' || line.back() == '|')) line.pop_back();
    out += line + "\n";
    if (r == 0) {
      std::string rule = "  ";
      for (std::size_t c = 0; c < columns; ++c)
        rule += std::string(width[c], '-') + (c + 1 < columns ? "-+-" : "");
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
  auto j = trace_to_json(trace, ts);
  make_valid_utf8(j);
  return j.dump(2) + "\n";
}

std::string trace_vcd(const logic::Trace& trace, const semantics::TransitionSystem& ts,
                      const VcdOptions& options) {
  const auto& obs = ts.observables();
  const auto& inputs = ts.inputs();
  const bool grafcet = ts.kind() == semantics::SemanticsKind::Grafcet;
  struct Signal {
    std::string scope, name;
    bool is_bool;
    std::function<std::int64_t(const logic::TraceStep&)> value;
  };
  std::vector<Signal> signals;
  for (std::size_t k = 0; k < inputs.size(); ++k)
    signals.push_back(
        {"inputs", inputs[k].name, is_bool(inputs[k]),
         [k](const logic::TraceStep& st) { return k < st.inputs.size() ? st.inputs[k] : 0; }});
  auto observed = [&ts](std::uint32_t o) {
    return [&ts, o](const logic::TraceStep& st) { return ts.observe(st.state, o); };
  };
  for (std::uint32_t o = 0; o < obs.size(); ++o) {
    const char* scope = obs[o].kind == ObservableKind::Step     ? "steps"
                        : obs[o].kind == ObservableKind::Action ? "actions"
                        : obs[o].is_output                      ? "outputs"
                        : marked(trace, o)                      ? "atoms"
                                                                : nullptr;
    if (scope)
      signals.push_back(
          {scope, obs[o].name, obs[o].type.kind == model::TypeKind::Bool, observed(o)});
  }
  // A lasso's loop point as a signal: 1 from the step the run returns to, so a waveform viewer
  // shows which part repeats forever.
  if (trace.loop_start) {
    const std::size_t loop = *trace.loop_start;
    const auto* first = trace.steps.empty() ? nullptr : &trace.steps.front();
    signals.push_back({"trace", "in_loop", true, [loop, first](const logic::TraceStep& st) {
                         return static_cast<std::int64_t>(static_cast<std::size_t>(&st - first) >=
                                                          loop);
                       }});
  }
  std::string out = "$comment sfcv trace: ";
  out += grafcet ? "one time unit per stable situation (Grafcet has no scan cycle)"
                 : "one scan cycle of " + std::to_string(options.step_ms) + " ms per step";
  out += " $end\n";
  const std::int64_t unit = grafcet ? 1 : std::max<std::int64_t>(1, options.step_ms);
  if (trace.loop_start)
    out += "$comment loop: the last step is step " + std::to_string(*trace.loop_start) +
           " again (time " + std::to_string(static_cast<std::int64_t>(*trace.loop_start) * unit) +
           "): steps " + std::to_string(*trace.loop_start) + ".." +
           std::to_string(trace.steps.size() - 1) + " repeat forever (signal trace.in_loop) $end\n";
  if (trace.ends_in_deadlock)
    out += "$comment the run ends: the last situation has no successor $end\n";
  out += "$version sfcv " + build_version() + " $end\n$timescale 1 ms $end\n";
  std::string scope;
  for (std::size_t i = 0; i < signals.size(); ++i) {
    if (signals[i].scope != scope) {
      if (!scope.empty()) out += "$upscope $end\n";
      scope = signals[i].scope;
      out += "$scope module " + scope + " $end\n";
    }
    out += std::string("$var ") + (signals[i].is_bool ? "wire 1 " : "integer 64 ") + vcd_id(i) +
           " " + vcd_name(signals[i].name) + " $end\n";
  }
  if (!scope.empty()) out += "$upscope $end\n";
  out += "$enddefinitions $end\n";
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    out += "#" + std::to_string(static_cast<std::int64_t>(i) * unit) + "\n";
    if (i == 0) out += "$dumpvars\n";
    for (std::size_t k = 0; k < signals.size(); ++k) {
      const auto v = signals[k].value(trace.steps[i]);
      if (i > 0 && v == signals[k].value(trace.steps[i - 1])) continue;
      out += signals[k].is_bool ? std::string(v ? "1" : "0") + vcd_id(k) + "\n"
                                : "b" + binary(v) + " " + vcd_id(k) + "\n";
    }
    if (i == 0) out += "$end\n";
  }
  out += "#" + std::to_string(static_cast<std::int64_t>(trace.steps.size()) * unit) + "\n";
  return out;
}

std::string trace_csv(const logic::Trace& trace, const semantics::TransitionSystem& ts) {
  const auto& inputs = ts.inputs();
  // IEC 61131-3: the initial situation is reached before any scan, so row 1 is the first
  // cycle's inputs. Grafcet: the initial situation already reacted to the initial inputs
  // (stabilisation), so they are the first row.
  const bool grafcet = ts.kind() == semantics::SemanticsKind::Grafcet;
  const std::size_t first = grafcet ? 0 : 1;
  std::string out =
      grafcet ? "# sfcv check trace: one row per stable situation, the first the initial inputs"
              : "# sfcv check trace: one row per cycle after the initial situation";
  if (trace.loop_start)
    out += "; rows from " + std::string(grafcet ? "situation " : "cycle ") +
           std::to_string(*trace.loop_start + (grafcet ? 0 : 1)) + " on repeat forever";
  out += "\n";
  for (std::size_t k = 0; k < inputs.size(); ++k) out += (k ? "," : "") + csv_field(inputs[k].name);
  out += "\n";
  for (std::size_t i = first; i < trace.steps.size(); ++i) {
    for (std::size_t k = 0; k < inputs.size(); ++k)
      out += (k ? "," : "") +
             std::to_string(k < trace.steps[i].inputs.size() ? trace.steps[i].inputs[k] : 0);
    out += "\n";
  }
  return out;
}

}  // namespace sfcv::report
