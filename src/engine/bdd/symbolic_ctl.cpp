#include "engine/bdd/symbolic_ctl.hpp"

#include <stdexcept>

#include "logic/formula.hpp"
#include "logic/push_negation.hpp"

namespace sfcv::engine {

using bdd::Bdd;
using logic::FormulaPtr;
using logic::Op;

SymbolicCtl::SymbolicCtl(SymbolicSystem& sys, std::vector<FormulaPtr> fairness)
    : sys_(sys), fairness_(std::move(fairness)) {
  for (const auto& f : fairness_) fair_sets_.push_back(sys_.atom(*f));
  if (!fair_sets_.empty()) fair_ = eg_fair(Bdd::constant(true));
}

Bdd SymbolicCtl::sat(const FormulaPtr& f) {
  if (auto it = memo_.find(f.get()); it != memo_.end()) return it->second;
  Bdd r = compute(*f);
  memo_.emplace(f.get(), r);
  keep_.push_back(f);
  return r;
}

Bdd SymbolicCtl::compute(const logic::Formula& f) {
  const bool fair = !fair_sets_.empty();
  auto arg = [&](std::size_t i) { return sat(f.args[i]); };
  switch (f.op) {
    case Op::True:
    case Op::False:
    case Op::Atom:
    case Op::Compare:
    case Op::Relation:
      return sys_.atom(f);
    case Op::Not:
      return !arg(0);
    case Op::And:
      return arg(0) & arg(1);
    case Op::Or:
      return arg(0) | arg(1);
    case Op::Implies:
      return (!arg(0)) | arg(1);
    case Op::Iff:
      return arg(0).iff(arg(1));
    case Op::Xor:
      return arg(0) ^ arg(1);
    case Op::EX:
      return ex(arg(0));
    case Op::AX:
      return !ex(!arg(0));
    case Op::EF:
      return eu(Bdd::constant(true), arg(0));
    case Op::AG:
      return !eu(Bdd::constant(true), !arg(0));
    case Op::EG:
      return fair ? eg_fair(arg(0)) : eg(arg(0));
    case Op::AF:
      return !(fair ? eg_fair(!arg(0)) : eg(!arg(0)));
    case Op::EU:
      return eu(arg(0), arg(1));
    case Op::AU: {
      const Bdd p = arg(0), q = arg(1);
      const Bdd g = fair ? eg_fair(!q) : eg(!q);
      return !(eu(!q, (!p) & (!q)) | g);
    }
    case Op::X:
    case Op::F:
    case Op::G:
    case Op::U:
    case Op::R:
    case Op::W:
      break;  // LTL: can_handle refuses it (logic::first_ltl_property)
    case Op::Value:
    case Op::Number:
    case Op::Neg:
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
      break;  // terms: only inside a Relation
  }
  throw std::logic_error("symbolic CTL labelling of an LTL operator: " + logic::to_string(f));
}

Bdd SymbolicCtl::fair_states() const {
  return fair_sets_.empty() ? Bdd::constant(true) : fair_;
}

Bdd SymbolicCtl::ex(const Bdd& p) {
  return sys_.preimage(fair_and(p));
}

Bdd SymbolicCtl::eu(const Bdd& p, const Bdd& q) {
  const Bdd target = fair_and(q);
  // The least fixpoint below, in one backward search when the reached graph is known.
  if (auto on_graph = sys_.reach_on_reached_graph(target, p, true)) return target | *on_graph;
  Bdd z = target;
  for (;;) {
    const Bdd next = target | (p & sys_.preimage(z));
    if (next == z) return z;
    z = next;
  }
}

/// Maximal paths: p holds forever, or until a state without successor.
Bdd SymbolicCtl::eg(const Bdd& p) {
  const Bdd dead = !sys_.has_successor();
  Bdd z = p;
  for (;;) {
    const Bdd next = p & (sys_.preimage(z) | dead);
    if (next == z) return z;
    z = next;
  }
}

/// Emerson-Lei: nu Z. p & AND_i EX E[p U (Z & F_i)].
Bdd SymbolicCtl::eg_fair(const Bdd& p) {
  Bdd z = p;
  for (;;) {
    Bdd next = p;
    for (const auto& fi : fair_sets_) {
      // Plain EU here: fairness is what this fixpoint computes.
      const Bdd target = z & fi;
      Bdd u = target;
      for (;;) {
        const Bdd step = target | (p & sys_.preimage(u));
        if (step == u) break;
        u = step;
      }
      next = next & sys_.preimage(u);
    }
    if (next == z) return z;
    z = next;
  }
}

Bdd SymbolicCtl::eg_infinite(const Bdd& p) {
  Bdd z = p;
  for (;;) {
    const Bdd next = p & sys_.preimage(z);
    if (next == z) return z;
    z = next;
  }
}

// ------------------------------------------------------------------------------ witnesses

bool SymbolicCtl::shortest(const Bdd& sources, const Bdd& through, const Bdd& target,
                           bool min_one_edge, State& start, std::vector<State>& path) {
  path.clear();
  if (!min_one_edge) {
    const Bdd here = sources & target;
    if (!here.is_false()) {
      start = sys_.pick(here);
      return true;
    }
  }
  // rings[k]: states whose shortest path into `target` (through `through`) has k edges.
  std::vector<Bdd> rings{target};
  Bdd reached = target;
  for (;;) {
    const Bdd pre = sys_.preimage(rings.back());
    const Bdd hit = sources & pre;
    if (!hit.is_false()) {
      start = sys_.pick(hit);
      State at = start;
      for (std::size_t j = rings.size(); j-- > 0;) {
        at = sys_.pick(sys_.image(sys_.singleton(at)) & rings[j]);
        path.push_back(at);
      }
      return true;
    }
    const Bdd next = pre & through & !reached;
    if (next.is_false()) return false;
    reached = reached | next;
    rings.push_back(next);
  }
}

void SymbolicCtl::explain_eu(const Bdd& through, const Bdd& target, const FormulaPtr& then,
                             const Bdd& sources, SymbolicRun& run, int depth) {
  State start;
  std::vector<State> path;
  if (!shortest(sources, through, target, false, start, path)) return;
  if (run.states.empty()) run.states.push_back(start);
  for (auto& s : path) run.states.push_back(std::move(s));
  explain_at(then, run, depth + 1);
}

void SymbolicCtl::close_loop(const Bdd& region, const std::vector<Bdd>& fair, SymbolicRun& run) {
  // Each failed round ends in a state that cannot reach the round's start: a strictly lower
  // strongly connected component of `region`, so the search ends (Clarke, Grumberg, McMillan
  // and Zhao's fair EG witnesses, as in NuSMV).
  for (;;) {
    const std::size_t loop_at = run.states.size() - 1;
    const Bdd start = sys_.singleton(run.states.back());
    for (const auto& f : fair) {
      const Bdd here = sys_.singleton(run.states.back());
      if (!(here & f).is_false()) continue;
      State from;
      std::vector<State> path;
      if (!shortest(here, region, region & f, false, from, path)) return;  // not in the region
      for (auto& s : path) run.states.push_back(std::move(s));
    }
    const Bdd here = sys_.singleton(run.states.back());
    State from;
    std::vector<State> path;
    if (shortest(here, region, start, true, from, path)) {
      for (auto& s : path) run.states.push_back(std::move(s));
      run.loop_start = loop_at;
      return;
    }
    // Start the next round here: this state cannot reach the round's start. When the round
    // did not move (the start is in every fair set), take one step first.
    if (!(here == start)) continue;
    const Bdd succ = sys_.image(here) & region;
    if (succ.is_false()) return;
    run.states.push_back(sys_.pick(succ));
  }
}

void SymbolicCtl::lasso(const FormulaPtr& eg_formula, const Bdd& sources, SymbolicRun& run) {
  const Bdd z = sat(eg_formula);
  const Bdd p = sat(eg_formula->args[0]);
  if (fair_sets_.empty()) {
    // Maximal paths: EG p = E[p U p & dead] | (infinite p-paths). Go to the nearest state of
    // either kind, then end there or loop.
    const Bdd dead = p & !sys_.has_successor();
    Bdd infinite;
    if (auto it = infinite_memo_.find(eg_formula.get()); it != infinite_memo_.end()) {
      infinite = it->second;
    } else {
      infinite = eg_infinite(p);
      infinite_memo_.emplace(eg_formula.get(), infinite);
    }
    State start;
    std::vector<State> path;
    if (!shortest(sources, z, dead | infinite, false, start, path)) return;
    if (run.states.empty()) run.states.push_back(start);
    for (auto& s : path) run.states.push_back(std::move(s));
    if (!(sys_.singleton(run.states.back()) & dead).is_false()) {
      run.ends_in_deadlock = true;
      return;
    }
    close_loop(infinite, {Bdd::constant(true)}, run);
    return;
  }
  if (run.states.empty()) run.states.push_back(sys_.pick(sources & z));
  close_loop(z, fair_sets_, run);
}

void SymbolicCtl::explain_at(const FormulaPtr& f, SymbolicRun& run, int depth) {
  const Bdd sources = run.states.empty() ? trace_sources_ : sys_.singleton(run.states.back());
  const Bdd ok = sources & sat(f);
  if (ok.is_false()) return;
  auto settle = [&] {
    if (run.states.empty()) run.states.push_back(sys_.pick(ok));
  };
  // The lasso of EG closes the run: nothing can follow it.
  if (depth > 8 || run.loop_start || run.ends_in_deadlock) return settle();
  const auto& a = f->args;
  switch (f->op) {
    case Op::Not: {
      auto pushed = logic::push_negation(a[0]);
      if (pushed->op == Op::Not) return settle();
      keep_.push_back(pushed);
      trace_sources_ = ok;
      return explain_at(pushed, run, depth + 1);
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
        // Prefer the temporal disjunct that holds at a source.
        std::vector<FormulaPtr> order = {first, a[1]};
        if (logic::is_propositional(*first)) std::swap(order[0], order[1]);
        for (const auto& cand : order)
          if (!(ok & sat(cand)).is_false()) {
            pick = cand;
            break;
          }
      }
      if (!pick || logic::is_propositional(*pick)) return settle();
      trace_sources_ = ok;
      return explain_at(pick, run, depth + 1);
    }
    case Op::EX: {
      settle();
      const Bdd succ = sys_.image(sys_.singleton(run.states.back())) & fair_and(sat(a[0]));
      if (succ.is_false()) return;
      run.states.push_back(sys_.pick(succ));
      return explain_at(a[0], run, depth + 1);
    }
    case Op::EF:
      return explain_eu(Bdd::constant(true), fair_and(sat(a[0])), a[0], ok, run, depth);
    case Op::EU:
      return explain_eu(sat(a[0]), fair_and(sat(a[1])), a[1], ok, run, depth);
    case Op::EG:
      return lasso(f, ok, run);
    default:
      return settle();
  }
}

SymbolicRun SymbolicCtl::explain(const FormulaPtr& f, const Bdd& sources) {
  SymbolicRun run;
  trace_sources_ = sources;
  explain_at(f, run, 0);
  return run;
}

}  // namespace sfcv::engine
