#include "engine/portfolio/engine_by_name.hpp"

#include <stdexcept>
#include <string>

#include "engine/portfolio/portfolio_model_checker.hpp"
#include "engine/sat/sat_model_checker.hpp"

namespace sfcv::engine {

bool is_builtin_engine(std::string_view name) {
  for (const char* known : {"explicit", "bdd", "bmc", "kind", "ic3", "auto"})
    if (name == known) return true;
  return false;
}

ModelCheckerPtr make_engine_by_name(std::string_view name, const EngineSelection& selection) {
  if (name == "bmc" || name == "kind" || name == "ic3") {
    SatEngineOptions sat;
    sat.algorithm = name == "bmc"    ? SatAlgorithm::Bmc
                    : name == "kind" ? SatAlgorithm::KInduction
                                     : SatAlgorithm::Ic3;
    sat.max_depth = selection.max_depth;
    sat.min_depth = selection.min_depth;
    return make_sat_model_checker(sat);
  }
  if (name == "bdd") return make_bdd_model_checker(selection.bdd);
  if (name == "explicit") return make_explicit_model_checker(selection.explicit_engine);
  if (name == "auto") {
    PortfolioOptions options;
    options.bdd = selection.bdd;
    options.explicit_engine = selection.explicit_engine;
    options.note = selection.note;
    options.abandon_after = selection.abandon_after;
    return make_portfolio_model_checker(options);
  }
  throw std::invalid_argument("no engine called '" + std::string(name) + "'");
}

}  // namespace sfcv::engine
