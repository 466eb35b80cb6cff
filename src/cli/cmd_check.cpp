// sfcv check: CTL properties and the standard checks. This file only maps options to library
// calls: logic (properties), semantics (the system), engine (checking), report (rendering).

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/build_info.hpp"
#include "cli/check_shards.hpp"
#include "cli/check_traces.hpp"
#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/iec_options.hpp"
#include "cli/interrupt.hpp"
#include "cli/load_model.hpp"
#include "cli/memory_watchdog.hpp"
#include "cli/name_hints.hpp"
#include "cli/output_file.hpp"
#include "cli/progress_line.hpp"
#include "cli/run_guard.hpp"
#include "cli/run_limits.hpp"
#include "cli/system_options.hpp"
#include "engine/auto_policy.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/external/nusmv_runner.hpp"
#include "engine/portfolio/engine_by_name.hpp"
#include "engine/portfolio/portfolio_model_checker.hpp"
#include "logic/check_inputs.hpp"
#include "logic/requirements.hpp"
#include "logic/vacuity.hpp"
#include "logic/work_units.hpp"
#include "model/input_file.hpp"
#include "model/names.hpp"
#include "report/check_html.hpp"
#include "report/check_junit.hpp"
#include "report/check_render.hpp"
#include "report/check_sarif.hpp"
#include "report/shard_result.hpp"
#include "report/trace_render.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::cli {

