#pragma once
// A transition system extended with the history a property reads (docs/semantics.md, "Inputs
// and previous values in properties"): the value of an input in the cycle that produced the
// state, and the previous value of an observable (prev(x), rise(x), fall(x)). Only the fields a
// property needs are added, after the base state in fresh words, so the base's states are a
// prefix of these.
//
// - A recorded input (IEC 61131-3 only; Boolean): its value in the cycle that led to the state.
//   Each base successor is split by the recorded inputs' values. In the initial state (before
//   the first cycle) no input has been read: recorded inputs are FALSE there.
// - prev(x): x's value in the source of the edge that led to the state (the previous cycle,
//   Grafcet: the previous stable situation); in an initial state prev(x) = x (no edge there).
//
// Grafcet needs no recorded inputs: under the single-input-change hypothesis its situations
// already hold every input the grafcet reads (an observable of the base system).

#include <cstdint>
#include <vector>

#include "semantics/transition_system.hpp"

namespace sfcv::semantics {

struct HistoryRequest {
  /// Base inputs to record (indices into base.inputs(); Boolean, not pseudo; IEC 61131-3).
  std::vector<std::uint32_t> inputs;
  /// Observables whose previous value to keep, in order: entry k becomes observable
  /// base.observables().size() + inputs.size() + k, so it may name an earlier entry (prev of
  /// prev) or a recorded input.
  std::vector<std::uint32_t> previous;
};

class HistorySystem final : public TransitionSystem {
 public:
  /// Throws std::invalid_argument for a request the system cannot keep (see HistoryRequest).
  HistorySystem(const TransitionSystem& base, HistoryRequest request);

  const TransitionSystem& base() const { return base_; }
  const HistoryRequest& request() const { return request_; }
  /// The observable of recorded input k (request().inputs[k]).
  std::uint32_t input_observable(std::size_t k) const;
  /// The state field of recorded input k / previous value k.
  std::uint32_t input_field(std::size_t k) const { return input_fields_[k]; }
  std::uint32_t previous_field(std::size_t k) const { return previous_fields_[k]; }

  SemanticsKind kind() const override { return base_.kind(); }
  const StateLayout& layout() const override { return layout_; }
  const std::vector<InputVariable>& inputs() const override { return base_.inputs(); }
  const std::vector<Observable>& observables() const override { return observables_; }
  const std::vector<TransitionInfo>& transitions() const override { return base_.transitions(); }
  std::vector<PouInstance> pou_instances() const override { return base_.pou_instances(); }
  // The base layout's fields keep their indices here (the history fields come after).
  std::vector<MixedVariable> mixed_variables() const override { return base_.mixed_variables(); }
  void initial_states(SuccessorSink& sink) const override;
  std::optional<double> estimate_initial_states() const override {
    return base_.estimate_initial_states();
  }
  void successors(StateView state, SuccessorSink& sink) const override;
  std::int64_t observe(StateView state, std::uint32_t index) const override;
  std::string describe(StateView state) const override;
  std::optional<std::uint32_t> previous_observable(std::uint32_t index) const override;

 private:
  friend class HistorySink;
  const TransitionSystem& base_;
  HistoryRequest request_;
  StateLayout layout_;
  std::vector<Observable> observables_;
  std::vector<std::uint32_t> input_fields_, previous_fields_;
  std::uint32_t base_words_ = 0;
};

/// The history system of `ts` when `ts` is one, else null.
const HistorySystem* as_history(const TransitionSystem& ts);

}  // namespace sfcv::semantics
