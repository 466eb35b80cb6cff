#include "engine/external/export_model.hpp"

#include <algorithm>
#include <climits>
#include <map>
#include <stdexcept>
#include <tuple>

#include "logic/formula.hpp"

namespace sfcv::engine {

using semantics::Aig;
using semantics::AigLit;
using semantics::BitVector;

namespace {

const char* kDummyInput = "sfcv_dummy";

std::string field_comment(const semantics::StateField& f) {
  using semantics::FieldKind;
  switch (f.kind) {
    case FieldKind::StepReady:
      return "step " + f.name + " ready";
    case FieldKind::StepActive:
      return "step " + f.name + " active";
    case FieldKind::ActionActive:
      return "action " + f.name + " active";
    case FieldKind::ActionStored:
      return "action " + f.name + " stored (S without R yet)";
    case FieldKind::ActionFinalCall:
      return "action " + f.name + " stopped: its final call is due (--dialect codesys|twincat)";
    case FieldKind::Variable:
      return "variable " + f.name;
    case FieldKind::InputMemory:
      return "previous value of input " + f.name;
    case FieldKind::Timer:
      return "timer " + f.name;
    case FieldKind::FbState:
      return "function block memory " + f.name;
  }
  return f.name;
}

// The encoded value e = v - lo (unsigned, LSB first) compared with constant c.
AigLit compare_bits(Aig& aig, const BitVector& bits, std::int64_t lo, logic::CompareOp op,
                    std::int64_t c) {
  using logic::CompareOp;
  const auto width = static_cast<std::uint32_t>(bits.size());
  std::int64_t k = 0;
  const bool overflow = __builtin_sub_overflow(c, lo, &k);  // constants far outside the range
  const std::int64_t max = width >= 62 ? INT64_MAX : (std::int64_t{1} << width) - 1;
  // e < k, e == k with k clamped to the representable range.
  AigLit less, equal;
  if (overflow) {
    less = c > lo ? Aig::kTrue : Aig::kFalse;
    equal = Aig::kFalse;
  } else if (k < 0) {
    less = Aig::kFalse;
    equal = Aig::kFalse;
  } else if (k > max) {
    less = Aig::kTrue;
    equal = Aig::kFalse;
  } else {
    const auto kk = semantics::bv_constant(k, width);
    less = semantics::bv_less_unsigned(aig, bits, kk);
    equal = semantics::bv_equal(aig, bits, kk);
  }
  switch (op) {
    case CompareOp::Eq:
      return equal;
    case CompareOp::Ne:
      return Aig::make_not(equal);
    case CompareOp::Lt:
      return less;
    case CompareOp::Le:
      return aig.make_or(less, equal);
    case CompareOp::Gt:
      return Aig::make_not(aig.make_or(less, equal));
    case CompareOp::Ge:
      return Aig::make_not(less);
  }
  return Aig::kFalse;
}

class Builder {
 public:
  Builder(const semantics::TransitionSystem& ts, ExportedModel& out) : ts_(ts), out_(out) {}

  // The literal of a propositional formula over the latches.
  AigLit literal(const logic::Formula& f) {
    Aig& aig = out_.model.aig;
    using logic::Op;
    switch (f.op) {
      case Op::True:
        return Aig::kTrue;
      case Op::False:
        return Aig::kFalse;
      case Op::Atom:
      case Op::Compare:
        return atom(f);
      case Op::Not:
        return Aig::make_not(literal(*f.args[0]));
      case Op::And:
        return aig.make_and(literal(*f.args[0]), literal(*f.args[1]));
      case Op::Or:
        return aig.make_or(literal(*f.args[0]), literal(*f.args[1]));
      case Op::Implies:
        return aig.make_implies(literal(*f.args[0]), literal(*f.args[1]));
      case Op::Iff:
        return aig.make_xnor(literal(*f.args[0]), literal(*f.args[1]));
      case Op::Xor:
        return aig.make_xor(literal(*f.args[0]), literal(*f.args[1]));
      case Op::Relation:
        throw ExportError("the comparison of two expressions '" + logic::to_string(f) +
                          "' is not exported yet: check it with the explicit, bdd or SAT engines");
      default:
        throw ExportError("a temporal operator inside a state formula");
    }
  }

