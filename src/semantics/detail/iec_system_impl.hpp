#pragma once
// Internal: the IEC 61131-3 TransitionSystem class (make_iec61131_system returns it). The
// simulator uses step_once to follow given inputs without enumerating successors.

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "semantics/detail/iec_program.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::semantics::iec {

class Iec61131System final : public TransitionSystem {
 public:
  explicit Iec61131System(std::unique_ptr<Program> p);

  SemanticsKind kind() const override { return SemanticsKind::Iec61131; }
  const StateLayout& layout() const override { return p_->layout; }
  const std::vector<InputVariable>& inputs() const override { return p_->inputs; }
  const std::vector<Observable>& observables() const override { return p_->observables; }
  const std::vector<TransitionInfo>& transitions() const override { return p_->transition_infos; }
  std::vector<PouInstance> pou_instances() const override;
  void initial_states(SuccessorSink& sink) const override;
  void successors(StateView state, SuccessorSink& sink) const override;
  std::int64_t observe(StateView state, std::uint32_t index) const override;
  std::optional<std::vector<std::uint32_t>> observed_fields(std::uint32_t index) const override;

  /// One cycle under a complete input valuation; false (and `error`) on an assumption
  /// violation or a range error.
  bool step_once(StateView state, const std::vector<std::int64_t>& valuation,
                 std::vector<StateWord>& out, std::vector<std::uint32_t>* fired,
                 std::string* error) const;

  const Program& program() const { return *p_; }

 private:
  struct Entry {
    std::uint64_t hash = 0;
    std::size_t slot = 0;
    std::vector<StateWord> target;
    std::vector<std::uint32_t> fired;
    InputCondition condition;
    std::size_t cubes = 0;
  };
  struct AnomalyEntry {
    std::string message;
    InputCondition condition;
    std::size_t cubes = 0;
  };
  Entry& entry_for(std::span<const std::uint32_t> fired) const;
  void add_cube(InputCondition& cond, std::size_t& n) const;
  void trim(InputCondition& cond, std::size_t n) const;

  std::unique_ptr<Program> p_;
  // Scratch reused across calls: no heap allocation per successor once warmed up. The lock
  // makes the calls that use it safe from several threads (the engines of --engine auto build
  // their circuits from one system at once); a sink may call back in, hence recursive.
  mutable std::recursive_mutex scratch_lock_;
  mutable Machine machine_;
  mutable std::vector<StateWord> scratch_;
  mutable std::vector<Entry> entries_;
  mutable std::size_t used_ = 0;
  mutable std::vector<std::uint32_t> table_;    ///< open addressing: entry index + 1, 0 = empty
  mutable std::vector<InputCube> spare_cubes_;  ///< cubes (with their capacity) between calls
  mutable std::vector<AnomalyEntry> anomalies_;
  mutable std::size_t anomalies_used_ = 0;
};

}  // namespace sfcv::semantics::iec
