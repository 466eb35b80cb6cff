#pragma once
// SFC networks: the connected parts of a chart. IEC 61131-3 lets an SFC body hold several
// networks, each with its own initial step; `sfcv info` reports them and `validate` uses them.

#include <cstddef>
#include <vector>

#include "model/chart.hpp"

namespace sfcv::model {

/// For each step of `chart` (by index), the index of its network (0, 1, ... in step order).
/// Transitions join their declared source and target steps; undeclared names are ignored.
std::vector<int> step_networks(const Chart& chart);

/// The number of networks of `chart` (0 for a chart without steps).
std::size_t count_networks(const Chart& chart);

}  // namespace sfcv::model
