#include "engine/explicit/query_evaluator.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace sfcv::engine {

using logic::Signal;
using logic::Sort;
using logic::Term;

QueryEvaluator::QueryEvaluator(const ReachableSituationGraph& graph) : g_(graph) {
  sources_.resize(g_.num_edges());
  for (std::uint32_t s = 0; s < g_.num_states(); ++s)
    if (g_.expanded(s))
      for (auto e = g_.edges_begin(s); e < g_.edges_end(s); ++e) sources_[e] = s;
}

std::uint64_t QueryEvaluator::universe(Sort s) const {
  switch (s) {
    case Sort::States:
      return g_.num_states();
    case Sort::Evolutions:
      return g_.num_edges();
    case Sort::Steps:
      return g_.system().observables().size();
    default:
      return 0;
  }
}

QueryResult QueryEvaluator::evaluate(const logic::CompiledQuery& query) {
  slot_values_.assign(query.slots, 0);
  QueryResult r;
  const Term& t = query.root;
  r.sort = t.sort;
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
  return r;
}

DynamicBitset QueryEvaluator::set(const Term& t) {
  const auto n = universe(t.sort);
  switch (t.op) {
    case Term::Op::AllStates:
    case Term::Op::AllEvolutions:
      return DynamicBitset(n, true);
    case Term::Op::Initial: {
      DynamicBitset r(n);
      for (auto s : g_.initial_states()) r.set(s);
      return r;
    }
    case Term::Op::AllSteps: {
      DynamicBitset r(n);
      const auto& obs = g_.system().observables();
      for (std::uint32_t i = 0; i < obs.size(); ++i)
        if (obs[i].kind == semantics::ObservableKind::Step) r.set(i);
      return r;
    }
    case Term::Op::Empty:
      return DynamicBitset(n);
    case Term::Op::Clearing: {
      DynamicBitset r(n);
      for (std::uint64_t e = 0; e < n; ++e)
        if (!g_.fired(e).empty()) r.set(e);
      return r;
    }
    case Term::Op::StepLiteral: {
      DynamicBitset r(n);
      for (auto s : t.steps) r.set(s);
      return r;
    }
    case Term::Op::StepVar: {
      DynamicBitset r(n);
      r.set(slot_values_[t.slot]);
      return r;
    }
    case Term::Op::Union:
      return set(t.args[0]) |= set(t.args[1]);
    case Term::Op::Inter:
      return set(t.args[0]) &= set(t.args[1]);
    case Term::Op::Diff:
      return set(t.args[0]).subtract(set(t.args[1]));
    case Term::Op::Int:
    case Term::Op::Ext: {
      const auto ys = set(t.args[0]);
      DynamicBitset r(n);
      for (std::uint64_t e = 0; e < n; ++e)
        if (ys.test(t.op == Term::Op::Int ? sources_[e] : g_.target(e))) r.set(e);
      return r;
    }
    case Term::Op::Amont:
    case Term::Op::Aval: {
      const auto ts = set(t.args[0]);
      DynamicBitset r(n);
      ts.for_each(
          [&](std::uint64_t e) { r.set(t.op == Term::Op::Amont ? sources_[e] : g_.target(e)); });
      return r;
    }
    case Term::Op::Succ:
    case Term::Op::Pred: {
      // Ys itself is included (zero evolutions), semantics-notes item 9.
      auto r = set(t.args[0]);
      const auto ts = set(t.args[1]);
      std::vector<std::uint32_t> queue;
      r.for_each([&](std::uint64_t s) { queue.push_back(static_cast<std::uint32_t>(s)); });
      const bool forward = t.op == Term::Op::Succ;
      const std::vector<std::uint64_t>* pred_off = nullptr;
      const std::vector<std::uint64_t>* pred_edges = nullptr;
      if (!forward) {
        pred_off = &g_.predecessor_offsets();
        pred_edges = &g_.predecessor_edges();
      }
      while (!queue.empty()) {
        const auto s = queue.back();
        queue.pop_back();
        auto visit = [&](std::uint64_t e, std::uint32_t next) {
          if (ts.test(e) && !r.test(next)) {
            r.set(next);
            queue.push_back(next);
          }
        };
        if (forward) {
          if (!g_.expanded(s)) continue;
          for (auto e = g_.edges_begin(s); e < g_.edges_end(s); ++e) visit(e, g_.target(e));
        } else {
          for (auto i = (*pred_off)[s]; i < (*pred_off)[s + 1]; ++i) {
            const auto e = (*pred_edges)[i];
            visit(e, sources_[e]);
          }
        }
      }
      return r;
    }
    case Term::Op::Act:
    case Term::Op::Des: {
      const auto steps = set(t.args[0]).elements();
      const bool want = t.op == Term::Op::Act;
      DynamicBitset r(n);
      for (std::uint32_t s = 0; s < g_.num_states(); ++s) {
        const auto state = g_.states().at(s);
        bool all = true;
        for (auto o : steps)
          if ((g_.system().observe(state, static_cast<std::uint32_t>(o)) != 0) != want) {
            all = false;
            break;
          }
        if (all) r.set(s);
      }
      return r;
    }
    case Term::Op::Nec:
      return nec(t.signal);
    case Term::Op::Emis:
      return emis(t.signal);
    case Term::Op::SetBuilder: {
      const auto domain = set(t.args[0]);
      DynamicBitset r(n);
      domain.for_each([&](std::uint64_t step) {
        slot_values_[t.slot] = static_cast<std::uint32_t>(step);
        if (test(t.args[1])) r.set(step);
      });
      return r;
    }
    default:
      break;
  }
  throw QueryEvaluationError("internal error: not a set term");
}