  // The formula with every atom replaced by `{k}`, k the index of its circuit output (NuSMV
  // syntax via to_string): a number, so that no chart name reaches the formula text.
  logic::FormulaPtr with_output_atoms(const logic::Formula& f) {
    if (f.op == logic::Op::Relation) literal(f);  // refused, by name
    if (f.op == logic::Op::Atom || f.op == logic::Op::Compare) {
      atom(f);
      return logic::make_atom("{" + std::to_string(output_index_.at(key_of(f))) + "}");
    }
    auto copy = std::make_shared<logic::Formula>(f);
    for (auto& a : copy->args) a = with_output_atoms(*a);
    return copy;
  }

 private:
  std::string output_name(const logic::Formula& f) const {
    const auto& obs = ts_.observables().at(static_cast<std::size_t>(f.observable));
    if (f.op == logic::Op::Atom) return obs.name;
    return obs.name + " " + std::string(logic::to_string(f.cmp)) + " " + std::to_string(f.value);
  }

  // An output per observable and comparison, never per name: two observables may bear one
  // name (a Boolean action of an instance and the variable it drives, "Main.Lift.Extend"),
  // and a cache by name once gave the variable's atom the action's latch.
  using OutputKey = std::tuple<std::int32_t, bool, int, std::int64_t>;
  static OutputKey key_of(const logic::Formula& f) {
    const bool compare = f.op != logic::Op::Atom;
    return {f.observable, compare, compare ? static_cast<int>(f.cmp) : 0, compare ? f.value : 0};
  }

  AigLit atom(const logic::Formula& f) {
    if (f.observable < 0) throw ExportError("unresolved atom '" + f.name + "'");
    const auto o = static_cast<std::size_t>(f.observable);
    const auto& bits = out_.circuit.observable_bits.at(o);
    const auto name = output_name(f);
    const auto key = key_of(f);
    if (const auto it = outputs_.find(key); it != outputs_.end()) return it->second;
    Aig& aig = out_.model.aig;
    AigLit l;
    if (f.op == logic::Op::Atom) {
      if (bits.size() != 1)
        throw ExportError("'" + f.name + "' is an integer: compare it with a constant");
      l = bits[0];
    } else {
      l = compare_bits(aig, bits, out_.circuit.observable_lo.at(o), f.cmp, f.value);
    }
    output_index_.emplace(key, aig.outputs().size());
    aig.add_output(name, l);
    outputs_.emplace(key, l);
    return l;
  }

 public:
  /// The circuit output of one-bit observable `o` (after literal() of its atom).
  std::size_t output_of(std::size_t o) const {
    return output_index_.at(OutputKey{static_cast<std::int32_t>(o), false, 0, 0});
  }

