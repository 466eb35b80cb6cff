// Validation of the chart hierarchy: charts held by actions, enclosing steps and macro-step
// expansions, without cycles; chart look-ups by name.

#include <algorithm>
#include <array>
#include <cctype>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "model/detail/validator.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"
#include "model/networks.hpp"

namespace sfcv::model::detail {

void Validator::check_hierarchy() {
  const std::size_t n = pou_->charts.size();
  std::vector<std::vector<Edge>> edges(n);
  for (const auto& as : pou_->associations) {
    const int from = chart_index_of_step(as.chart, as.step);
    const Action* a = pou_->find_action(as.action);
    if (from < 0 || !a || a->kind != ActionBodyKind::Chart) continue;
    if (a->chart < 0 || static_cast<std::size_t>(a->chart) >= n) continue;
    edges[static_cast<std::size_t>(from)].push_back(
        {static_cast<std::size_t>(a->chart), &as.where});
  }
  for (std::size_t c = 0; c < n; ++c)
    for (const auto& s : pou_->charts[c].steps) {
      std::vector<std::string> below;
      if (s.kind == StepKind::MacroStep) below.push_back(s.expansion);
      if (s.kind == StepKind::Enclosing) below = s.enclosed;
      for (const auto& name : below)
        if (const int i = chart_index(name); i >= 0)
          edges[c].push_back({static_cast<std::size_t>(i), &s.where});
    }

  std::vector<int> color(n, 0);  // 0 new, 1 on the DFS path, 2 done
  std::vector<std::size_t> path;
  auto name_of = [&](std::size_t c) {
    const Chart& ch = pou_->charts[c];
    return ch.parent_action.empty() ? quoted(ch.name.empty() ? pou_->name : ch.name)
                                    : quoted(ch.parent_action);
  };
  bool too_deep = false;
  auto dfs = [&](auto&& self, std::size_t c) -> void {
    color[c] = 1;
    path.push_back(c);
    for (const auto& e : edges[c]) {
      if (path.size() >= static_cast<std::size_t>(kMaxNesting) && color[e.to] != 2) {
        // Deeper than any real chart: refused, so that no pass over the hierarchy (this
        // search, the macro-steps' derived activity) recurses or grows with its square.
        if (!too_deep)
          error(at(*e.where, pou_->where),
                "charts nested more than " + std::to_string(kMaxNesting) +
                    " levels deep (macro-steps, enclosing steps or SFC actions inside "
                    "each other, from " +
                    name_of(path.front()) + ")");
        too_deep = true;
        continue;
      }
      if (color[e.to] == 1) {
        std::string cycle;
        auto it = std::find(path.begin(), path.end(), e.to);
        for (; it != path.end(); ++it) cycle += name_of(*it) + " -> ";
        cycle += name_of(e.to);
        error(at(*e.where, pou_->where),
              "hierarchy cycle: " + cycle + " (a chart would contain itself)");
      } else if (color[e.to] == 0) {
        self(self, e.to);
      }
    }
    path.pop_back();
    color[c] = 2;
  };
  for (std::size_t c = 0; c < n; ++c)
    if (color[c] == 0) dfs(dfs, c);
  if (grafcet()) check_activation_links();
}

// IEC 60848: an enclosed partial grafcet enters at its activation-linked steps (`*`) when its
// enclosing step is activated. One without any is read with its initial steps as the entry
// (docs/semantics.md 2.12), which files exported without the mark rely on: said, not silent.
void Validator::check_activation_links() {
  for (const auto& chart : pou_->charts)
    for (const auto& s : chart.steps) {
      if (s.kind != StepKind::Enclosing) continue;
      for (const auto& name : s.enclosed) {
        const Chart* enclosed = find_chart(name);
        if (!enclosed) continue;
        const auto has = [&](bool Step::*mark) {
          return std::any_of(enclosed->steps.begin(), enclosed->steps.end(),
                             [&](const Step& x) { return x.*mark; });
        };
        if (has(&Step::activation_link)) continue;
        warning(s.where,
                "partial grafcet " + quoted(name) + " enclosed by step " + quoted(s.name) +
                    " has no activation-linked step (*): " +
                    (has(&Step::initial) ? "its initial steps are activated with " + quoted(s.name)
                                         : "no step of it is activated with " + quoted(s.name)));
      }
    }
}

int Validator::chart_index(std::string_view name) const {
  const auto it = chart_by_name_.find(to_upper(name));
  return it == chart_by_name_.end() ? -1 : it->second;
}

const Chart* Validator::find_chart(std::string_view name) const {
  const int i = chart_index(name);
  return i < 0 ? nullptr : &pou_->charts[static_cast<std::size_t>(i)];
}

int Validator::chart_index_of_step(const std::string& chart_name, const std::string& step) const {
  if (const int i = chart_index(chart_name); i >= 0) return i;
  if (!chart_name.empty()) return -1;
  for (std::size_t c = 0; c < pou_->charts.size(); ++c)
    if (has_step(pou_->charts[c], step)) return static_cast<int>(c);
  return -1;
}

}  // namespace sfcv::model::detail
