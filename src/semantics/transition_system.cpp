#include "semantics/transition_system.hpp"

#include <unordered_map>

#include "model/names.hpp"
#include "model/suggest.hpp"

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

struct TransitionSystem::NameIndex {
  const Observable* data = nullptr;  ///< the observables it was built from
  std::size_t size = 0;
  std::unordered_map<std::string, std::uint32_t> by_name;  ///< the first observable of a name
  std::unordered_map<std::string, std::vector<std::uint32_t>> by_alias;  ///< each once, in order
};

TransitionSystem::LazyNameIndex::LazyNameIndex() = default;
TransitionSystem::LazyNameIndex::LazyNameIndex(const LazyNameIndex&) {}
TransitionSystem::LazyNameIndex& TransitionSystem::LazyNameIndex::operator=(const LazyNameIndex&) {
  return *this;  // the copy's index is built from its own observables
}
TransitionSystem::LazyNameIndex::~LazyNameIndex() = default;

std::optional<std::uint32_t> find_observable(const TransitionSystem& ts, std::string_view name,
                                             std::string* error) {
  const auto& obs = ts.observables();
  const TransitionSystem::NameIndex* index = nullptr;
  {
    auto& lazy = ts.names_;
    const std::lock_guard<std::mutex> lock(lazy.mutex);
    if (!lazy.index || lazy.index->data != obs.data() || lazy.index->size != obs.size()) {
      auto built = std::make_unique<TransitionSystem::NameIndex>();
      built->data = obs.data();
      built->size = obs.size();
      for (std::uint32_t i = 0; i < obs.size(); ++i) {
        built->by_name.emplace(model::to_upper(obs[i].name), i);
        for (const auto& a : obs[i].aliases) {
          auto& hits = built->by_alias[model::to_upper(a)];
          if (hits.empty() || hits.back() != i) hits.push_back(i);
        }
      }
      lazy.index = std::move(built);
    }
    index = lazy.index.get();  // replaced only when the observables change, not during a look-up
  }
  const std::string key = model::to_upper(name);
  if (const auto it = index->by_name.find(key); it != index->by_name.end()) return it->second;
  const auto it = index->by_alias.find(key);
  if (it != index->by_alias.end() && it->second.size() == 1) return it->second.front();
  if (error) {
    if (it == index->by_alias.end()) {
      // A typo ("s1X" for "S1.X") or a name without its instance path gets the closest
      // observable.
      std::vector<std::string> known;
      known.reserve(obs.size());
      for (const auto& o : obs) known.push_back(o.name);
      *error = "unknown name '" + std::string(name) + "'" + model::did_you_mean(name, known);
    } else {
      *error = "ambiguous name '" + std::string(name) + "': could be";
      for (auto h : it->second) *error += " " + obs[h].name;
    }
  }
  return std::nullopt;
}

}  // namespace sfcv::semantics
