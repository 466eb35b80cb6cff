#pragma once
// Independent re-checks of the engines' proofs, each with fresh solvers that share nothing with
// the engine that produced the certificate:
// - an inductive invariant Inv (clauses over latches): init => Inv (initiation),
//   Inv(s) & step_ok(s, i) => Inv(next(s, i)) (consecution), Inv(s) => !target(s, i);
// - a k-induction depth k: no target within k - 1 steps of the initial state (base), and no
//   loop-free run of k non-target frames followed by a target frame (step).

#include <string>
#include <vector>

#include "engine/sat/reachability.hpp"
#include "engine/sat/sat_solver.hpp"

namespace sfcv::engine::sat {

struct CertificateCheck {
  bool ok = false;
  std::string
      failed;  ///< when !ok: "initiation", "consecution", "property", "base", "step", "time"
};

CertificateCheck recheck(const ReachQuery& query, std::size_t target, const Certificate& cert,
                         Deadline deadline = {});

/// The certificate as readable text over the circuit's latch names, e.g.
/// "invariant, 2 clauses:\n  !S2 | cnt[1]\n  ...".
std::string certificate_text(const semantics::Aig& aig, const Certificate& cert);

}  // namespace sfcv::engine::sat
