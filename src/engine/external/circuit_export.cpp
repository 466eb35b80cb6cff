#include "engine/external/circuit_export.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/external/identifiers.hpp"
#include "model/errors.hpp"

namespace sfcv::engine {

using semantics::Aig;
using semantics::AigLit;

namespace {

// One naming scheme for every kind of bit: each kind has a prefix of its own (in_ inputs, s_
// latches, g_ gates, o_ outputs, p_ properties, a_ assumptions) that no other kind's identifiers
// start with, so identifiers of different kinds never meet (a nested step's ready latch and its
// activity output once did); within a kind, chart names that sanitize alike get _2, _3
// (IdentifierTable).
constexpr const char* kInputPrefix = "in_";
constexpr const char* kLatchPrefix = "s_";
constexpr const char* kGatePrefix = "g_";
constexpr const char* kOutputPrefix = "o_";
constexpr const char* kPropertyPrefix = "p_";
constexpr const char* kAssumptionPrefix = "a_";

// Names of every node of the circuit in a target language.
struct Naming {
  std::vector<std::string> node;  ///< per node: identifier, "" for the constant
  IdentifierTable ids;

  Naming(const Aig& aig, std::unordered_set<std::string> reserved)
      : node(aig.nodes().size()), ids(std::move(reserved)) {
    for (const auto& in : aig.inputs())
      node[Aig::node_of(in.literal)] = ids.fresh(kInputPrefix, in.name);
    // fresh, not get: two bits may bear one chart name (a TwinCAT Boolean action's activity
    // and the variable it drives are both "MAIN.Valve"), and each needs its own identifier.
    for (const auto& l : aig.latches())
      node[Aig::node_of(l.current)] = ids.fresh(kLatchPrefix, l.name);
    for (std::size_t n = 1; n < aig.nodes().size(); ++n)
      if (aig.nodes()[n].kind == Aig::NodeKind::And)
        node[n] = ids.get(kGatePrefix, std::to_string(n));
  }

  std::string lit(AigLit l, const char* t, const char* f, const char* neg) const {
    if (l == Aig::kFalse) return f;
    if (l == Aig::kTrue) return t;
    return (Aig::is_negated(l) ? std::string(neg) : std::string()) + node[Aig::node_of(l)];
  }
};

const std::unordered_set<std::string> kNusmvReserved = {
    "MODULE",  "DEFINE",     "MDEFINE",   "CONSTANTS", "VAR",     "IVAR",       "FROZENVAR",
    "INIT",    "TRANS",      "INVAR",     "SPEC",      "CTLSPEC", "LTLSPEC",    "PSLSPEC",
    "COMPUTE", "NAME",       "INVARSPEC", "FAIRNESS",  "JUSTICE", "COMPASSION", "ISA",
    "ASSIGN",  "CONSTRAINT", "SIMPWFF",   "CTLWFF",    "LTLWFF",  "PSLWFF",     "COMPWFF",
    "IN",      "MIN",        "MAX",       "MIRROR",    "PRED",    "PREDICATES", "process",
    "array",   "of",         "boolean",   "integer",   "real",    "word",       "word1",
    "bool",    "signed",     "unsigned",  "extend",    "resize",  "sizeof",     "uwconst",
    "swconst", "EX",         "AX",        "EF",        "AF",      "EG",         "AG",
    "E",       "F",          "O",         "G",         "H",       "X",          "Y",
    "Z",       "A",          "U",         "S",         "V",       "T",          "BU",
    "EBF",     "ABF",        "EBG",       "ABG",       "case",    "esac",       "mod",
    "next",    "init",       "union",     "in",        "xor",     "xnor",       "self",
    "TRUE",    "FALSE",      "count",     "abs",       "max",     "min",        "toint",
    "floor",   "running"};

const std::unordered_set<std::string> kPromelaReserved = {
    "active",   "assert",     "atomic",  "bit",   "bool",     "break",   "byte",     "chan",
    "d_step",   "D_proctype", "do",      "else",  "empty",    "enabled", "fi",       "full",
    "goto",     "hidden",     "if",      "init",  "int",      "len",     "mtype",    "nempty",
    "never",    "nfull",      "od",      "of",    "pc_value", "printf",  "priority", "proctype",
    "provided", "run",        "short",   "skip",  "timeout",  "typedef", "unless",   "unsigned",
    "xr",       "xs",         "true",    "false", "local",    "show",    "c_code",   "c_decl",
    "c_expr",   "c_state",    "c_track", "ltl",   "select",   "for",     "in",       "eval",
    "trace",    "notrace",    "inline",  "np_"};

// The identifier of each circuit output: always a DEFINE of its own, also when the output is
// exactly a latch.
std::vector<std::string> output_identifiers(const Aig& aig, Naming& names) {
  std::vector<std::string> ids;
  for (const auto& o : aig.outputs()) ids.push_back(names.ids.fresh(kOutputPrefix, o.name));
  return ids;
}

// Replaces each {k} in `text` by the expression of circuit output k (CircuitExport::ctl): the
// placeholder is a number, so no chart name ever reaches the formula text.
std::string resolve_outputs(const std::string& text, const std::vector<std::string>& output_ids) {
  std::string r;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '{') {
      r += text[i];
      continue;
    }
    const auto close = text.find('}', i);
    if (close == std::string::npos) throw std::invalid_argument("CTL text: '{' without '}'");
    const std::string key = text.substr(i + 1, close - i - 1);
    if (key.empty() || key.find_first_not_of("0123456789") != std::string::npos ||
        std::stoul(key) >= output_ids.size())
      throw std::invalid_argument("CTL text: '{" + key + "}' is not a circuit output");
    r += output_ids[std::stoul(key)];
    i = close;
  }
  return r;
}

