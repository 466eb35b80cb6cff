#include "engine/explicit/ctl_checker.hpp"

#include <algorithm>
#include <deque>

#include "logic/formula.hpp"
#include "logic/push_negation.hpp"
#include "model/errors.hpp"

namespace sfcv::engine {

using logic::Formula;
using logic::FormulaPtr;
using logic::Op;

namespace {

StateSet negate(const StateSet& a) {
  StateSet r(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) r[i] = !a[i];
  return r;
}
StateSet conj(const StateSet& a, const StateSet& b) {
  StateSet r(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) r[i] = a[i] && b[i];
  return r;
}
StateSet disj(const StateSet& a, const StateSet& b) {
  StateSet r(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) r[i] = a[i] || b[i];
  return r;
}

}  // namespace

CtlChecker::CtlChecker(const ReachableSituationGraph& graph, std::vector<FormulaPtr> fairness)
    : g_(graph), fairness_(std::move(fairness)) {
  for (const auto& f : fairness_) fair_sets_.push_back(sat(f));
}

const StateSet& CtlChecker::sat(const FormulaPtr& f) {
  auto it = memo_.find(f.get());
  if (it != memo_.end()) return it->second;
  auto result = compute(*f);
  keep_.push_back(f);
  return memo_.emplace(f.get(), std::move(result)).first->second;
}

const StateSet& CtlChecker::fair_states() {
  if (!fair_computed_) {
    const StateSet all(g_.num_states(), 1);
    fair_ = fairness_.empty() ? all : eg(all);
    fair_computed_ = true;
  }
  return fair_;
}

StateSet CtlChecker::compute(const Formula& f) {
  const std::uint32_t n = g_.num_states();
  const auto& ts = g_.system();
  auto arg = [&](std::size_t i) -> const StateSet& { return sat(f.args[i]); };
  // Fair versions of the path operators: targets must be fair states.
  auto fair_and = [&](const StateSet& s) { return fairness_.empty() ? s : conj(s, fair_states()); };
  switch (f.op) {
    case Op::True:
      return StateSet(n, 1);
    case Op::False:
      return StateSet(n, 0);
    case Op::Atom:
    case Op::Compare: {
      StateSet r(n, 0);
      const auto obs = static_cast<std::uint32_t>(f.observable);
      for (std::uint32_t s = 0; s < n; ++s) {
        const auto v = ts.observe(g_.states().at(s), obs);
        r[s] = f.op == Op::Atom ? v != 0 : logic::compare(f.cmp, v, f.value);
      }
      return r;
    }
    case Op::Relation: {
      StateSet r(n, 0);
      for (std::uint32_t s = 0; s < n; ++s) {
        const auto state = g_.states().at(s);
        r[s] = logic::relation_holds(f, [&](std::uint32_t o) { return ts.observe(state, o); });
      }
      return r;
    }
    case Op::Not:
      return negate(arg(0));
    case Op::And:
      return conj(arg(0), arg(1));
    case Op::Or:
      return disj(arg(0), arg(1));
    case Op::Implies:
      return disj(negate(arg(0)), arg(1));
    case Op::Iff:
    case Op::Xor: {
      const auto& a = arg(0);
      const auto& b = arg(1);
      StateSet r(n);
      for (std::uint32_t s = 0; s < n; ++s) r[s] = (a[s] == b[s]) == (f.op == Op::Iff);
      return r;
    }
    case Op::EX:
      return ex(fair_and(arg(0)));
    case Op::AX:
      return negate(ex(fair_and(negate(arg(0)))));
    case Op::EF:
      return eu(StateSet(n, 1), fair_and(arg(0)));
    case Op::AG:
      return negate(eu(StateSet(n, 1), fair_and(negate(arg(0)))));
    case Op::EG:
      return eg(arg(0));
    case Op::AF:
      return negate(eg(negate(arg(0))));
    case Op::EU:
      return eu(arg(0), fair_and(arg(1)));
    case Op::AU: {
      const auto nq = negate(arg(1));
      const auto np = negate(arg(0));
      return negate(disj(eu(nq, fair_and(conj(np, nq))), eg(nq)));
    }
    case Op::X:
    case Op::F:
    case Op::G:
    case Op::U:
    case Op::R:
    case Op::W:
      break;  // LTL: path formulas, checked by ltl_checker.hpp, never labelled on states
    case Op::Value:
    case Op::Number:
    case Op::Neg:
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
      throw InternalError("CTL labelling of a term: " + logic::to_string(f));
  }
  throw InternalError("CTL labelling of an LTL operator: " + logic::to_string(f));
}

StateSet CtlChecker::ex(const StateSet& p) {
  const std::uint32_t n = g_.num_states();
  StateSet r(n, 0);
  for (std::uint32_t s = 0; s < n; ++s) {
    if (!g_.expanded(s)) continue;
    for (auto e = g_.edges_begin(s); e < g_.edges_end(s); ++e)
      if (p[g_.target(e)]) {
        r[s] = 1;
        break;
      }
  }
  return r;
}

StateSet CtlChecker::eu(const StateSet& p, const StateSet& q) {
  const auto& po = g_.predecessor_offsets();
  const auto& pe = g_.predecessor_edges();
  StateSet r = q;
  std::vector<std::uint32_t> queue;
  for (std::uint32_t s = 0; s < r.size(); ++s)
    if (r[s]) queue.push_back(s);
  while (!queue.empty()) {
    const auto t = queue.back();
    queue.pop_back();
    for (auto i = po[t]; i < po[t + 1]; ++i) {
      const auto s = g_.source(pe[i]);
      if (!r[s] && p[s]) {
        r[s] = 1;
        queue.push_back(s);
      }
    }
  }
  return r;
}

std::vector<std::int32_t> CtlChecker::good_sccs(const StateSet& mask) {
  const std::uint32_t n = g_.num_states();
  constexpr std::uint32_t kUnvisited = ~0U;
  std::vector<std::uint32_t> index(n, kUnvisited), low(n, 0);
  std::vector<std::uint8_t> on_stack(n, 0);
  std::vector<std::uint32_t> stack;
  std::vector<std::int32_t> good(n, -1);
  struct Frame {
    std::uint32_t v;
    std::uint64_t e;
  };
  std::vector<Frame> calls;
  std::uint32_t counter = 0;
  std::int32_t next_id = 0;
  auto edges_end = [&](std::uint32_t v) {
    return g_.expanded(v) ? g_.edges_end(v) : g_.edges_begin(v);
  };
  for (std::uint32_t root = 0; root < n; ++root) {
    if (!mask[root] || index[root] != kUnvisited) continue;
    auto open = [&](std::uint32_t v) {
      index[v] = low[v] = counter++;
      stack.push_back(v);
      on_stack[v] = 1;
      calls.push_back({v, g_.expanded(v) ? g_.edges_begin(v) : 0});
    };
    open(root);
    while (!calls.empty()) {
      auto& fr = calls.back();
      const auto v = fr.v;
      if (g_.expanded(v) && fr.e < edges_end(v)) {
        const auto w = g_.target(fr.e++);
        if (!mask[w]) continue;
        if (index[w] == kUnvisited) {
          open(w);
        } else if (on_stack[w]) {
          low[v] = std::min(low[v], index[w]);
        }
        continue;
      }
      calls.pop_back();
      if (!calls.empty()) low[calls.back().v] = std::min(low[calls.back().v], low[v]);
      if (low[v] != index[v]) continue;
      // v is the root of an SCC: pop it and decide whether it is a good one.
      std::vector<std::uint32_t> members;
      std::uint32_t w;
      do {
        w = stack.back();
        stack.pop_back();
        on_stack[w] = 0;
        members.push_back(w);
      } while (w != v);
      bool nontrivial = members.size() > 1;
      if (!nontrivial && g_.expanded(v))
        for (auto e = g_.edges_begin(v); e < g_.edges_end(v); ++e) nontrivial |= g_.target(e) == v;
      if (!nontrivial) continue;
      bool meets_all = true;
      for (const auto& fs : fair_sets_) {
        bool meets = false;
        for (auto m : members) meets |= fs[m] != 0;
        meets_all &= meets;
      }
      if (!meets_all) continue;
      for (auto m : members) good[m] = next_id;
      ++next_id;
    }
  }
  return good;
}

StateSet CtlChecker::eg(const StateSet& p) {
  const std::uint32_t n = g_.num_states();
  const auto good = good_sccs(p);
  StateSet seeds(n, 0);
  for (std::uint32_t s = 0; s < n; ++s) {
    if (good[s] >= 0) seeds[s] = 1;
    // A maximal finite path ends in a deadlock; fair paths are infinite.
    if (fairness_.empty() && p[s] && !has_successor(s)) seeds[s] = 1;
  }
  return eu(p, seeds);
}

// ------------------------------------------------------------------------------ witnesses

std::vector<CtlChecker::Hop> CtlChecker::bfs(const std::vector<std::uint32_t>& sources,
                                             const StateSet& allowed, const StateSet& target,
                                             bool min_one_edge, std::uint32_t& start, bool& found) {
  found = false;
  const std::uint32_t n = g_.num_states();
  constexpr std::uint32_t kNone = ~0U;
  std::vector<std::uint32_t> parent(n, kNone);
  std::vector<std::uint64_t> via(n, kNoEdge);
  std::vector<std::uint32_t> origin(n, kNone);
  std::deque<std::uint32_t> queue;
  for (auto s : sources) {
    if (!min_one_edge && target[s]) {
      start = s;
      found = true;
      return {};
    }
    if (origin[s] == kNone) {
      origin[s] = s;
      queue.push_back(s);
    }
  }
  while (!queue.empty()) {
    const auto s = queue.front();
    queue.pop_front();
    if (!g_.expanded(s)) continue;
    for (auto e = g_.edges_begin(s); e < g_.edges_end(s); ++e) {
      const auto t = g_.target(e);
      if (target[t]) {
        std::vector<Hop> hops{{t, e}};
        auto x = s;
        while (via[x] != kNoEdge) {
          hops.push_back({x, via[x]});
          x = parent[x];
        }
        std::reverse(hops.begin(), hops.end());
        start = x;
        found = true;
        return hops;
      }
      if (origin[t] == kNone && allowed[t]) {
        origin[t] = origin[s];
        parent[t] = s;
        via[t] = e;
        queue.push_back(t);
      }
    }
  }
  return {};
}

void CtlChecker::explain_eu(const StateSet& through, const StateSet& target, const FormulaPtr& then,
                            const std::vector<std::uint32_t>& sources, std::vector<Hop>& run,
                            logic::Trace& trace, int depth) {
  std::uint32_t start = 0;
  bool found = false;
  auto hops = bfs(sources, through, target, false, start, found);
  if (!found) return;
  if (run.empty()) run.push_back({start, kNoEdge});
  run.insert(run.end(), hops.begin(), hops.end());
  explain_at(then, run, trace, depth + 1);
}

void CtlChecker::lasso(const FormulaPtr& eg_formula, const std::vector<std::uint32_t>& sources,
                       std::vector<Hop>& run, logic::Trace& trace) {
  const auto& z = sat(eg_formula);
  const auto& p = sat(eg_formula->args[0]);
  const auto good = good_sccs(p);
  const std::uint32_t n = g_.num_states();
  StateSet core(n, 0);
  for (std::uint32_t s = 0; s < n; ++s)
    core[s] = good[s] >= 0 || (fairness_.empty() && p[s] && !has_successor(s) && g_.expanded(s));
  std::uint32_t start = 0;
  bool found = false;
  auto hops = bfs(sources, z, core, false, start, found);
  if (!found) return;
  if (run.empty()) run.push_back({start, kNoEdge});
  run.insert(run.end(), hops.begin(), hops.end());
  const auto c = run.back().state;
  if (good[c] < 0) {
    trace.ends_in_deadlock = true;
    return;
  }
  StateSet scc(n, 0);
  for (std::uint32_t s = 0; s < n; ++s) scc[s] = good[s] == good[c];
  const std::size_t loop_at = run.size() - 1;
  auto current = c;
  for (const auto& fs : fair_sets_) {
    if (fs[current]) continue;
    auto to = conj(scc, fs);
    std::uint32_t st = 0;
    bool ok = false;
    auto part = bfs({current}, scc, to, false, st, ok);
    if (!ok) return;
    run.insert(run.end(), part.begin(), part.end());
    current = run.back().state;
  }
  StateSet back(n, 0);
  back[c] = 1;
  std::uint32_t st = 0;
  bool ok = false;
  auto part = bfs({current}, scc, back, true, st, ok);
  if (!ok) return;
  run.insert(run.end(), part.begin(), part.end());
  trace.loop_start = loop_at;
}

void CtlChecker::explain_at(const FormulaPtr& f, std::vector<Hop>& run, logic::Trace& trace,
                            int depth) {
  std::vector<std::uint32_t> sources;
  if (!run.empty()) {
    sources.push_back(run.back().state);
  } else {
    for (auto s : trace_sources_) sources.push_back(s);
  }
  const auto& holds = sat(f);
  std::vector<std::uint32_t> ok;
  for (auto s : sources)
    if (holds[s]) ok.push_back(s);
  if (ok.empty()) return;
  auto settle = [&] {
    if (run.empty()) run.push_back({ok.front(), kNoEdge});
  };
  // The lasso of EG closes the run: nothing can follow it.
  if (depth > 8 || trace.loop_start || trace.ends_in_deadlock) return settle();
  const std::uint32_t n = g_.num_states();
  auto fair_and = [&](const StateSet& s) { return fairness_.empty() ? s : conj(s, fair_states()); };
  const auto& a = f->args;
  switch (f->op) {
    case Op::Not: {
      auto pushed = logic::push_negation(a[0]);
      if (pushed->op == Op::Not) return settle();
      keep_.push_back(pushed);
      trace_sources_ = ok;
      return explain_at(pushed, run, trace, depth + 1);
    }
    case Op::And:
    case Op::Or:
    case Op::Implies: {
      FormulaPtr pick;
      if (f->op == Op::And) {
        pick = logic::is_propositional(*a[0]) ? a[1] : a[0];
      } else {
        auto first = f->op == Op::Implies ? logic::make_not(a[0]) : a[0];
        keep_.push_back(first);
        const auto& s0 = sat(first);
        const auto& s1 = sat(a[1]);
        // Prefer the temporal disjunct that holds at a source.
        std::vector<FormulaPtr> order = {first, a[1]};
        if (logic::is_propositional(*first)) std::swap(order[0], order[1]);
        for (const auto& cand : order) {
          const auto& set = cand == first ? s0 : s1;
          for (auto s : ok)
            if (set[s]) {
              pick = cand;
              break;
            }
          if (pick) break;
        }
      }
      if (!pick || logic::is_propositional(*pick)) return settle();
      trace_sources_ = ok;
      return explain_at(pick, run, trace, depth + 1);
    }
    case Op::EX: {
      settle();
      const auto s = run.back().state;
      const auto target = fair_and(sat(a[0]));
      for (auto e = g_.edges_begin(s); g_.expanded(s) && e < g_.edges_end(s); ++e)
        if (target[g_.target(e)]) {
          run.push_back({g_.target(e), e});
          return explain_at(a[0], run, trace, depth + 1);
        }
      return;
    }
    case Op::EF:
      return explain_eu(StateSet(n, 1), fair_and(sat(a[0])), a[0], ok, run, trace, depth);
    case Op::EU:
      return explain_eu(sat(a[0]), fair_and(sat(a[1])), a[1], ok, run, trace, depth);
    case Op::EG:
      return lasso(f, ok, run, trace);
    default:
      return settle();
  }
}

logic::Trace CtlChecker::explain(const FormulaPtr& f, const std::vector<std::uint32_t>& sources) {
  logic::Trace trace;
  std::vector<Hop> run;
  trace_sources_ = sources;
  explain_at(f, run, trace, 0);
  return to_trace(run, std::move(trace));
}

logic::Trace CtlChecker::path_to(std::uint32_t target) {
  std::vector<Hop> run{{g_.path_initial(target), kNoEdge}};
  for (auto e : g_.shortest_path_edges(target)) run.push_back({g_.target(e), e});
  return to_trace(run, logic::Trace{});
}

logic::Trace CtlChecker::to_trace(const std::vector<Hop>& run, logic::Trace base) const {
  const auto& inputs = g_.system().inputs();
  std::vector<std::int64_t> previous;
  for (const auto& h : run) {
    logic::TraceStep step;
    const auto view = g_.states().at(h.state);
    step.state.assign(view.begin(), view.end());
    if (h.edge == kNoEdge) {
      const auto& init = g_.initial_states();
      const auto it = std::find(init.begin(), init.end(), h.state);
      step.inputs = it == init.end()
                        ? logic::pick_inputs(semantics::InputCondition::always(), inputs, {})
                        : logic::pick_inputs(g_.initial_condition(it - init.begin()), inputs, {});
    } else {
      step.inputs = logic::pick_inputs(g_.condition(h.edge), inputs, previous);
      const auto fired = g_.fired(h.edge);
      step.fired.assign(fired.begin(), fired.end());
    }
    previous = step.inputs;
    base.steps.push_back(std::move(step));
  }
  return base;
}

// ------------------------------------------------------------------------------ verdicts

logic::PropertyResult CtlChecker::check(const logic::Property& p) {
  logic::PropertyResult r;
  r.name = p.name;
  r.formula = logic::to_string(p.formula);
  r.where = p.where;
  const auto marked = logic::atom_observables(*p.formula);
  const auto& init = g_.initial_states();
  if (init.empty()) {
    r.verdict = logic::Verdict::Unknown;
    r.message =
        "no initial state: the assumptions exclude every initial situation, or none is stable (see "
        "the instability check)";
    return r;
  }
  const auto& f = p.formula;
  if (!g_.complete()) {
    r.verdict = logic::Verdict::Unknown;
    r.message = "exploration stopped at the " + g_.limit_reached() + " limit after " +
                std::to_string(g_.num_states()) + " states";
    // Reachable states are real: a bad state already refutes AG p, a good one proves EF p.
    const bool ag = f->op == Op::AG && logic::is_propositional(*f->args[0]);
    const bool ef = f->op == Op::EF && logic::is_propositional(*f->args[0]) && fairness_.empty();
    if (ag || ef) {
      const auto& inner = sat(f->args[0]);
      std::uint32_t best = ReachableSituationGraph::kNone;
      for (std::uint32_t s = 0; s < g_.num_states(); ++s)
        if ((inner[s] != 0) == ef && g_.has_path(s) &&
            (best == ReachableSituationGraph::kNone || g_.depth(s) < g_.depth(best)))
          best = s;
      // Under fairness a violating state must also be fair, which needs the whole graph. A state
      // without a known path (found from a state left unexpanded) cannot be shown: not used.
      if (best != ReachableSituationGraph::kNone && (ef || fairness_.empty())) {
        r.verdict = ef ? logic::Verdict::Holds : logic::Verdict::Violated;
        r.message.clear();
        r.trace = path_to(best);
        r.trace->kind = ef ? logic::TraceKind::Witness : logic::TraceKind::Counterexample;
        r.trace->marked = marked;
      }
    }
    return r;
  }
  const auto& holds = sat(f);
  std::vector<std::uint32_t> bad;
  for (auto s : init)
    if (!holds[s]) bad.push_back(s);
  if (bad.empty()) {
    r.verdict = logic::Verdict::Holds;
    if (!logic::is_propositional(*f)) {
      auto t = explain(f, init);
      if (t.steps.size() > 1 || t.loop_start) {
        t.kind = logic::TraceKind::Witness;
        t.marked = marked;
        r.trace = std::move(t);
      }
    }
  } else {
    r.verdict = logic::Verdict::Violated;
    auto neg = logic::push_negation(f);
    keep_.push_back(neg);
    auto t = explain(neg, bad);
    t.kind = logic::TraceKind::Counterexample;
    t.marked = marked;
    r.trace = std::move(t);
  }
  return r;
}

}  // namespace sfcv::engine
