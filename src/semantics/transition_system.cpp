#include "semantics/transition_system.hpp"

#include "model/names.hpp"

namespace sfcv::semantics {

std::string_view to_string(SemanticsKind k) {
  return k == SemanticsKind::Iec61131 ? "iec61131" : "grafcet";
}

std::string TransitionSystem::describe(StateView state) const {
  std::string steps, outputs;
  const auto& obs = observables();
  for (std::uint32_t i = 0; i < obs.size(); ++i) {
    if (obs[i].kind == ObservableKind::Step && observe(state, i)) {
      steps += (steps.empty() ? "" : ", ") + obs[i].name;
    } else if (obs[i].kind == ObservableKind::Variable && obs[i].is_output) {
      const auto v = observe(state, i);
      if (obs[i].type.kind == model::TypeKind::Bool) {
        if (v) outputs += " " + obs[i].name;
      } else {
        outputs += " " + obs[i].name + "=" + std::to_string(v);
      }
    }
  }
  return "{" + steps + "}" + outputs;
}

std::optional<std::uint32_t> find_observable(const TransitionSystem& ts, std::string_view name,
                                             std::string* error) {
  const auto& obs = ts.observables();
  for (std::uint32_t i = 0; i < obs.size(); ++i)
    if (model::iequals(obs[i].name, name)) return i;
  std::vector<std::uint32_t> hits;
  for (std::uint32_t i = 0; i < obs.size(); ++i)
    for (const auto& a : obs[i].aliases)
      if (model::iequals(a, name)) {
        hits.push_back(i);
        break;
      }
  if (hits.size() == 1) return hits.front();
  if (error) {
    if (hits.empty()) {
      *error = "unknown name '" + std::string(name) + "'";
    } else {
      *error = "ambiguous name '" + std::string(name) + "': could be";
      for (auto h : hits) *error += " " + obs[h].name;
    }
  }
  return std::nullopt;
}

}  // namespace sfcv::semantics