bool depends_on_inputs(const Aig& aig, AigLit root) {
  std::vector<AigLit> stack{root};
  std::vector<bool> seen(aig.nodes().size(), false);
  while (!stack.empty()) {
    const auto n = Aig::node_of(stack.back());
    stack.pop_back();
    if (seen[n]) continue;
    seen[n] = true;
    const auto& node = aig.nodes()[n];
    if (node.kind == Aig::NodeKind::Input) return true;
    if (node.kind == Aig::NodeKind::And) {
      stack.push_back(node.left);
      stack.push_back(node.right);
    }
  }
  return false;
}

// Every chart name, file name and property name in a comment goes through comment_text().
std::string comment(const std::string& text, CommentKind kind = CommentKind::Line) {
  return comment_text(text, kind);
}

void comment_lines(std::ostream& out, const std::vector<std::string>& lines, const char* prefix,
                   CommentKind kind = CommentKind::Line) {
  for (const auto& l : lines) out << prefix << comment(l, kind) << "\n";
}

}  // namespace

std::vector<std::string> nusmv_input_identifiers(const CircuitExport& model) {
  const Naming names(model.aig, kNusmvReserved);
  std::vector<std::string> ids;
  for (const auto& in : model.aig.inputs()) ids.push_back(names.node[Aig::node_of(in.literal)]);
  return ids;
}

