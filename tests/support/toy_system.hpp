#pragma once
// A hand-built transition system for engine tests: explicit successor lists with conditions on
// Boolean inputs, so that tests can state exact graphs without any chart.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "semantics/transition_system.hpp"

namespace sfcv::test {

class ToySystem final : public semantics::TransitionSystem {
 public:
  struct Arc {
    std::uint32_t from, to;
    semantics::InputCondition condition;
    std::vector<std::uint32_t> fired;
  };

  /// `n` states numbered 0..n-1 stored in one field "s"; `labels[i]` names the Boolean
  /// observables true in state i; inputs are Boolean.
  ToySystem(std::uint32_t n, std::vector<std::string> input_names,
            std::vector<std::string> atom_names = {})
      : n_(n) {
    field_ = layout_.add_field("s", semantics::FieldKind::Variable, 0, n == 0 ? 0 : n - 1);
    for (auto& name : input_names) inputs_.push_back({std::move(name), model::Type::boolean()});
    for (auto& a : atom_names) {
      semantics::Observable o;
      o.name = a;
      o.kind = semantics::ObservableKind::Step;
      o.type = model::Type::boolean();
      observables_.push_back(o);
    }
    truth_.assign(n, std::vector<bool>(observables_.size(), false));
  }

  /// Adds a Boolean observable that is not a step (an output unless `is_output` is false);
  /// returns its index for set_true.
  std::uint32_t add_output(std::string name, bool is_output = true) {
    semantics::Observable o;
    o.name = std::move(name);
    o.kind = semantics::ObservableKind::Variable;
    o.type = model::Type::boolean();
    o.is_output = is_output;
    observables_.push_back(o);
    for (auto& row : truth_) row.push_back(false);
    return static_cast<std::uint32_t>(observables_.size() - 1);
  }

  /// Makes input `i` an integer input (conditions then use intervals of `type`).
  void set_input_type(std::uint32_t i, model::Type type) { inputs_[i].type = std::move(type); }

  void set_initial(std::vector<std::uint32_t> initial) { initial_ = std::move(initial); }
  void add_arc(std::uint32_t from, std::uint32_t to,
               semantics::InputCondition c = semantics::InputCondition::always(),
               std::vector<std::uint32_t> fired = {}) {
    arcs_.push_back({from, to, std::move(c), std::move(fired)});
    for (auto f : arcs_.back().fired)
      while (transitions_.size() <= f)
        transitions_.push_back({"t" + std::to_string(transitions_.size()), "P", "C", {}});
  }
  void set_true(std::uint32_t state, std::uint32_t atom) { truth_[state][atom] = true; }
  /// Makes atom `atom` an action (or a variable) instead of a step; `output` marks outputs.
  void set_kind(std::uint32_t atom, semantics::ObservableKind kind, bool output = false) {
    observables_[atom].kind = kind;
    observables_[atom].is_output = output;
  }

  semantics::SemanticsKind kind() const override { return kind_; }
  /// Renderers read traces differently per semantics (a Grafcet trace's first step has inputs).
  void set_semantics(semantics::SemanticsKind k) { kind_ = k; }
  const semantics::StateLayout& layout() const override { return layout_; }
  const std::vector<semantics::InputVariable>& inputs() const override { return inputs_; }
  const std::vector<semantics::Observable>& observables() const override { return observables_; }
  const std::vector<semantics::TransitionInfo>& transitions() const override {
    return transitions_;
  }
  void initial_states(semantics::SuccessorSink& sink) const override {
    for (auto i : initial_) emit(i, semantics::InputCondition::always(), {}, sink);
  }
  void successors(semantics::StateView state, semantics::SuccessorSink& sink) const override {
    const auto s = static_cast<std::uint32_t>(layout_.get(state, field_));
    for (const auto& a : arcs_)
      if (a.from == s) emit(a.to, a.condition, a.fired, sink);
  }
  std::int64_t observe(semantics::StateView state, std::uint32_t index) const override {
    return truth_[static_cast<std::size_t>(layout_.get(state, field_))][index] ? 1 : 0;
  }
  std::uint32_t state_of(semantics::StateView state) const {
    return static_cast<std::uint32_t>(layout_.get(state, field_));
  }

  /// A literal "input i has value v".
  static semantics::InputCondition lit(std::uint32_t input, bool value) {
    return semantics::InputCondition{{semantics::InputCube{{{input, value, value}}}}};
  }

 private:
  semantics::SemanticsKind kind_ = semantics::SemanticsKind::Iec61131;
  void emit(std::uint32_t to, const semantics::InputCondition& c,
            const std::vector<std::uint32_t>& fired, semantics::SuccessorSink& sink) const {
    std::vector<semantics::StateWord> buf(layout_.words(), 0);
    layout_.set(buf, field_, to);
    sink.successor(semantics::Successor{buf, c, fired});
  }

  std::uint32_t n_;
  std::uint32_t field_;
  semantics::StateLayout layout_;
  std::vector<semantics::InputVariable> inputs_;
  std::vector<semantics::Observable> observables_;
  std::vector<semantics::TransitionInfo> transitions_;
  std::vector<std::vector<bool>> truth_;
  std::vector<std::uint32_t> initial_;
  std::vector<Arc> arcs_;
};

}  // namespace sfcv::test
