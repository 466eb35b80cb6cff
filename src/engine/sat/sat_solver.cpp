#include "engine/sat/sat_solver.hpp"

#include <cadical.hpp>
#include <cstdlib>
#include <stdexcept>

namespace sfcv::engine::sat {

Deadline Deadline::after_seconds(double seconds) {
  Deadline d;
  if (seconds > 0)
    d.at = Clock::now() +
           std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  return d;
}

namespace {
// CaDiCaL polls this during search: a single hard call must not outlive --timeout.
class DeadlineTerminator final : public CaDiCaL::Terminator {
 public:
  explicit DeadlineTerminator(Deadline d) : deadline_(d) {}
  bool terminate() override { return deadline_.passed(); }

 private:
  Deadline deadline_;
};
}  // namespace

struct Solver::Impl {
  CaDiCaL::Solver solver;
  DeadlineTerminator terminator;
  Deadline deadline;
  Impl(Deadline d, SolverProfile profile) : terminator(d), deadline(d) {
    solver.set("quiet", 1);  // library code prints nothing
    if (profile == SolverProfile::ManySmallQueries) {
      solver.set("phase", 0);
      solver.set("reduce", 0);
    }
    if (d.set()) solver.connect_terminator(&terminator);
    if (profile == SolverProfile::Deepening) {
      solver.set("reduce", 0);
      solver.set("shrink", 0);
    }
  }
  ~Impl() {
    if (deadline.set()) solver.disconnect_terminator();
  }
};

Solver::Solver(Deadline deadline, SolverProfile profile)
    : impl_(std::make_unique<Impl>(deadline, profile)) {}
Solver::~Solver() = default;

int Solver::new_var() {
  return ++vars_;
}

int Solver::true_lit() {
  if (true_ == 0) {
    true_ = new_var();
    add_clause({true_});
  }
  return true_;
}

void Solver::add_clause(const int* lits, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) {
    if (lits[i] == 0) throw std::logic_error("sat::Solver::add_clause: literal 0");
    impl_->solver.add(lits[i]);
  }
  impl_->solver.add(0);
}

SatResult Solver::solve(const std::vector<int>& assumptions) {
  return solve(assumptions, {});
}

SatResult Solver::solve(const std::vector<int>& assumptions, const std::vector<int>& constraint) {
  if (impl_->deadline.passed()) return SatResult::Interrupted;
  ++calls_;
  for (int l : assumptions) impl_->solver.assume(l);
  if (!constraint.empty()) {
    for (int l : constraint) {
      if (l == 0) throw std::logic_error("sat::Solver::solve: literal 0 in the constraint");
      impl_->solver.constrain(l);
    }
    impl_->solver.constrain(0);
  }
  const int r = impl_->solver.solve();
  if (r == 10) return SatResult::Sat;
  if (r == 20) return SatResult::Unsat;
  return SatResult::Interrupted;
}

bool Solver::value(int lit) const {
  // CaDiCaL's val returns the literal itself when true; variables it never saw are false.
  if (std::abs(lit) > impl_->solver.vars()) return lit < 0;
  return impl_->solver.val(lit) > 0;
}

bool Solver::failed(int lit) const {
  return impl_->solver.failed(lit);
}

}  // namespace sfcv::engine::sat