void write_nusmv(std::ostream& out, const CircuitExport& m) {
  const Aig& aig = m.aig;
  Naming names(aig, kNusmvReserved);
  auto lit = [&names](AigLit l) { return names.lit(l, "TRUE", "FALSE", "!"); };
  comment_lines(out, m.header, "-- ");
  out << "MODULE main\n";
  if (!aig.inputs().empty()) out << "IVAR\n";
  for (std::size_t i = 0; i < aig.inputs().size(); ++i)
    out << "  " << names.node[Aig::node_of(aig.inputs()[i].literal)] << " : boolean;"
        << (i < m.input_comments.size() ? "  -- " + comment(m.input_comments[i]) : "") << "\n";
  if (!aig.latches().empty()) out << "VAR\n";
  for (std::size_t l = 0; l < aig.latches().size(); ++l)
    out << "  " << names.node[Aig::node_of(aig.latches()[l].current)] << " : boolean;"
        << (l < m.latch_comments.size() ? "  -- " + comment(m.latch_comments[l]) : "") << "\n";
  bool has_gates = false;
  for (std::size_t n = 1; n < aig.nodes().size() && !has_gates; ++n)
    has_gates = aig.nodes()[n].kind == Aig::NodeKind::And;
  if (has_gates || !aig.outputs().empty()) out << "DEFINE\n";
  for (std::size_t n = 1; n < aig.nodes().size(); ++n) {
    const auto& node = aig.nodes()[n];
    if (node.kind == Aig::NodeKind::And)
      out << "  " << names.node[n] << " := " << lit(node.left) << " & " << lit(node.right) << ";\n";
  }
  IdentifierTable& ids = names.ids;
  const auto output_ids = output_identifiers(aig, names);
  for (std::size_t o = 0; o < aig.outputs().size(); ++o)
    out << "  " << output_ids[o] << " := " << lit(aig.outputs()[o].literal) << ";  -- "
        << comment(aig.outputs()[o].name) << "\n";
  if (!aig.latches().empty()) out << "ASSIGN\n";
  for (const auto& l : aig.latches()) {
    const auto& id = names.node[Aig::node_of(l.current)];
    out << "  init(" << id << ") := " << (l.initial ? "TRUE" : "FALSE") << ";\n";
    out << "  next(" << id << ") := " << lit(l.next) << ";\n";
  }
  for (const auto& c : aig.constraints())
    out << "TRANS " << lit(c.literal) << "  -- assumption " << comment(c.name) << "\n";
  for (const auto& b : aig.bad())
    out << "INVARSPEC NAME " << ids.fresh(kPropertyPrefix, b.name) << " := !(" << lit(b.literal)
        << ");\n";
  for (const auto& [name, formula] : m.ctl)
    out << "CTLSPEC NAME " << ids.fresh(kPropertyPrefix, name)
        << " := " << resolve_outputs(formula, output_ids) << ";\n";
}

