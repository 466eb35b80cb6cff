#pragma once
// A thin facade over BuDDy: one global manager, initialised on first use, and an RAII value
// class. No other file includes bdd.h, so BuDDy's global state and its error handling (which
// would exit the process) stay behind this interface: errors become BddError exceptions.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <vector>

#include "logic/big_count.hpp"
#include "model/errors.hpp"

namespace sfcv::engine::bdd {

/// BuDDy reported an error other than running out of nodes: a bug (the node table full under
/// --memory, and the deadline, are LimitReached).
class BddError : public InternalError {
 public:
  using InternalError::InternalError;
};

/// Initialises BuDDy once (later calls do nothing): node table, cache, hooks.
void ensure_manager(int nodes = 1 << 18, int cache = 1 << 15);
/// Makes sure variables 0..count-1 exist.
void ensure_variables(int count);

/// Sizes the node table and cache of the manager; only effective before its first use (BuDDy
/// keeps one global manager). Measured on this machine: a 200-process example stalls with the
/// default sizing and runs in 3 s with (4000000, 1000000) and cache ratio 4.
void configure_manager(int nodes, int cache, int cache_ratio = 4);

/// Past `deadline` (none: no limit) the next operation throws LimitReached(Time), and so does
/// the next garbage collection (a single operation that blows up is otherwise not
/// interruptible; collections happen whenever the node table fills). The run's one deadline
/// (model::Budget), not a timeout of its own.
/// `cancel` (model::Budget::cancel, may be null): once raised, the deadline counts as passed.
void set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline,
                  const std::atomic<bool>* cancel = nullptr);

/// Sets the deadline for its lifetime (the manager is global: a deadline must not outlive the
/// check that set it).
class DeadlineScope {
 public:
  explicit DeadlineScope(std::optional<std::chrono::steady_clock::time_point> deadline,
                         const std::atomic<bool>* cancel = nullptr) {
    set_deadline(deadline, cancel);
  }
  ~DeadlineScope() { set_deadline(std::nullopt); }
  DeadlineScope(const DeadlineScope&) = delete;
  DeadlineScope& operator=(const DeadlineScope&) = delete;
};

/// Brings the deadline forward to `earlier` for its lifetime when that is sooner (a phase's
/// share of the run's time), keeping the cancel flag; then restores the run's deadline.
class EarlierDeadlineScope {
 public:
  explicit EarlierDeadlineScope(std::chrono::steady_clock::time_point earlier);
  ~EarlierDeadlineScope();
  EarlierDeadlineScope(const EarlierDeadlineScope&) = delete;
  EarlierDeadlineScope& operator=(const EarlierDeadlineScope&) = delete;

 private:
  bool had_deadline_;
  std::chrono::steady_clock::time_point deadline_;
};

/// Whether the deadline set_deadline() gave has passed (or the cancel flag is raised).
bool deadline_passed();
/// Throws LimitReached(Time) once deadline_passed(): for the long loops between BDD operations
/// (simulating the circuit on explicit states).
void poll_deadline();

/// Nodes currently allocated in the manager's table.
int allocated_nodes();

/// What one symbolic system asks of the manager.
struct ManagerOptions {
  int nodes = 1 << 16;  ///< initial node table (grows on demand, doubling)
  int cache = 1 << 14;
  int cache_ratio = 4;
  int max_nodes = 0;  ///< 0 = unlimited; past it an operation throws BddError
};

/// Approximate bytes per node of the table, with its share of the operation caches (20 bytes
/// a node, six caches of 16-byte entries at one entry per 4 nodes, and slack for reordering):
/// `--memory` divides its budget by this.
constexpr std::uint64_t kBytesPerNode = 64;

/// Starts the manager for a new symbolic system. The running manager is replaced by a fresh one
/// (identity variable order, no blocks) when no Bdd is alive and it cannot serve as it is: after
/// an error (BuDDy's state is then in doubt), after dynamic reordering was enabled, or when its
/// table is larger than `max_nodes`. Throws BddError when a failed manager cannot be replaced.
void start_manager(const ManagerOptions& options);

/// Makes variables first..last (adjacent levels) one block for dynamic reordering, in a fixed
/// order inside (a current/next pair). Without blocks BuDDy's reordering moves nothing.
void add_variable_block(int first, int last);
/// Automatic reordering by sifting of the blocks, at most `max_passes` times (0: off). The
/// first pass runs when a garbage collection leaves `first_pass_nodes` live nodes (at most the
/// table: when its initial size is in use, BuDDy's own rule), or after
/// start_automatic_reordering(); then BuDDy sifts when a collection of a full table leaves at
/// least twice the live nodes of the last pass (more when that pass gained less than 20 %).
/// Stops after a pass that shrank the live nodes by less than `min_gain_percent`.
void set_automatic_reordering(int max_passes, int min_gain_percent, int first_pass_nodes = 0);
/// Before the first automatic pass: it now waits for at least `first_pass_nodes` live nodes.
void delay_automatic_reordering(int first_pass_nodes);
/// Whether automatic reordering is on and its first pass has not started yet.
bool automatic_reordering_waits();
/// The first automatic pass runs at the next garbage collection, whatever the live nodes.
void start_automatic_reordering();
/// Sifts the blocks once, now (a first order for the relation just built).
void reorder_now();
/// Reorderings done since the program started (each sifting pass counts once).
int reorderings();

