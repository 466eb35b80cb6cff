// sfcv equiv OLD NEW: regression verification (docs/equivalence.md). This file only maps options
// to library calls: semantics (the product of the two programs), logic (one invariant per
// question), engine (checking), report (the side-by-side rendering).

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/iec_options.hpp"
#include "cli/interrupt.hpp"
#include "cli/load_model.hpp"
#include "cli/output_file.hpp"
#include "cli/run_guard.hpp"
#include "cli/run_limits.hpp"
#include "cli/system_options.hpp"
#include "engine/portfolio/engine_by_name.hpp"
#include "engine/portfolio/portfolio_model_checker.hpp"
#include "logic/check_inputs.hpp"
#include "model/errors.hpp"
#include "report/equivalence_render.hpp"
#include "semantics/equivalence.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::cli {

namespace {

struct EquivOptions {
  std::string old_model, new_model;
  std::string format = "auto";
  std::vector<std::string> map;
  std::string outputs;
  std::vector<std::string> ignore;
  std::vector<std::string> compare;
  std::vector<std::string> assume;
  std::string engine = "auto";
  std::uint32_t within = 0;
  bool changed = false;
  std::string priority = "standard";
  std::string time = "abstract";
  std::string cycle = "10ms";
  std::string unwritten = "free";
  std::string dialect;  ///< empty: the two files' vendor
  std::uint32_t depth = 200;
  LimitOptions limits;
  bool json = false;
  std::string trace = "table";
  std::string trace_file;
  std::string html;
};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

/// --dialect, else the vendor that wrote both files; two vendors must be told apart by hand.
semantics::VendorDialect equiv_dialect(const EquivOptions& o, const model::Project& old_project,
                                       const model::Project& new_project) {
  if (const auto d = given_dialect(o.dialect)) return *d;
  const auto old_dialect = semantics::file_dialect(old_project);
  const auto new_dialect = semantics::file_dialect(new_project);
  if (old_dialect != new_dialect)
    throw UsageError("sfcv equiv: OLD is in " + std::string(semantics::to_string(old_dialect)) +
                     "'s dialect and NEW in " + std::string(semantics::to_string(new_dialect)) +
                     "'s (docs/semantics.md 1.4a): say which one runs both with --dialect");
  return old_dialect;
}

semantics::EquivalenceOptions library_options(const EquivOptions& o,
                                              const std::vector<model::ExprPtr>& assumptions,
                                              semantics::VendorDialect dialect) {
  semantics::EquivalenceOptions e;
  for (const auto& m : o.map) {
    const auto eq = m.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == m.size())
      throw UsageError("bad --map '" + m + "' (expected old=new)");
    e.map.emplace_back(m.substr(0, eq), m.substr(eq + 1));
  }
  e.outputs = split_list(o.outputs);
  for (const auto& c : o.compare)
    for (const auto& n : split_list(c)) e.compare.push_back(n);
  e.ignore = o.ignore;
  e.within = o.within;
  e.semantics.priority = parse_priority(o.priority);
  e.semantics.time = parse_time_mode(o.time);
  e.semantics.cycle_ms = parse_cycle_ms(o.cycle);
  e.semantics.unwritten = parse_unwritten(o.unwritten);
  semantics::set_dialect(e.semantics, dialect);
  e.semantics.assumptions = assumptions;
  return e;
}

/// One invariant per question: every compared signal at once, or (--changed) one each.
std::string spec_text(const semantics::EquivalenceProduct& p, bool per_signal) {
  std::string text;
  if (!per_signal) {
    std::string any;
    for (const auto& s : p.compared) any += (any.empty() ? "" : " | ") + s.differs;
    return "property equivalent: AG !(" + any + ");\n";
  }
  for (std::size_t i = 0; i < p.compared.size(); ++i)
    text += "property s" + std::to_string(i) + ": AG !" + p.compared[i].differs + ";\n";
  return text;
}

engine::ModelCheckerPtr make_engine(const std::string& name, std::uint32_t depth,
                                    const model::Budget* budget = nullptr) {
  engine::EngineSelection selection;
  selection.max_depth = depth;
  // As in check: a racer that does not stop must not hold the report back (run_guard.hpp).
  if (budget)
    selection.abandon_after = race_grace_seconds(budget->deadline ? budget->seconds_left() : 0.0);
  selection.note = [](const std::string& text) {
    if (!global_options().quiet) std::cerr << "sfcv: --engine auto: " << text << "\n";
  };
  return engine::make_engine_by_name(name, selection);
}

