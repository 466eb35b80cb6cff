#pragma once
// Building small chart IRs in tests without an importer. Every element gets its own line in a
// pretend file "test.sfc" (the line of the n-th element added is n), so tests can check where a
// diagnostic points.

#include <string>
#include <utility>
#include <vector>

#include "model/chart.hpp"
#include "model/types.hpp"

namespace sfcv::test {

class PouBuilder {
 public:
  explicit PouBuilder(std::string name = "P", model::PouKind kind = model::PouKind::Program) {
    pou_.name = std::move(name);
    pou_.kind = kind;
    pou_.where = next();
  }

  /// The line the next element will get.
  int line() const { return line_; }

  PouBuilder& var(std::string name, const std::string& type,
                  model::VarDirection dir = model::VarDirection::Local) {
    model::Variable v;
    v.name = std::move(name);
    v.type = *model::elementary_type(type);
    v.direction = dir;
    v.where = next();
    pou_.variables.push_back(std::move(v));
    return *this;
  }
  PouBuilder& input(std::string name, const std::string& type) {
    return var(std::move(name), type, model::VarDirection::Input);
  }
  PouBuilder& output(std::string name, const std::string& type) {
    return var(std::move(name), type, model::VarDirection::Output);
  }

  /// Starts a new chart; the steps and transitions that follow go into it.
  PouBuilder& chart(std::string name, std::string parent_action = "") {
    model::Chart c;
    c.name = std::move(name);
    c.parent_action = std::move(parent_action);
    c.where = next();
    pou_.charts.push_back(std::move(c));
    return *this;
  }

  PouBuilder& step(std::string name, bool initial = false,
                   model::StepKind kind = model::StepKind::Normal) {
    model::Step s;
    s.name = std::move(name);
    s.initial = initial;
    s.kind = kind;
    s.where = next();
    current().steps.push_back(std::move(s));
    return *this;
  }
  PouBuilder& initial(std::string name) { return step(std::move(name), true); }
  /// Marks the last step with the activation link (IEC 60848's `*`).
  PouBuilder& linked() {
    current().steps.back().activation_link = true;
    return *this;
  }
  PouBuilder& macro_step(std::string name, std::string expansion) {
    step(std::move(name), false, model::StepKind::MacroStep);
    current().steps.back().expansion = std::move(expansion);
    return *this;
  }
  PouBuilder& enclosing_step(std::string name, std::vector<std::string> enclosed,
                             bool initial = false) {
    step(std::move(name), initial, model::StepKind::Enclosing);
    current().steps.back().enclosed = std::move(enclosed);
    return *this;
  }

  PouBuilder& trans(std::vector<std::string> from, std::vector<std::string> to,
                    model::ExprPtr guard = nullptr, std::string name = "") {
    model::Transition t;
    t.name = std::move(name);
    t.sources = std::move(from);
    t.targets = std::move(to);
    t.where = next();
    t.guard = guard ? std::move(guard) : model::make_bool(true, t.where);
    t.order = static_cast<int>(current().transitions.size());
    current().transitions.push_back(std::move(t));
    return *this;
  }

  PouBuilder& action_st(std::string name, model::StmtList body) {
    model::Action a;
    a.name = std::move(name);
    a.kind = model::ActionBodyKind::Statements;
    a.body = std::move(body);
    a.where = next();
    pou_.actions.push_back(std::move(a));
    return *this;
  }
  PouBuilder& action_var(std::string name, std::string variable) {
    model::Action a;
    a.name = std::move(name);
    a.kind = model::ActionBodyKind::Variable;
    a.variable = std::move(variable);
    a.where = next();
    pou_.actions.push_back(std::move(a));
    return *this;
  }
  /// An action whose body is chart number `chart_index` of the POU.
  PouBuilder& action_chart(std::string name, int chart_index) {
    model::Action a;
    a.name = std::move(name);
    a.kind = model::ActionBodyKind::Chart;
    a.chart = chart_index;
    a.where = next();
    pou_.actions.push_back(std::move(a));
    return *this;
  }

  PouBuilder& assoc(std::string chart, std::string step, std::string action,
                    model::Qualifier q = model::Qualifier::N) {
    model::ActionAssociation as;
    as.chart = std::move(chart);
    as.step = std::move(step);
    as.action = std::move(action);
    as.qualifier = q;
    as.where = next();
    pou_.associations.push_back(std::move(as));
    return *this;
  }
  /// Changes the last association.
  model::ActionAssociation& last_assoc() { return pou_.associations.back(); }

  PouBuilder& stored(std::string chart, std::string step, std::string variable,
                     model::ExprPtr value, model::StoredWhen when = model::StoredWhen::Activation) {
    model::StoredAction sa;
    sa.chart = std::move(chart);
    sa.step = std::move(step);
    sa.variable = std::move(variable);
    sa.value = std::move(value);
    sa.when = when;
    sa.where = next();
    pou_.stored_actions.push_back(std::move(sa));
    return *this;
  }

  PouBuilder& forcing(std::string chart, std::string step, std::string target,
                      std::vector<std::string> situation) {
    model::ForcingOrder fo;
    fo.chart = std::move(chart);
    fo.step = std::move(step);
    fo.target = std::move(target);
    fo.kind = model::ForcingKind::Situation;
    fo.situation = std::move(situation);
    fo.where = next();
    pou_.forcing_orders.push_back(std::move(fo));
    return *this;
  }

  PouBuilder& body(model::StmtList stmts) {
    pou_.body = std::move(stmts);
    return *this;
  }

  model::Pou& pou() { return pou_; }

  model::Project project(model::Dialect dialect = model::Dialect::Iec61131) const {
    model::Project p;
    p.name = "test";
    p.dialect = dialect;
    p.source_format = "test";
    p.pous.push_back(pou_);
    return p;
  }

  /// A location on the line the next element would get (for expressions and statements).
  model::SourceLocation here() const { return {"test.sfc", line_, 1, {}}; }

 private:
  model::Pou pou_;
  int line_ = 1;

  model::SourceLocation next() { return {"test.sfc", line_++, 1, {}}; }
  model::Chart& current() {
    if (pou_.charts.empty()) chart("main");
    return pou_.charts.back();
  }
};

}  // namespace sfcv::test
