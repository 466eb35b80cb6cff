#include "engine/bdd/symbolic_query_evaluator.hpp"

#include <chrono>
#include <string>

namespace sfcv::engine {

using bdd::Bdd;
using logic::Sort;
using logic::Term;

SymbolicQueryEvaluator::SymbolicQueryEvaluator(SymbolicSystem& sys,
                                               const SymbolicQueryOptions& options)
    : sys_(sys) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  reached_ = sys_.initial();
  Bdd frontier = reached_;
  while (!frontier.is_false()) {
    below_.push_back(reached_ & !frontier);
    layers_.push_back(frontier);
    layer_counts_.push_back(sys_.count(frontier));
    if (options.max_states > 0 && sys_.count(reached_) > static_cast<double>(options.max_states))
      throw LimitReached(Limit::States, "more than " + std::to_string(options.max_states) +
                                            " reachable situations (--max-states)");
    if (options.timeout_seconds > 0 &&
        std::chrono::duration<double>(Clock::now() - start).count() > options.timeout_seconds)
      throw LimitReached(Limit::Time, "the reachable situations were not all found within " +
                                          std::to_string(options.timeout_seconds) +
                                          " s (--timeout)");
    frontier = sys_.image(frontier) & !reached_;
    reached_ = reached_ | frontier;
  }
  evolutions_ = sys_.evolutions(reached_);
}

SymbolicSet SymbolicQueryEvaluator::make(Sort sort, Bdd b) const {
  SymbolicSet s;
  s.sort = sort;
  s.bdd = std::move(b);
  s.steps = DynamicBitset(sys_.system().observables().size());
  return s;
}

SymbolicQueryResult SymbolicQueryEvaluator::evaluate(const logic::CompiledQuery& query) {
  slot_values_.assign(query.slots, 0);
  SymbolicQueryResult r;
  const Term& t = query.root;
  r.sort = t.sort;
  try {
    switch (t.sort) {
      case Sort::Bool:
        r.truth = test(t);
        if (const Term* a = logic::emptiness_tested_set(t)) {
          r.witness_sort = a->sort;
          r.witness = set(*a);
        }
        break;
      case Sort::Int:
        r.number = number(t);
        break;
      default:
        r.set = set(t);
        break;
    }
  } catch (const std::invalid_argument& e) {
    throw SymbolicQueryError(e.what());
  }
  return r;
}

SymbolicSet SymbolicQueryEvaluator::set(const Term& t) {
  const auto& obs = sys_.system().observables();
  switch (t.op) {
    case Term::Op::AllStates:
      return make(t.sort, reached_);
    case Term::Op::AllEvolutions:
      return make(t.sort, evolutions_);
    case Term::Op::Initial:
      return make(t.sort, sys_.initial() & reached_);
    case Term::Op::AllSteps: {
      auto r = make(t.sort, Bdd::constant(false));
      for (std::uint32_t i = 0; i < obs.size(); ++i)
        if (obs[i].kind == semantics::ObservableKind::Step) r.steps.set(i);
      return r;
    }
    case Term::Op::Empty:
      return make(t.sort, Bdd::constant(false));
    case Term::Op::Clearing:
      // The explicit edge x -> x' carries the union of the transitions fired by every input
      // leading there: it clears one when some input that leads there fires one.
      if (!clearing_) clearing_ = sys_.evolutions(reached_, sys_.fires_any_under_inputs());
      return make(t.sort, *clearing_);
    case Term::Op::StepLiteral: {
      auto r = make(t.sort, Bdd::constant(false));
      for (auto s : t.steps) r.steps.set(s);
      return r;
    }
    case Term::Op::StepVar: {
      auto r = make(t.sort, Bdd::constant(false));
      r.steps.set(slot_values_[t.slot]);
      return r;
    }
    case Term::Op::Union:
    case Term::Op::Inter:
    case Term::Op::Diff: {
      auto a = set(t.args[0]);
      const auto b = set(t.args[1]);
      a.sort = t.sort;
      if (t.op == Term::Op::Union) {
        a.bdd = a.bdd | b.bdd;
        a.steps |= b.steps;
      } else if (t.op == Term::Op::Inter) {
        a.bdd = a.bdd & b.bdd;
        a.steps &= b.steps;
      } else {
        a.bdd = a.bdd & !b.bdd;
        a.steps.subtract(b.steps);
      }
      return a;
    }
    case Term::Op::Int:
      return make(t.sort, evolutions_ & set(t.args[0]).bdd);
    case Term::Op::Ext:
      return make(t.sort, evolutions_ & sys_.to_next(set(t.args[0]).bdd));
    case Term::Op::Amont:
      return make(t.sort, sys_.sources(set(t.args[0]).bdd));
    case Term::Op::Aval:
      return make(t.sort, sys_.targets(set(t.args[0]).bdd));
    case Term::Op::Succ:
    case Term::Op::Pred: {
      // Ys itself is included (zero evolutions), semantics-notes item 9, as in the explicit
      // evaluator; the evolutions only lead between reachable situations.
      Bdd r = set(t.args[0]).bdd;
      const Bdd ts = set(t.args[1]).bdd;
      Bdd frontier = r;
      while (!frontier.is_false()) {
        const Bdd step = t.op == Term::Op::Succ ? sys_.targets(ts & frontier)
                                                : sys_.sources(ts & sys_.to_next(frontier));
        frontier = step & !r;
        r = r | frontier;
      }
      return make(t.sort, r);
    }
    case Term::Op::Act:
    case Term::Op::Des: {
      const auto steps = set(t.args[0]).steps;
      Bdd r = reached_;
      steps.for_each([&](std::uint64_t o) {
        const Bdd active = sys_.observable_nonzero(static_cast<std::uint32_t>(o));
        r = r & (t.op == Term::Op::Act ? active : !active);
      });
      return make(t.sort, r);
    }
    case Term::Op::Nec: {
      // The evolutions whose every input valuation satisfies the expression (evaluated with the
      // upstream situation for step and output names).
      const Bdd phi = sys_.signal(t.signal, slot_values_);
      return make(t.sort, sys_.evolutions_only_under(evolutions_, phi));
    }
    case Term::Op::Emis: {
      const Bdd phi = sys_.signal(t.signal, slot_values_);
      if (sys_.depends_on_inputs(phi))
        throw SymbolicQueryError(
            "Emis: the expression depends on the inputs of the cycle in "
            "this system's circuit; the symbolic engine cannot evaluate it");
      return make(t.sort, reached_ & phi);
    }
    case Term::Op::SetBuilder: {
      const auto domain = set(t.args[0]).steps;
      auto r = make(t.sort, Bdd::constant(false));
      domain.for_each([&](std::uint64_t step) {
        slot_values_[t.slot] = static_cast<std::uint32_t>(step);
        if (test(t.args[1])) r.steps.set(step);
      });
      return r;
    }
    default:
      break;
  }
  throw SymbolicQueryError("internal error: not a set term");
}

