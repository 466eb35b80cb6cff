#pragma once
// A specification file: named properties, assumptions and fairness constraints.
//
//   -- comments start with -- or //
//   property no_overfill_T1: AG !(V1 & V3);
//   ltl drains: G (V3 -> F !V3);  -- an LTL property (X F G U R W), over every path
//   pattern fills_T1: response(start, V1, within 5 cycles);   -- logic/pattern.hpp
//   assume !(LIS1 & LIS2);      -- an assumption over inputs and state (propositional)
//   fair S1;                    -- runs that visit S1 infinitely often

#include <string>
#include <vector>

#include "logic/fwd.hpp"
#include "model/source_location.hpp"

namespace sfcv::logic {

struct NamedFormula {
  std::string name;  ///< property name; empty for assumptions and fairness
  FormulaPtr formula;
  model::SourceLocation where;
  std::string description;    ///< a pattern's English sentence; empty for a formula
  std::string justification;  ///< a requirement file's justification (logic/requirements.hpp)
};

struct Spec {
  std::vector<NamedFormula> properties;
  std::vector<NamedFormula> assumptions;  ///< propositional
  std::vector<NamedFormula> fairness;     ///< propositional
};

}  // namespace sfcv::logic
