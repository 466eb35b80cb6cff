// sfcv simulate: runs an IEC 61131-3 chart cycle by cycle (a Grafcet event by event) on the
// inputs of a CSV file (or of a trace written by `sfcv check --trace json`) and prints a table
// (optionally a VCD waveform).

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/iec_options.hpp"
#include "cli/json_input.hpp"
#include "cli/load_model.hpp"
#include "cli/output_file.hpp"
#include "cli/run_guard.hpp"
#include "cli/system_options.hpp"
#include "io/st_parser.hpp"
#include "logic/trace.hpp"
#include "model/input_file.hpp"
#include "model/literal.hpp"
#include "model/names.hpp"
#include "report/trace_render.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"

namespace sfcv::cli {

namespace {

struct SimulateOptions {
  std::string model;
  std::string format = "auto";
  std::string inputs;
  std::string vcd;
  SystemOptions system;
  std::vector<std::string> assumptions;
  long long max_cycles = -1;
  LimitOptions limits;
};

/// One record of the input CSV from text[pos] on (RFC 4180, which `sfcv check --trace csv`
/// writes: a field in double quotes may hold separators, doubled quotes and line breaks;
/// spaces around a field are dropped). The separator is ',', or ';' when only ';' separates
/// the record's fields. `pos` and `line` move past the record; `columns` gets each field's
/// column (1-based, on the line where the field starts).
std::vector<std::string> csv_record(const std::string& text, std::size_t& pos, int& line,
                                    std::vector<std::size_t>& columns, const std::string& path) {
  bool quoted = false, comma = false, semicolon = false;
  std::size_t end = pos;
  for (; end < text.size(); ++end) {
    const char c = text[end];
    if (c == '"')
      quoted = !quoted;
    else if (!quoted && c == '\n')
      break;
    else if (!quoted && c == ',')
      comma = true;
    else if (!quoted && c == ';')
      semicolon = true;
  }
  const std::string at = path + ":" + std::to_string(line) + ":";
  if (quoted) throw InputError(at + "1: a quoted field is not closed");
  const char sep = semicolon && !comma ? ';' : ',';
  auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  std::vector<std::string> cells;
  columns.clear();
  std::size_t line_start = pos, i = pos;
  while (true) {
    while (i < end && is_space(text[i])) ++i;
    columns.push_back(i - line_start + 1);
    std::string cell;
    if (i < end && text[i] == '"') {
      for (++i;; ++i) {
        if (text[i] == '"') {
          if (i + 1 < end && text[i + 1] == '"') {
            cell += '"';
            ++i;
            continue;
          }
          ++i;
          break;
        }
        if (text[i] == '\n') {
          ++line;
          line_start = i + 1;
        }
        cell += text[i];
      }
      while (i < end && is_space(text[i])) ++i;
      if (i < end && text[i] != sep)
        throw InputError(path + ":" + std::to_string(line) + ":" +
                         std::to_string(i - line_start + 1) + ": text after a quoted field");
    } else {
      const auto stop = std::min(text.find(sep, i), end);
      cell = text.substr(i, stop - i);
      while (!cell.empty() && is_space(cell.back())) cell.pop_back();
      i = stop;
    }
    cells.push_back(std::move(cell));
    if (i >= end) break;
    ++i;  // the separator
  }
  pos = end + 1;
  ++line;
  return cells;
}

/// The CSV: header of input names, one row per cycle. Pseudo-inputs without a column take
/// their default (no timeout, first alternative, no elapse); other missing inputs are an error.
std::vector<std::vector<std::int64_t>> read_trace(const std::string& path,
                                                  const semantics::TransitionSystem& ts,
                                                  std::vector<int>& shown) {
  const std::string text = model::read_input_file(path, "the input trace");
  const auto& inputs = ts.inputs();
  std::vector<int> column_input;
  std::vector<std::vector<std::int64_t>> rows;
  int lineno = 1;
  bool header = false;
  std::vector<std::size_t> cols;
  for (std::size_t pos = 0; pos < text.size();) {
    // Blank lines and lines starting with '#' are comments (a name starting with '#' is
    // quoted by the writer).
    const auto eol = std::min(text.find('\n', pos), text.size());
    const auto first = text.find_first_not_of(" \t\r", pos);
    if (first >= eol || text[first] == '#') {
      pos = eol + 1;
      ++lineno;
      continue;
    }
    const std::string at = path + ":" + std::to_string(lineno) + ":";
    const auto cells = csv_record(text, pos, lineno, cols, path);
    if (!header) {
      header = true;
      std::vector<bool> seen(inputs.size());
      for (std::size_t c = 0; c < cells.size(); ++c) {
        int found = -1;
        if (model::iequals(cells[c], "cycle")) {  // a cycle-number column, for readability
          column_input.push_back(-1);
          continue;
        }
        for (std::size_t i = 0; i < inputs.size(); ++i)
          if (model::iequals(inputs[i].name, cells[c])) found = static_cast<int>(i);
        if (found < 0) {
          std::string known;
          for (const auto& in : inputs) known += (known.empty() ? "" : ", ") + in.name;
          throw InputError(at + std::to_string(cols[c]) + ": unknown input '" + cells[c] +
                           "' (the model's inputs: " + (known.empty() ? "none" : known) + ")");
        }
        if (seen[static_cast<std::size_t>(found)])
          throw InputError(at + std::to_string(cols[c]) + ": input '" + cells[c] +
                           "' appears twice");
        seen[static_cast<std::size_t>(found)] = true;
        column_input.push_back(found);
      }
      for (std::size_t i = 0; i < inputs.size(); ++i)
        if (!seen[i] && !inputs[i].pseudo)
          throw InputError(at + "1: the header has no column for input '" + inputs[i].name + "'");
      for (std::size_t i = 0; i < inputs.size(); ++i)
        if (seen[i]) shown.push_back(static_cast<int>(i));
      continue;
    }
    if (cells.size() != column_input.size())
      throw InputError(at + "1: expected " + std::to_string(column_input.size()) +
                       " values, found " + std::to_string(cells.size()));
    std::vector<std::int64_t> row(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i)
      row[i] = inputs[i].type.kind == model::TypeKind::Bool ? 0 : inputs[i].type.lo;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (column_input[c] < 0) continue;
      const auto& in = inputs[static_cast<std::size_t>(column_input[c])];
      const std::string u = model::to_upper(cells[c]);
      std::int64_t v = 0;
      bool good = true;
      if (u == "TRUE")
        v = 1;
      else if (u == "FALSE")
        v = 0;
      else {
        // The one checked conversion (model/literal.hpp), as the model's readers.
        const std::string& cell = cells[c];
        const auto blanks = std::min(cell.find_first_not_of(" \t"), cell.size());
        const auto read = model::integer_literal(std::string_view(cell).substr(blanks));
        good = read.value.has_value();
        v = read.value.value_or(0);
      }
      if (!good || v < in.type.lo || v > in.type.hi)
        throw InputError(at + std::to_string(cols[c]) + ": bad value '" + cells[c] +
                         "' for input '" + in.name + "' (expected " +
                         (in.type.kind == model::TypeKind::Bool
                              ? std::string("0, 1, TRUE or FALSE")
                              : "an integer in " + std::to_string(in.type.lo) + ".." +
                                    std::to_string(in.type.hi)) +
                         ")");
      row[static_cast<std::size_t>(column_input[c])] = v;
    }
    rows.push_back(std::move(row));
  }
  if (!header) throw InputError(path + ":1:1: empty trace (expected a header row of input names)");
  return rows;
}

/// A trace written by `sfcv check --trace json`: the inputs of its steps, as the CSV trace
/// gives them (IEC: from the first cycle on, step 0 being the initial state; Grafcet: from the
/// initial inputs on).
std::vector<std::vector<std::int64_t>> read_json_trace(const std::string& path,
                                                       const semantics::TransitionSystem& ts,
                                                       std::vector<int>& shown) {
  const nlohmann::json doc = read_json_file(path, "the input trace", "not a JSON trace");
  if (!doc.is_object() || !doc.contains("steps") || !doc["steps"].is_array())
    throw InputError(path + ": not a trace of 'sfcv check --trace json' (no \"steps\" array)");
  const auto& inputs = ts.inputs();
  const bool grafcet = ts.kind() == semantics::SemanticsKind::Grafcet;
  std::vector<bool> seen(inputs.size());
  std::vector<std::vector<std::int64_t>> rows;
  const auto& steps = doc["steps"];
  for (std::size_t s = grafcet ? 0 : 1; s < steps.size(); ++s) {
    const std::string at = path + ": step " + std::to_string(s) + ": ";
    const auto& given = steps[s].value("inputs", nlohmann::json::object());
    if (!given.is_object()) throw InputError(at + "\"inputs\" is not an object");
    std::vector<std::int64_t> row(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const auto& in = inputs[i];
      row[i] = in.type.kind == model::TypeKind::Bool ? 0 : in.type.lo;
      const auto it = given.find(in.name);
      if (it == given.end()) {
        if (!in.pseudo) throw InputError(at + "no value for input '" + in.name + "'");
        continue;
      }
      seen[i] = true;
      if (it->is_boolean())
        row[i] = it->get<bool>() ? 1 : 0;
      else if (it->is_number_integer() &&
               !(it->is_number_unsigned() &&
                 it->get<std::uint64_t>() > model::kMaxLiteralMagnitude - 1))
        row[i] = it->get<std::int64_t>();  // an unsigned past LINT's range would wrap around
      else
        throw InputError(at + "bad value for input '" + in.name + "'");
      if (row[i] < in.type.lo || row[i] > in.type.hi)
        throw InputError(at + "value " + std::to_string(row[i]) + " of input '" + in.name +
                         "' is out of its range");
    }
    for (const auto& [name, value] : given.items()) {
      bool known = false;
      for (const auto& in : inputs) known = known || in.name == name;
      if (!known) throw InputError(at + "unknown input '" + name + "'");
    }
    rows.push_back(std::move(row));
  }
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (seen[i] || !inputs[i].pseudo) shown.push_back(static_cast<int>(i));
  return rows;
}

bool looks_like_json(const std::string& path) {
  std::ifstream f(path);
  char c = 0;
  while (f.get(c))
    if (!std::isspace(static_cast<unsigned char>(c))) return c == '{';
  return false;
}

/// The run as a trace, for the one VCD writer in src/report; rows[c] are the inputs beside
/// states[c].
logic::Trace run_as_trace(const semantics::SimulationResult& r,
                          const std::vector<std::vector<std::int64_t>>& rows) {
  logic::Trace trace;
  for (std::size_t c = 0; c < r.states.size(); ++c)
    trace.steps.push_back(
        {rows[c], r.states[c],
         c == 0 || c > r.fired.size() ? std::vector<std::uint32_t>{} : r.fired[c - 1]});
  return trace;
}

void write_vcd(const std::string& path, const semantics::TransitionSystem& ts,
               const semantics::SimulationResult& r,
               const std::vector<std::vector<std::int64_t>>& rows, std::int64_t cycle_ms) {
  write_output({path, "--vcd"}, report::trace_vcd(run_as_trace(r, rows), ts, {cycle_ms}));
}

int run_simulate(const SimulateOptions& o, const RunGuard& guard) {
  check_output_paths({{o.vcd, "--vcd"}});
  const auto& budget = guard.budget();
  auto project = load_model_or_throw(o.model, parse_format(o.format), false, &budget);
  std::vector<model::ExprPtr> assumptions;
  for (const auto& a : o.assumptions) {
    model::Diagnostics d;
    model::SourceLocation where;
    where.file = "--assume";
    where.line = where.column = 1;
    auto e = io::parse_st_expression(a, where, d);
    for (const auto& x : d) std::cerr << x.str() << "\n";
    if (!e) throw InputError("bad --assume '" + a + "'");
    assumptions.push_back(e);
  }
  const bool grafcet = chosen_semantics(project, o.system) == "grafcet";
  const auto built = build_system(project, o.system, assumptions, "sfcv simulate",
                                  semantics::ActionOrder::Declaration, &budget);
  guard.check("building the system");
  const auto& ts = built.system;
  const std::int64_t cycle_ms = parse_cycle_ms(o.system.cycle);

  std::vector<int> shown;
  auto rows = looks_like_json(o.inputs) ? read_json_trace(o.inputs, *ts, shown)
                                        : read_trace(o.inputs, *ts, shown);
  // Grafcet: the first row is the initial inputs, so N events are N + 1 rows.
  const std::size_t keep = static_cast<std::size_t>(o.max_cycles) + (grafcet ? 1 : 0);
  if (o.max_cycles >= 0 && keep < rows.size()) rows.resize(keep);
  // --max-states: the run stops after that many states (cycles, or events), unknown past them.
  std::optional<LimitReached> stopped;
  if (budget.max_states > 0 && rows.size() > budget.max_states) {
    rows.resize(budget.max_states);
    stopped = LimitReached(
        Limit::States, "states limit reached after " + std::to_string(budget.max_states) + " rows");
  }
  guard.check("reading the inputs");
  semantics::SimulationResult r;
  if (grafcet) {
    r = semantics::simulate_events(*ts, rows, !o.system.multi_input_change, !assumptions.empty());
  } else {
    r = semantics::simulate(*ts, semantics::first_initial_state(*ts), rows);
    // The IEC start state has no cycle before it: its inputs are the defaults.
    std::vector<std::int64_t> defaults;
    for (const auto& in : ts->inputs())
      defaults.push_back(in.type.kind == model::TypeKind::Bool ? 0 : in.type.lo);
    rows.insert(rows.begin(), std::move(defaults));
  }
  // From here rows[c] holds the inputs beside states[c].

  const auto& obs = ts->observables();
  auto list = [&](std::size_t c, semantics::ObservableKind kind) {
    std::string s;
    for (std::size_t i = 0; i < obs.size(); ++i) {
      if (obs[i].kind != kind) continue;
      const auto v = ts->observe(r.states[c], static_cast<std::uint32_t>(i));
      if (kind == semantics::ObservableKind::Variable) {
        if (!obs[i].is_output) continue;
        s += (s.empty() ? "" : " ") + obs[i].name + "=" + std::to_string(v);
      } else if (v) {
        s += (s.empty() ? "" : " ") + obs[i].name;
      }
    }
    return s.empty() ? std::string("-") : s;
  };
  std::cout << (grafcet ? "event" : "cycle")
            << " | inputs | active steps | active actions | outputs\n";
  model::BudgetPoll poll(budget, 256);
  for (std::size_t c = 0; c < r.states.size(); ++c) {
    if (poll.tick()) {  // the rows printed so far stand; the rest is unknown
      stopped = guard.reason(LimitReached(
          Limit::Time, "time limit reached while printing, after " + std::to_string(c) + " rows"));
      break;
    }
    std::string ins;
    if (c == 0 && !grafcet) {
      ins = "(initial)";
    } else {
      for (int i : shown)
        ins += (ins.empty() ? "" : " ") + ts->inputs()[static_cast<std::size_t>(i)].name + "=" +
               std::to_string(rows[c][static_cast<std::size_t>(i)]);
      if (ins.empty()) ins = "-";
    }
    std::cout << c << " | " << ins << " | " << list(c, semantics::ObservableKind::Step) << " | "
              << list(c, semantics::ObservableKind::Action) << " | "
              << list(c, semantics::ObservableKind::Variable) << "\n";
  }
  if (stopped && r.ok) return report_limit(*stopped);  // a failed row is a finding: exit 2
  guard.check("writing the VCD waveform");
  if (!o.vcd.empty()) write_vcd(o.vcd, *ts, r, rows, cycle_ms);
  if (!r.ok) {
    std::cerr << "sfcv: error: " << o.inputs << ": " << (grafcet ? "row " : "cycle ")
              << r.failed_cycle << ": " << r.error << "\n";
    return kBadInput;
  }
  return kHolds;
}

}  // namespace