void write_casmv(std::ostream& out, const CircuitExport& m) {
  Aig aig = m.aig;  // cofactors extend the circuit
  // Set and reset conditions of each latch, as in the seed's Figure 5.
  std::vector<std::pair<AigLit, AigLit>> set_reset;
  for (const auto& l : m.aig.latches())
    set_reset.emplace_back(aig.cofactor(l.next, l.current, false),
                           Aig::make_not(aig.cofactor(l.next, l.current, true)));
  Naming names(aig, {"module", "input",  "output", "init",  "next",    "default", "in",
                     "case",   "assert", "using",  "prove", "boolean", "if",      "else",
                     "switch", "for",    "G",      "F",     "X",       "U",       "SPEC"});
  auto lit = [&names](AigLit l) { return names.lit(l, "1", "0", "~"); };
  comment_lines(out, m.header, "-- ");
  out << "module main()\n{\n";
  for (std::size_t i = 0; i < aig.inputs().size(); ++i)
    out << "  input " << names.node[Aig::node_of(aig.inputs()[i].literal)] << " : boolean;"
        << (i < m.input_comments.size() ? "  -- " + comment(m.input_comments[i]) : "") << "\n";
  for (std::size_t l = 0; l < aig.latches().size(); ++l)
    out << "  " << names.node[Aig::node_of(aig.latches()[l].current)] << " : boolean;"
        << (l < m.latch_comments.size() ? "  -- " + comment(m.latch_comments[l]) : "") << "\n";
  for (std::size_t n = 1; n < aig.nodes().size(); ++n)
    if (aig.nodes()[n].kind == Aig::NodeKind::And) out << "  " << names.node[n] << " : boolean;\n";
  for (std::size_t n = 1; n < aig.nodes().size(); ++n) {
    const auto& node = aig.nodes()[n];
    if (node.kind == Aig::NodeKind::And)
      out << "  " << names.node[n] << " := " << lit(node.left) << " & " << lit(node.right) << ";\n";
  }
  for (std::size_t i = 0; i < aig.latches().size(); ++i) {
    const auto& l = aig.latches()[i];
    const auto& id = names.node[Aig::node_of(l.current)];
    out << "  init(" << id << ") := " << (l.initial ? 1 : 0) << ";\n";
    out << "  default next(" << id << ") := " << id << ";\n  in case {\n";
    if (set_reset[i].first != Aig::kFalse)
      out << "    ~" << id << " & " << lit(set_reset[i].first) << " : next(" << id << ") := 1;\n";
    if (set_reset[i].second != Aig::kFalse)
      out << "    " << id << " & " << lit(set_reset[i].second) << " : next(" << id << ") := 0;\n";
    out << "  }\n";
  }
  IdentifierTable& ids = names.ids;
  for (const auto& c : aig.constraints()) {
    const auto id = ids.fresh(kAssumptionPrefix, c.name);
    out << "  " << id << " : assert G " << lit(c.literal) << ";\n  assume " << id << ";\n";
  }
  for (const auto& b : aig.bad())
    out << "  " << ids.fresh(kPropertyPrefix, b.name) << " : assert G ~" << lit(b.literal) << ";\n";
  std::vector<std::string> output_exprs;
  for (const auto& o : aig.outputs()) output_exprs.push_back("(" + lit(o.literal) + ")");
  for (const auto& [name, formula] : m.ctl)
    out << "  SPEC " << resolve_outputs(formula, output_exprs) << ";  -- " << comment(name) << "\n";
  out << "}\n";
}

// The LTL claims' atoms as macros over the latches only: a claim reads the state between two
// statements, when the hidden gate bytes hold the previous cycle's values. Each AND gate of an
// atom's cone becomes a macro sfcv_g<n>; sfcv_start is "at the start of a cycle" (the label
// sfcv_cycle before the loop, where the latches hold the state at the end of the last cycle).
namespace {
void write_ltl_atoms(std::ostream& out, const CircuitExport& m, const Naming& names) {
  const Aig& aig = m.aig;
  std::vector<bool> defined(aig.nodes().size(), false);
  auto ref = [&](AigLit l) -> std::string {
    if (l == Aig::kFalse) return "0";
    if (l == Aig::kTrue) return "1";
    const auto n = Aig::node_of(l);
    const auto& id =
        aig.nodes()[n].kind == Aig::NodeKind::And ? "sfcv_g" + std::to_string(n) : names.node[n];
    return (Aig::is_negated(l) ? "!" : "") + id;
  };
  std::vector<std::size_t> stack;
  auto define = [&](AigLit root) {
    stack.push_back(Aig::node_of(root));
    while (!stack.empty()) {
      const auto n = stack.back();
      const auto& node = aig.nodes()[n];
      if (node.kind == Aig::NodeKind::Input)
        throw UnsupportedConstruct("write_promela: an LTL atom reads inputs");
      if (node.kind != Aig::NodeKind::And || defined[n]) {
        stack.pop_back();
        continue;
      }
      const auto l = Aig::node_of(node.left), r = Aig::node_of(node.right);
      const bool ready_l = aig.nodes()[l].kind != Aig::NodeKind::And || defined[l];
      const bool ready_r = aig.nodes()[r].kind != Aig::NodeKind::And || defined[r];
      if (!ready_l) stack.push_back(l);
      if (!ready_r) stack.push_back(r);
      if (!ready_l || !ready_r) continue;
      out << "#define sfcv_g" << n << " (" << ref(node.left) << " && " << ref(node.right) << ")\n";
      defined[n] = true;
      stack.pop_back();
    }
  };
  out << "\n";
  for (std::size_t k = 0; k < m.ltl_atoms.size(); ++k) {
    define(m.ltl_atoms[k]);
    out << "#define sfcv_atom_" << k << " (" << ref(m.ltl_atoms[k]) << ")\n";
  }
  out << "#define sfcv_start (cycle@sfcv_cycle)\n";
}
}  // namespace

