#include "semantics/history_system.hpp"

#include <algorithm>
#include <stdexcept>

namespace sfcv::semantics {

namespace {

/// `cond` with Boolean input `input` fixed to `value` (false when no cube allows it).
InputCondition restrict(const InputCondition& cond, std::uint32_t input, std::int64_t value) {
  InputCondition out;
  for (const auto& cube : cond.cubes) {
    auto it = std::find_if(cube.literals.begin(), cube.literals.end(),
                           [&](const InputLiteral& l) { return l.input >= input; });
    if (it != cube.literals.end() && it->input == input) {
      if (value < it->lo || value > it->hi) continue;
      InputCube c = cube;
      auto& lit = c.literals[static_cast<std::size_t>(it - cube.literals.begin())];
      lit.lo = lit.hi = value;
      out.cubes.push_back(std::move(c));
    } else {
      InputCube c = cube;
      c.literals.insert(c.literals.begin() + (it - cube.literals.begin()),
                        InputLiteral{input, value, value});
      out.cubes.push_back(std::move(c));
    }
  }
  return out;
}

}  // namespace

/// Turns the base system's successors into the history system's: the base target, then the
/// recorded inputs (one successor per valuation that the condition allows), then the previous
/// values read from the source (an initial state is its own source).
class HistorySink final : public SuccessorSink {
 public:
  HistorySink(const HistorySystem& h, SuccessorSink& out, StateView source, bool initial)
      : h_(h), out_(out), source_(source), initial_(initial) {}

  void successor(const Successor& s) override {
    target_.assign(h_.layout_.words(), 0);
    std::copy(s.target.begin(), s.target.end(), target_.begin());
    const bool split = !(initial_ && h_.kind() == SemanticsKind::Iec61131);
    split_from(s, s.condition, 0, split);
  }
  void anomaly(const Anomaly& a) override { out_.anomaly(a); }
  /// Back to the base source: the history source itself (its recorded values unchanged).
  void returning(const Successor& s) override {
    out_.returning(Successor{source_, s.condition, s.fired, s.entered});
  }

 private:
  void split_from(const Successor& s, const InputCondition& cond, std::size_t k, bool split) {
    const auto& inputs = h_.request_.inputs;
    if (k == inputs.size() || !split) {
      finish(s, cond);
      return;
    }
    for (std::int64_t v = 0; v <= 1; ++v) {
      const auto c = restrict(cond, inputs[k], v);
      if (c.is_false()) continue;
      h_.layout_.set(target_, h_.input_fields_[k], v);
      split_from(s, c, k + 1, split);
    }
  }
  void finish(const Successor& s, const InputCondition& cond) {
    const StateView from = initial_ ? StateView(target_) : source_;
    // In order: entry k may read entry j < k, whose value in `from` is already final (the
    // source's own, or the initial state's just computed).
    for (std::size_t k = 0; k < h_.request_.previous.size(); ++k)
      h_.layout_.set(target_, h_.previous_fields_[k], h_.observe(from, h_.request_.previous[k]));
    out_.successor(Successor{StateView(target_), cond, s.fired, s.entered});
  }

  const HistorySystem& h_;
  SuccessorSink& out_;
  StateView source_;
  bool initial_;
  std::vector<StateWord> target_;
};

HistorySystem::HistorySystem(const TransitionSystem& base, HistoryRequest request)
    : base_(base),
      request_(std::move(request)),
      layout_(base.layout()),
      observables_(base.observables()),
      base_words_(base.layout().words()) {
  layout_.align_to_word();
  for (auto i : request_.inputs) {
    if (i >= base.inputs().size())
      throw std::invalid_argument("HistorySystem: no input " + std::to_string(i));
    const auto& in = base.inputs()[i];
    if (in.type.kind != model::TypeKind::Bool || in.pseudo ||
        base.kind() != SemanticsKind::Iec61131)
      throw std::invalid_argument("HistorySystem: input '" + in.name +
                                  "' cannot be recorded (only Boolean inputs of the IEC 61131-3 "
                                  "scan cycle are)");
    input_fields_.push_back(layout_.add_field("input " + in.name, FieldKind::Variable, 0, 1));
    Observable o;
    o.name = in.name;
    o.kind = ObservableKind::Variable;
    o.type = model::Type::boolean();
    observables_.push_back(std::move(o));
  }
  for (auto j : request_.previous) {
    if (j >= observables_.size())
      throw std::invalid_argument("HistorySystem: prev of an observable not defined before it");
    const Observable of = observables_[j];
    std::int64_t lo = 0, hi = 1;
    if (of.type.kind == model::TypeKind::Int) {
      lo = of.type.lo;
      hi = of.type.hi;
    } else if (of.type.kind != model::TypeKind::Bool) {
      throw std::invalid_argument("HistorySystem: prev(" + of.name +
                                  "): only Boolean and "
                                  "integer observables have a previous value");
    }
    previous_fields_.push_back(layout_.add_field("prev " + of.name, FieldKind::Variable, lo, hi));
    Observable o;
    o.name = "prev(" + of.name + ")";
    for (const auto& a : of.aliases) o.aliases.push_back("prev(" + a + ")");
    o.kind = ObservableKind::Variable;
    o.type = of.type;
    observables_.push_back(std::move(o));
  }
}

std::uint32_t HistorySystem::input_observable(std::size_t k) const {
  return static_cast<std::uint32_t>(base_.observables().size() + k);
}

void HistorySystem::initial_states(SuccessorSink& sink) const {
  HistorySink h(*this, sink, {}, true);
  base_.initial_states(h);
}

void HistorySystem::successors(StateView state, SuccessorSink& sink) const {
  HistorySink h(*this, sink, state, false);
  base_.successors(state.first(base_words_), h);
}

std::int64_t HistorySystem::observe(StateView state, std::uint32_t index) const {
  const auto nb = base_.observables().size();
  if (index < nb) return base_.observe(state.first(base_words_), index);
  const auto k = index - nb;
  if (k < input_fields_.size()) return layout_.get(state, input_fields_[k]);
  return layout_.get(state, previous_fields_[k - input_fields_.size()]);
}

std::string HistorySystem::describe(StateView state) const {
  return base_.describe(state.first(base_words_));
}

std::optional<std::uint32_t> HistorySystem::previous_observable(std::uint32_t index) const {
  const auto first = base_.observables().size() + input_fields_.size();
  for (std::size_t k = 0; k < request_.previous.size(); ++k)
    if (request_.previous[k] == index) return static_cast<std::uint32_t>(first + k);
  return std::nullopt;
}

const HistorySystem* as_history(const TransitionSystem& ts) {
  return dynamic_cast<const HistorySystem*>(&ts);
}

}  // namespace sfcv::semantics
