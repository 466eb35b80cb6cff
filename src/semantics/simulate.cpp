#include "semantics/simulate.hpp"

namespace sfcv::semantics {

namespace {
struct Pick : SuccessorSink {
  const std::vector<std::int64_t>* valuation = nullptr;
  bool found = false;
  std::vector<StateWord> target;
  std::vector<std::uint32_t> fired;
  std::string anomaly;
  void successor(const Successor& s) override {
    if (found || (valuation && !s.condition.holds(*valuation))) return;
    found = true;
    target.assign(s.target.begin(), s.target.end());
    fired.assign(s.fired.begin(), s.fired.end());
  }
  void anomaly(const Anomaly& a) override {
    if (anomaly.empty() && valuation && a.condition.holds(*valuation)) anomaly = a.message;
  }
};
}  // namespace

std::vector<StateWord> first_initial_state(const TransitionSystem& ts) {
  Pick p;
  ts.initial_states(p);
  return p.target;
}

SimulationResult simulate(const TransitionSystem& ts, StateView start,
                          const std::vector<std::vector<std::int64_t>>& inputs) {
  SimulationResult r;
  r.states.emplace_back(start.begin(), start.end());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    Pick p;
    p.valuation = &inputs[i];
    ts.successors(r.states.back(), p);
    if (!p.found) {
      r.ok = false;
      r.failed_cycle = i + 1;
      r.error = !p.anomaly.empty() ? p.anomaly : "no successor: the inputs violate an assumption";
      return r;
    }
    r.states.push_back(std::move(p.target));
    r.fired.push_back(std::move(p.fired));
  }
  return r;
}

}  // namespace sfcv::semantics
