#pragma once
// An And-Inverter Graph: the Boolean circuit of a transition system. Latches hold the state
// bits, inputs the (pseudo-)inputs; each latch has a next-state function. The BDD engine builds
// its transition relation from it and the AIGER export writes it, so both mean the same thing.
//
// A literal is 2 * node + negation bit; node 0 is the constant FALSE (literal 0), so literal 1 is
// TRUE. Nodes are numbered in creation order; the AIGER writer renumbers them.

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace sfcv::semantics {

using AigLit = std::uint32_t;

class Aig {
 public:
  static constexpr AigLit kFalse = 0;
  static constexpr AigLit kTrue = 1;

  enum class NodeKind : std::uint8_t { Constant, Input, Latch, And };
  struct Node {
    NodeKind kind = NodeKind::Constant;
    AigLit left = 0, right = 0;  ///< And: the two fan-in literals (left <= right)
    std::uint32_t index = 0;     ///< Input/Latch: position in inputs()/latches()
  };
  struct Latch {
    std::string name;
    AigLit current = 0;  ///< the latch's own (positive) literal
    AigLit next = 0;     ///< next-state function
    bool initial = false;
  };
  struct Input {
    std::string name;
    AigLit literal = 0;
  };
  struct Named {
    std::string name;
    AigLit literal = 0;
  };

  Aig();

  AigLit add_input(std::string name);
  /// A latch with its initial value; its next-state function is set later (default: itself).
  AigLit add_latch(std::string name, bool initial = false);
  void set_next(std::uint32_t latch_index, AigLit next);
  /// A copy started elsewhere (the SAT engines' EF on Grafcet runs from one situation).
  void set_initial(std::uint32_t latch_index, bool value) { latches_[latch_index].initial = value; }

  AigLit make_and(AigLit a, AigLit b);  ///< constant folding + structural hashing
  /// Past `deadline`, make_and throws LimitReached(Time) (polled every 64k calls): building the
  /// circuit of a large chart must hold the run's budget too. None: no limit.
  void set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline) {
    deadline_ = deadline;
  }
  /// Past `bytes` (memory_bytes(), polled every 4096 new And nodes), make_and throws
  /// LimitReached(Memory): --memory holds while a large chart's circuit is built. 0: no limit.
  void set_memory_limit(std::uint64_t bytes) { memory_limit_ = bytes; }
  /// What the graph holds: its nodes, the structural hash table, names.
  std::uint64_t memory_bytes() const;
  static AigLit make_not(AigLit a) { return a ^ 1U; }
  AigLit make_or(AigLit a, AigLit b) { return make_not(make_and(make_not(a), make_not(b))); }
  AigLit make_xor(AigLit a, AigLit b);
  AigLit make_xnor(AigLit a, AigLit b) { return make_not(make_xor(a, b)); }
  AigLit make_implies(AigLit a, AigLit b) { return make_or(make_not(a), b); }
  AigLit make_ite(AigLit c, AigLit t, AigLit e);
  AigLit make_and(const std::vector<AigLit>& lits);
  AigLit make_or(const std::vector<AigLit>& lits);

  /// Safety property: `bad` must never hold in a reachable state (AIGER 1.9 B section).
  void add_bad(std::string name, AigLit bad) { bad_.push_back({std::move(name), bad}); }
  void clear_bad() { bad_.clear(); }
  /// Invariant constraint on inputs and state (AIGER 1.9 C section): runs leave it never.
  void add_constraint(std::string name, AigLit c) { constraints_.push_back({std::move(name), c}); }
  void clear_constraints() { constraints_.clear(); }
  /// Named signals kept for people (outputs, steps), exported as AIGER outputs / comments.
  void add_output(std::string name, AigLit lit) { outputs_.push_back({std::move(name), lit}); }
  void clear_outputs() { outputs_.clear(); }

  /// `root` with latch or input literal `var` (positive) replaced by the constant `value`.
  AigLit cofactor(AigLit root, AigLit var, bool value);

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<Input>& inputs() const { return inputs_; }
  const std::vector<Latch>& latches() const { return latches_; }
  const std::vector<Named>& bad() const { return bad_; }
  const std::vector<Named>& constraints() const { return constraints_; }
  const std::vector<Named>& outputs() const { return outputs_; }
  std::size_t num_ands() const { return num_ands_; }

  static std::uint32_t node_of(AigLit l) { return l >> 1; }
  static bool is_negated(AigLit l) { return (l & 1U) != 0; }

  /// Evaluates every node under the given input and latch values (simulation, tests).
  std::vector<bool> evaluate(const std::vector<bool>& input_values,
                             const std::vector<bool>& latch_values) const;
  static bool value_of(const std::vector<bool>& node_values, AigLit l) {
    return node_values[node_of(l)] != is_negated(l);
  }

 private:
  std::vector<Node> nodes_;
  std::vector<Input> inputs_;
  std::vector<Latch> latches_;
  std::vector<Named> bad_, constraints_, outputs_;
  std::unordered_map<std::uint64_t, AigLit> strash_;
  std::size_t num_ands_ = 0;
  std::optional<std::chrono::steady_clock::time_point> deadline_;
  std::uint32_t calls_ = 0;
  std::uint64_t memory_limit_ = 0;
};

/// Little-endian two's-complement bit vectors over an Aig, for bounded integers.
using BitVector = std::vector<AigLit>;

BitVector bv_constant(std::int64_t value, std::uint32_t width);
BitVector bv_add(Aig& aig, const BitVector& a, const BitVector& b);  ///< wraps at the width
BitVector bv_sub(Aig& aig, const BitVector& a, const BitVector& b);
BitVector bv_neg(Aig& aig, const BitVector& a);
BitVector bv_mux(Aig& aig, AigLit c, const BitVector& t, const BitVector& e);
AigLit bv_equal(Aig& aig, const BitVector& a, const BitVector& b);
AigLit bv_less_signed(Aig& aig, const BitVector& a, const BitVector& b);
AigLit bv_less_unsigned(Aig& aig, const BitVector& a, const BitVector& b);
/// Sign- or zero-extends (or truncates) to `width` bits.
BitVector bv_resize(const BitVector& a, std::uint32_t width, bool is_signed);

}  // namespace sfcv::semantics
