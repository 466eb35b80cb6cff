#pragma once
// How the BDD engine changes its variable order (`--reorder none|once|dynamic`).

#include <optional>
#include <string_view>

namespace sfcv::engine {

enum class ReorderMode {
  None,  ///< the static (FORCE) order throughout
  Once,  ///< one sifting pass, right after the transition relation is built
  /// Sifting whenever the live nodes grew past a threshold: first the node table's initial
  /// size (sized from the circuit), then twice the live nodes after the last pass (BuDDy's
  /// rule, as NuSMV's -dynamic); a small chart never sifts.
  Dynamic,
};

/// Passes Dynamic does at most (NuSMV's -dynamic has no cap; a cap keeps a model whose BDDs
/// grow without bound from sifting forever).
inline constexpr int kMaxAutomaticReorderings = 12;
/// Dynamic stops after a pass that shrank the live nodes by less than this many percent.
inline constexpr int kMinReorderGainPercent = 10;

inline std::optional<ReorderMode> parse_reorder_mode(std::string_view text) {
  if (text == "none") return ReorderMode::None;
  if (text == "once") return ReorderMode::Once;
  if (text == "dynamic") return ReorderMode::Dynamic;
  return std::nullopt;
}

inline std::string_view to_string(ReorderMode mode) {
  switch (mode) {
    case ReorderMode::None:
      return "none";
    case ReorderMode::Once:
      return "once";
    case ReorderMode::Dynamic:
      return "dynamic";
  }
  return "none";
}

}  // namespace sfcv::engine