namespace {

struct CheckOptions {
  std::string model;
  std::string format = "auto";
  std::vector<std::string> ctl;
  std::vector<std::string> ltl;
  std::vector<std::string> patterns;
  std::string spec;
  std::string requirements;  ///< --requirements: PLCverif JSON or ESBMC-PLC YAML
  std::string checks;        ///< empty: all when no property is given, else none
  std::vector<std::string> fair;
  std::vector<std::string> assume;
  std::string engine = "auto";
  SystemOptions system;
  LimitOptions limits;
  std::string reorder = "dynamic";
  std::uint32_t depth = 200;
  unsigned threads = 0;
  std::string certificate;
  bool json = false;
  std::string trace = "table";
  std::string trace_file;
  std::string trace_dir;
  std::string sarif_root;  ///< empty: the enclosing git work tree, else the working directory
  std::string junit;
  std::string sarif;
  std::string html;
  bool all_findings = false;
  bool coverage = false;
  std::string deadlock_paths = "stutter";
  std::string shard;       ///< --shard I/N (docs/distributed.md)
  bool diversify = false;  ///< --diversify: a swarm, every shard on every unit
};

report::TraceFormat parse_trace_format(const std::string& s) {
  if (s == "table") return report::TraceFormat::Table;
  if (s == "json") return report::TraceFormat::Json;
  if (s == "vcd") return report::TraceFormat::Vcd;
  if (s == "csv") return report::TraceFormat::Csv;
  if (s == "none") return report::TraceFormat::None;
  throw UsageError("bad --trace '" + s + "' (expected table, json, vcd, csv or none)");
}

void print_diagnostics(const model::Diagnostics& diags, const char* what) {
  std::size_t errors = 0;
  std::vector<std::string> printed;  // a pattern's argument used twice is reported once
  for (const auto& d : diags) {
    const auto line = d.str();
    if (std::find(printed.begin(), printed.end(), line) != printed.end()) continue;
    printed.push_back(line);
    std::cerr << line << "\n";
    errors += d.severity == model::Severity::Error;
  }
  if (errors) throw InputError(std::string("sfcv check: ") + what);
}

engine::ModelCheckerPtr choose_engine(const std::string& name, const logic::CheckTask& task,
                                      const engine::BddEngineOptions& bdd_options,
                                      const engine::ExplicitEngineOptions& explicit_options,
                                      std::uint32_t depth, std::uint32_t min_depth = 0) {
  std::string why;
  if (name == "nusmv") {
    const auto nusmv = engine::find_nusmv();
    if (!nusmv)
      throw InputError(
          "sfcv check --engine nusmv: no NuSMV found on PATH (NuSMV is not packaged "
          "in Debian; see docs/exports.md)");
    auto checker = engine::make_nusmv_model_checker(*nusmv);
    if (!checker->can_handle(task, &why)) throw InputError("sfcv check: " + why);
    return checker;
  }
  engine::EngineSelection selection;
  selection.bdd = bdd_options;
  selection.explicit_engine = explicit_options;
  selection.max_depth = depth;
  selection.min_depth = min_depth;
  auto checker = engine::make_engine_by_name(name, selection);
  if (!checker->can_handle(task, &why)) throw InputError("sfcv check: " + why);
  return checker;
}

/// An engine that decides none of the questions asked (each is "not checked", or has no meaning
/// on the system) is bad usage, exit 2: a run that verifies nothing must neither pass in CI nor
/// read as a limit. The engines' "not checked" lines say which engines can decide them.
void refuse_if_nothing_decided(const logic::CheckReport& result, const std::string& engine) {
  if (!logic::nothing_decided(result)) return;
  std::vector<std::string> reasons;
  for (const auto& r : result.results)
    if (r.verdict == logic::Verdict::NotChecked &&
        std::find(reasons.begin(), reasons.end(), r.message) == reasons.end())
      reasons.push_back(r.message);
  std::string text = "sfcv check --engine " + engine + " decides none of the " +
                     std::to_string(result.results.size()) + " questions asked:";
  for (const auto& why : reasons) text += "\n  " + why;
  throw UsageError(text);
}

/// --engine auto: the portfolio (engine/portfolio), its notes on stderr unless --quiet.
logic::CheckReport check_auto(const logic::CheckTask& task,
                              const engine::BddEngineOptions& bdd_options,
                              const engine::ExplicitEngineOptions& explicit_options,
                              ProgressLine& progress) {
  engine::EngineSelection selection;
  selection.bdd = bdd_options;
  selection.explicit_engine = explicit_options;
  selection.note = [&progress](const std::string& text) {
    if (global_options().quiet) return;
    progress.clear();
    std::cerr << "sfcv: --engine auto: " << text << "\n";
  };
  // A racer that does not stop (one long BDD operation on a loaded machine) must not hold the
  // report back until the backstop ends the process without one.
  selection.abandon_after =
      race_grace_seconds(task.limits.deadline ? task.limits.seconds_left() : 0.0);
  return engine::make_engine_by_name("auto", selection)->check(task);
}

/// The files `sfcv check` writes, with their options.
std::vector<OutputPath> output_paths(const CheckOptions& o) {
  return {{o.trace_file, "--trace-file"},
          {o.certificate, "--certificate"},
          {o.junit, "--junit"},
          {o.sarif, "--sarif"},
          {o.html, "--html"}};
}

/// The run was stopped from outside the engines (a signal, the memory watchdog), which they saw
/// as a cancel and word as a time limit: what they had not decided is unknown for `why`, and
/// the report's limit is `limit`.
void mark_stopped(logic::CheckReport& result, const std::string& why, const std::string& limit) {
  bool undecided = false;
  for (auto& r : result.results)
    if (r.verdict == logic::Verdict::Unknown) {
      r.message = why;
      undecided = true;
    }
  if (undecided || !result.complete) {
    result.complete = false;
    result.limit = limit;
  }
}

/// SARIF URIs are relative to --sarif-root, by default the git work tree around the working
/// directory (code scanning resolves them against the repository), else that directory.
std::string sarif_root(const CheckOptions& o) {
  if (!o.sarif_root.empty()) return o.sarif_root;
  std::error_code ec;
  const auto cwd = std::filesystem::current_path(ec);
  if (ec) return ".";
  for (auto dir = cwd; !dir.empty(); dir = dir.parent_path()) {
    if (std::filesystem::exists(dir / ".git", ec)) return dir.string();
    if (dir == dir.parent_path()) break;
  }
  return cwd.string();
}

/// Who ran what, when, on which files, with which engine and settings (report/provenance.hpp).
report::Provenance check_provenance(const CheckOptions& o, const std::string& semantics,
                                    const std::string& dialect) {
  auto p = run_provenance();
  p.inputs.push_back(report::digest_file(o.model));
  if (!o.spec.empty()) p.inputs.push_back(report::digest_file(o.spec));
  p.engine = o.engine;
  auto& s = p.settings;
  s.emplace_back("semantics", semantics);
  if (semantics == "iec61131") {
    std::string pous;
    for (const auto& pou : o.system.pous) pous += (pous.empty() ? "" : ",") + pou;
    s.emplace_back("pou", pous.empty() ? "every PROGRAM" : pous);
    s.emplace_back("priority", o.system.priority);
    s.emplace_back("time", o.system.time);
    if (o.system.time == "discrete") s.emplace_back("cycle", o.system.cycle);
    s.emplace_back("unwritten", o.system.unwritten);
    s.emplace_back("dialect", dialect);
    s.emplace_back("action_order",
                   o.system.action_order.empty() ? "the dialect's default" : o.system.action_order);
  } else {
    s.emplace_back("input_changes", o.system.multi_input_change ? "multiple" : "single");
  }
  s.emplace_back("checks", o.checks.empty() ? "default" : o.checks);
  s.emplace_back("deadlock_paths", o.deadlock_paths);
  s.emplace_back("reorder", o.reorder);
  s.emplace_back("depth", std::to_string(o.depth));
  s.emplace_back("threads", std::to_string(o.threads));
  s.emplace_back("timeout", o.limits.timeout.empty() ? "none" : o.limits.timeout);
  s.emplace_back("max_states", o.limits.max_states.empty() ? "none" : o.limits.max_states);
  s.emplace_back("memory", o.limits.memory.empty() ? "none" : o.limits.memory);
  // One key each (JSON objects): several constraints joined by "; ".
  auto joined = [](const std::vector<std::string>& v) {
    std::string out;
    for (const auto& e : v) out += (out.empty() ? "" : "; ") + e;
    return out;
  };
  if (!o.fair.empty()) s.emplace_back("fair", joined(o.fair));
  if (!o.assume.empty()) s.emplace_back("assume", joined(o.assume));
  return p;
}

int run_check_body(const CheckOptions& o, const RunGuard& guard, CheckMode mode) {
  // A wrong output path ends the run now, not after the exploration (docs/reliability.md).
  const auto outputs = output_paths(o);
  check_output_paths(outputs);
  // The budget holds for every phase below; SIGINT/SIGTERM and the memory watchdog cancel it.
  const model::Budget& budget = guard.budget();
  const MemoryWatchdog& watchdog = guard.watchdog();
  // Properties first: a typo in a formula should not wait for the model.
  logic::CheckInputs inputs{
      o.ctl,    o.spec.empty() ? "" : model::read_input_file(o.spec, "the spec file"),
      o.spec,   o.fair,
      o.assume, o.patterns,
      {},       o.ltl};
  // A bound in time ("within 2 s") counts cycles of --cycle when time is discrete.
  if (o.system.time == "discrete") inputs.pattern_options.cycle_ms = parse_cycle_ms(o.system.cycle);
  auto parsed = logic::parse_check_inputs(inputs);
  if (!o.requirements.empty()) {
    auto r =
        logic::parse_requirements(model::read_input_file(o.requirements, "the requirements file"),
                                  o.requirements, inputs.pattern_options);
    parsed.diagnostics.insert(parsed.diagnostics.end(), r.diagnostics.begin(), r.diagnostics.end());
    for (auto& p : r.spec.properties) parsed.spec.properties.push_back(std::move(p));
  }
  print_diagnostics(parsed.diagnostics, "errors in the properties");
  const bool has_properties = !parsed.spec.properties.empty();
  std::string why;
  const auto checks = logic::parse_check_selection(
      o.checks.empty() ? (has_properties ? "none" : "all") : o.checks, &why);
  if (!checks) throw InputError(why);
  const auto trace_format = parse_trace_format(o.trace);
  const TraceRequest traces{trace_format, o.trace_file, o.trace_dir, o.json,
                            parse_cycle_ms(o.system.cycle)};
  check_trace_request(traces);
  static const std::vector<std::string> engines = {"auto", "explicit", "bdd",  "bmc",
                                                   "kind", "ic3",      "nusmv"};
  if (std::find(engines.begin(), engines.end(), o.engine) == engines.end())
    throw UsageError("bad --engine '" + o.engine +
                     "' (expected auto, explicit, bdd, bmc, kind, ic3 or nusmv)");

  if (!o.shard.empty() && !logic::parse_shard(o.shard, &why))
    throw UsageError(why);  // before the model is loaded
  ProgressLine progress(!global_options().quiet);
  progress.phase("load");
  const auto project = load_model_or_throw(o.model, parse_format(o.format), false, &budget);
  budget.check_time("loading the model");
  progress.phase("build");
  const auto built = build_system(project, o.system, logic::assumption_exprs(parsed.spec),
                                  "sfcv check", semantics::ActionOrder::Declaration, &budget);
  budget.check_time("building the system");
  // Inputs and previous values named by a property are kept in the state only then.
  model::Diagnostics history_diags;
  const auto history = logic::history_system_for(parsed.spec, *built.system, history_diags);
  print_diagnostics(history_diags, "errors in the properties");
  const semantics::TransitionSystem* ts = history ? history.get() : built.system.get();

  logic::CheckTask task;
  task.system = ts;
  task.project = &project;
  task.checks = *checks;
  task.priority_resolves_conflicts =
      built.semantics == "iec61131" &&
      parse_priority(o.system.priority) == semantics::PriorityMode::Standard;
  model::Diagnostics resolve_diags;
  logic::resolve_into(parsed.spec, *ts, task, resolve_diags);
  explain_left_out_names(resolve_diags, project);
  print_diagnostics(resolve_diags, "errors in the properties");
  if (o.deadlock_paths != "stutter" && o.deadlock_paths != "drop")
    throw UsageError("bad --deadlock-paths '" + o.deadlock_paths + "' (expected stutter or drop)");
  if (o.deadlock_paths == "drop" && o.engine != "auto" && o.engine != "explicit" &&
      o.engine != "bdd")
    throw UsageError("--deadlock-paths drop: the " + o.engine +
                     " engine does not check it; use --engine explicit, bdd or auto");
  logic::set_deadlock_paths(task, o.deadlock_paths == "drop" ? logic::DeadlockPaths::Drop
                                                             : logic::DeadlockPaths::Stutter);
  // The run's work units; a shard keeps its own (docs/distributed.md).
  if (mode == CheckMode::Plan) return print_plan(logic::work_units(task), o.shard);
  const auto shard = plan_shard(logic::work_units(task), o.shard, o.diversify, o.engine, o.depth);
  logic::restrict_task(task, shard.covered);
  const auto* stored = stored_run();
  task.max_findings = o.all_findings ? 0 : task.max_findings;
  // AG (a -> f): also ask EF a, to tell a vacuous pass.
  const auto num_properties = task.properties.size();
  const auto vacuity = logic::add_vacuity_questions(task);
  task.coverage = o.coverage;
  task.limits = budget;
  task.limits.progress = progress.callback();
  engine::BddEngineOptions bdd_options;
  bdd_options.reorder = *engine::parse_reorder_mode(o.reorder);
  engine::ExplicitEngineOptions explicit_options;
  explicit_options.threads = o.threads;

  progress.phase("explore");
  logic::CheckReport result;
  try {
    if (stored) {
      result = stored->report;  // sfcv merge: the shards' answers, already complete
      replay_stored_traces(result, *ts);
    } else if (task.properties.empty() && task.checks.empty()) {
      result.engine = o.engine;  // a shard without units: nothing to explore
      result.states_known = result.edges_known = false;
    } else {
      result = o.engine == "auto"
                   ? check_auto(task, bdd_options, explicit_options, progress)
                   : choose_engine(o.engine, task, bdd_options, explicit_options,
                                   shard.diversify ? shard.max_depth : o.depth, shard.min_depth)
                         ->check(task);
    }
  } catch (const LimitReached& e) {
    // Stopped before it had a report: every question is unknown, and still reported.
    result = logic::unknown_report(task, o.engine, e);
  }
  if (interrupted())
    mark_stopped(
        result,
        std::string("interrupted by ") + interrupt_signal_name() + " before an answer was certain",
        "interrupted");
  else if (watchdog.tripped())
    mark_stopped(result, guard.memory_text() + " before an answer was certain",
                 to_string(Limit::Memory));
  progress.phase("render");
  if (!stored) {
    logic::answer_vacuity(result, vacuity, num_properties);
    logic::describe_results(result, parsed.spec);
  }
  // A shard may hold only questions its engine leaves open; the merge decides for the run.
  if (!shard.spec) refuse_if_nothing_decided(result, o.engine);
  if (o.coverage && !result.coverage && !global_options().quiet) {
    progress.clear();
    std::cerr << "sfcv: --coverage: the " << result.engine
              << " engine does not measure coverage (use --engine explicit)\n";
  }

  report::RenderOptions render;
  render.trace = trace_format;
  render.model = o.model;
  render.semantics = std::string(semantics::to_string(ts->kind()));
  render.cycle_ms = parse_cycle_ms(o.system.cycle);
  render.verbose = global_options().verbose;
  render.provenance =
      stored
          ? stored->provenance
          : check_provenance(o, render.semantics,
                             std::string(semantics::to_string(chosen_dialect(project, o.system))));
  render.sarif_root = sarif_root(o);
  // Every requested file is written, even when another could not be. The files come before
  // standard output (`sfcv check ... | head` ends sfcv by SIGPIPE), and the verdicts are printed
  // whatever happened to them: a report that cannot be written, or a renderer's bug, must not
  // hide a verdict.
  std::vector<std::string> write_errors;
  std::exception_ptr render_error;
  auto write = [&](const OutputPath& out, auto&& render_text) {
    if (out.path.empty() || render_error) return;
    try {
      write_output(out, render_text());
    } catch (const UsageError& e) {
      write_errors.push_back(e.what());
    } catch (...) {
      render_error = std::current_exception();
    }
  };
  // Every trace, one per property (cli/check_traces.hpp); the report names where each went.
  auto written = write_traces(result, *ts, traces);
  render.trace_files = written.where;
  write_errors.insert(write_errors.end(), written.errors.begin(), written.errors.end());
  write(outputs[1], [&] {
    std::string text;
    for (const auto& r : result.results)
      if (!r.certificate.empty()) text += "# " + r.name + "\n" + r.certificate;
    return text;
  });
  write(outputs[2], [&] { return report::check_junit(result, *ts, render); });
  write(outputs[3],
        [&] { return report::check_sarif(result, *ts, &project, render).dump(2) + "\n"; });
  write(outputs[4], [&] {
    return report::check_html(report::html_report(report::check_json(result, *ts, render), project,
                                                  *ts, picture_limits(budget)));
  });
  if (o.json) {
    auto json = report::check_json(result, *ts, render);
    if (shard.spec)
      json["shard"] = report::shard_json(*shard.spec, shard.diversify, shard.units, shard.covered,
                                         result, *render.provenance);
    std::cout << json.dump(2) << "\n";
  } else if (traces_on_standard_output(traces)) {
    // Standard output holds the trace alone (a VCD file, a CSV for simulate): the report
    // goes to standard error.
    progress.clear();
    std::cerr << report::check_text(result, *ts, render);
    std::cout << written.standard_output;
  } else {
    std::cout << report::check_text(result, *ts, render);
  }
  if (render_error) rethrow_unless_racers_left_behind(render_error, o.json ? &std::cout : nullptr);
  if (!write_errors.empty()) {
    progress.clear();
    for (const auto& e : write_errors) std::cerr << "sfcv: error: " << e << "\n";
    return end_here_if_racers_left_behind(kBadInput);
  }
  return end_here_if_racers_left_behind(logic::exit_code(result));
}

int run_check(const CheckOptions& o, CheckMode mode) {
  const InterruptScope interrupt;  // the first signal stops the engines, the reports follow
  // Past --memory, the whole process stops as at its deadline (the engines' own counts miss
  // what they share); a limit reached while loading or building names itself (run_guard.hpp).
  return run_limited(
      o.limits, [&o, mode](const RunGuard& guard) { return run_check_body(o, guard, mode); },
      interrupt_flag());
}

}  // namespace

