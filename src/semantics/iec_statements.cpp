// The IEC 61131-3 machine, part 2: timers, ST statements and the standard function blocks
// (phase 2 of a cycle).

#include <algorithm>
#include <string>
#include <vector>

#include "model/errors.hpp"
#include "semantics/detail/iec_program.hpp"

namespace sfcv::semantics::iec {

using model::StandardFb;

// ------------------------------------------------------------------------------------ timers

bool Machine::timer_expired(const Timer& t, std::int64_t v) const {
  if (v == 0) return false;
  if (p_.options.time == TimeMode::Abstract) return v == 2;
  return (v - 1) * p_.options.cycle_ms >= t.duration_ms;
}

void Machine::advance_clock() {
  if (p_.options.time == TimeMode::Abstract) {
    std::fill(started_.begin(), started_.end(), std::uint8_t{0});
    std::fill(step_started_.begin(), step_started_.end(), std::uint8_t{0});
    return;
  }
  // So does a step of an instance: .T is the time since the step's activation.
  for (auto s : clocked_steps_) age_step(s);
  // ET is the time since the start, whether or not the instance is called in between: the
  // cycle ages every running instance, saturating where its expiry no longer changes.
  for (auto i : clocked_) {
    const auto& t = p_.timers[i];
    if (const auto v = cur_[t.field]; v != 0) nxt_[t.field] = std::min(v + 1, t.max_value);
  }
}

void Machine::age_step(std::uint32_t step) {
  const auto& st = p_.steps[step];
  const auto f = static_cast<std::uint32_t>(st.t_field);
  if (step_active_cur(step)) nxt_[f] = std::min(cur_[f] + 1, st.t_max);
}

std::int64_t Machine::timer_next(const Timer& t, bool run, bool restart) {
  const auto v = nxt_[t.field];
  if (!run) return 0;
  const auto index = static_cast<std::size_t>(&t - p_.timers.data());
  if (p_.options.time == TimeMode::Abstract) {
    if (v == 0 || restart) {
      started_[index] = 1;
      return t.duration_ms <= 0 ? 2 : 1;
    }
    if (v == 2) return 2;
    // Started in this cycle (a second call): no time has passed yet.
    if (t.clocked && started_[index]) return 1;
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
  // A clocked timer's field already holds this cycle's age (advance_clock); a qualifier's
  // timer is aged here, by the one update of its step per cycle.
  return t.clocked ? v : std::min(v + 1, t.max_value);
}

// -------------------------------------------------------------------------------- statements

void Machine::assign(std::uint32_t field, std::int64_t v, const std::string& where) {
  if (v < p_.field_lo[field] || v > p_.field_hi[field])
    throw RangeAbort{"value out of the range of the variable's type", &where};
  nxt_[field] = v;
}

std::int64_t Machine::call_function(const Node& n, const std::uint32_t* kid) {
  // The arguments first (one may call this function too), then the body on fresh variables.
  const Function& fn = p_.functions[n.a];
  std::vector<std::int64_t> args(n.count);
  for (std::uint32_t i = 0; i < n.count; ++i) args[i] = eval(kid[i]);
  for (auto f : fn.fields) nxt_[f] = p_.initial[f];
  for (std::uint32_t i = 0; i < n.count; ++i) assign(fn.inputs[i], args[i], fn.where);
  exec_block(fn.body);  // RETURN only ends the body
  const auto result = nxt_[fn.result];
  if (n.k > 0)
    for (const auto& [from, to] : p_.call_output_copies[static_cast<std::size_t>(n.k - 1)])
      assign(to, nxt_[from], fn.where);
  for (auto f : fn.fields) nxt_[f] = p_.initial[f];
  return result;
}

Flow Machine::exec_block(Block b) {
  for (std::uint32_t i = 0; i < b.count; ++i)
    if (const auto f = exec_stmt(p_.stmts[p_.block_items[b.first + i]]); f != Flow::Normal)
      return f;
  return Flow::Normal;
}

Flow Machine::exec_loop(const Stmt& s) {
  if (const auto f = exec_block(s.init); f != Flow::Normal) return f;
  // Within a cycle the inputs are fixed, so an iteration depends only on the variables: when
  // they repeat at the start of an iteration the loop never ends (a range error, as a PLC's
  // watchdog). Checked against snapshots taken at iterations 64, 128, 256, 512 (Brent), so
  // short loops pay nothing. A loop that reaches the bound without repeating might still end:
  // the bound is a limit of sfcv, unknown, not a finding.
  std::vector<std::int64_t> mark;
  std::int64_t mark_at = 64;
  for (std::int64_t n = 0;; ++n) {
    if (!s.test_after && !eval(s.expr)) return Flow::Normal;
    if (n >= 64) {
      if (n == mark_at) {
        mark = nxt_;
        mark_at *= 2;
      } else if (nxt_ == mark) {
        throw RangeAbort{"loop never ends (its variables repeat)", &s.where};
      }
    }
    if (n == kMaxLoopIterations)
      throw LimitReached(Limit::Enumeration,
                         "a loop at " + s.where + " ran " + std::to_string(kMaxLoopIterations) +
                             " iterations (the bound kMaxLoopIterations) without ending or "
                             "repeating its variables: it may still end, the verdict is unknown");
    const auto f = exec_block(s.body);
    if (f == Flow::Return) return f;
    if (f == Flow::Exit) return Flow::Normal;
    exec_block(s.step);
    if (s.test_after && eval(s.expr)) return Flow::Normal;
  }
}

Flow Machine::exec_stmt(const Stmt& s) {
  switch (s.op) {
    case SOp::Assign: {
      std::int64_t v = 0;
      try {
        v = eval(s.expr);
      } catch (const RangeAbort& e) {
        throw RangeAbort{e.what, &s.where};
      }
      assign(s.target, v, s.where);
      return Flow::Normal;
    }
    case SOp::Eval:
      try {
        eval(s.expr);
      } catch (const RangeAbort& e) {
        throw RangeAbort{e.what, &s.where};
      }
      return Flow::Normal;
    case SOp::If:
      for (std::uint32_t i = 0; i < s.arm_count; ++i) {
        const auto& arm = p_.if_arms[s.arm_first + i];
        if (eval(arm.cond)) return exec_block(arm.body);
      }
      return exec_block(s.else_body);
    case SOp::Case: {
      const auto sel = eval(s.expr);
      for (std::uint32_t i = 0; i < s.arm_count; ++i) {
        const auto& arm = p_.case_arms[s.arm_first + i];
        for (std::uint32_t l = 0; l < arm.label_count; ++l) {
          const auto& lab = p_.case_labels[arm.label_first + l];
          if (sel >= lab.lo && sel <= lab.hi) return exec_block(arm.body);
        }
      }
      return exec_block(s.else_body);
    }
    case SOp::FbCall:
      fb_call(s);
      return Flow::Normal;
    case SOp::Call:
      call_instance(p_.pous[s.target]);
      return Flow::Normal;
    case SOp::Loop:
      return exec_loop(s);
    case SOp::Exit:
      return Flow::Exit;
    case SOp::Continue:
      return Flow::Continue;
    case SOp::Return:
      return Flow::Return;
  }
  return Flow::Normal;
}

void Machine::fb_call(const Stmt& s) {
  const Fb& fb = p_.fbs[s.target];
  auto arg = [&](std::int32_t node) {
    return node == kNone ? 0 : eval(static_cast<std::uint32_t>(node));
  };
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
      if (r)
        cv = 0;
      else if (rise && cv < p_.field_hi[field(fb.cv)])
        ++cv;
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
      nxt_[q] = in && (s.pt_zero || timer_expired(t, v));
      snapshot_et(fb, t);
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
      snapshot_et(fb, t);
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
      snapshot_et(fb, t);
      return;
    }
    case StandardFb::None:
      return;
  }
}

}  // namespace sfcv::semantics::iec
