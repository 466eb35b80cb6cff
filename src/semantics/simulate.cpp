#include "semantics/simulate.hpp"

#include "semantics/detail/iec_system_impl.hpp"

namespace sfcv::semantics {

namespace {
struct Pick : SuccessorSink {
  const std::vector<std::int64_t>* valuation = nullptr;
  bool found = false;
  std::vector<StateWord> target;
  std::vector<std::uint32_t> fired;
  std::string anomaly_message;
  void successor(const Successor& s) override {
    if (found || (valuation && !s.condition.holds(*valuation))) return;
    found = true;
    target.assign(s.target.begin(), s.target.end());
    fired.assign(s.fired.begin(), s.fired.end());
  }
  void anomaly(const Anomaly& a) override {
    if (anomaly_message.empty() && valuation && a.condition.holds(*valuation))
      anomaly_message = a.message;
  }
  const std::vector<std::int64_t>* only_valuation() const override { return valuation; }
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
  // The IEC system follows a full valuation directly: no successor enumeration, so integer
  // inputs of any range work.
  if (const auto* iec = dynamic_cast<const iec::Iec61131System*>(&ts)) {
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      std::vector<StateWord> next;
      std::vector<std::uint32_t> fired;
      std::string error;
      if (!iec->step_once(r.states.back(), inputs[i], next, &fired, &error)) {
        r.ok = false;
        r.failed_cycle = i + 1;
        r.error = error;
        return r;
      }
      r.states.push_back(std::move(next));
      r.fired.push_back(std::move(fired));
    }
    return r;
  }
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    Pick p;
    p.valuation = &inputs[i];
    ts.successors(r.states.back(), p);
    if (!p.found) {
      r.ok = false;
      r.failed_cycle = i + 1;
      r.error = !p.anomaly_message.empty() ? p.anomaly_message
                                           : "no successor: the inputs violate an assumption";
      return r;
    }
    r.states.push_back(std::move(p.target));
    r.fired.push_back(std::move(p.fired));
  }
  return r;
}

SimulationResult simulate_events(const TransitionSystem& ts,
                                 const std::vector<std::vector<std::int64_t>>& inputs,
                                 bool single_input_change, bool assumptions) {
  SimulationResult r;
  if (inputs.empty()) {
    r.ok = false;
    r.failed_cycle = 1;
    r.error = "no row: the first row gives the initial input values";
    return r;
  }
  Pick start;
  start.valuation = &inputs[0];
  ts.initial_states(start);
  if (!start.found) {
    r.ok = false;
    r.failed_cycle = 1;
    r.error = !start.anomaly_message.empty()
                  ? start.anomaly_message
                  : "no initial situation under these inputs (an assumption is violated)";
    return r;
  }
  r.states.push_back(std::move(start.target));
  const auto& declared = ts.inputs();
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    if (single_input_change) {
      std::vector<std::string> changed;
      for (std::size_t k = 0; k < declared.size(); ++k)
        if (!declared[k].pseudo && inputs[i][k] != inputs[i - 1][k])
          changed.push_back(declared[k].name);
      if (changed.size() > 1) {
        r.ok = false;
        r.failed_cycle = i + 1;
        r.error = "inputs " + changed[0] + " and " + changed[1] +
                  " change at once: one event per row under the single-input-change "
                  "hypothesis (--multi-input-change lifts it)";
        return r;
      }
    }
    Pick p;
    p.valuation = &inputs[i];
    ts.successors(r.states.back(), p);
    if (!p.found) {
      if (!p.anomaly_message.empty() || (assumptions && inputs[i] != inputs[i - 1])) {
        r.ok = false;
        r.failed_cycle = i + 1;
        r.error = !p.anomaly_message.empty()
                      ? p.anomaly_message
                      : "no successor: the inputs change nothing or violate an assumption";
        return r;
      }
      r.states.push_back(r.states.back());  // nothing changes: implicit stuttering
      r.fired.emplace_back();
      continue;
    }
    r.states.push_back(std::move(p.target));
    r.fired.push_back(std::move(p.fired));
  }
  return r;
}

}  // namespace sfcv::semantics
