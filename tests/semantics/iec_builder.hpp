#pragma once
// Builds IEC 61131-3 test models with the IR (ST snippets parsed by the io layer's ST parser)
// and runs them through the scan-cycle semantics.

#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "io/st_parser.hpp"
#include "model/chart.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"

namespace sfcv::test {

inline std::vector<std::string> split_names(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

class IecBuilder {
 public:
  explicit IecBuilder(const std::string& vars, std::string pou_name = "MAIN") {
    model::Pou pou;
    pou.name = std::move(pou_name);
    model::Diagnostics d;
    pou.variables = io::parse_var_sections(vars, {}, d);
    EXPECT_FALSE(model::has_errors(d)) << (d.empty() ? "" : d.front().str());
    project.pous.push_back(std::move(pou));
    chart("main");
  }

  model::Pou& pou() { return project.pous.back(); }

  /// A chart; with `parent_action`, also the SFC action holding it.
  int chart(const std::string& name, const std::string& parent_action = "") {
    model::Chart c;
    c.name = name;
    c.parent_action = parent_action;
    pou().charts.push_back(c);
    const int idx = static_cast<int>(pou().charts.size() - 1);
    if (!parent_action.empty()) {
      model::Action a;
      a.name = parent_action;
      a.kind = model::ActionBodyKind::Chart;
      a.chart = idx;
      pou().actions.push_back(a);
    }
    current_ = idx;
    return idx;
  }
  IecBuilder& in(int chart_index) {
    current_ = chart_index;
    return *this;
  }
  IecBuilder& step(const std::string& name, bool initial = false) {
    model::Step s;
    s.name = name;
    s.initial = initial;
    pou().charts[static_cast<std::size_t>(current_)].steps.push_back(s);
    return *this;
  }
  IecBuilder& trans(const std::string& from, const std::string& to, const std::string& guard,
                    std::optional<int> priority = std::nullopt) {
    model::Transition t;
    t.sources = split_names(from);
    t.targets = split_names(to);
    model::Diagnostics d;
    t.guard = io::parse_st_expression(guard, {}, d);
    EXPECT_TRUE(t.guard) << guard;
    t.priority = priority;
    auto& c = pou().charts[static_cast<std::size_t>(current_)];
    t.order = static_cast<int>(c.transitions.size());
    c.transitions.push_back(t);
    return *this;
  }
  IecBuilder& action_var(const std::string& name, const std::string& var) {
    model::Action a;
    a.name = name;
    a.kind = model::ActionBodyKind::Variable;
    a.variable = var;
    pou().actions.push_back(a);
    return *this;
  }
  IecBuilder& action_st(const std::string& name, const std::string& body) {
    model::Action a;
    a.name = name;
    a.kind = model::ActionBodyKind::Statements;
    model::Diagnostics d;
    a.body = io::parse_st_statements(body, {}, d);
    EXPECT_FALSE(model::has_errors(d)) << (d.empty() ? "" : d.front().str());
    pou().actions.push_back(a);
    return *this;
  }
  IecBuilder& assoc(const std::string& step, const std::string& action, const std::string& q,
                    std::optional<std::int64_t> duration_ms = std::nullopt) {
    model::ActionAssociation a;
    a.chart = pou().charts[static_cast<std::size_t>(current_)].name;
    a.step = step;
    a.action = action;
    a.qualifier = *model::parse_qualifier(q);
    a.duration_ms = duration_ms;
    pou().associations.push_back(a);
    return *this;
  }
  IecBuilder& body(const std::string& text) {
    model::Diagnostics d;
    pou().body = io::parse_st_statements(text, {}, d);
    EXPECT_FALSE(model::has_errors(d));
    return *this;
  }

  semantics::TransitionSystemPtr build(semantics::Iec61131Options options = {}) {
    model::Diagnostics d;
    auto ts = semantics::make_iec61131_system(project, options, d);
    std::string msg;
    for (const auto& x : d) msg += x.str() + "\n";
    EXPECT_TRUE(ts) << msg;
    return ts;
  }
  /// The diagnostics of a build expected to fail.
  std::string build_error(semantics::Iec61131Options options = {}) {
    model::Diagnostics d;
    auto ts = semantics::make_iec61131_system(project, options, d);
    EXPECT_FALSE(ts);
    std::string msg;
    for (const auto& x : d) msg += x.str() + "\n";
    return msg;
  }

  model::Project project;

 private:
  int current_ = 0;
};

inline semantics::Iec61131Options discrete(std::int64_t cycle_ms = 10) {
  semantics::Iec61131Options o;
  o.time = semantics::TimeMode::Discrete;
  o.cycle_ms = cycle_ms;
  return o;
}

inline std::uint32_t obs(const semantics::TransitionSystem& ts, const std::string& name) {
  std::string err;
  auto i = semantics::find_observable(ts, name, &err);
  EXPECT_TRUE(i.has_value()) << err;
  return i.value_or(0);
}

inline std::uint32_t input_index(const semantics::TransitionSystem& ts, const std::string& name) {
  for (std::uint32_t i = 0; i < ts.inputs().size(); ++i)
    if (ts.inputs()[i].name == name) return i;
  ADD_FAILURE() << "no input " << name;
  return 0;
}

/// Drives a system cycle by cycle with named input values (unnamed inputs are 0 / lowest).
class Runner {
 public:
  explicit Runner(const semantics::TransitionSystem& ts)
      : ts_(ts), state_(semantics::first_initial_state(ts)) {}

  /// One cycle; `inputs` like {{"a", 1}, {"timeout:MAIN.TON1", 1}}. Returns false (and records
  /// the error) when the cycle has no successor.
  bool cycle(const std::map<std::string, std::int64_t>& inputs = {}) {
    std::vector<std::int64_t> v(ts_.inputs().size());
    for (std::size_t i = 0; i < v.size(); ++i)
      v[i] = ts_.inputs()[i].type.kind == model::TypeKind::Bool ? 0 : ts_.inputs()[i].type.lo;
    for (const auto& [name, value] : inputs) v[input_index(ts_, name)] = value;
    auto r = semantics::simulate(ts_, state_, {v});
    error = r.error;
    if (!r.ok) return false;
    state_ = r.states.back();
    fired = r.fired.back();
    return true;
  }
  std::int64_t operator[](const std::string& name) const {
    return ts_.observe(state_, obs(ts_, name));
  }
  const std::vector<semantics::StateWord>& state() const { return state_; }
  void set_state(std::vector<semantics::StateWord> s) { state_ = std::move(s); }
  std::string describe() const { return ts_.describe(state_); }

  std::string error;
  std::vector<std::uint32_t> fired;

 private:
  const semantics::TransitionSystem& ts_;
  std::vector<semantics::StateWord> state_;
};

struct CollectedSuccessor {
  std::vector<semantics::StateWord> target;
  std::string condition;
  std::vector<std::uint32_t> fired;
};

struct Collector : semantics::SuccessorSink {
  explicit Collector(const semantics::TransitionSystem& t) : ts(&t) {}
  const semantics::TransitionSystem* ts;
  std::vector<CollectedSuccessor> all;
  std::vector<std::string> anomalies;
  void successor(const semantics::Successor& s) override {
    all.push_back({{s.target.begin(), s.target.end()},
                   s.condition.to_string(ts->inputs()),
                   {s.fired.begin(), s.fired.end()}});
  }
  void anomaly(const semantics::Anomaly& a) override {
    anomalies.push_back(a.message + " when " + a.condition.to_string(ts->inputs()));
  }
};

inline Collector successors_of(const semantics::TransitionSystem& ts, semantics::StateView s) {
  Collector c(ts);
  ts.successors(s, c);
  return c;
}

/// The conditions of the successors, in the order produced.
inline std::vector<std::string> conditions(const Collector& c) {
  std::vector<std::string> out;
  for (const auto& s : c.all) out.push_back(s.condition);
  return out;
}

}  // namespace sfcv::test