void add_check_command(CLI::App& app, CommandRunner& selected) {
  add_check_like_command(app, selected, CheckMode::Check);
}

void add_check_like_command(CLI::App& app, CommandRunner& selected, CheckMode mode) {
  auto opts = std::make_shared<CheckOptions>();
  auto* sub =
      mode == CheckMode::Plan
          ? app.add_subcommand("plan",
                               "The work units of a check (same arguments) and their "
                               "estimated costs, as JSON (docs/distributed.md)")
          : app.add_subcommand("check", "Model-check CTL properties and the standard checks");
  sub->add_option("model", opts->model, "Chart file (PLCopen XML, IEC text, .g7, AGRAFE .grafcet)")
      ->required();
  sub->add_option("--format", opts->format, kFormatHelp);
  sub->add_option("--ctl", opts->ctl, "A CTL property, e.g. 'AG !(V1 & V3)' (repeatable)");
  sub->add_option(
      "--ltl", opts->ltl,
      "An LTL property (X F G U R W), e.g. 'G (V1 -> F !V1)' (repeatable; engines explicit, "
      "bdd (IEC 61131-3) and auto)");
  sub->add_option("--pattern", opts->patterns,
                  "A requirement pattern, e.g. 'response(start, V1, within 5 cycles)' or "
                  "'absence(V1 & V3, after start)' (repeatable; list: sfcv patterns)");
  sub->add_option("--requirements", opts->requirements,
                  "A requirements file: PLCverif-style JSON or ESBMC-PLC YAML, detected by content "
                  "(docs/properties.md)");
  sub->add_option("--spec", opts->spec,
                  "A file of 'property name: formula;', 'pattern name: pattern;', "
                  "'ltl name: formula;', 'assume e;', 'fair e;'");
  std::string names;
  for (const auto& c : logic::standard_checks())
    names += (names.empty() ? "" : ", ") + std::string(c.name);
  sub->add_option(
      "--checks", opts->checks,
      "Standard checks: all (default without properties), none, or a list of: " + names);
  sub->add_option("--fair", opts->fair,
                  "Fairness: only runs visiting this infinitely often (repeatable)");
  sub->add_option("--assume", opts->assume,
                  "Assumption on inputs and state, e.g. '!(LIS1plus & LIS1minus)' (repeatable)");
  sub->add_option("--engine", opts->engine,
                  "auto (default: explicit up to " + std::to_string(engine::kAutoProbeStates) +
                      " states, then bdd, ic3 and bmc side by side), explicit, bdd, bmc, kind, ic3 "
                      "(SAT engines: invariants and reachability), or nusmv (a NuSMV on PATH)");
  sub->add_option("--depth", opts->depth,
                  "bmc and kind: the deepest unrolling in cycles (default 200)");
  sub->add_option("--threads", opts->threads,
                  "explicit engine: threads generating successors when only invariants are asked "
                  "(default 0: one per core; at most one per core; results do not depend on it)");
  sub->add_option("--certificate", opts->certificate,
                  "kind and ic3: write the re-checked proof of each result there (inductive "
                  "invariant clauses over latch names, or the k of k-induction)");
  add_system_options(*sub, opts->system);
  add_limit_options(*sub, opts->limits, "answers not decided by then become unknown");
  // A bare --reorder (the old switch) means dynamic.
  sub->add_option(
         "--reorder", opts->reorder,
         "bdd engine: variable reordering by sifting: none, once (after the "
         "relation is built), dynamic (the default: whenever the live nodes doubled); a bare "
         "--reorder means dynamic")
      ->expected(0, 1)
      ->default_str("dynamic")
      ->check(CLI::IsMember({"none", "once", "dynamic"}));
  sub->add_flag("--json", opts->json,
                "JSON output (schema: share/sfcv/check-result.schema.json, docs/formats.md)");
  sub->add_option("--trace", opts->trace,
                  "Trace format: table (default), json, vcd, csv (sfcv simulate input), none; "
                  "vcd and csv without --trace-file or --trace-dir: the trace alone on standard "
                  "output, the report on standard error");
  sub->add_option("--trace-file", opts->trace_file,
                  "Write the counterexample (else witness) there; several: one file per "
                  "property beside it, named by the property id (t.vcd -> t.check-reachable.vcd)");
  sub->add_option("--trace-dir", opts->trace_dir,
                  "Write every trace into this directory, one file per property named by its id "
                  "(check-reachable.vcd, property-ctl-3a7bd3e2360a.vcd)");
  sub->add_option("--sarif-root", opts->sarif_root,
                  "SARIF URIs relative to this directory (default: the git work tree around the "
                  "working directory, else the working directory)");
  sub->add_option(
      "--junit", opts->junit,
      "Also write a JUnit XML report there, for CI (violated = failure, unknown = error)");
  sub->add_option("--sarif", opts->sarif,
                  "Also write a SARIF 2.1.0 log there, for code-scanning views (docs/reports.md)");
  sub->add_option("--html", opts->html,
                  "Also write a self-contained HTML report there: summary, chart, trace player "
                  "(docs/reports.md)");
  sub->add_flag("--coverage", opts->coverage,
                "Also report the steps, transitions and actions the reachable states visit "
                "(explicit engine)");
  sub->add_option("--deadlock-paths", opts->deadlock_paths,
                  "A state without a successor: stutter (default: it repeats forever, as Spin "
                  "reads it) or drop (no path passes there; only infinite paths count, as in "
                  "NuSMV); explicit and bdd engines (docs/properties.md)");
  sub->add_flag("--all", opts->all_findings,
                "Every finding of the standard checks (else the first 20 of each, with a count)");
  sub->footer(
      "Properties: steps, actions, variables, inputs, prev(p), rise(p), fall(p); "
      "AG (a -> f) reports whether it holds vacuously. Patterns (--pattern, 'sfcv "
      "patterns' lists them) and a cookbook: docs/properties.md.\n"
      "Exit codes: 0 every property and check holds (those n/a on the chart aside), 1 some "
      "property is violated, 2 bad usage or input (also: the engine decides nothing that was "
      "asked), 3 unknown (a limit was reached before an answer was certain, or some answer is "
      "'not checked' by the engine), 4 internal error.");
  if (mode == CheckMode::Plan)
    sub->footer("Exit codes: 0 the plan was printed, 2 bad usage or input, 4 internal error.");
  sub->add_option("--shard", opts->shard,
                  "Run only shard I of N (1-based, e.g. 2/4): a deterministic part of the "
                  "properties and checks, balanced by cost; sfcv merge joins the --json results "
                  "(docs/distributed.md)");
  sub->add_flag("--diversify", opts->diversify,
                "With --shard: every shard asks every question in its own part of the search "
                "(--engine bmc: depth ranges); sfcv merge keeps the first answer");
  sub->callback(
      [opts, &selected, mode] { selected = [opts, mode] { return run_check(*opts, mode); }; });
}

}  // namespace sfcv::cli
