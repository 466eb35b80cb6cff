#pragma once
// Exports of a transition system's circuit (semantics::Aig) to the input languages of outside
// checkers: NuSMV 2.6, Cadence SMV and Promela (Spin). All three are printed from the same
// circuit as the AIGER export and the BDD engine, so they mean exactly what sfcv means.

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "semantics/aig.hpp"

namespace sfcv::engine {

struct CircuitExport {
  semantics::Aig aig;
  std::vector<std::string> header;          ///< comment lines: source, semantics, options
  std::vector<std::string> latch_comments;  ///< per latch: what it is in the chart
  std::vector<std::string> input_comments;  ///< per input
  /// CTL properties (NuSMV/Cadence SMV only): name and formula in NuSMV syntax, where `{k}`
  /// stands for circuit output k, aig.outputs()[k] (a step, an action, a variable): an index,
  /// never a name, so that a name cannot add to the formula.
  std::vector<std::pair<std::string, std::string>> ctl;
  /// LTL properties (Promela only): name and claim in Spin's LTL syntax, where `{k}` stands for
  /// the state literal ltl_atoms[k] and `{b}` for "the process is at the start of a cycle"
  /// (the only states Spin's claim reads: export_model.cpp, ltl_claim).
  std::vector<std::pair<std::string, std::string>> ltl;
  std::vector<semantics::AigLit> ltl_atoms;
};

/// Identifiers in all three languages: in_<input>, s_<latch>, g_<gate node>, o_<output>,
/// p_<property>, a_<assumption>; a prefix per kind keeps them unique by construction. Chart
/// names appear only in comments, through comment_text() (engine/external/identifiers.hpp).

/// NuSMV 2.6: inputs as IVAR, latches as VAR with init/next, gates and outputs as DEFINE,
/// assumptions as TRANS, invariants (the Aig bad literals) as INVARSPEC, CTL as CTLSPEC.
void write_nusmv(std::ostream& out, const CircuitExport& model);

/// The NuSMV identifier of each circuit input (aig.inputs() order), as write_nusmv declares it
/// (to read NuSMV's traces back).
std::vector<std::string> nusmv_input_identifiers(const CircuitExport& model);

/// Cadence SMV, in the seed's `default next(x) := x in case { set : ...; reset : ...; }` form.
void write_casmv(std::ostream& out, const CircuitExport& model);

/// Promela: one process running the cycle (inputs chosen nondeterministically, the circuit
/// evaluated in a d_step), invariants as assertions, LTL properties as `ltl sfcv_ltl_<k>`
/// claims (select one with `pan -a -N sfcv_ltl_<k>`). With `only_bad`, only that invariant is
/// asserted (a violated assertion ends Spin's search). Each cycle prints its inputs so that a
/// Spin trail can be mapped back (`@cycle name=value ...`).
void write_promela(std::ostream& out, const CircuitExport& model,
                   std::optional<std::size_t> only_bad = std::nullopt);

}  // namespace sfcv::engine
