#pragma once
// Internal helpers shared by the symbolic systems: the structural support of an Aig literal and
// the static FORCE variable order of a circuit.

#include <cstdint>
#include <vector>

#include "semantics/aig.hpp"

namespace sfcv::engine {

/// The circuit inputs and latches an Aig literal depends on (structural support); `seen` is
/// per node and is not cleared.
void aig_support(const semantics::Aig& aig, semantics::AigLit root, std::vector<bool>& seen,
                 std::vector<std::uint32_t>& inputs, std::vector<std::uint32_t>& latches);

/// Units in BDD order: latch l is unit l, input i is unit L + i (L latches). `extra_ties` adds
/// groups of units that should sit together (besides each latch and its next function).
std::vector<std::uint32_t> force_order(
    const semantics::Aig& aig, const std::vector<std::vector<std::uint32_t>>& extra_ties = {});

}  // namespace sfcv::engine