/// Position of variable `var` in the current order (0 = top).
int level_of(int var);

/// Number of Bdd values alive that hold a non-constant node (a manager can only be replaced
/// when there are none).
long live_bdds();

/// Empties BuDDy's operation caches (by a garbage collection). Their keys include node numbers and
/// the ids of renamings; entries left by a previous, destroyed system gave wrong results for
/// the next one (measured: a reachable set of 16 states instead of 33). Every symbolic system
/// calls this when it starts.
void reset_operation_caches();

class Bdd;

/// A renaming or substitution of variables (BuDDy's bddPair), owned.
class VarMap {
 public:
  VarMap();
  ~VarMap();
  VarMap(const VarMap&) = delete;
  VarMap& operator=(const VarMap&) = delete;
  /// Variable `from` becomes variable `to` (for Bdd::replace).
  void rename(int from, int to);
  /// Variable `var` becomes the function `f` (for Bdd::compose).
  void substitute(int var, const Bdd& f);

 private:
  friend class Bdd;
  void* pair_;
};

/// A BDD node held with a reference count (copyable value; comparison is canonical equality).
class Bdd {
 public:
  Bdd();  ///< false (needs no manager)
  Bdd(const Bdd& other);
  Bdd(Bdd&& other) noexcept;
  Bdd& operator=(const Bdd& other);
  Bdd& operator=(Bdd&& other) noexcept;
  ~Bdd();

  static Bdd constant(bool value);
  static Bdd variable(int index);  ///< ensures the variable exists

  Bdd operator&(const Bdd& o) const;
  Bdd operator|(const Bdd& o) const;
  Bdd operator!() const;
  Bdd operator^(const Bdd& o) const;
  Bdd iff(const Bdd& o) const;
  Bdd ite(const Bdd& then, const Bdd& otherwise) const;  ///< *this ? then : otherwise

  /// The conjunction of the positive variables `vars`: a variable set for quantification.
  static Bdd cube(const std::vector<int>& vars);
  /// Existential quantification over the variables of `vars` (a cube).
  Bdd exist(const Bdd& vars) const;
  /// exist(vars) of (*this & o), computed in one pass (relational product).
  Bdd and_exist(const Bdd& o, const Bdd& vars) const;
  Bdd replace(const VarMap& map) const;
  Bdd compose(const VarMap& map) const;  ///< simultaneous substitution of functions
  /// One satisfying assignment as a full cube over the variables of `vars`; false if none.
  Bdd sat_one(const Bdd& vars) const;
  /// Value of `var` in a cube (sat_one's result): -1 when the cube does not mention it.
  int value_in_cube(int var) const;
  /// log2 of the number of assignments of the variables of `vars` that satisfy *this.
  double sat_count_log2(const Bdd& vars) const;
  /// The exact number of assignments of `vars` (every variable *this mentions must be among
  /// them) that satisfy *this; nullopt when it does not fit in 64 bits. With `nodes`, it
  /// receives node_count(), which the same walk counts.
  std::optional<std::uint64_t> sat_count_u64(const std::vector<int>& vars,
                                             int* nodes = nullptr) const;
  /// The same count exactly, of any size (64-bit arithmetic first, big integers when that
  /// overflows).
  logic::BigCount sat_count_exact(const std::vector<int>& vars) const;
  int node_count() const;
  /// Calls `visit(values)` once per satisfying assignment of `vars` (values[k]: vars[k]), in
  /// no particular order, until it returns false; returns false then, or when *this mentions
  /// a variable outside `vars` (nothing more is visited). Creates no node: `visit` must not
  /// either (a garbage collection would reuse the nodes being walked).
  bool for_each_assignment(const std::vector<int>& vars,
                           const std::function<bool(const std::vector<bool>&)>& visit) const;
  bool operator==(const Bdd& o) const { return root_ == o.root_; }
  bool operator!=(const Bdd& o) const { return root_ != o.root_; }

  bool is_true() const;
  bool is_false() const;
  /// Top variable (precondition: not constant; its level is level_of(top())); low/high
  /// cofactors of the top node.
  int top() const;
  Bdd low() const;
  Bdd high() const;
  /// Cofactor with respect to `var` when it is the top variable, else *this (the caller walks
  /// variables in level order, so a non-top variable does not occur above the root).
  Bdd cofactor(int var, bool value) const;

 private:
  friend class VarMap;
  explicit Bdd(int root);
  int root_;
};

}  // namespace sfcv::engine::bdd