void add_simulate_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<SimulateOptions>();
  auto* sub =
      app.add_subcommand("simulate",
                         "Run an IEC 61131-3 chart cycle by cycle, or a Grafcet event by event, "
                         "on given inputs");
  sub->add_option("model", opts->model, "Chart file (PLCopen XML, IEC text, .g7, AGRAFE)")
      ->required();
  sub->add_option(
         "--inputs", opts->inputs,
         "CSV trace: a header row of input names, then one row of values per cycle "
         "(0/1, TRUE/FALSE, integers; ',' or ';' separated; '#' comments; an optional column "
         "'cycle' is ignored, which also lets a model without inputs run). Pseudo-inputs "
         "(timeout:<timer>, choice:<step>, elapse:<step>) may be given as columns; when "
         "absent they default to 0: no timeout, the first enabled alternative, no time "
         "elapsing. Every other input needs a column. Grafcet: the first row is the initial "
         "inputs, each later row the inputs after one event (a trace written by "
         "'sfcv check --trace csv' replays as it is). A JSON trace of 'sfcv check --trace json "
         "--trace-file F' replays too.")
      ->required();
  sub->add_option("--vcd", opts->vcd,
                  "Also write a VCD waveform (GTKWave) of steps, actions, outputs, inputs");
  sub->add_option("--format", opts->format, kFormatHelp);
  add_system_options(*sub, opts->system);
  sub->add_option("--assume", opts->assumptions,
                  "Assumption on inputs and state (ST expression), repeatable");
  sub->add_option("--max-cycles", opts->max_cycles, "Run at most N cycles of the trace");
  add_limit_options(*sub, opts->limits, "the rows so far are printed, exit 3");
  sub->footer(
      "Exit codes: 0 the trace ran to its end; 2 bad usage or input, or a cycle had no "
      "successor (an assumption is violated, or a range error such as an integer overflow; "
      "Grafcet: an instability, or two inputs changing in one row without "
      "--multi-input-change).");
  sub->callback([opts, &selected] {
    selected = [opts] {
      return run_limited(opts->limits, [&](const RunGuard& g) { return run_simulate(*opts, g); });
    };
  });
}

}  // namespace sfcv::cli