/// The counterexample is the shortest input sequence: BMC up to the length found (which
/// deepens one cycle at a time) replaces a longer trace of IC3, k-induction or the BDD engine.
void shorten_traces(logic::CheckReport& report, const logic::CheckTask& task) {
  for (std::size_t i = 0; i < report.results.size() && i < task.properties.size(); ++i) {
    auto& r = report.results[i];
    if (r.verdict != logic::Verdict::Violated || !r.trace || r.trace->steps.size() <= 1) continue;
    logic::CheckTask one = task;
    one.properties = {task.properties[i]};
    auto bmc = make_engine("bmc", static_cast<std::uint32_t>(r.trace->steps.size() - 1));
    if (!bmc->can_handle(one, nullptr)) continue;
    try {
      auto again = bmc->check(one);
      if (!again.results.empty() && again.results[0].verdict == logic::Verdict::Violated &&
          again.results[0].trace && again.results[0].trace->steps.size() < r.trace->steps.size())
        r.trace = again.results[0].trace;
    } catch (const LimitReached&) {
      // The trace found stands; it is a real counterexample, only perhaps not the shortest.
    }
  }
}

/// The counterexamples shortened, then the trace file, the HTML page and the report.
int write_equivalence_reports(const EquivOptions& o, report::EquivalenceRun& run,
                              const logic::CheckTask& task,
                              const semantics::EquivalenceProduct& product,
                              const semantics::TransitionSystem& system);

int run_equiv(const EquivOptions& o, const RunGuard& guard) {
  static const std::vector<std::string> engines = {"auto", "explicit", "bdd", "bmc", "kind", "ic3"};
  if (std::find(engines.begin(), engines.end(), o.engine) == engines.end())
    throw UsageError("bad --engine '" + o.engine +
                     "' (expected auto, explicit, bdd, bmc, kind or ic3)");
  if (o.trace != "table" && o.trace != "json" && o.trace != "vcd" && o.trace != "none")
    throw UsageError("bad --trace '" + o.trace + "' (expected table, json, vcd or none)");
  const OutputPath trace_out{o.trace_file, "--trace-file"};
  const OutputPath html_out{o.html, "--html"};
  check_output_paths({trace_out, html_out});
  const model::Budget& budget = guard.budget();

  logic::CheckInputs assume_inputs;
  assume_inputs.assume = o.assume;
  auto assumptions = logic::parse_check_inputs(assume_inputs);
  for (const auto& d : assumptions.diagnostics) std::cerr << d.str() << "\n";
  if (model::has_errors(assumptions.diagnostics))
    throw InputError("sfcv equiv: errors in the assumptions");

  const auto old_project =
      load_model_or_throw(o.old_model, parse_format(o.format), global_options().quiet, &budget);
  const auto new_project =
      load_model_or_throw(o.new_model, parse_format(o.format), global_options().quiet, &budget);
  auto product = semantics::make_equivalence_product(
      old_project, new_project,
      library_options(o, logic::assumption_exprs(assumptions.spec),
                      equiv_dialect(o, old_project, new_project)));

  model::Diagnostics diags;
  auto options = product.options;
  options.deadline = budget.deadline;
  const auto system = semantics::make_iec61131_system(product.project, options, diags);
  if (!system) {
    std::string text = "sfcv equiv: the product of the two programs cannot be run:";
    for (const auto& d : diags)
      if (d.severity == model::Severity::Error) text += "\n  " + d.str();
    throw InputError(text);
  }

  product.notes.push_back(semantics::abstract_time_note(*system));
  if (product.notes.back().empty()) product.notes.pop_back();

  logic::CheckInputs inputs;
  inputs.spec_text = spec_text(product, o.changed);
  inputs.spec_file = "(equiv)";
  auto parsed = logic::parse_check_inputs(inputs);
  logic::CheckTask task;
  task.system = system.get();
  task.project = &product.project;
  model::Diagnostics resolve_diags;
  logic::resolve_into(parsed.spec, *system, task, resolve_diags);
  if (model::has_errors(parsed.diagnostics) || model::has_errors(resolve_diags)) {
    std::string text = "sfcv equiv: the product's properties do not resolve:";
    for (const auto* list : {&parsed.diagnostics, &resolve_diags})
      for (const auto& d : *list) text += "\n  " + d.str();
    throw InternalError(text);
  }
  task.limits = budget;

  report::EquivalenceRun run;
  run.old_path = o.old_model;
  run.new_path = o.new_model;
  run.within = o.within;
  run.per_signal = o.changed;
  auto checker = make_engine(o.engine, o.depth, &budget);
  std::string why;
  if (!checker->can_handle(task, &why)) throw InputError("sfcv equiv: " + why);
  try {
    run.report = checker->check(task);
  } catch (const LimitReached& e) {
    run.report = logic::unknown_report(task, o.engine, guard.reason(e));
  }
  // A racer left behind still reads the system: whatever happens from here, the process ends
  // in this function once the report is out (end_here_if_racers_left_behind).
  try {
    return write_equivalence_reports(o, run, task, product, *system);
  } catch (...) {
    rethrow_unless_racers_left_behind(std::current_exception(), o.json ? &std::cout : nullptr);
  }
}

