#pragma once
// Building small grafcets directly in the IR (no parser), and listing their RSG the way
// `sfcv rsg --list` does, for the Grafcet semantics tests and the benchmark.

#include <algorithm>
#include <string>
#include <vector>

#include "engine/bdd/condition_simplifier.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "model/chart.hpp"
#include "semantics/grafcet_system.hpp"

namespace sfcv::test {

class GrafcetBuilder {
 public:
  GrafcetBuilder() {
    project_.dialect = model::Dialect::Grafcet;
    project_.source_format = "test";
    project_.pous.emplace_back();
    pou().name = "G";
  }

  model::Pou& pou() { return project_.pous.front(); }
  const model::Project& project() const { return project_; }

  GrafcetBuilder& input(const std::string& name, model::Type type = model::Type::boolean()) {
    pou().variables.push_back(
        {name, model::VarDirection::Input, type, std::nullopt, "", {}, {}, {}, false});
    return *this;
  }
  GrafcetBuilder& output(const std::string& name, model::Type type = model::Type::boolean()) {
    pou().variables.push_back(
        {name, model::VarDirection::Output, type, std::nullopt, "", {}, {}, {}, false});
    return *this;
  }
  GrafcetBuilder& local(const std::string& name, model::Type type) {
    pou().variables.push_back(
        {name, model::VarDirection::Local, std::move(type), std::nullopt, "", {}, {}, {}, false});
    return *this;
  }
  GrafcetBuilder& chart(const std::string& name) {
    model::Chart c;
    c.name = name;
    pou().charts.push_back(c);
    return *this;
  }
  /// Adds a step to the last chart.
  GrafcetBuilder& step(const std::string& name, bool initial = false,
                       model::StepKind kind = model::StepKind::Normal,
                       std::vector<std::string> refs = {}) {
    model::Step s;
    s.name = name;
    s.initial = initial;
    s.kind = kind;
    if (kind == model::StepKind::MacroStep) s.expansion = refs.empty() ? "" : refs.front();
    if (kind == model::StepKind::Enclosing) s.enclosed = refs;
    pou().charts.back().steps.push_back(s);
    return *this;
  }
  GrafcetBuilder& transition(std::vector<std::string> from, std::vector<std::string> to,
                             model::ExprPtr guard) {
    model::Transition t;
    t.sources = std::move(from);
    t.targets = std::move(to);
    t.guard = std::move(guard);
    t.order = static_cast<int>(pou().charts.back().transitions.size());
    // Located as a file's transitions are: the checks that read the chart (conflicts) match
    // the system's transitions with the chart's by their location.
    t.where.file = "builder:" + pou().charts.back().name;
    t.where.line = t.order + 1;
    pou().charts.back().transitions.push_back(t);
    return *this;
  }
  GrafcetBuilder& continuous(const std::string& step, const std::string& variable,
                             model::ExprPtr condition = nullptr) {
    model::ActionAssociation a;
    a.chart = pou().charts.back().name;
    a.step = step;
    a.action = variable;
    a.condition = std::move(condition);
    pou().associations.push_back(a);
    return *this;
  }
  GrafcetBuilder& stored(const std::string& step, model::StoredWhen when,
                         const std::string& variable, model::ExprPtr value,
                         model::ExprPtr event = nullptr) {
    model::StoredAction a;
    a.chart = pou().charts.back().name;
    a.step = step;
    a.when = when;
    a.variable = variable;
    a.value = std::move(value);
    a.event = std::move(event);
    pou().stored_actions.push_back(a);
    return *this;
  }
  GrafcetBuilder& forcing(const std::string& step, const std::string& target,
                          model::ForcingKind kind, std::vector<std::string> situation = {}) {
    model::ForcingOrder f;
    f.chart = pou().charts.back().name;
    f.step = step;
    f.target = target;
    f.kind = kind;
    f.situation = std::move(situation);
    pou().forcing_orders.push_back(f);
    return *this;
  }

 private:
  model::Project project_;
};

// Expression shorthands.
inline model::ExprPtr v(const std::string& name) {
  return model::make_name(name);
}
inline model::ExprPtr lit(bool b) {
  return model::make_bool(b);
}
inline model::ExprPtr num(std::int64_t n) {
  return model::make_int(n);
}
inline model::ExprPtr not_(model::ExprPtr e) {
  return model::make_unary(model::ExprKind::Not, std::move(e));
}
inline model::ExprPtr rise(model::ExprPtr e) {
  return model::make_unary(model::ExprKind::Rising, std::move(e));
}
inline model::ExprPtr fall(model::ExprPtr e) {
  return model::make_unary(model::ExprKind::Falling, std::move(e));
}
inline model::ExprPtr and_(model::ExprPtr a, model::ExprPtr b) {
  return model::make_nary(model::ExprKind::And, {std::move(a), std::move(b)});
}
inline model::ExprPtr cmp(model::ExprKind k, model::ExprPtr a, model::ExprPtr b) {
  return model::make_binary(k, std::move(a), std::move(b));
}

/// A built RSG with its system (the graph refers to the system).
struct BuiltRsg {
  model::Diagnostics diagnostics;
  semantics::TransitionSystemPtr system;
  engine::ReachableSituationGraph graph;
};

inline BuiltRsg build_rsg(const model::Project& p, semantics::GrafcetOptions options = {}) {
  model::Diagnostics d;
  auto ts = semantics::make_grafcet_system(p, options, d);
  if (!ts) {
    std::string all;
    for (const auto& x : d) all += x.str() + "\n";
    throw std::runtime_error("grafcet system not built:\n" + all);
  }
  auto g = engine::build_reachable_situation_graph(*ts);
  return BuiltRsg{std::move(d), std::move(ts), std::move(g)};
}

/// "{1} --[a & !b]--> {2} y" lines, sorted.
inline std::vector<std::string> rsg_lines(const BuiltRsg& r) {
  std::vector<std::string> out;
  const auto& g = r.graph;
  const auto& ts = *r.system;
  for (std::uint32_t s = 0; s < g.num_states(); ++s)
    for (auto e = g.edges_begin(s); e < g.edges_end(s); ++e)
      out.push_back(ts.describe(g.states().at(s)) + " --[" +
                    engine::simplify(g.condition(e), ts.inputs()).to_string(ts.inputs()) + "]--> " +
                    ts.describe(g.states().at(g.target(e))));
  std::sort(out.begin(), out.end());
  return out;
}

/// Number of states in which every step of `steps` is active and all others listed in `off` are
/// not.
inline std::size_t count_states(const BuiltRsg& r, const std::vector<std::string>& on,
                                const std::vector<std::string>& off = {}) {
  std::size_t n = 0;
  for (std::uint32_t s = 0; s < r.graph.num_states(); ++s) {
    bool ok = true;
    for (const auto& name : on)
      ok = ok && r.system->observe(r.graph.states().at(s),
                                   *semantics::find_observable(*r.system, name)) != 0;
    for (const auto& name : off)
      ok = ok && r.system->observe(r.graph.states().at(s),
                                   *semantics::find_observable(*r.system, name)) == 0;
    if (ok) ++n;
  }
  return n;
}

}  // namespace sfcv::test