bool SymbolicQueryEvaluator::test(const Term& t) {
  const auto r = logic::judge_query_test(
      t, [this](const Term& x) { return number(x); },
      [this](const Term& a, const Term& b) {
        const auto x = set(a), y = set(b);
        return x.bdd == y.bdd && x.steps == y.steps;
      });
  if (!r) throw SymbolicQueryError("internal error: not a test");
  return *r;
}

std::int64_t SymbolicQueryEvaluator::number(const Term& t) {
  if (t.op == Term::Op::Number) return t.value;
  if (t.op == Term::Op::Count) {
    const auto s = set(t.args[0]);
    switch (t.args[0].sort) {
      case Sort::States:
        return static_cast<std::int64_t>(sys_.count(s.bdd));
      case Sort::Evolutions:
        return static_cast<std::int64_t>(sys_.count_pairs(s.bdd));
      case Sort::Steps:
        return static_cast<std::int64_t>(s.steps.count());
      default:
        return 0;  // `#{}`
    }
  }
  throw SymbolicQueryError("internal error: not a number");
}

std::size_t SymbolicQueryEvaluator::layer_of(semantics::StateView state) const {
  const Bdd one = sys_.singleton(state);
  for (std::size_t d = 0; d < layers_.size(); ++d)
    if (!(layers_[d] & one).is_false()) return d;
  throw std::invalid_argument("SymbolicQueryEvaluator: the state is not reachable");
}

Bdd SymbolicQueryEvaluator::ranked_before(semantics::StateView state) const {
  const auto d = layer_of(state);
  return below_[d] | (layers_[d] & sys_.canonically_before(state));
}

std::uint64_t SymbolicQueryEvaluator::state_id(semantics::StateView state) const {
  return static_cast<std::uint64_t>(sys_.count(ranked_before(state)));
}

std::uint64_t SymbolicQueryEvaluator::evolution_id(semantics::StateView source,
                                                   semantics::StateView target) const {
  const Bdd earlier_sources = evolutions_ & ranked_before(source);
  const Bdd same_source =
      evolutions_ & sys_.singleton(source) & sys_.to_next(ranked_before(target));
  return static_cast<std::uint64_t>(sys_.count_pairs(earlier_sources) +
                                    sys_.count_pairs(same_source));
}

std::vector<std::vector<semantics::StateWord>> SymbolicQueryEvaluator::states_of(
    const Bdd& set, std::uint64_t limit) const {
  return sys_.enumerate(set, limit);
}

std::vector<std::pair<std::vector<semantics::StateWord>, std::vector<semantics::StateWord>>>
SymbolicQueryEvaluator::evolutions_of(const Bdd& set, std::uint64_t limit) const {
  std::vector<std::pair<std::vector<semantics::StateWord>, std::vector<semantics::StateWord>>> out;
  for (auto& src : sys_.enumerate(sys_.sources(set), limit)) {
    const Bdd targets = sys_.targets(set & sys_.singleton(src));
    for (auto& dst : sys_.enumerate(targets, limit)) {
      if (out.size() >= limit)
        throw std::length_error("more than " + std::to_string(limit) + " elements to list");
      out.emplace_back(src, std::move(dst));
    }
  }
  return out;
}

}  // namespace sfcv::engine
