#pragma once
// Observer circuits that turn questions beyond plain reachability into one target of the
// circuit the SAT engines unroll (docs/engines.md): the states without a successor, and the
// bounded response AG (p -> W_n(s)) of the `response(P, S, within N cycles)` pattern.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "semantics/aig.hpp"

namespace sfcv::engine::sat {

/// "No input valuation allows a step": `step_ok` with every input of its cone universally
/// quantified (Shannon expansion), a literal over latches. nullopt when the expansion adds more
/// than `max_new_ands` AND nodes (too many inputs decide whether a step exists).
std::optional<semantics::AigLit> no_successor(semantics::Aig& aig, semantics::AigLit step_ok,
                                              std::size_t max_new_ands = 200000);

/// "Some input valuation makes one of `lits` true": each literal with the inputs of its cone
/// existentially quantified (Shannon expansion), then their disjunction, a literal over
/// latches. nullopt when the expansions add more than `max_new_ands` AND nodes in all.
std::optional<semantics::AigLit> some_input_satisfies(semantics::Aig& aig,
                                                      const std::vector<semantics::AigLit>& lits,
                                                      std::size_t max_new_ands = 200000);

/// `root` one cycle later: every latch of its cone replaced by its next-state function (whose
/// inputs are this cycle's). nullopt when that adds more than `max_new_ands` AND nodes.
std::optional<semantics::AigLit> at_next_cycle(semantics::Aig& aig, semantics::AigLit root,
                                               std::size_t max_new_ands = 200000);

/// The target of the violations of AG (p -> W_n) with W_0 = s and
/// W_k = s | (EX TRUE & AX W_{k-1}), n >= 1, over latches `p` and `s` and the deadlock literal
/// `dead` (no_successor). Adds the observer's latches to `aig`: a flag "an obligation of p is
/// pending (s not yet seen)" and a saturating counter of the cycles since its oldest p, both
/// FALSE/0 initially (no cycle has run before the initial state). The target holds in a state
/// where an obligation is pending and either n cycles have passed or the state has no successor:
/// exactly the states some run from a p-state reaches without s on the way, as CTL reads it.
semantics::AigLit bounded_response_target(semantics::Aig& aig, semantics::AigLit p,
                                          semantics::AigLit s, std::uint32_t n,
                                          semantics::AigLit dead, const std::string& name);

}  // namespace sfcv::engine::sat
