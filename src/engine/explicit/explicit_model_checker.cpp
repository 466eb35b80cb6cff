#include "engine/explicit/explicit_model_checker.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

#include "engine/explicit/compiled_successors.hpp"
#include "engine/explicit/invariant_search.hpp"
#include "engine/explicit/ltl_checker.hpp"
#include "logic/formula.hpp"
#include "logic/standard_checks.hpp"
#include "logic/trace_replay.hpp"
#include "model/errors.hpp"

namespace sfcv::engine {

namespace {

/// The report of a run the semantics stopped before a graph existed (an integer input too wide
/// to enumerate): every answer is unknown, the limit says why.
logic::CheckReport all_unknown(const logic::CheckTask& task, const LimitReached& stop) {
  auto report = logic::unknown_report(task, "explicit", stop);
  report.states_known = true;  // none explored: zero states
  return report;
}

}  // namespace

bool ExplicitModelChecker::can_handle(const logic::CheckTask& task, std::string* why) const {
  if (!task.system) {
    if (why) *why = "no transition system";
    return false;
  }
  return true;
}

namespace {

logic::Coverage measure_coverage(const ReachableSituationGraph& graph) {
  const auto& ts = graph.system();
  logic::Coverage c;
  const auto& obs = ts.observables();
  std::vector<bool> seen(obs.size(), false);
  for (std::uint32_t s = 0; s < graph.num_states(); ++s) {
    const auto state = graph.states().at(s);
    for (std::uint32_t o = 0; o < obs.size(); ++o)
      if (!seen[o] && obs[o].kind != semantics::ObservableKind::Variable && ts.observe(state, o))
        seen[o] = true;
  }
  for (std::uint32_t o = 0; o < obs.size(); ++o) {
    if (obs[o].kind == semantics::ObservableKind::Step) {
      ++c.steps;
      c.steps_visited += seen[o];
      if (!seen[o]) c.unvisited.push_back("step " + obs[o].name);
    } else if (obs[o].kind == semantics::ObservableKind::Action) {
      ++c.actions;
      c.actions_active += seen[o];
      if (!seen[o]) c.unvisited.push_back("action " + obs[o].name);
    }
  }
  const auto& fired = graph.fired_somewhere();
  c.transitions = static_cast<std::uint32_t>(ts.transitions().size());
  for (std::uint32_t t = 0; t < c.transitions; ++t) {
    const bool f = t < fired.size() && fired[t];
    c.transitions_fired += f;
    if (!f) c.unvisited.push_back("transition " + ts.transitions()[t].name);
  }
  return c;
}

/// A Grafcet trace row lists what its own inputs clear, as `sfcv simulate` does: an edge of the
/// graph carries the union of the fired sets of every valuation between its two nodes
/// (logic::fire_as_replayed).
logic::CheckReport fired_as_replayed(const logic::CheckTask& task, logic::CheckReport report) {
  if (task.system->kind() != semantics::SemanticsKind::Grafcet) return report;
  for (auto& r : report.results)
    if (r.trace) logic::fire_as_replayed(*task.system, *r.trace);
  return report;
}

}  // namespace

logic::CheckReport ExplicitModelChecker::check(const logic::CheckTask& task) const {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  // Invariants alone need neither the edges nor their labels: decided during the search.
  if (invariants_only(task)) {
    // An input too wide to enumerate ends the search as any limit does: a report of unknowns
    // naming it (the portfolio then races the symbolic engines), never a bare error.
    try {
      const auto compiled = make_compiled_enumerator(*task.system, task.limits);
      // More threads than cores only add contention (and --threads 100000 would exhaust the
      // process table): the request is capped at the cores available.
      const unsigned cores = std::max(1U, std::thread::hardware_concurrency());
      const unsigned threads = options_.threads > 0 ? std::min(options_.threads, cores) : cores;
      return fired_as_replayed(task, check_invariants(task, compiled.get(), threads));
    } catch (const LimitReached& stop) {
      auto report = all_unknown(task, stop);
      report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      return report;
    }
  }
  ExplorationOptions opts;
  opts.max_states = task.limits.max_states;
  opts.deadline = task.limits.deadline;
  opts.cancel = task.limits.cancel.get();
  opts.max_memory_bytes = task.limits.max_memory_bytes;
  opts.max_valuations = task.limits.max_valuations;
  opts.forecast = options_.forecast;
  if (task.limits.progress) {
    opts.progress_interval = 4096;
    opts.progress = [cb = task.limits.progress](const ExplorationProgress& p) {
      logic::Progress q;
      q.phase = "explore";
      q.states = p.states;
      q.edges = p.edges;
      q.depth = p.depth;
      q.seconds = p.seconds;
      cb(q);
    };
  }
  std::optional<ReachableSituationGraph> built;
  try {
    built.emplace(build_reachable_situation_graph(*task.system, opts));
  } catch (const LimitReached& stop) {
    auto report = all_unknown(task, stop);
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return report;
  }
  const auto& graph = *built;
  logic::CheckReport report;
  report.engine = "explicit";
  report.states = graph.num_states();
  report.edges = graph.num_edges();
  for (std::uint32_t s = 0; s < graph.num_states(); ++s)
    report.depth = std::max(report.depth, graph.depth(s));
  report.complete = graph.complete();
  report.limit = graph.limit_reached();

  CtlChecker checker(graph, task.fairness);
  for (const auto& p : task.properties) {
    const auto t0 = Clock::now();
    logic::PropertyResult r;
    try {
      // Each property is linear in the graph: checking the deadline between them bounds the
      // overrun by one property.
      task.limits.check_time("checking the properties");
      r = logic::is_ltl(*p.formula)
              ? check_ltl(checker, p, task.fairness, task.limits, task.deadlock_paths)
              : checker.check(p);
    } catch (const LimitReached& stop) {
      r = logic::PropertyResult{};
      r.name = p.name;
      r.formula = logic::to_string(p.formula);
      r.where = p.where;
      r.verdict = logic::Verdict::Unknown;
      r.message = stop.what();
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count() +
                (report.results.empty() ? graph.build_seconds() : 0.0);
    report.results.push_back(std::move(r));
  }
  for (auto& r : run_standard_checks(graph, checker, task)) report.results.push_back(std::move(r));
  if (task.coverage) report.coverage = measure_coverage(graph);
  report = fired_as_replayed(task, std::move(report));
  report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return report;
}

ModelCheckerPtr make_explicit_model_checker(const ExplicitEngineOptions& options) {
  return std::make_unique<ExplicitModelChecker>(options);
}

}  // namespace sfcv::engine
