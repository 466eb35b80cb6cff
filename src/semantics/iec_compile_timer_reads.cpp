// The IEC compiler's reads of a timer's PT and, in abstract time, of its ET (TwinCAT's blinking
// lamp `Timer(IN := NOT Timer.Q, PT := t); IF Timer.ET < Timer.PT / 2 THEN ...`): placeholder
// nodes while the calls are compiled, filled once every call is known (docs/semantics.md 1.6).

#include <algorithm>
#include <map>
#include <set>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

std::uint32_t Compiler::timer_read(std::uint32_t fb, bool et, const model::Expr& e) {
  if (timer_reads_done) {  // an assumption, compiled after the statements
    error(e.where, "'" + model::to_st(e) + "': a timer's " + (et ? "ET" : "PT") +
                       " can only be read in the program's code, not in an assumption");
    return constant(0);
  }
  const auto n = constant(0);  // filled by timer_reads()
  timer_reads_pending.push_back(TimerRead{n, fb, et, e.where});
  return n;
}

namespace {

Node plain(Op op) {
  return Node{op, Op::Eq, false, 0, 0, 0, 0};
}

}  // namespace

void Compiler::timer_reads() {
  timer_reads_done = true;
  if (timer_reads_pending.empty()) return;
  std::set<std::uint32_t> read;
  for (const auto& r : timer_reads_pending) read.insert(r.fb);
  // The PT values the calls give: the PT field's range.
  std::map<std::uint32_t, std::int64_t> max_pt;
  std::set<std::uint32_t> unknown;
  for (const auto& s : p.stmts)
    if (s.op == SOp::FbCall && read.count(s.target)) {
      auto& m = max_pt[s.target];
      if (s.pt_ms >= 0) m = std::max(m, s.pt_ms);
    }
  for (const auto& s : p.stmts)
    if (s.op == SOp::FbCall && read.count(s.target) && s.pt_ms == Stmt::kPtNotConstant)
      unknown.insert(s.target);
  std::map<std::uint32_t, std::uint32_t> pt_field;
  for (const auto fb_index : read) {
    const auto& fb = p.fbs[fb_index];
    if (unknown.count(fb_index)) {
      const auto at = std::find_if(timer_reads_pending.begin(), timer_reads_pending.end(),
                                   [&](const TimerRead& r) { return r.fb == fb_index; });
      error(at->where,
            "the PT of '" + fb.name +
                "' is read, and a call with IN := FALSE gives it a value that is not a constant");
      continue;
    }
    pt_field[fb_index] =
        add_field(fb.name + ".PT", FieldKind::FbState, 0, max_pt[fb_index], 0, false);
  }
  if (!ok) return;
  // Every call that gives PT leaves it in the field: the call becomes IF TRUE THEN call;
  // PT := value; END_IF (statement indices stay valid).
  const auto count = p.stmts.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Stmt call = p.stmts[i];
    if (call.op != SOp::FbCall || !pt_field.count(call.target) || call.pt_ms < 0) continue;
    Stmt assign;
    assign.op = SOp::Assign;
    assign.target = pt_field[call.target];
    assign.expr = constant(call.pt_ms);
    assign.where = call.where;
    p.stmts.push_back(call);
    p.stmts.push_back(assign);
    Block body;
    body.first = static_cast<std::uint32_t>(p.block_items.size());
    body.count = 2;
    p.block_items.push_back(static_cast<std::uint32_t>(p.stmts.size() - 2));
    p.block_items.push_back(static_cast<std::uint32_t>(p.stmts.size() - 1));
    Stmt wrapper;
    wrapper.op = SOp::If;
    wrapper.where = call.where;
    wrapper.arm_first = static_cast<std::uint32_t>(p.if_arms.size());
    wrapper.arm_count = 1;
    p.if_arms.push_back(IfArm{constant(1), body});
    wrapper.else_body = Block{static_cast<std::uint32_t>(p.block_items.size()), 0};
    p.stmts[i] = wrapper;
  }
  // Abstract time, ET: 0 while the timer holds no time, PT once it expired, and while it runs
  // any value below PT (a pseudo-input `et:<instance>`), as abstract time already lets any
  // time pass between calls. Sound for every cycle time; ET's growth between reads is not
  // kept (a read may see a smaller ET than the read before).
  std::map<std::uint32_t, std::uint32_t> et_input;
  for (const auto& r : timer_reads_pending) {
    const auto& fb = p.fbs[r.fb];
    Node result;
    if (!r.et) {
      result.op = Op::Field;
      result.a = pt_field[r.fb];
      p.nodes[r.node] = result;
      continue;
    }
    if (zero_pt.count(r.fb) && fb.pt_set) {
      error(r.where, "'" + fb.name +
                         "' is called with PT := 0 in one place and a positive PT elsewhere, and "
                         "its ET is read: ET after such a call is not modelled");
      continue;
    }
    if (fb.timer == kNone) continue;  // never called: ET stays 0 (the placeholder)
    if (!et_input.count(r.fb))
      et_input[r.fb] = add_input(
          "et:" + fb.name,
          model::Type::integer("TIME", 0, std::max<std::int64_t>(max_pt[r.fb] - 1, 0)), true);
    const auto& t = p.timers[static_cast<std::size_t>(fb.timer)];
    Node field;
    field.op = Op::Field;
    field.a = t.field;
    Node pt;
    pt.op = Op::Field;
    pt.a = pt_field[r.fb];
    Node free;
    free.op = Op::Input;
    free.a = et_input[r.fb];
    const auto free_value = node(free);
    const auto pt_value = node(pt);
    const auto running = node(
        plain(Op::Ite), {node(plain(Op::Lt), {free_value, pt_value}), free_value, constant(0)});
    const auto expired = node(plain(Op::Eq), {node(field), constant(2)});
    const auto idle = node(plain(Op::Eq), {node(field), constant(0)});
    const auto et = node(plain(Op::Ite),
                         {idle, constant(0), node(plain(Op::Ite), {expired, pt_value, running})});
    p.nodes[r.node] = p.nodes[et];
  }
}

}  // namespace sfcv::semantics::iec::detail
