#include "engine/sat/certificate.hpp"

#include "engine/sat/unrolling.hpp"

namespace sfcv::engine::sat {

namespace {

CertificateCheck fail(std::string what) {
  return {false, std::move(what)};
}

int clause_literal(Unrolling& frames, const LatchLiteral& l, std::size_t frame) {
  const int x = frames.latch(l.latch, frame);
  return l.value ? x : -x;
}

void add_invariant(Unrolling& frames, const std::vector<LatchClause>& clauses, std::size_t frame) {
  for (const auto& c : clauses) {
    std::vector<int> lits;
    for (const auto& l : c) lits.push_back(clause_literal(frames, l, frame));
    frames.solver().add_clause(lits);
  }
}

CertificateCheck recheck_invariant(const ReachQuery& q, semantics::AigLit target,
                                   const std::vector<LatchClause>& clauses, Deadline deadline) {
  const auto& aig = *q.aig;
  // Initiation: the initial state is one concrete valuation; evaluate each clause on it.
  for (const auto& c : clauses) {
    bool satisfied = false;
    for (const auto& l : c) satisfied = satisfied || aig.latches()[l.latch].initial == l.value;
    if (!satisfied) return fail("initiation");
  }
  {  // Inv(s) excludes the target.
    Solver solver(deadline);
    Unrolling frames(aig, solver, false);
    add_invariant(frames, clauses, 0);
    switch (solver.solve({frames.literal(target, 0)})) {
      case SatResult::Sat:
        return fail("property");
      case SatResult::Interrupted:
        return fail("time");
      case SatResult::Unsat:
        break;
    }
  }
  {  // Consecution: Inv(s) & step_ok(s, i) & !Inv(s') is unsatisfiable.
    Solver solver(deadline);
    Unrolling frames(aig, solver, false);
    add_invariant(frames, clauses, 0);
    solver.add_clause({frames.literal(q.step_ok, 0)});
    std::vector<int> some_clause_false;
    for (const auto& c : clauses) {
      const int broken = solver.new_var();
      for (const auto& l : c) solver.add_clause({-broken, -clause_literal(frames, l, 1)});
      some_clause_false.push_back(broken);
    }
    solver.add_clause(some_clause_false);
    switch (solver.solve()) {
      case SatResult::Sat:
        return fail("consecution");
      case SatResult::Interrupted:
        return fail("time");
      case SatResult::Unsat:
        break;
    }
  }
  return {true, ""};
}

CertificateCheck recheck_k_induction(const ReachQuery& q, semantics::AigLit target,
                                     std::uint32_t depth, Deadline deadline) {
  if (depth == 0) return fail("step");
  {  // Base: no target within depth - 1 steps of the initial state.
    Solver solver(deadline);
    Unrolling frames(*q.aig, solver, true);
    for (std::uint32_t k = 0; k < depth; ++k) {
      switch (solver.solve({frames.literal(target, k)})) {
        case SatResult::Sat:
          return fail("base");
        case SatResult::Interrupted:
          return fail("time");
        case SatResult::Unsat:
          break;
      }
      solver.add_clause({frames.literal(q.step_ok, k)});
    }
  }
  {  // Step: no loop-free run of `depth` non-target frames followed by a target frame.
    Solver solver(deadline);
    Unrolling frames(*q.aig, solver, false);
    const auto cone = cone_latches(*q.aig, {target, q.step_ok});
    for (std::uint32_t j = 0; j < depth; ++j) {
      solver.add_clause({-frames.literal(target, j)});
      solver.add_clause({frames.literal(q.step_ok, j)});
    }
    for (std::uint32_t b = 1; b <= depth; ++b)
      for (std::uint32_t a = 0; a < b; ++a) add_frames_differ(frames, cone, a, b);
    switch (solver.solve({frames.literal(target, depth)})) {
      case SatResult::Sat:
        return fail("step");
      case SatResult::Interrupted:
        return fail("time");
      case SatResult::Unsat:
        break;
    }
  }
  return {true, ""};
}

}  // namespace

CertificateCheck recheck(const ReachQuery& query, std::size_t target, const Certificate& cert,
                         Deadline deadline) {
  switch (cert.kind) {
    case Certificate::Kind::Invariant:
      return recheck_invariant(query, query.targets[target], cert.clauses, deadline);
    case Certificate::Kind::KInduction:
      return recheck_k_induction(query, query.targets[target], cert.depth, deadline);
    case Certificate::Kind::None:
      break;
  }
  return fail("no certificate");
}

std::string certificate_text(const semantics::Aig& aig, const Certificate& cert) {
  switch (cert.kind) {
    case Certificate::Kind::KInduction:
      return "k-induction, k = " + std::to_string(cert.depth) + " (base: no target within " +
             std::to_string(cert.depth - 1) + " cycles; step: no loop-free run of " +
             std::to_string(cert.depth) + " non-target cycles reaches one)\n";
    case Certificate::Kind::Invariant: {
      std::string out = "inductive invariant, " + std::to_string(cert.clauses.size()) +
                        " clauses (each holds in every reachable state):\n";
      for (const auto& c : cert.clauses) {
        std::string line;
        for (const auto& l : c)
          line += (line.empty() ? "" : " | ") + std::string(l.value ? "" : "!") +
                  aig.latches()[l.latch].name;
        out += "  " + (line.empty() ? std::string("FALSE") : line) + "\n";
      }
      return out;
    }
    case Certificate::Kind::None:
      break;
  }
  return "";
}

}  // namespace sfcv::engine::sat
