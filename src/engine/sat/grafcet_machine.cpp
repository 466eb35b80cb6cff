#include "engine/sat/grafcet_machine.hpp"

#include <limits>

namespace sfcv::engine::sat {

using semantics::Aig;
using semantics::AigLit;

namespace {
constexpr AigLit kUnset = std::numeric_limits<AigLit>::max();
}

GrafcetMachine::GrafcetMachine(const semantics::GrafcetCircuit& circuit) : circuit_(circuit) {
  const Aig& c = circuit_.aig;
  const std::size_t n = circuit_.num_state_latches;
  std::vector<AigLit> inputs, state, prev, kept;
  for (const auto& in : c.inputs()) inputs.push_back(aig_.add_input(in.name));
  for (std::size_t l = 0; l < n; ++l)
    state.push_back(aig_.add_latch(c.latches()[l].name, c.latches()[l].initial));
  for (std::size_t k = 0; k < circuit_.prev_of.size(); ++k)
    prev.push_back(aig_.add_latch(c.latches()[n + k].name));
  std::vector<AigLit> input_as_kept = inputs;  // evolutions read the event's kept inputs
  for (auto i : circuit_.kept_inputs) {
    kept.push_back(aig_.add_latch("event " + c.inputs()[i].name));
    input_as_kept[i] = kept.back();
  }
  const auto boot_latch = boot_latch_ = static_cast<std::uint32_t>(aig_.latches().size());
  boot_ = aig_.add_latch("boot", true);
  const auto stable_latch = stable_latch_ = static_cast<std::uint32_t>(aig_.latches().size());
  const AigLit stable_bit = aig_.add_latch("stable", false);
  stable_ = aig_.make_and(Aig::make_not(boot_), stable_bit);
  transient_ = aig_.make_and(Aig::make_not(boot_), Aig::make_not(stable_bit));

  // Translation memos: circuit latches and inputs are the substitution; AND nodes follow.
  auto seed = [&](std::vector<AigLit>& memo, const std::vector<AigLit>& ins) {
    memo.assign(c.nodes().size(), kUnset);
    memo[0] = Aig::kFalse;
    for (std::size_t l = 0; l < c.latches().size(); ++l)
      memo[Aig::node_of(c.latches()[l].current)] = l < n ? state[l] : prev[l - n];
    for (std::size_t i = 0; i < c.inputs().size(); ++i)
      memo[Aig::node_of(c.inputs()[i].literal)] = ins[i];
  };
  seed(on_n_, input_as_kept);
  seed(on_source_, inputs);
  seed(on_boot_, inputs);

  const AigLit error = translate(circuit_.range_error, on_n_);
  const AigLit settled = translate(circuit_.stable, on_n_);
  std::vector<AigLit> boot_next(n);
  for (std::size_t l = 0; l < n; ++l) {
    boot_next[l] = translate(circuit_.initial_next[l], on_boot_);
    const AigLit evolve = aig_.make_ite(settled, translate(circuit_.final_next[l], on_n_),
                                        translate(c.latches()[l].next, on_n_));
    const AigLit start = translate(circuit_.start_next[l], on_source_);
    aig_.set_next(static_cast<std::uint32_t>(l),
                  aig_.make_ite(boot_, boot_next[l], aig_.make_ite(stable_, start, evolve)));
  }
  for (std::size_t k = 0; k < prev.size(); ++k)
    aig_.set_next(static_cast<std::uint32_t>(n + k),
                  aig_.make_ite(boot_, boot_next[circuit_.prev_of[k]], state[circuit_.prev_of[k]]));
  for (std::size_t j = 0; j < kept.size(); ++j)
    aig_.set_next(static_cast<std::uint32_t>(n + prev.size() + j),
                  aig_.make_ite(transient_, kept[j], inputs[circuit_.kept_inputs[j]]));
  aig_.set_next(boot_latch, Aig::kFalse);
  aig_.set_next(stable_latch, aig_.make_and(transient_, settled));

  const AigLit event =
      aig_.make_and(translate(circuit_.event, on_source_), translate(circuit_.valid, on_source_));
  step_ok_ = aig_.make_ite(boot_, translate(circuit_.initial_event, on_boot_),
                           aig_.make_ite(stable_, event, Aig::make_not(error)));
  for (auto f : circuit_.fired) fired_.push_back(translate(f, on_n_));
  anomaly_ = aig_.make_and(transient_, error);
  configuration_latches_ = n + prev.size();
}

AigLit GrafcetMachine::at_repeated_transient() {
  if (repeated_ != 0) return repeated_;
  const AigLit save = aig_.add_input("keep this configuration");
  const auto armed_latch = static_cast<std::uint32_t>(aig_.latches().size());
  const AigLit armed = aig_.add_latch("a configuration is kept", false);
  // Armed from the micro-step after the chosen one to the end of the event (a stable
  // situation disarms it), so a match is a later micro-step of the same event.
  aig_.set_next(armed_latch, aig_.make_and(transient_, aig_.make_or(armed, save)));
  std::vector<AigLit> same{armed, transient_};
  for (std::size_t l = 0; l < configuration_latches_; ++l) {
    const AigLit now = aig_.latches()[l].current;
    const auto shadow_latch = static_cast<std::uint32_t>(aig_.latches().size());
    const AigLit shadow = aig_.add_latch("kept " + aig_.latches()[l].name, false);
    aig_.set_next(shadow_latch, aig_.make_ite(armed, shadow, now));
    same.push_back(aig_.make_xnor(shadow, now));
  }
  repeated_ = aig_.make_and(same);
  return repeated_;
}

AigLit GrafcetMachine::seen_during_event(AigLit lit, std::string name, bool also_stable) {
  const auto latch = static_cast<std::uint32_t>(aig_.latches().size());
  const AigLit seen = aig_.add_latch(std::move(name), false);
  observers_.push_back(latch);
  const AigLit now = aig_.make_and(transient_, lit);
  aig_.set_next(latch, aig_.make_and(Aig::make_not(stable_), aig_.make_or(seen, now)));
  return aig_.make_and(stable_, also_stable ? aig_.make_or(seen, lit) : seen);
}

AigLit GrafcetMachine::held_at_event_source(AigLit lit, std::string name) {
  const auto latch = static_cast<std::uint32_t>(aig_.latches().size());
  const AigLit held = aig_.add_latch(std::move(name), false);
  aig_.set_next(latch, aig_.make_ite(stable_, lit, held));
  return held;
}

AigLit GrafcetMachine::at_initial_stable() {
  if (initial_stable_ != 0) return initial_stable_;
  const auto latch = static_cast<std::uint32_t>(aig_.latches().size());
  const AigLit left = aig_.add_latch("left the initial situation", false);
  aig_.set_next(latch, aig_.make_or(left, stable_));
  initial_stable_ = aig_.make_and(stable_, Aig::make_not(left));
  return initial_stable_;
}

AigLit GrafcetMachine::in_stable_situation(AigLit circuit_lit) {
  return aig_.make_and(stable_, translate(circuit_lit, on_n_));
}

AigLit GrafcetMachine::translate(AigLit lit, std::vector<AigLit>& memo) {
  const Aig& c = circuit_.aig;
  if (memo.size() < c.nodes().size()) memo.resize(c.nodes().size(), kUnset);
  // Iterative post-order: arithmetic cones are deep.
  std::vector<std::uint32_t> stack{Aig::node_of(lit)};
  while (!stack.empty()) {
    const auto id = stack.back();
    if (memo[id] != kUnset) {
      stack.pop_back();
      continue;
    }
    const auto& node = c.nodes()[id];
    const AigLit a = memo[Aig::node_of(node.left)], b = memo[Aig::node_of(node.right)];
    if (a == kUnset || b == kUnset) {
      if (a == kUnset) stack.push_back(Aig::node_of(node.left));
      if (b == kUnset) stack.push_back(Aig::node_of(node.right));
      continue;
    }
    memo[id] = aig_.make_and(a ^ (node.left & 1U), b ^ (node.right & 1U));
    stack.pop_back();
  }
  return memo[Aig::node_of(lit)] ^ (lit & 1U);
}

}  // namespace sfcv::engine::sat
