// The IEC 61131-3 machine, part 2: one scan cycle. Statements and standard function blocks
// (phase 2), transition firing (phase 3), readiness, qualifiers and timers (phase 4).

#include <algorithm>

#include "semantics/iec_program.hpp"

namespace sfcv::semantics::iec {

using model::Qualifier;
using model::StandardFb;

// ------------------------------------------------------------------------------------ timers

bool Machine::timer_expired(const Timer& t, std::int64_t v) const {
  if (v == 0) return false;
  if (p_.options.time == TimeMode::Abstract) return v == 2;
  return (v - 1) * p_.options.cycle_ms >= t.duration_ms;
}

std::int64_t Machine::timer_next(const Timer& t, bool run, bool restart) {
  const auto v = nxt_[t.field];
  if (!run) return 0;
  if (p_.options.time == TimeMode::Abstract) {
    if (v == 0 || restart) return t.duration_ms <= 0 ? 2 : 1;
    if (v == 2) return 2;
    // Running: the timeout pseudo-input says whether it expires in this cycle.
    std::int64_t timeout = 0;
    const auto in = static_cast<std::uint32_t>(t.timeout_input);
    if (fixed_ || in_lo_[in] == in_hi_[in]) {
      timeout = in_lo_[in];
    } else {
      timeout = decide(in, 2);
      touch(in, timeout, timeout);
    }
    return timeout ? 2 : 1;
  }
  if (v == 0 || restart) return 1;
  return std::min(v + 1, t.max_value);
}

// -------------------------------------------------------------------------------- statements

void Machine::assign(std::uint32_t field, std::int64_t v, const std::string& where) {
  if (v < p_.field_lo[field] || v > p_.field_hi[field])
    throw RangeAbort{"value out of the range of the variable's type", &where};
  nxt_[field] = v;
}

void Machine::exec_block(Block b) {
  for (std::uint32_t i = 0; i < b.count; ++i) exec_stmt(p_.stmts[p_.block_items[b.first + i]]);
}

void Machine::exec_stmt(const Stmt& s) {
  switch (s.op) {
    case SOp::Assign: {
      std::int64_t v = 0;
      try {
        v = eval(s.expr);
      } catch (const RangeAbort& e) {
        throw RangeAbort{e.what, &s.where};
      }
      assign(s.target, v, s.where);
      return;
    }
    case SOp::If:
      for (std::uint32_t i = 0; i < s.arm_count; ++i) {
        const auto& arm = p_.if_arms[s.arm_first + i];
        if (eval(arm.cond)) {
          exec_block(arm.body);
          return;
        }
      }
      exec_block(s.else_body);
      return;
    case SOp::Case: {
      const auto sel = eval(s.expr);
      for (std::uint32_t i = 0; i < s.arm_count; ++i) {
        const auto& arm = p_.case_arms[s.arm_first + i];
        for (std::uint32_t l = 0; l < arm.label_count; ++l) {
          const auto& lab = p_.case_labels[arm.label_first + l];
          if (sel >= lab.lo && sel <= lab.hi) {
            exec_block(arm.body);
            return;
          }
        }
      }
      exec_block(s.else_body);
      return;
    }
    case SOp::FbCall:
      fb_call(s);
      return;
  }
}

void Machine::fb_call(const Stmt& s) {
  const Fb& fb = p_.fbs[s.target];
  auto arg = [&](std::int32_t node) { return node == kNone ? 0 : eval(static_cast<std::uint32_t>(node)); };
  auto field = [](std::int32_t f) { return static_cast<std::uint32_t>(f); };
  const auto q = field(fb.q);
  switch (fb.kind) {
    case StandardFb::R_TRIG: {
      const bool clk = arg(s.arg1) != 0;
      nxt_[q] = clk && !nxt_[field(fb.mem)];
      nxt_[field(fb.mem)] = clk;
      return;
    }
    case StandardFb::F_TRIG: {  // IEC: Q := NOT CLK AND NOT M; M := NOT CLK
      const bool clk = arg(s.arg1) != 0;
      nxt_[q] = !clk && !nxt_[field(fb.mem)];
      nxt_[field(fb.mem)] = !clk;
      return;
    }
    case StandardFb::SR: {  // Q1 := S1 OR (NOT R AND Q1)
      const bool s1 = arg(s.arg1) != 0, r = arg(s.arg2) != 0;
      nxt_[q] = s1 || (!r && nxt_[q]);
      return;
    }
    case StandardFb::RS: {  // Q1 := NOT R1 AND (S OR Q1)
      const bool set = arg(s.arg1) != 0, r1 = arg(s.arg2) != 0;
      nxt_[q] = !r1 && (set || nxt_[q]);
      return;
    }
    case StandardFb::CTU: {
      const bool cu = arg(s.arg1) != 0, r = arg(s.arg2) != 0;
      const auto pv = arg(s.arg3);
      const bool rise = cu && !nxt_[field(fb.mem)];
      nxt_[field(fb.mem)] = cu;
      auto& cv = nxt_[field(fb.cv)];
      if (r) cv = 0;
      else if (rise && cv < p_.field_hi[field(fb.cv)]) ++cv;
      nxt_[q] = cv >= pv;
      return;
    }
    case StandardFb::CTD: {
      const bool cd = arg(s.arg1) != 0, ld = arg(s.arg2) != 0;
      const auto pv = arg(s.arg3);
      const bool rise = cd && !nxt_[field(fb.mem)];
      nxt_[field(fb.mem)] = cd;
      auto& cv = nxt_[field(fb.cv)];
      if (ld) {
        if (pv < p_.field_lo[field(fb.cv)] || pv > p_.field_hi[field(fb.cv)])
          throw RangeAbort{"PV out of the range of CV", &s.where};
        cv = pv;
      } else if (rise && cv > p_.field_lo[field(fb.cv)]) {
        --cv;
      }
      nxt_[q] = cv <= 0;
      return;
    }
    case StandardFb::TON: {
      const bool in = arg(s.arg1) != 0;
      const auto& t = p_.timers[static_cast<std::size_t>(fb.timer)];
      const auto v = timer_next(t, in, false);
      nxt_[t.field] = v;
      nxt_[q] = in && timer_expired(t, v);
      return;
    }
    case StandardFb::TOF: {
      const bool in = arg(s.arg1) != 0;
      const auto& t = p_.timers[static_cast<std::size_t>(fb.timer)];
      if (in) {
        nxt_[t.field] = 0;
        nxt_[q] = 1;
      } else if (nxt_[q] || nxt_[t.field] != 0) {
        const auto v = timer_next(t, true, false);
        nxt_[t.field] = v;
        nxt_[q] = !timer_expired(t, v);
      }
      return;
    }
    case StandardFb::TP: {
      const bool in = arg(s.arg1) != 0;
      const auto& t = p_.timers[static_cast<std::size_t>(fb.timer)];
      const bool last_in = nxt_[field(fb.mem)] != 0;
      nxt_[field(fb.mem)] = in;
      if (nxt_[t.field] == 0) {
        if (in && !last_in) {
          const auto v = timer_next(t, true, true);
          nxt_[t.field] = v;
          nxt_[q] = !timer_expired(t, v);
          if (!nxt_[q] && !in) nxt_[t.field] = 0;
        } else {
          nxt_[q] = 0;
        }
      } else {
        const auto v = timer_next(t, true, false);
        nxt_[t.field] = v;
        const bool done = timer_expired(t, v);
        nxt_[q] = !done;
        if (done && !in) nxt_[t.field] = 0;
      }
      return;
    }
    case StandardFb::None:
      return;
  }
}

// ------------------------------------------------------------------------------------ cycle

bool Machine::run() {
  fixed_ = false;
  for (auto i : touched_) {
    in_lo_[i] = p_.inputs[i].type.lo;
    in_hi_[i] = p_.inputs[i].type.hi;
  }
  touched_.clear();
  pos_ = 0;
  nxt_ = cur_;
  fired_.clear();
  std::fill(consumed_.begin(), consumed_.end(), std::uint8_t{0});
  std::fill(entered_.begin(), entered_.end(), std::uint8_t{0});
  std::fill(left_.begin(), left_.end(), std::uint8_t{0});
  for (auto a : p_.assumptions)
    if (!eval(a)) return false;
  for (const auto& pou : p_.pous) cycle_pou(pou);
  std::sort(fired_.begin(), fired_.end());
  return true;
}

bool Machine::run_fixed(const std::vector<std::int64_t>& valuation) {
  for (std::size_t i = 0; i < valuation.size() && i < in_lo_.size(); ++i)
    in_lo_[i] = in_hi_[i] = valuation[i];
  touched_.clear();
  fixed_ = true;
  pos_ = 0;
  nxt_ = cur_;
  fired_.clear();
  std::fill(consumed_.begin(), consumed_.end(), std::uint8_t{0});
  std::fill(entered_.begin(), entered_.end(), std::uint8_t{0});
  std::fill(left_.begin(), left_.end(), std::uint8_t{0});
  bool ok = true;
  for (auto a : p_.assumptions)
    if (!eval(a)) ok = false;
  if (ok)
    for (const auto& pou : p_.pous) cycle_pou(pou);
  std::sort(fired_.begin(), fired_.end());
  fixed_ = false;
  for (std::size_t i = 0; i < in_lo_.size(); ++i) {
    in_lo_[i] = p_.inputs[i].type.lo;
    in_hi_[i] = p_.inputs[i].type.hi;
  }
  return ok;
}

void Machine::initial(MutableStateView out) {
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
  pack(out);
}

void Machine::cycle_pou(const Pou& pou) {
  // Phase 2: the POU's own body, then the active actions in action order.
  exec_block(pou.body);
  for (auto a : pou.exec_order) {
    const auto& act = p_.actions[a];
    if (act.kind == model::ActionBodyKind::Statements && cur_[act.active]) exec_block(act.body);
  }
  // Phase 3: guards see the new inputs, the current activity, the variables as actions left them.
  for (auto c : pou.charts)
    if (chart_active_cur(c)) fire_chart(p_.charts[c]);
  // Phase 4.
  update_pou(pou);
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
        pick = static_cast<std::uint32_t>(std::min<std::int64_t>(std::max<std::int64_t>(in_lo_[in], 0), m - 1));
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
        case Qualifier::N: act |= sa; break;
        case Qualifier::S: act |= sa; set |= sa; break;
        case Qualifier::R: break;
        case Qualifier::P: case Qualifier::P1: act |= !cur_[st.ready] && nxt_[st.ready]; break;
        case Qualifier::P0: act |= cur_[st.ready] && !nxt_[st.ready]; break;
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
        case Qualifier::DL: break;  // rejected by the compiler
      }
    }
    bool stored = false;
    if (a.stored != kNone) {
      const auto f = static_cast<std::uint32_t>(a.stored);
      stored = (set || cur_[f]) && !reset;
      nxt_[f] = stored;
    }
    const bool active = (act || stored) && !reset;
    nxt_[a.active] = active;
    if (a.variable != kNone) nxt_[static_cast<std::uint32_t>(a.variable)] = active;
  }
  // Step .T: restarts on entry, advances while the step stays active, frozen while suspended.
  for (auto c : pou.charts)
    for (auto s : p_.charts[c].steps) {
      const auto& st = p_.steps[s];
      if (st.t_field == kNone) continue;
      const auto f = static_cast<std::uint32_t>(st.t_field);
      if (!nxt_[st.ready] || entered_[s]) {
        nxt_[f] = 0;
      } else if (step_active_next(s) && step_active_cur(s)) {
        const auto v = cur_[f];
        if (p_.options.time == TimeMode::Discrete) {
          nxt_[f] = std::min(v + 1, st.t_max);
        } else if (v < static_cast<std::int64_t>(st.thresholds.size())) {
          const auto in = static_cast<std::uint32_t>(st.elapse_input);
          const auto top = static_cast<std::int64_t>(st.thresholds.size());
          if (fixed_ || in_lo_[in] == in_hi_[in]) {
            nxt_[f] = std::max(v, std::min(in_lo_[in], top));
          } else {
            const auto alt = decide(in, static_cast<std::uint32_t>(top - v + 1));
            if (alt == 0) touch(in, 0, v);
            else touch(in, v + alt, v + alt);
            nxt_[f] = v + alt;
          }
        }
      }
    }
}

}  // namespace sfcv::semantics::iec
