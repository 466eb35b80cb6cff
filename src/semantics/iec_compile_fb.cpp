// The IEC compiler's standard function block instances: their state fields (edge detectors,
// counters, timers), their calls, and the timers' preset times.

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

void Compiler::make_fb(std::uint32_t pi, const model::Variable& v) {
  Fb fb;
  fb.name = scopes[pi].name + "." + v.name;
  fb.kind = v.type.fb;
  fb.pou = pi;
  switch (fb.kind) {
    case StandardFb::R_TRIG:
    case StandardFb::F_TRIG:
      fb.mem =
          static_cast<std::int32_t>(add_field(fb.name + ".M", FieldKind::FbState, 0, 1, 0, true));
      break;
    case StandardFb::CTU:
    case StandardFb::CTD:
      fb.mem =
          static_cast<std::int32_t>(add_field(fb.name + ".M", FieldKind::FbState, 0, 1, 0, true));
      fb.cv = static_cast<std::int32_t>(
          add_field(fb.name + ".CV", FieldKind::FbState, -32768, 32767, 0, false));
      break;
    case StandardFb::TP:
      fb.mem =
          static_cast<std::int32_t>(add_field(fb.name + ".IN", FieldKind::FbState, 0, 1, 0, true));
      break;
    case StandardFb::None:
      error(v.where, "'" + v.name + "' is an instance of an unsupported function block");
      return;
    default:
      break;
  }
  fb.q = static_cast<std::int32_t>(
      add_field(fb.name + (fb.kind == StandardFb::SR || fb.kind == StandardFb::RS ? ".Q1" : ".Q"),
                FieldKind::FbState, 0, 1, 0, true));
  p.fbs.push_back(fb);
  scopes[pi].names[model::to_upper(v.name)] =
      Ref{Ref::FbInst, static_cast<std::uint32_t>(p.fbs.size() - 1), false};
}

void Compiler::fb_call(const PouScope& sc, const model::Stmt& s, Stmt& out) {
  auto it = sc.names.find(model::to_upper(s.target));
  if (it == sc.names.end() || it->second.kind != Ref::FbInst) {
    error(s.where,
          "call of '" + s.target +
              "', which is not an instance of a standard function "
              "block (instances of user function blocks are not modelled; check the function "
              "block's own POU with --pou)");
    return;
  }
  out.target = it->second.index;
  auto& fb = p.fbs[out.target];
  std::vector<std::string> params;
  switch (fb.kind) {
    case StandardFb::R_TRIG:
    case StandardFb::F_TRIG:
      params = {"CLK"};
      break;
    case StandardFb::SR:
      params = {"S1", "R"};
      break;
    case StandardFb::RS:
      params = {"S", "R1"};
      break;
    case StandardFb::TON:
    case StandardFb::TOF:
    case StandardFb::TP:
      params = {"IN", "PT"};
      break;
    case StandardFb::CTU:
      params = {"CU", "R", "PV"};
      break;
    case StandardFb::CTD:
      params = {"CD", "LD", "PV"};
      break;
    default:
      return;
  }
  std::vector<std::int32_t> nodes(params.size(), kNone);
  // CODESYS's reset idiom `T(IN := FALSE, PT := T#0MS)` beside `T(IN := x, PT := T#5S)`: a
  // TON with IN = FALSE is idle whatever PT is (Q = FALSE, ET = 0), so the PT of such a call
  // is not one of the instance's PT values. (TOF and TP do use PT while IN is FALSE.)
  bool pt_irrelevant = false;
  if (fb.kind == StandardFb::TON)
    for (const auto& [name, value] : s.arguments)
      if (model::iequals(name, "IN") && value && literal(*value) == 0) pt_irrelevant = true;
  bool pt_given = false;
  for (const auto& [written_name, value] : s.arguments) {
    auto up = model::to_upper(written_name);
    // CODESYS and TwinCAT name the counters' reset/load inputs RESET and LOAD (IEC: R, LD).
    if (fb.kind == StandardFb::CTU && up == "RESET") up = "R";
    if (fb.kind == StandardFb::CTD && up == "LOAD") up = "LD";
    const auto& name = written_name;
    auto pos = std::find(params.begin(), params.end(), up);
    if (pos == params.end()) {
      error(s.where, "'" + s.target + "' (" + std::string(model::to_string(fb.kind)) +
                         ") has no input '" + name + "'");
      continue;
    }
    const auto i = static_cast<std::size_t>(pos - params.begin());
    if (up == "PT") {
      // The value this call leaves in the instance's PT (read as `t.PT`, timer_reads()).
      std::optional<std::int64_t> given = literal(*value);
      if (!given && value->kind == ExprKind::Name) given = constant_variable(*sc.pou, value->name);
      out.pt_ms = given ? *given : Stmt::kPtNotConstant;
    }
    if (up == "PT" && pt_irrelevant) continue;
    if (up == "PT") {
      pt_given = true;
      std::optional<std::int64_t> pt = literal(*value);
      if (!pt && value->kind == ExprKind::Name) pt = constant_variable(*sc.pou, value->name);
      if (!pt) {
        error(value->where.known() ? value->where : s.where,
              "PT of '" + s.target +
                  "' must be a constant (a literal, or a VAR or VAR_OUTPUT that no statement, "
                  "output binding or other POU writes)");
        continue;
      }
      // TwinCAT's xPPU calls one TON with PT := T#0ms in one place (Q = IN at once) and a
      // positive PT elsewhere. IEC 61131-3's TON sets Q when ET >= PT, ET counting from the
      // rise of IN whatever PT the calls give: that call's Q is IN, and the timer runs on
      // with the positive PT for the other calls (its ET read is refused, finish_timers).
      if (fb.kind == StandardFb::TON && *pt == 0 && (!fb.pt_set || fb.pt_ms > 0)) {
        out.pt_zero = true;
        pt_given = true;
        zero_pt.emplace(out.target, s.where);
        continue;
      }
      // Abstract time only distinguishes PT = 0 (at once) from PT > 0 (some later cycle), so
      // calls with different positive PTs (CODESYS's PPU) share one timer; discrete time
      // counts cycles and needs one PT.
      const bool same_abstract =
          p.options.time == TimeMode::Abstract && (fb.pt_ms > 0) == (*pt > 0);
      if (fb.pt_set && fb.pt_ms != *pt && !same_abstract) {
        error(s.where, "'" + s.target + "' is called with different PT values" +
                           std::string(p.options.time == TimeMode::Abstract
                                           ? " (zero and positive)"
                                           : "; discrete time needs one (--time abstract accepts "
                                             "several positive ones)"));
        continue;
      }
      if (fb.pt_set) continue;
      fb.pt_ms = *pt;
      fb.pt_set = true;
      continue;
    }
    VT t;
    nodes[i] = static_cast<std::int32_t>(expr(sc, *value, -1, t));
    const bool want_int = up == "PV";
    if (!want_int) t = bool_if_literal(*value, t);
    if ((t == VT::Int) != want_int)
      error(value->where.known() ? value->where : s.where,
            "input " + name + " of '" + s.target + "' has the wrong type");
  }
  for (std::size_t i = 0; i < params.size(); ++i)
    if (nodes[i] == kNone && params[i] != "PT")
      error(s.where, "call of '" + s.target + "' must give " + params[i] +
                         " (sfcv does not keep function block inputs between calls)");
  if (params.size() == 2 && params[1] == "PT") {
    // A call without PT keeps the PT of the previous call, T#0s before any (TwinCAT code
    // often gives none): decided once every call is compiled (finish_timers).
    if (!pt_given && !pt_irrelevant) omitted_pt.emplace(out.target, s.where);
    called_timers.insert(out.target);
    if (fb.pt_set && fb.timer == kNone) {
      fb.timer = make_timer(fb.name, fb.pt_ms, fb.name);
      p.timers[static_cast<std::size_t>(fb.timer)].clocked = true;
    }
  }
  out.arg1 = nodes[0];
  if (nodes.size() > 1) out.arg2 = nodes[1];
  if (nodes.size() > 2) out.arg3 = nodes[2];
}