int write_equivalence_reports(const EquivOptions& o, report::EquivalenceRun& run,
                              const logic::CheckTask& task,
                              const semantics::EquivalenceProduct& product,
                              const semantics::TransitionSystem& system) {
  const OutputPath trace_out{o.trace_file, "--trace-file"};
  const OutputPath html_out{o.html, "--html"};
  if (o.engine != "explicit" && o.engine != "bmc") shorten_traces(run.report, task);

  if (!o.trace_file.empty()) {
    const logic::Trace* first = nullptr;
    for (const auto& r : run.report.results)
      if (r.verdict == logic::Verdict::Violated && r.trace) {
        first = &*r.trace;
        break;
      }
    std::string text;
    if (first) {
      if (o.trace == "json")
        text = report::equivalence_trace_json(*first, product, system).dump(2) + "\n";
      else if (o.trace == "vcd")
        text = report::equivalence_trace_vcd(*first, product, system, parse_cycle_ms(o.cycle));
      else
        text = report::equivalence_trace_table(*first, product, system);
    }
    write_output(trace_out, text);
  }
  if (!o.html.empty())
    write_output(html_out,
                 report::equivalence_html(report::equivalence_json(run, product, system)));
  if (o.json)
    std::cout << report::equivalence_json(run, product, system).dump(2) << "\n";
  else
    std::cout << report::equivalence_text(run, product, system);
  return end_here_if_racers_left_behind(logic::exit_code(run.report));
}

}  // namespace

void add_equiv_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<EquivOptions>();
  auto* sub = app.add_subcommand(
      "equiv", "Regression verification: do two IEC 61131-3 programs give the same outputs?");
  sub->add_option("old", opts->old_model, "The program before the change")->required();
  sub->add_option("new", opts->new_model, "The program after the change")->required();
  sub->add_option("--format", opts->format, "Input format of both: auto, xml, iec");
  sub->add_option("--map", opts->map,
                  "old=new: NEW's variable 'new' is OLD's 'old' (an input or a compared signal; "
                  "repeatable)");
  sub->add_option("--outputs", opts->outputs,
                  "Signals to compare, a,b,... (default: every VAR_OUTPUT and %Q variable of "
                  "OLD's programs that NEW declares too); inst.q names a variable of an instance");
  sub->add_option("--ignore", opts->ignore, "An output not to compare (repeatable)");
  sub->add_option("--compare", opts->compare,
                  "Internal variables to compare as well, x,y,... (repeatable)");
  sub->add_option("--assume", opts->assume,
                  "Assumption on the shared inputs, e.g. '!(up & down)' (repeatable)");
  sub->add_option("--engine", opts->engine, "auto (default), explicit, bdd, bmc, kind or ic3");
  sub->add_option("--within", opts->within,
                  "N: NEW may lag: at every cycle its value equals OLD's value of one of the "
                  "last N+1 cycles (docs/equivalence.md)");
  sub->add_flag("--changed", opts->changed,
                "List each compared signal with its own verdict and trace, instead of stopping "
                "at the first difference");
  sub->add_option("--priority", opts->priority, "standard or none (docs/semantics.md 1.5)");
  sub->add_option("--time", opts->time,
                  "abstract (default) or discrete; with timers use discrete, under abstract time "
                  "the two sides' timers expire independently");
  sub->add_option("--cycle", opts->cycle, "The scan cycle of --time discrete (default 10ms)");
  sub->add_option("--unwritten", opts->unwritten,
                  "free (default: shared inputs) or keep (docs/semantics.md 1.8)");
  sub->add_option("--dialect", opts->dialect,
                  "iec, codesys, twincat, siemens or rockwell: whose final calls and action order "
                  "run both sides (default: the vendor that wrote both files; "
                  "docs/semantics.md 1.4a)");
  sub->add_option("--depth", opts->depth, "bmc and kind: the deepest unrolling (default 200)");
  add_limit_options(*sub, opts->limits, "answers not decided by then become unknown");
  sub->add_flag("--json", opts->json, "JSON output (docs/equivalence.md)");
  sub->add_option("--trace", opts->trace,
                  "Format of --trace-file: table (default), json, vcd or none");
  sub->add_option("--trace-file", opts->trace_file, "Write the first counterexample there");
  sub->add_option("--html", opts->html,
                  "Write the result as one HTML page, each counterexample side by side");
  sub->footer(
      "Exit codes: 0 equivalent, 1 some compared signal differs, 2 bad usage or input "
      "(mismatched input types, a Grafcet side, globals both declare), 3 unknown, 4 internal "
      "error.");
  sub->callback([opts, &selected] {
    selected = [opts] {
      const InterruptScope interrupt;  // the first signal stops the engines, the report follows
      return run_limited(
          opts->limits, [&](const RunGuard& g) { return run_equiv(*opts, g); }, interrupt_flag());
    };
  });
}

}  // namespace sfcv::cli
