// The IEC 61131-3 machine, part 3: one scan cycle. Running the POUs and actions (phase 2),
// transition firing (phase 3), readiness, qualifiers and action timers (phase 4).

#include <algorithm>

#include "semantics/detail/iec_program.hpp"

namespace sfcv::semantics::iec {

using model::Qualifier;

// ------------------------------------------------------------------------------------ cycle

bool Machine::run() {
  fixed_ = false;
  if (cur_dirty_ || p_.has_instances) {
    cur_ = loaded_;
    cur_dirty_ = false;
  }
  for (auto i : touched_) {
    in_lo_[i] = p_.inputs[i].type.lo;
    in_hi_[i] = p_.inputs[i].type.hi;
  }
  touched_.clear();
  pos_ = 0;
  nxt_ = cur_;
  advance_clock();
  fired_.clear();
  std::fill(consumed_.begin(), consumed_.end(), std::uint8_t{0});
  std::fill(entered_.begin(), entered_.end(), std::uint8_t{0});
  std::fill(left_.begin(), left_.end(), std::uint8_t{0});
  for (auto a : p_.assumptions)
    if (!eval(a)) return false;
  for (const auto& pou : p_.pous)
    if (!pou.instance) cycle_pou(pou);
  std::sort(fired_.begin(), fired_.end());
  fired_.erase(std::unique(fired_.begin(), fired_.end()), fired_.end());
  return true;
}

bool Machine::run_fixed(const std::vector<std::int64_t>& valuation) {
  for (std::size_t i = 0; i < valuation.size() && i < in_lo_.size(); ++i)
    in_lo_[i] = in_hi_[i] = valuation[i];
  touched_.clear();
  fixed_ = true;
  if (cur_dirty_ || p_.has_instances) {
    cur_ = loaded_;
    cur_dirty_ = false;
  }
  pos_ = 0;
  nxt_ = cur_;
  advance_clock();
  fired_.clear();
  std::fill(consumed_.begin(), consumed_.end(), std::uint8_t{0});
  std::fill(entered_.begin(), entered_.end(), std::uint8_t{0});
  std::fill(left_.begin(), left_.end(), std::uint8_t{0});
  bool ok = true;
  for (auto a : p_.assumptions)
    if (!eval(a)) ok = false;
  if (ok)
    for (const auto& pou : p_.pous)
      if (!pou.instance) cycle_pou(pou);
  std::sort(fired_.begin(), fired_.end());
  fired_.erase(std::unique(fired_.begin(), fired_.end()), fired_.end());
  fixed_ = false;
  for (std::size_t i = 0; i < in_lo_.size(); ++i) {
    in_lo_[i] = p_.inputs[i].type.lo;
    in_hi_[i] = p_.inputs[i].type.hi;
  }
  return ok;
}

void Machine::initial(MutableStateView out) {
  initial_configuration();
  pack(out);
}

void Machine::initial_configuration() {
  // The initial configuration is phase 4 applied to "nothing ready yet" with the top-level
  // initial steps entered: their P1 and N actions are active from the start. Nested charts'
  // initial steps are ready as history (no P1).
  cur_ = p_.initial;
  for (const auto& s : p_.steps)
    if (s.initial && p_.charts[s.chart].parent_action != kNone) cur_[s.ready] = 1;
  nxt_ = cur_;
  fired_.clear();
  std::fill(entered_.begin(), entered_.end(), std::uint8_t{0});
  std::fill(left_.begin(), left_.end(), std::uint8_t{0});
  for (std::uint32_t i = 0; i < p_.steps.size(); ++i)
    if (p_.steps[i].initial && p_.charts[p_.steps[i].chart].parent_action == kNone) entered_[i] = 1;
  fixed_ = true;  // no input is read: every timer starts from idle
  for (const auto& pou : p_.pous) update_pou(pou);
  fixed_ = false;
  cur_dirty_ = false;
}

bool Machine::sfc_flags(const Pou& pou) {
  // CODESYS reads its implicit flags when the chart's code starts, after the POU's own body:
  // a write by the body or by the caller counts this cycle, one by an action the next.
  const bool init = pou.sfc_init != kNone && eval(static_cast<std::uint32_t>(pou.sfc_init));
  const bool reset =
      init || (pou.sfc_reset != kNone && eval(static_cast<std::uint32_t>(pou.sfc_reset)));
  if (!reset) return false;
  for (auto f : pou.chart_fields) cur_[f] = nxt_[f] = reset_values_[f];
  cur_dirty_ = true;
  // A reset chart ages as a program's does in its reset cycle: its steps count as active since
  // the last cycle (the clock aged the old situation, which the reset discarded).
  if (!init && p_.options.time == TimeMode::Discrete)
    for (auto c : pou.charts)
      for (auto s : p_.charts[c].steps)
        if (p_.steps[s].clocked && p_.steps[s].t_field != kNone) age_step(s);
  return init;
}

void Machine::cycle_pou(const Pou& pou) {
  // Phase 2: the POU's own body, then the active actions in action order.
  exec_block(pou.body);
  // SFCInit/SFCReset: the charts restart from their initial situation; under SFCInit they stay
  // there, running no action.
  if ((pou.sfc_init != kNone || pou.sfc_reset != kNone) && sfc_flags(pou)) return;
  // The vendor dialects' first pass: the IEC actions that stopped being active run once more.
  for (auto a : pou.exec_order) {
    const auto& act = p_.actions[a];
    if (act.final_call != kNone && cur_[static_cast<std::uint32_t>(act.final_call)])
      exec_block(act.body);
  }
  if (pou.order_groups.empty()) {
    for (auto a : pou.exec_order) {
      const auto& act = p_.actions[a];
      if (act.kind == model::ActionBodyKind::Statements && cur_[act.active]) exec_block(act.body);
    }
  } else {
    run_ordered_actions(pou);
  }
  // Phase 3: guards see the new inputs, the current activity, the variables as actions left them.
  for (auto c : pou.charts)
    if (chart_active_cur(c)) fire_chart(p_.charts[c]);
  // Phase 4.
  update_pou(pou);
}

std::uint32_t Machine::order_of(const OrderGroup& g) {
  // The order matters only when two members run: otherwise the choice input stays free.
  int running = 0;
  for (auto a : g.members)
    if (cur_[p_.actions[a].active]) ++running;
  if (running < 2) return 0;
  const auto last = static_cast<std::int64_t>(g.orders.size()) - 1;
  return static_cast<std::uint32_t>(std::clamp<std::int64_t>(read_input(g.choice_input), 0, last));
}

void Machine::run_ordered_actions(const Pou& pou) {
  // Each group's order is chosen once per run of the POU, at its first slot.
  std::vector<std::uint32_t> chosen(pou.order_groups.size(), 0);
  for (std::size_t i = 0; i < pou.exec_order.size(); ++i) {
    auto a = pou.exec_order[i];
    if (const auto gi = pou.exec_group[i]; gi != kNone) {
      const auto& g = pou.order_groups[static_cast<std::size_t>(gi)];
      const auto slot = static_cast<std::size_t>(pou.exec_slot[i]);
      if (slot == 0) chosen[static_cast<std::size_t>(gi)] = order_of(g);
      a = g.orders[chosen[static_cast<std::size_t>(gi)]][slot];
    }
    const auto& act = p_.actions[a];
    if (act.kind == model::ActionBodyKind::Statements && cur_[act.active]) exec_block(act.body);
  }
}

void Machine::call_instance(const Pou& pou) {
  // One cycle of a user function block instance, as the cycle runs a program; then its chart
  // state is committed, so that a second call evolves from where this one left it.
  cycle_pou(pou);
  for (auto f : pou.commit) cur_[f] = nxt_[f];
  for (auto c : pou.charts)
    for (auto s : p_.charts[c].steps) consumed_[s] = entered_[s] = left_[s] = 0;
}

void Machine::fire(const Transition& t) {
  for (auto s : t.sources) consumed_[s] = left_[s] = 1;
  for (auto s : t.targets) entered_[s] = 1;
  fired_.push_back(t.index);
}

void Machine::fire_chart(const Chart& c) {
  auto can_fire = [&](const Transition& t) {
    for (auto s : t.sources)
      if (consumed_[s] || !step_active_cur(s)) return false;
    return true;
  };
  if (p_.options.priority == PriorityMode::Standard) {
    for (auto ti : c.ordered) {
      const auto& t = p_.transitions[ti];
      if (can_fire(t) && eval(t.guard)) fire(t);
    }
    return;
  }
  for (const auto& g : c.groups) {
    if (!step_active_cur(g.step)) continue;
    enabled_scratch_.clear();
    for (auto ti : g.transitions)
      if (eval(p_.transitions[ti].guard)) enabled_scratch_.push_back(ti);
    if (enabled_scratch_.empty()) continue;
    std::uint32_t pick = 0;
    const auto m = static_cast<std::uint32_t>(enabled_scratch_.size());
    if (m > 1) {
      const auto in = g.choice_input;
      if (fixed_ || in_lo_[in] == in_hi_[in]) {
        pick = static_cast<std::uint32_t>(
            std::min<std::int64_t>(std::max<std::int64_t>(in_lo_[in], 0), m - 1));
      } else {
        pick = decide(in, m);
        touch(in, pick, pick + 1 == m ? p_.inputs[in].type.hi : pick);
      }
    }
    fire(p_.transitions[enabled_scratch_[pick]]);
  }
  for (auto ti : c.singles) {
    const auto& t = p_.transitions[ti];
    if (can_fire(t) && eval(t.guard)) fire(t);
  }
}

void Machine::update_pou(const Pou& pou) {
  // New readiness: sources of fired transitions leave, targets enter.
  for (auto c : pou.charts)
    for (auto s : p_.charts[c].steps) {
      const auto& st = p_.steps[s];
      nxt_[st.ready] = (cur_[st.ready] && !left_[s]) || entered_[s];
    }
  // Actions, parents before the actions of the charts they hold.
  for (auto ai : pou.topo_order) {
    const auto& a = p_.actions[ai];
    bool reset = false;
    for (auto x : a.assocs)
      if (p_.assocs[x].q == Qualifier::R && step_active_next(p_.assocs[x].step)) reset = true;
    bool act = false, set = false;
    for (auto x : a.assocs) {
      const auto& as = p_.assocs[x];
      const auto& st = p_.steps[as.step];
      const bool sa = step_active_next(as.step);
      const Timer* t = as.timer == kNone ? nullptr : &p_.timers[static_cast<std::size_t>(as.timer)];
      switch (as.q) {
        case Qualifier::N:
          act |= sa;
          break;
        case Qualifier::S:
          act |= sa;
          set |= sa;
          break;
        case Qualifier::R:
          break;
        case Qualifier::P:
        case Qualifier::P1:
          act |= !cur_[st.ready] && nxt_[st.ready];
          break;
        case Qualifier::P0:
          act |= cur_[st.ready] && !nxt_[st.ready];
          break;
        case Qualifier::L: {
          const auto v = timer_next(*t, sa, entered_[as.step]);
          nxt_[t->field] = v;
          act |= sa && !timer_expired(*t, v);
          break;
        }
        case Qualifier::D: {
          const auto v = timer_next(*t, sa, entered_[as.step]);
          nxt_[t->field] = v;
          act |= sa && timer_expired(*t, v);
          break;
        }
        case Qualifier::DS: {
          const auto v = timer_next(*t, sa, entered_[as.step]);
          nxt_[t->field] = v;
          set |= sa && timer_expired(*t, v);
          act |= sa && timer_expired(*t, v);
          break;
        }
        case Qualifier::SD: {
          const auto latch = static_cast<std::uint32_t>(as.latch);
          const bool l = (cur_[latch] || sa) && !reset;
          nxt_[latch] = l;
          const auto v = timer_next(*t, l, false);
          nxt_[t->field] = v;
          act |= l && timer_expired(*t, v);
          break;
        }
        case Qualifier::SL: {
          const auto latch = static_cast<std::uint32_t>(as.latch);
          const bool rising = sa && (!step_active_cur(as.step) || entered_[as.step]);
          const bool expired_before = timer_expired(*t, cur_[t->field]);
          const bool l = ((cur_[latch] && !expired_before) || rising) && !reset;
          nxt_[latch] = l;
          const auto v = timer_next(*t, l, rising);
          nxt_[t->field] = v;
          act |= l && !timer_expired(*t, v);
          break;
        }
        case Qualifier::DL:
          break;  // rejected by the compiler
      }
    }
    bool stored = false;
    if (a.stored != kNone) {
      const auto f = static_cast<std::uint32_t>(a.stored);
      stored = (set || cur_[f]) && !reset;
      nxt_[f] = stored;
    }
    const bool active = (act || stored) && !reset;
    if (a.final_call != kNone)
      nxt_[static_cast<std::uint32_t>(a.final_call)] = cur_[a.active] && !active;
    // The vendors write a Boolean action's variable when it runs (TRUE) and at its final call
    // (FALSE) only: an action that stays inactive leaves it to other writers (1.4a).
    if (a.variable != kNone && (!p_.vendor_final_calls() || active || cur_[a.active]))
      nxt_[static_cast<std::uint32_t>(a.variable)] = active;
    nxt_[a.active] = active;
  }
  // Step .T: restarts on entry, advances while the step stays active, frozen while suspended.
  for (auto c : pou.charts)
    for (auto s : p_.charts[c].steps) {
      const auto& st = p_.steps[s];
      if (st.t_field == kNone) continue;
      const auto f = static_cast<std::uint32_t>(st.t_field);
      if (!nxt_[st.ready] || entered_[s]) {
        nxt_[f] = 0;
        if (entered_[s]) step_started_[s] = 1;
      } else if (step_active_next(s) && step_active_cur(s)) {
        const auto v = cur_[f];
        if (st.clocked) {
          // An instance's step: the clock aged .T (discrete), or the step was entered at an
          // earlier call of this cycle (abstract): no time has passed since.
          if (p_.options.time == TimeMode::Discrete || step_started_[s]) continue;
        }
        if (p_.options.time == TimeMode::Discrete) {
          nxt_[f] = std::min(v + 1, st.t_max);
        } else if (v < static_cast<std::int64_t>(st.thresholds.size())) {
          const auto in = static_cast<std::uint32_t>(st.elapse_input);
          const auto top = static_cast<std::int64_t>(st.thresholds.size());
          if (fixed_ || in_lo_[in] == in_hi_[in]) {
            nxt_[f] = std::max(v, std::min(in_lo_[in], top));
          } else {
            const auto alt = decide(in, static_cast<std::uint32_t>(top - v + 1));
            if (alt == 0)
              touch(in, 0, v);
            else
              touch(in, v + alt, v + alt);
            nxt_[f] = v + alt;
          }
        }
      } else if (st.clocked) {
        nxt_[f] = cur_[f];  // suspended: frozen, the clock's aging undone
      }
    }
}

}  // namespace sfcv::semantics::iec