 private:
  const semantics::TransitionSystem& ts_;
  ExportedModel& out_;
  std::map<OutputKey, AigLit> outputs_;
  std::map<OutputKey, std::size_t> output_index_;
};

}  // namespace

namespace {
// An LTL formula over the cycle-end states as a Spin claim. The cycle is one atomic sequence
// ending in the d_step that writes the latches, and Spin's claim moves once per atomic
// sequence, so the states the claim reads are exactly the states at the start of a cycle (the
// latches then hold the state at the end of the last one): sfcv's states, one per cycle. The
// differential test checks this reading with the claim `[] {b}` ({b}: the process is at the
// start of a cycle). X is refused: Debian's Spin parses no X in ltl claims.
std::string ltl_claim(const logic::Formula& f, Builder& builder, std::vector<AigLit>& atoms) {
  using logic::Op;
  if (logic::is_propositional(f)) {
    atoms.push_back(builder.literal(f));
    return "{" + std::to_string(atoms.size() - 1) + "}";
  }
  auto t = [&](std::size_t i) { return ltl_claim(*f.args[i], builder, atoms); };
  switch (f.op) {
    case Op::Not:
      return "!(" + t(0) + ")";
    case Op::And:
      return "(" + t(0) + " && " + t(1) + ")";
    case Op::Or:
      return "(" + t(0) + " || " + t(1) + ")";
    case Op::Implies:
      return "(" + t(0) + " -> " + t(1) + ")";
    case Op::Iff:
      return "(" + t(0) + " <-> " + t(1) + ")";
    case Op::Xor:
      return "!(" + t(0) + " <-> " + t(1) + ")";
    case Op::F:
      return "<> " + t(0);
    case Op::G:
      return "[] " + t(0);
    case Op::U: {
      const auto a = t(0), c = t(1);
      return "(" + a + " U " + c + ")";
    }
    case Op::R: {
      const auto a = t(0), c = t(1);
      return "(" + a + " V " + c + ")";
    }
    case Op::W: {  // a W b = (a U b) | G a
      const auto a = t(0), c = t(1);
      return "((" + a + " U " + c + ") || [] " + a + ")";
    }
    default:
      throw ExportError("a CTL operator in an LTL property");
  }
}
}  // namespace

namespace {
// The latch `sfcv_loop_limit` (TransitionCircuit::loop_limit): set by a cycle that meets the ST
// loop bound, then kept; kFalse when no cycle can meet it. Also an output, for CTL text.
AigLit add_loop_limit_flag(ExportedModel& out) {
  if (out.circuit.loop_limit == Aig::kFalse) return Aig::kFalse;
  CircuitExport& m = out.model;
  const auto index = static_cast<std::uint32_t>(m.aig.latches().size());
  const AigLit flag = m.aig.add_latch("sfcv_loop_limit", false);
  m.aig.set_next(index, m.aig.make_or(flag, out.circuit.loop_limit));
  m.latch_comments.push_back(
      "set by a cycle whose ST loop meets the loop bound, then kept: every property fails");
  m.aig.add_output("sfcv_loop_limit", flag);
  out.loop_limit_latch = index;
  m.header.push_back("sfcv_loop_limit: " + out.circuit.loop_limit_message() + ". Such a");
  m.header.push_back("cycle sets the latch sfcv_loop_limit, and every property fails once it is");
  m.header.push_back("set (invariants: bad | sfcv_loop_limit; CTL: AG !sfcv_loop_limit & ...): a");
  m.header.push_back("violation whose trace ends with it set is unknown, not a finding.");
  return flag;
}

// CTL text that fails wherever the flag state is reachable (the flag's output is `{k}`).
std::string guarded_ctl(const ExportedModel& out, const std::string& text) {
  if (!out.loop_limit_latch) return text;
  const auto& outputs = out.model.aig.outputs();
  for (std::size_t k = 0; k < outputs.size(); ++k)
    if (outputs[k].name == "sfcv_loop_limit" &&
        outputs[k].literal == out.model.aig.latches()[*out.loop_limit_latch].current)
      return "(AG !{" + std::to_string(k) + "}) & (" + text + ")";
  throw std::logic_error("guarded_ctl: no output for sfcv_loop_limit");
}
}  // namespace

static bool has_next(const logic::Formula& f) {
  if (f.op == logic::Op::X) return true;
  return std::any_of(f.args.begin(), f.args.end(), [](const auto& a) { return has_next(*a); });
}

bool is_invariant(const logic::Formula& f) {
  return f.op == logic::Op::AG && logic::is_propositional(*f.args[0]);
}

ExportedModel build_export(const semantics::TransitionSystem& ts, const ExportRequest& request) {
  if (ts.kind() != semantics::SemanticsKind::Iec61131)
    throw ExportError("exports are not supported for Grafcet yet (only IEC 61131-3 charts)");
  ExportedModel out;
  try {
    out.circuit = semantics::build_iec61131_circuit(ts);
  } catch (const semantics::CircuitUnsupported& e) {
    throw ExportError(std::string("the chart cannot be exported as a circuit: ") + e.what());
  }
  CircuitExport& m = out.model;
  m.aig = out.circuit.aig;
  Aig& aig = m.aig;

  // Comments: every latch and input back to the chart.
  const auto& fields = ts.layout().fields();
  m.latch_comments.assign(aig.latches().size(), "");
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const auto& latches = out.circuit.field_latches[f];
    for (std::size_t k = 0; k < latches.size(); ++k) {
      std::string c = field_comment(fields[f]);
      if (latches.size() > 1)
        c += ", bit " + std::to_string(k) + " of value - " + std::to_string(fields[f].lo) +
             " (LSB first)";
      m.latch_comments[latches[k]] = c;
    }
  }
  m.input_comments.assign(aig.inputs().size(), "");
  for (std::size_t i = 0; i < ts.inputs().size(); ++i) {
    const auto& in = ts.inputs()[i];
    const auto& bits = out.circuit.input_bits[i];
    for (std::size_t k = 0; k < bits.size(); ++k) {
      std::string c = (in.pseudo ? "pseudo-input " : "input ") + in.name;
      if (in.pseudo) c += " (a nondeterministic choice of the semantics)";
      if (bits.size() > 1)
        c += ", bit " + std::to_string(k) + " of value - " + std::to_string(in.type.lo) +
             " (LSB first)";
      m.input_comments[aig.nodes()[Aig::node_of(bits[k])].index] = c;
    }
  }
  if (aig.inputs().empty()) {
    // ABC's `int` and `dprove` crash on designs without inputs.
    aig.add_input(kDummyInput);
    m.input_comments.push_back("dummy input (the chart has none), never read");
  }