bool QueryEvaluator::test(const Term& t) {
  const auto r = logic::judge_query_test(
      t, [this](const Term& x) { return number(x); },
      [this](const Term& a, const Term& b) { return set(a) == set(b); });
  if (!r) throw QueryEvaluationError("internal error: not a test");
  return *r;
}

std::int64_t QueryEvaluator::number(const Term& t) {
  if (t.op == Term::Op::Number) return t.value;
  if (t.op == Term::Op::Count) return static_cast<std::int64_t>(set(t.args[0]).count());
  throw QueryEvaluationError("internal error: not a number");
}

std::int64_t QueryEvaluator::signal_value(const Signal& s, const std::vector<std::int64_t>& inputs,
                                          semantics::StateView state) const {
  switch (s.op) {
    case Signal::Op::Const:
      return s.value;
    case Signal::Op::Input:
      return inputs[s.index];
    case Signal::Op::Observable:
      return g_.system().observe(state, s.index);
    case Signal::Op::StepVar:
      return g_.system().observe(state, slot_values_[s.index]) != 0;
    case Signal::Op::Not:
      return !signal_value(s.args[0], inputs, state);
    case Signal::Op::And:
      return signal_value(s.args[0], inputs, state) && signal_value(s.args[1], inputs, state);
    case Signal::Op::Or:
      return signal_value(s.args[0], inputs, state) || signal_value(s.args[1], inputs, state);
    case Signal::Op::Cmp: {
      auto a = signal_value(s.args[0], inputs, state), b = signal_value(s.args[1], inputs, state);
      if (!s.args[0].is_int) {  // Booleans compare as truth values
        a = a != 0;
        b = b != 0;
      }
      return logic::compare(s.cmp, a, b);
    }
  }
  return 0;
}

DynamicBitset QueryEvaluator::emis(const Signal& s) {
  DynamicBitset r(g_.num_states());
  const std::vector<std::int64_t> no_inputs;
  for (std::uint32_t st = 0; st < g_.num_states(); ++st)
    if (signal_value(s, no_inputs, g_.states().at(st))) r.set(st);
  return r;
}

namespace {

/// The inputs an expression mentions, with the constants each is compared with.
void collect_inputs(const Signal& s, std::map<std::uint32_t, std::set<std::int64_t>>& out) {
  if (s.op == Signal::Op::Input) out[s.index];
  if (s.op == Signal::Op::Cmp && s.args[0].op == Signal::Op::Input)
    out[s.args[0].index].insert(s.args[1].value);
  for (const auto& a : s.args) collect_inputs(a, out);
}

}  // namespace

// Nec(phi): the evolutions whose condition implies phi, i.e. every input valuation that causes
// the evolution satisfies phi (evaluated with the upstream situation for step/output names).
// A condition is a union of cubes (boxes); inside one box the truth of phi only changes at the
// constants its inputs are compared with, so checking the box's corners and the points around
// each constant decides the implication exactly.
DynamicBitset QueryEvaluator::nec(const Signal& s) {
  const auto& inputs = g_.system().inputs();
  DynamicBitset r(g_.num_edges());
  if (g_.num_edges() && !g_.has_conditions())
    throw QueryEvaluationError(
        "Nec needs the evolutions' input conditions, but the graph was "
        "built without them");
  std::map<std::uint32_t, std::set<std::int64_t>> used;
  collect_inputs(s, used);
  std::vector<std::uint32_t> vars;
  for (const auto& [i, _] : used) vars.push_back(i);

  std::vector<std::int64_t> valuation(inputs.size(), 0);
  std::vector<std::vector<std::int64_t>> candidates(vars.size());
  constexpr std::uint64_t kMaxPoints = 1u << 22;

  for (std::uint64_t e = 0; e < g_.num_edges(); ++e) {
    const auto state = g_.states().at(sources_[e]);
    bool implies = true;
    for (const auto& cube : g_.condition(e).cubes) {
      std::uint64_t points = 1;
      for (std::size_t v = 0; v < vars.size(); ++v) {
        const auto& in = inputs[vars[v]];
        std::int64_t lo = in.type.kind == model::TypeKind::Bool ? 0 : in.type.lo;
        std::int64_t hi = in.type.kind == model::TypeKind::Bool ? 1 : in.type.hi;
        for (const auto& lit : cube.literals)
          if (lit.input == vars[v]) {
            lo = std::max(lo, lit.lo);
            hi = std::min(hi, lit.hi);
          }
        auto& c = candidates[v];
        c.clear();
        if (lo > hi) {
          points = 0;
          break;
        }
        c.push_back(lo);
        c.push_back(hi);
        for (auto k : used[vars[v]])
          for (auto p : {k - 1, k, k + 1})
            if (p >= lo && p <= hi) c.push_back(p);
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(), c.end()), c.end());
        points *= c.size();
        if (points > kMaxPoints)
          throw QueryEvaluationError(
              "Nec: the expression mentions too many inputs to decide "
              "the implication by enumeration");
      }
      if (points == 0) continue;  // an empty cube implies anything
      std::vector<std::size_t> idx(vars.size(), 0);
      for (;;) {
        for (std::size_t v = 0; v < vars.size(); ++v) valuation[vars[v]] = candidates[v][idx[v]];
        if (!signal_value(s, valuation, state)) {
          implies = false;
          break;
        }
        std::size_t v = 0;
        while (v < vars.size() && ++idx[v] == candidates[v].size()) idx[v++] = 0;
        if (v == vars.size()) break;
      }
      if (!implies) break;
    }
    if (implies) r.set(e);
  }
  return r;
}

}  // namespace sfcv::engine
