#pragma once
// Shared by the engine agreement tests: random CTL over a system's Boolean observables, and a
// CheckTask resolved from formula texts (any parse or name error fails the test).

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "logic/check_inputs.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::test {

class FormulaGenerator {
 public:
  using AtomFilter = std::function<bool(const semantics::Observable&)>;
  /// Atoms are the Boolean observables `keep` accepts (all of them by default).
  FormulaGenerator(const semantics::TransitionSystem& ts, std::uint64_t seed,
                   const AtomFilter& keep = {})
      : rng_(seed) {
    for (const auto& o : ts.observables())
      if (o.type.kind == model::TypeKind::Bool && (!keep || keep(o))) atoms_.push_back(o.name);
  }
  std::string formula(int depth) {
    if (depth == 0 || pick(4) == 0) return atom();
    static const char* unary[] = {"!", "EX ", "AX ", "EF ", "AF ", "EG ", "AG "};
    static const char* binary[] = {" & ", " | ", " -> "};
    switch (pick(3)) {
      case 0:
        return std::string(unary[pick(7)]) + "(" + formula(depth - 1) + ")";
      case 1:
        return "(" + formula(depth - 1) + binary[pick(3)] + formula(depth - 1) + ")";
      default:
        return std::string(pick(2) ? "E[" : "A[") + formula(depth - 1) + " U " +
               formula(depth - 1) + "]";
    }
  }
  std::string atom() {
    return atoms_.empty() ? "TRUE" : atoms_[pick(static_cast<std::uint32_t>(atoms_.size()))];
  }

 private:
  std::uint32_t pick(std::uint32_t n) { return static_cast<std::uint32_t>(rng_() % n); }
  std::mt19937_64 rng_;
  std::vector<std::string> atoms_;
};

inline logic::CheckTask task_for(const model::Project& p, const semantics::TransitionSystem& ts,
                                 const std::vector<std::string>& ctl,
                                 const std::vector<std::string>& fair) {
  logic::CheckInputs in;
  in.ctl = ctl;
  in.fair = fair;
  auto parsed = logic::parse_check_inputs(in);
  for (const auto& d : parsed.diagnostics) ADD_FAILURE() << d.str();
  logic::CheckTask task;
  task.system = &ts;
  task.project = &p;
  model::Diagnostics diags;
  logic::resolve_into(parsed.spec, ts, task, diags);
  for (const auto& d : diags) ADD_FAILURE() << d.str();
  return task;
}

}  // namespace sfcv::test