  m.header = request.header;
  m.header.push_back("IEC 61131-3 scan cycle of sfcv as a circuit: one Boolean variable per state");
  m.header.push_back("bit of sfcv's transition system, one input per bit of each (pseudo-)input.");
  // Built on the copy `aig`: the circuit's own graph stays as the engines see it.
  const AigLit flag = add_loop_limit_flag(out);
  // A loop-limit cycle is part of range_error but is not cut: it leads to the flag state,
  // which has every input allowed (so that NuSMV's infinite paths reach it too).
  const AigLit cut = aig.make_or(
      flag, aig.make_and(out.circuit.allowed,
                         Aig::make_not(aig.make_and(out.circuit.range_error,
                                                    Aig::make_not(out.circuit.loop_limit)))));
  if (cut != Aig::kTrue) {
    m.header.push_back("A cycle whose inputs break the assumptions or the input ranges, or which");
    m.header.push_back("raises a range error, has no successor: the constraint cuts it.");
    aig.add_constraint("assumptions_and_ranges", cut);
  }
  // Every property fails in the flag state: its bad state or CTL text is rewritten below.
  auto bad_or_flag = [&](AigLit bad) { return aig.make_or(flag, bad); };

  Builder builder(ts, out);
  // Observables as named outputs (steps, actions, Boolean variables).
  for (std::size_t o = 0; o < ts.observables().size(); ++o)
    if (out.circuit.observable_bits[o].size() == 1) {
      logic::Formula f;
      f.op = logic::Op::Atom;
      f.name = ts.observables()[o].name;
      f.observable = static_cast<std::int32_t>(o);
      builder.literal(f);
    }

