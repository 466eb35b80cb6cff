#pragma once
// A thin facade over CaDiCaL (like bdd_manager.hpp over BuDDy): one incremental solver per
// value, DIMACS-style literals (a variable is a positive int, its negation the negative one),
// assumptions, failed assumptions for cores, and a deadline that interrupts a running solve.
// No other file includes cadical.hpp.

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <vector>

namespace sfcv::engine::sat {

using Clock = std::chrono::steady_clock;

/// A point in time after which work stops (none: never).
struct Deadline {
  std::optional<Clock::time_point> at;
  /// model::Budget::cancel: raised, the deadline counts as passed (may be null).
  const std::atomic<bool>* cancel = nullptr;
  static Deadline after_seconds(double seconds);  ///< 0 or less: none
  bool passed() const {
    return (cancel && cancel->load(std::memory_order_relaxed)) || (at && Clock::now() >= *at);
  }
  bool set() const { return at || cancel; }
};

enum class SatResult { Sat, Unsat, Interrupted };

/// How a solver is tuned for its callers' queries.
enum class SolverProfile {
  Default,  ///< CaDiCaL's defaults: certificate re-checks, loop pumping
  /// BMC and k-induction: one query per depth on an unrolling that grows by a frame each
  /// time. Learned clauses are kept (the next depth repeats the last one's frames) and
  /// learned clauses are not shrunk: on bench/run's levels 8 and counter 6 (deepest runs)
  /// 0.15 -> 0.12 s and 0.23 -> 0.18 s of CPU (docs/engines.md).
  Deepening,
  /// IC3's frame and lifting solvers: hundreds of thousands of short queries, many alike.
  /// Decisions try false first: most latches start at 0, so the states a query finds lie
  /// nearer the initial state; learned clauses are never dropped: the next query reuses them.
  /// On bench/run's levels rows IC3 took 0.48 -> 0.20 s (levels 4, last tank) and 12.0 ->
  /// 2.1 s (levels 8), and 357 MB instead of 519 MB on corpus 06 in 60 s (docs/benchmarks.md).
  ManySmallQueries,
};

class Solver {
 public:
  explicit Solver(Deadline deadline = {}, SolverProfile profile = SolverProfile::Default);
  ~Solver();
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  int new_var();
  /// A literal that is always true (its variable is fixed by a unit clause).
  int true_lit();
  void add_clause(const std::vector<int>& lits) { add_clause(lits.data(), lits.size()); }
  /// (No vector: the unrollings add millions of short clauses.)
  void add_clause(std::initializer_list<int> lits) { add_clause(lits.begin(), lits.size()); }
  void add_clause(const int* lits, std::size_t size);
  /// Solves under the assumptions (they hold only for this call). Interrupted when the
  /// deadline passed before or during the search.
  SatResult solve(const std::vector<int>& assumptions = {});
  /// The same with one more clause that holds only for this call (CaDiCaL's `constrain`): a
  /// temporary clause costs no activation variable, which would stay in the solver for good
  /// and slow down every later call (IC3 makes hundreds of thousands of such calls).
  SatResult solve(const std::vector<int>& assumptions, const std::vector<int>& constraint);
  /// After Sat: the value of a literal in the model.
  bool value(int lit) const;
  /// After Unsat: whether assumption `lit` is part of the reason (the core).
  bool failed(int lit) const;
  std::size_t calls() const { return calls_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int vars_ = 0;
  int true_ = 0;
  std::size_t calls_ = 0;
};

}  // namespace sfcv::engine::sat