void Compiler::finish_timers() {
  // ET after a PT := 0 call is 0 (IEC: ET stops at PT), not the running timer's: not modelled.
  // (A TON whose calls all give PT := 0 is a timer of PT 0; the flag changes nothing there.)
  for (const auto& entry : zero_pt) {
    // Plain names: clang 15 refuses a lambda capturing a structured binding.
    const auto& index = entry.first;
    const auto& where = entry.second;
    if (!p.fbs[index].pt_set) continue;
    const bool et_read = std::any_of(p.nodes.begin(), p.nodes.end(), [&](const auto& n) {
      return n.op == Op::TimerET && n.a == index;
    });
    if (et_read)
      error(where, "'" + p.fbs[index].name +
                       "' is called with PT := 0 here and a positive PT elsewhere, and its ET is "
                       "read: ET after such a call is not modelled");
  }
  for (const auto& [index, where] : omitted_pt) {
    auto& fb = p.fbs[index];
    if (fb.pt_set && fb.pt_ms != 0) {
      error(where, "a call of '" + fb.name + "' gives no PT while another gives " +
                       std::to_string(fb.pt_ms) +
                       " ms: PT is then T#0s or that value depending "
                       "on the order of the calls; give PT in every call");
      continue;
    }
    fb.pt_ms = 0;
    fb.pt_set = true;
  }
  for (const auto index : called_timers) {
    auto& fb = p.fbs[index];
    if (fb.timer != kNone) continue;
    if (!fb.pt_set) {  // never called, or only with IN = FALSE
      fb.pt_ms = 0;
      fb.pt_set = true;
    }
    fb.timer = make_timer(fb.name, fb.pt_ms, fb.name);
    p.timers[static_cast<std::size_t>(fb.timer)].clocked = true;
  }
}

void Compiler::timer_snapshots() {
  if (p.options.time != TimeMode::Discrete) return;
  std::set<std::uint32_t> read;
  for (const auto& n : p.nodes)
    if (n.op == Op::TimerET) read.insert(n.a);
  for (const auto index : read) {
    auto& fb = p.fbs[index];
    if (fb.timer == kNone) continue;  // never called: ET stays 0
    const auto& t = p.timers[static_cast<std::size_t>(fb.timer)];
    fb.et = static_cast<std::int32_t>(
        add_field(fb.name + ".ET_AT_CALL", FieldKind::Timer, 0, t.max_value, 0, false));
  }
}

std::int32_t Compiler::make_timer(const std::string& field_name, std::int64_t d,
                                  const std::string& timeout_name) {
  Timer t;
  t.duration_ms = d;
  if (p.options.time == TimeMode::Abstract) {
    t.max_value = 2;
    t.timeout_input = static_cast<std::int32_t>(
        add_input("timeout:" + timeout_name, model::Type::boolean(), true));
  } else {
    const auto c = std::max<std::int64_t>(p.options.cycle_ms, 1);
    t.max_value = 1 + (d <= 0 ? 0 : (d + c - 1) / c);
  }
  t.field = add_field(field_name, FieldKind::Timer, 0, t.max_value, 0, false);
  p.timers.push_back(t);
  return static_cast<std::int32_t>(p.timers.size() - 1);
}

}  // namespace sfcv::semantics::iec::detail