  for (std::size_t p = 0; p < request.properties.size(); ++p) {
    const auto& prop = request.properties[p];
    if (logic::is_ltl(*prop.formula)) {
      if (request.target == ExportTarget::Smv)
        throw ExportError("LTL property '" + prop.name + "' is exported to Promela only");
      // Spin extends a run cut inside a cycle (end_excluded) by stuttering there, a path sfcv
      // does not have; and Debian's Spin parses no X in ltl claims.
      if (flag != Aig::kFalse)
        throw ExportError("LTL property '" + prop.name + "': not exported for a chart where " +
                          out.circuit.loop_limit_message());
      if (cut != Aig::kTrue)
        throw ExportError(
            "LTL property '" + prop.name +
            "': not exported for a chart whose "
            "assumptions or input ranges cut cycles (Spin would extend the cut runs)");
      if (has_next(*prop.formula))
        throw ExportError("LTL property '" + prop.name +
                          "': X is not exported (Spin's ltl "
                          "claims take no X)");
      m.ltl.emplace_back(prop.name, ltl_claim(*prop.formula, builder, m.ltl_atoms));
      continue;
    }
    if (is_invariant(*prop.formula)) {
      aig.add_bad(prop.name, bad_or_flag(Aig::make_not(builder.literal(*prop.formula->args[0]))));
      out.bad_property.push_back(static_cast<std::int32_t>(p));
    } else {
      m.ctl.emplace_back(
          prop.name, guarded_ctl(out, logic::to_string(builder.with_output_atoms(*prop.formula))));
      out.ctl_property.push_back(static_cast<std::int32_t>(p));
      out.ctl_only.push_back(prop.name);
    }
  }
  if (request.reachability) {
    for (std::size_t o = 0; o < ts.observables().size(); ++o) {
      const auto& obs = ts.observables()[o];
      if (obs.kind != semantics::ObservableKind::Step) continue;
      if (request.target == ExportTarget::Smv) {
        m.ctl.emplace_back("reachable_" + obs.name,
                           guarded_ctl(out, "EF {" + std::to_string(builder.output_of(o)) + "}"));
        out.ctl_property.push_back(-1);
      } else {
        aig.add_bad("unreachable_" + obs.name, bad_or_flag(out.circuit.observable_bits[o][0]));
        out.bad_property.push_back(-1);
      }
    }
  }
  if (flag != Aig::kFalse && request.target == ExportTarget::Smv) {
    // NuSMV: whether the flag is reachable at all, to read the CTL verdicts back.
    out.loop_limit_bad = aig.bad().size();
    aig.add_bad("no_loop_limit", flag);
    out.bad_property.push_back(-1);
  }
  if (cut != Aig::kTrue && !m.ctl.empty()) {
    m.header.push_back("CTL: sfcv quantifies over maximal paths (a path may end in a state whose");
    m.header.push_back("every cycle is cut), NuSMV over infinite ones; invariants agree always,");
    m.header.push_back("other CTL when every reachable state has an allowed successor.");
  }
  return out;
}

semantics::Aig aiger_circuit(const CircuitExport& model) {
  Aig aig = model.aig;
  aig.clear_outputs();
  if (aig.inputs().empty()) aig.add_input(kDummyInput);
  if (aig.constraints().empty()) return aig;
  AigLit all = Aig::kTrue;
  for (const auto& c : aig.constraints()) all = aig.make_and(all, c.literal);
  aig.clear_constraints();
  const auto index = static_cast<std::uint32_t>(aig.latches().size());
  const AigLit valid = aig.add_latch("sfcv_valid", true);
  aig.set_next(index, aig.make_and(valid, all));
  const auto bad = aig.bad();
  aig.clear_bad();
  for (const auto& b : bad) aig.add_bad(b.name, aig.make_and(valid, b.literal));
  return aig;
}

bool ends_in_loop_limit(const ExportedModel& exported,
                        const std::vector<std::vector<bool>>& frames) {
  if (!exported.loop_limit_latch) return false;
  const Aig& aig = exported.model.aig;
  std::vector<bool> latches;
  for (const auto& l : aig.latches()) latches.push_back(l.initial);
  for (auto frame : frames) {
    frame.resize(aig.inputs().size(), false);
    const auto values = aig.evaluate(frame, latches);
    for (std::size_t l = 0; l < latches.size(); ++l)
      latches[l] = Aig::value_of(values, aig.latches()[l].next);
  }
  return latches[*exported.loop_limit_latch];
}

std::vector<std::vector<std::int64_t>> frames_to_inputs(
    const semantics::TransitionSystem& ts, const semantics::TransitionCircuit& circuit,
    const std::vector<std::vector<bool>>& frames) {
  std::vector<std::vector<std::int64_t>> inputs;
  for (auto frame : frames) {
    frame.resize(std::max(frame.size(), circuit.aig.inputs().size()), false);
    inputs.push_back(semantics::inputs_from_bits(ts, circuit, frame));
  }
  return inputs;
}

}  // namespace sfcv::engine
