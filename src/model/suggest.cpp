#include "model/suggest.hpp"

#include <algorithm>
#include <cctype>

#include "model/names.hpp"

namespace sfcv::model {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  auto same = [](char x, char y) {
    return std::toupper(static_cast<unsigned char>(x)) ==
           std::toupper(static_cast<unsigned char>(y));
  };
  // Three rows: a transposition looks two rows back.
  std::vector<std::size_t> older(b.size() + 1), prev(b.size() + 1), row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = same(a[i - 1], b[j - 1]) ? 0 : 1;
      row[j] = std::min({prev[j] + 1, row[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
        row[j] = std::min(row[j], older[j - 2] + 1);
    }
    older.swap(prev);
    prev.swap(row);
  }
  return prev[b.size()];
}

std::string closest_name(std::string_view name, const std::vector<std::string>& candidates) {
  if (name.empty()) return {};
  for (const auto& c : candidates) {
    const auto dot = c.rfind('.');
    if (dot != std::string::npos && iequals(std::string_view(c).substr(dot + 1), name)) return c;
  }
  std::string best;
  std::size_t best_distance = 0;
  for (const auto& c : candidates) {
    if (iequals(c, name)) continue;  // the same name is no suggestion
    // A name written without its instance path ("s1X" for "Main.s1.X") is compared with every
    // tail of the candidate after a dot too.
    std::string_view tail = c;
    std::size_t d = edit_distance(name, c);
    for (auto dot = c.find('.'); dot != std::string::npos; dot = c.find('.', dot + 1)) {
      const auto t = std::string_view(c).substr(dot + 1);
      if (const auto dt = edit_distance(name, t); dt < d) {
        d = dt;
        tail = t;
      }
    }
    const std::size_t longer = std::max(name.size(), tail.size());
    if (d > 3 || 3 * d > longer) continue;
    if (best.empty() || d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates) {
  const auto best = closest_name(name, candidates);
  return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

}  // namespace sfcv::model
