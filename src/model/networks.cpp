#include "model/networks.hpp"

#include <numeric>
#include <string>
#include <unordered_map>

#include "model/names.hpp"

namespace sfcv::model {

namespace {
int find_root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) {
    auto& p = parent[static_cast<std::size_t>(i)];
    p = parent[static_cast<std::size_t>(p)];  // path halving
    i = p;
  }
  return i;
}
}  // namespace

std::vector<int> step_networks(const Chart& chart) {
  const std::size_t n = chart.steps.size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  // Indexed once: a linear Chart::step_index per transition is quadratic on long charts.
  std::unordered_map<std::string, int> index;
  for (std::size_t i = 0; i < n; ++i)
    index.try_emplace(to_upper(chart.steps[i].name), static_cast<int>(i));
  for (const auto& t : chart.transitions) {
    int first = -1;
    auto join = [&](const std::string& name) {
      const auto found = index.find(to_upper(name));
      if (found == index.end()) return;
      const int i = found->second;
      if (first < 0) {
        first = i;
        return;
      }
      parent[static_cast<std::size_t>(find_root(parent, i))] = find_root(parent, first);
    };
    for (const auto& s : t.sources) join(s);
    for (const auto& s : t.targets) join(s);
  }
  // Renumber roots densely, in step order.
  std::vector<int> id_of_root(n, -1), result(n, 0);
  int next = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(find_root(parent, static_cast<int>(i)));
    if (id_of_root[r] < 0) id_of_root[r] = next++;
    result[i] = id_of_root[r];
  }
  return result;
}

std::size_t count_networks(const Chart& chart) {
  int most = -1;
  for (int id : step_networks(chart)) most = id > most ? id : most;
  return static_cast<std::size_t>(most + 1);
}

}  // namespace sfcv::model