void write_promela(std::ostream& out, const CircuitExport& m, std::optional<std::size_t> only_bad) {
  const Aig& aig = m.aig;
  // The assertion is checked on a state before its inputs are chosen.
  for (const auto& b : aig.bad())
    if (depends_on_inputs(aig, b.literal))
      throw UnsupportedConstruct("write_promela: invariant " + b.name + " reads inputs");
  auto reserved = kPromelaReserved;
  for (const char* internal : {"assumed", "cycle", "end_excluded"}) reserved.insert(internal);
  // Names of Spin's generated C verifier (pan.c): struct types P<n>/Q<n> per process and
  // channel, and its globals; a Promela variable of that name breaks the C compilation.
  for (int k = 0; k < 1000; ++k) {
    reserved.insert("P" + std::to_string(k));
    reserved.insert("Q" + std::to_string(k));
  }
  for (const char* pan :
       {"now",    "depth",  "trpt",   "errors",    "nstates", "verbose", "Maxbody",  "Stack",
        "State",  "Trans",  "path",   "tau",       "memlim",  "hmax",    "mreached", "A_",
        "Mask",   "vsize",  "Uerror", "Nr_Trails", "main",    "exit",    "abort",    "printf",
        "memcpy", "memset", "strlen", "signal",    "time",    "stdout"})
    reserved.insert(pan);
  for (std::size_t l = 0; l < aig.latches().size(); ++l)
    reserved.insert("next_" + std::to_string(l));
  Naming names(aig, std::move(reserved));
  auto lit = [&names](AigLit l) { return names.lit(l, "1", "0", "!"); };
  out << "/*\n";
  comment_lines(out, m.header, " * ", CommentKind::Block);
  out << " */\n";
  for (std::size_t l = 0; l < aig.latches().size(); ++l)
    out << "bit " << names.node[Aig::node_of(aig.latches()[l].current)] << " = "
        << (aig.latches()[l].initial ? 1 : 0) << ";"
        << (l < m.latch_comments.size()
                ? "  /* " + comment(m.latch_comments[l], CommentKind::Block) + " */"
                : "")
        << "\n";
  // Inputs, gates and next values are recomputed every cycle: hidden keeps them out of the
  // state vector, so Spin's states are exactly the circuit's latch valuations (Spin cannot
  // hide a bit, hence bytes).
  for (std::size_t i = 0; i < aig.inputs().size(); ++i)
    out << "hidden byte " << names.node[Aig::node_of(aig.inputs()[i].literal)] << ";"
        << (i < m.input_comments.size()
                ? "  /* " + comment(m.input_comments[i], CommentKind::Block) + " */"
                : "")
        << "\n";
  for (std::size_t n = 1; n < aig.nodes().size(); ++n)
    if (aig.nodes()[n].kind == Aig::NodeKind::And) out << "hidden byte " << names.node[n] << ";\n";
  for (std::size_t l = 0; l < aig.latches().size(); ++l) out << "hidden byte next_" << l << ";\n";
  if (!aig.constraints().empty()) out << "hidden byte assumed;\n";
  if (!m.ltl.empty()) write_ltl_atoms(out, m, names);
  out << "\nactive proctype cycle()\n{\n"
      << (m.ltl.empty() ? "" : "sfcv_cycle:\n") << "  do\n  :: atomic {\n";
  std::vector<std::string> gates;  // one statement per gate, in topological order
  for (std::size_t n = 1; n < aig.nodes().size(); ++n) {
    const auto& node = aig.nodes()[n];
    if (node.kind == Aig::NodeKind::And)
      gates.push_back(names.node[n] + " = " + lit(node.left) + " && " + lit(node.right) + ";");
  }
  // Spin refuses a d_step of more than MAXDSTEP statements (1024 in older versions, 2048 in
  // Debian's: "d_step sequence too long", on every xPPU scenario): consecutive d_steps of at
  // most 1000 inside the cycle's atomic sequence compute the same.
  auto write_d_steps = [&out](const std::vector<std::string>& statements) {
    constexpr std::size_t kMaxDStep = 1000;
    for (std::size_t i = 0; i < statements.size(); i += kMaxDStep) {
      out << "       d_step {\n";
      for (std::size_t k = i; k < std::min(statements.size(), i + kMaxDStep); ++k)
        out << "         " << statements[k] << "\n";
      out << "       }\n";
    }
  };
  for (std::size_t b = 0; b < aig.bad().size() && !gates.empty(); ++b)
    if (!only_bad || *only_bad == b) {
      // The bad literal may read gates; evaluate them on the current state first.
      write_d_steps(gates);
      break;
    }
  for (std::size_t b = 0; b < aig.bad().size(); ++b)
    if (!only_bad || *only_bad == b)
      out << "       assert(!(" << lit(aig.bad()[b].literal) << "));  /* "
          << comment(aig.bad()[b].name, CommentKind::Block) << " */\n";
  for (const auto& in : aig.inputs()) {
    const auto& id = names.node[Aig::node_of(in.literal)];
    out << "       if :: " << id << " = 0 :: " << id << " = 1 fi;\n";
  }
  std::vector<std::string> cycle = gates;
  if (!aig.constraints().empty()) {
    // A jump may not leave a d_step: decide inside, cut the run outside.
    std::string assumed = "assumed = ";
    for (std::size_t c = 0; c < aig.constraints().size(); ++c)
      assumed += (c ? " && " : "") + lit(aig.constraints()[c].literal);
    cycle.push_back(assumed + ";");
    write_d_steps(cycle);
    out << "       if :: assumed -> skip :: else -> goto end_excluded fi;\n";
    cycle.clear();
  }
  // The identifiers, not the chart names, go into the format string: a name holding '"', '%'
  // or '\\' would change the statement (spin_runner.cpp reads the values by position).
  std::string print = "printf(\"@cycle";
  for (const auto& in : aig.inputs()) print += " " + names.node[Aig::node_of(in.literal)] + "=%d";
  print += "\\n\"";
  for (const auto& in : aig.inputs()) print += ", " + names.node[Aig::node_of(in.literal)];
  cycle.push_back(print + ");");
  for (std::size_t l = 0; l < aig.latches().size(); ++l)
    cycle.push_back("next_" + std::to_string(l) + " = " + lit(aig.latches()[l].next) + ";");
  for (std::size_t l = 0; l < aig.latches().size(); ++l)
    cycle.push_back(names.node[Aig::node_of(aig.latches()[l].current)] + " = next_" +
                    std::to_string(l) + ";");
  write_d_steps(cycle);
  out << "     }\n  od;\n";
  if (!aig.constraints().empty())
    out << "end_excluded:  /* an assumption excludes these inputs: the run is cut here */\n"
           "  false\n";
  out << "}\n";
  for (std::size_t k = 0; k < m.ltl.size(); ++k) {
    std::string claim;
    const auto& text = m.ltl[k].second;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] != '{') {
        claim += text[i];
        continue;
      }
      const auto close = text.find('}', i);
      const auto key = text.substr(i + 1, close - i - 1);
      claim += key == "b" ? "sfcv_start" : "sfcv_atom_" + key;
      i = close;
    }
    out << "\n/* " << comment(m.ltl[k].first, CommentKind::Block) << " */\nltl sfcv_ltl_" << k
        << " { " << claim << " }\n";
  }
}

}  // namespace sfcv::engine
