// Siemens TIA Portal SimaticML exports (TIA Portal Openness): S7-GRAPH function blocks and LAD
// blocks.
//
// A `<SW.Blocks.FB>` whose ProgrammingLanguage is GRAPH holds, in its compile unit's
// `NetworkSource`, a `<Graph>` (namespace .../NetworkSource/Graph[/vN], matched on local names):
// `Sequence`s of `Steps` (Number, Init, Name, an action table), `Transitions` (conditions are
// LAD networks `FlgNet` ending in a TrCoil), `Branches` (AltBegin/AltEnd/SimBegin/SimEnd) and
// the topology in `Connections` (Direct or Jump links between StepRef, TransitionRef and
// BranchRef). The block becomes a PROGRAM POU with one chart (docs/formats.md,
// docs/semantics.md 1.13). What S7-GRAPH gives a meaning IEC 61131-3 SFC has not (supervisions,
// interlocks, permanent instructions, event actions, interlocked qualifiers, skip mode, step
// supervision times) is refused with the element path unless it is provably empty.
//
// A LAD block (FB, FC or OB) is a PROGRAM whose body is its networks, each read by LadNetwork
// as the statements of its coils and timer boxes (docs/semantics.md 1.13a); LAD permanent
// instructions before a GRAPH sequencer are read the same way into its POU's body.

#include <algorithm>
#include <cctype>
#include <functional>
#include <map>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "io/plcopen_xml_dom.hpp"
#include "model/data_types.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"
#include "model/types.hpp"

namespace sfcv::io {

namespace {

using plcopen::child;
using plcopen::children;
using plcopen::element_children;
using plcopen::local_name;
using plcopen::trim;
using plcopen::XmlContext;

// The parameters S7-GRAPH gives every sequencer FB (operating modes, sequencer control,
// display): the model reads the block in automatic mode without them, so a use is refused.
const std::set<std::string> kFbParameters = {
    "OFF_SQ",        "INIT_SQ",   "ACK_EF",    "S_PREV",     "S_NEXT",     "SW_AUTO",
    "SW_TAP",        "SW_TOP",    "SW_MAN",    "S_SEL",      "S_ON",       "S_OFF",
    "T_PUSH",        "S_NO",      "S_MORE",    "S_ACTIVE",   "ERR_FLT",    "AUTO_ON",
    "TAP_ON",        "TOP_ON",    "MAN_ON",    "REG_EF",     "ACK_S",      "REG_S",
    "HALT_SQ",       "HALT_TM",   "ZERO_OP",   "EN_IL",      "EN_SV",      "EN_ACKREQ",
    "EN_SSKIP",      "DISP_SACT", "DISP_SEF",  "DISP_SALL",  "T_PREV",     "T_NEXT",
    "SQ_HALTED",     "TM_HALTED", "OP_ZEROED", "IL_ENABLED", "SV_ENABLED", "ACKREQ_ENABLED",
    "SSKIP_ENABLED", "SACT_DISP", "SEF_DISP",  "SALL_DISP",  "S_EDGE",     "S_DISPLAY",
    "S_DISPLAYAUTO", "T_DISPLAY", "T_NO",      "T_MORE",     "T_CRIT",     "T_CRITOLD",
    "T_CRITFLT",     "ERROR",     "FAULT",     "SQ_ISOFF",   "ACK_ERR",    "ILP_MAN",
    "ACK_REQ",       "S_ACT_NO"};

bool is_identifier(const std::string& s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

std::string attr(pugi::xml_node n, const char* name) {
  return trim(n.attribute(name).value());
}

// The text of `<AttributeList><Name>` and its siblings.
std::string block_attribute(pugi::xml_node block, std::string_view name) {
  return trim(child(child(block, "AttributeList"), name).text().get());
}

// Known Graph namespaces: TIA Portal V14 SP1 (no version) to V21 (v6).
bool known_graph_namespace(const std::string& ns) {
  static const std::string base =
      "http://www.siemens.com/automation/Openness/SW/NetworkSource/Graph";
  if (ns == base) return true;
  for (int v = 1; v <= 6; ++v)
    if (ns == base + "/v" + std::to_string(v)) return true;
  return false;
}

// Where the reader keeps the names a block's networks and actions use.
struct Scope {
  model::Pou* pou = nullptr;
  std::set<std::string> steps;              ///< upper case
  std::set<std::string> fb_parameters;      ///< upper case: declared system parameters
  std::map<std::string, std::string> tags;  ///< upper-case name -> name: global PLC tags
};

class GraphBlockReader;

// One LAD network (`FlgNet`): its parts and wires read as a Boolean expression of the coil's
// input. Contacts (NO, NC) in series are AND, an `O` box joins parallel branches (OR), `Not`
// inverts the power flow, comparison boxes compare two operands.
class LadNetwork {
 public:
  LadNetwork(XmlContext& ctx, GraphBlockReader& block, pugi::xml_node net, std::string coil,
             std::string what)
      : ctx_(ctx), block_(block), net_(net), coil_(std::move(coil)), what_(std::move(what)) {}

  /// The condition feeding the coil; *empty set when the coil has no input (an empty
  /// network). Null on error.
  model::ExprPtr read(bool& empty);

  /// A network of a LAD block as statements appended to `out` (docs/semantics.md 1.13a): each
  /// coil (Coil, SCoil, RCoil) and timer box (TON, TOF, TP) in the order the power flow
  /// reaches them. False on error.
  bool statements(model::StmtList& out);

 private:
  struct Source {
    enum class Kind { Rail, Pin, Ident } kind = Kind::Rail;
    std::string uid, pin;
    pugi::xml_node node;
  };
  bool read_wires();
  bool output_pin(const std::string& uid, const std::string& pin) const;
  bool is_timer(const std::string& uid) const;
  void emit(model::StmtPtr stmt, pugi::xml_node at);
  model::ExprPtr timer_box(const std::string& uid, pugi::xml_node p);
  model::ExprPtr power(const std::string& uid, pugi::xml_node at);
  model::ExprPtr input(const std::string& uid, const std::string& pin, pugi::xml_node part,
                       bool required = true);
  model::ExprPtr operand(const std::string& uid, const std::string& pin, pugi::xml_node part,
                         const model::Type* type);
  void fail(pugi::xml_node n, const std::string& message) {
    ctx_.error(n, "unsupported: " + message + " in the LAD network of " + what_);
    ok_ = false;
  }

  XmlContext& ctx_;
  GraphBlockReader& block_;
  pugi::xml_node net_;
  std::string coil_, what_;
  std::map<std::string, pugi::xml_node> parts_, access_;
  std::vector<std::string> part_order_;  ///< UIds in document order
  std::map<std::pair<std::string, std::string>, Source> inputs_;
  std::set<std::string> visiting_, visited_;
  // Statements mode: what the network emits, the timer boxes already called (UId -> instance)
  // and the variables its coils wrote so far.
  model::StmtList* out_ = nullptr;
  std::map<std::string, std::string> called_;
  std::vector<std::string> written_;
  bool ok_ = true;
};

class GraphBlockReader {
 public:
  GraphBlockReader(XmlContext& ctx, model::Project& project) : ctx_(ctx), project_(project) {}

  void read(pugi::xml_node fb);

  const model::Pou& pou() const { return pou_; }

  /// The variable an `Access` element names, with `type` the type its use needs (null: any).
  model::ExprPtr access(pugi::xml_node a, const model::Type* type, const std::string& what);

 private:
  void interface(pugi::xml_node block);
  void ladder(pugi::xml_node block);
  void member(pugi::xml_node m, model::VarDirection dir, const std::string& section);
  void graph(pugi::xml_node g);
  void operations(pugi::xml_node ops, const char* when);
  void sequence(pugi::xml_node seq);
  void step(pugi::xml_node s, const std::string& name);
  void action(pugi::xml_node a, const std::string& step, int row);
  void guard_network(pugi::xml_node holder, const char* kind, const char* coil,
                     const std::string& step, bool empty_is_true);
  bool constant(const model::ExprPtr& e, bool value);
  void topology(pugi::xml_node seq);
  void check_operand_conflicts();
  void parallel_legs();
  bool concurrent(const std::string& a, const std::string& b) const;
  model::ExprPtr tag(const std::string& name, const model::Type& type, pugi::xml_node at);
  model::ExprPtr local(const std::string& name, pugi::xml_node at, const std::string& what);

  XmlContext& ctx_;
  model::Project& project_;
  model::Pou pou_;
  bool lad_ = false;  ///< a LAD block (its networks are its body), not a GRAPH block
  model::Chart chart_;
  Scope scope_;
  std::map<std::string, pugi::xml_node> step_nodes_;  ///< step number -> element
  std::map<std::string, std::string> step_names_;     ///< step number -> name
  std::vector<pugi::xml_node> sequences_;
  int initial_steps_ = 0;
  bool several_sequences_ = false;  ///< several sequences or initial steps: all may run together
  std::vector<std::vector<std::set<std::string>>> legs_;  ///< per simultaneous divergence
  /// Per operand (upper case): each association in table order, for the conflict rules.
  struct Use {
    std::string step;
    model::Qualifier q;
    int row;
    pugi::xml_node node;
  };
  std::map<std::string, std::vector<Use>> uses_;
};

// ------------------------------------------------------------------------------ LAD networks

bool LadNetwork::read_wires() {
  for (auto p : element_children(child(net_, "Parts"))) {
    const std::string uid = attr(p, "UId");
    const auto k = local_name(p);
    if (k == "Access") {
      access_[uid] = p;
    } else if (k == "Part") {
      parts_[uid] = p;
      part_order_.push_back(uid);
    } else {
      fail(p, "<" + std::string(k) + "> (calls and other elements are not read)");
    }
  }
  for (auto w : children(child(net_, "Wires"), "Wire")) {
    ctx_.poll();
    std::vector<Source> sources;
    std::vector<std::pair<std::string, std::string>> targets;
    for (auto c : element_children(w)) {
      const auto k = local_name(c);
      if (k == "Powerrail") {
        sources.push_back({Source::Kind::Rail, {}, {}, c});
      } else if (k == "IdentCon") {
        sources.push_back({Source::Kind::Ident, attr(c, "UId"), {}, c});
      } else if (k == "NameCon") {
        const std::string pin = attr(c, "Name");
        if (output_pin(attr(c, "UId"), pin))
          sources.push_back({Source::Kind::Pin, attr(c, "UId"), pin, c});
        else
          targets.emplace_back(attr(c, "UId"), pin);
      } else if (k == "OpenCon") {
        // An output left open (a timer's ET nobody reads): nothing to connect.
      } else {
        fail(c, "wire connection <" + std::string(k) + ">");
      }
    }
    if (sources.size() == 2 &&
        (sources[0].kind == Source::Kind::Pin) != (sources[1].kind == Source::Kind::Pin)) {
      const auto& pin = sources[0].kind == Source::Kind::Pin ? sources[0] : sources[1];
      fail(w, "output '" + pin.pin + "' of part " + pin.uid +
                  " written to an operand (box outputs are read only as power flow)");
      continue;
    }
    if (sources.size() != 1) {
      fail(w, "a wire with " + std::to_string(sources.size()) + " sources");
      continue;
    }
    for (const auto& t : targets)
      if (!inputs_.emplace(t, sources[0]).second)
        fail(w, "two wires into pin '" + t.second + "' of part " + t.first);
  }
  return ok_;
}

bool LadNetwork::is_timer(const std::string& uid) const {
  const auto it = parts_.find(uid);
  if (it == parts_.end()) return false;
  const auto name = attr(it->second, "Name");
  return name == "TON" || name == "TOF" || name == "TP";
}

// A timer box's outputs are Q and ET; every other part's are `out...` and `eno`.
bool LadNetwork::output_pin(const std::string& uid, const std::string& pin) const {
  if (is_timer(uid)) return pin == "Q" || pin == "ET" || pin == "eno";
  return pin.rfind("out", 0) == 0 || pin == "eno";
}

// A statement of the network, refused when it reads a variable a coil of the same network
// wrote before it: TIA Portal evaluates a network's power flow once, sfcv's statements one
// after the other, and the two would differ.
void LadNetwork::emit(model::StmtPtr stmt, pugi::xml_node at) {
  std::vector<model::ExprPtr> reads = stmt->conditions;
  if (stmt->value) reads.push_back(stmt->value);
  for (const auto& [pin, e] : stmt->arguments) reads.push_back(e);
  for (const auto& w : written_)
    for (const auto& e : reads)
      if (model::reads(*e, w)) {
        fail(at, "a network that reads '" + w +
                     "' after one of its coils wrote it (its power flow is evaluated once)");
        return;
      }
  if (stmt->kind == model::StmtKind::Assign) written_.push_back(stmt->target);
  if (stmt->kind == model::StmtKind::If) written_.push_back(stmt->bodies[0][0]->target);
  out_->push_back(std::move(stmt));
}

bool LadNetwork::statements(model::StmtList& out) {
  out_ = &out;
  if (!read_wires()) return false;
  const auto boolean = model::Type::boolean();
  for (const auto& uid : part_order_) {
    const auto p = parts_.at(uid);
    const std::string name = attr(p, "Name");
    if (is_timer(uid)) {
      if (!called_.count(uid)) timer_box(uid, p);
      continue;
    }
    if (name != "Coil" && name != "SCoil" && name != "RCoil") continue;
    visited_.insert(uid);
    for (auto c : element_children(p))
      if (!(local_name(c) == "Negated" && attr(c, "Name") == "operand" && name == "Coil")) {
        fail(c, "<" + std::string(local_name(c)) + "> on part '" + name + "'");
        return false;
      }
    if (inputs_.count({uid, "out"})) {
      fail(p, "a " + name + " whose output is wired on (a coil inside a rung)");
      return false;
    }
    auto in = input(uid, "in", p);
    auto op = operand(uid, "operand", p, &boolean);
    if (!in || !op) return false;
    if (op->kind != model::ExprKind::Name) {
      fail(p, "a " + name + " on an operand that is not a variable");
      return false;
    }
    const auto where = ctx_.where(p);
    if (name == "Coil") {
      if (child(p, "Negated")) in = model::make_unary(model::ExprKind::Not, in, where);
      emit(model::make_assign(op->name, in, where), p);
    } else {
      auto stmt = std::make_shared<model::Stmt>();
      stmt->kind = model::StmtKind::If;
      stmt->where = where;
      stmt->conditions.push_back(in);
      stmt->bodies.push_back(
          {model::make_assign(op->name, model::make_bool(name == "SCoil", where), where)});
      emit(std::move(stmt), p);
    }
    if (!ok_) return false;
  }
  for (const auto& uid : part_order_)
    if (!visited_.count(uid)) {
      fail(parts_.at(uid),
           "part '" + attr(parts_.at(uid), "Name") + "' (UId " + uid + ") that reaches no coil");
      return false;
    }
  return ok_;
}

// A TON/TOF/TP box on its instance (a static member of the block): the call, IN from the power
// flow and PT from its operand, emitted once; its Q is the power flow out of the box.
model::ExprPtr LadNetwork::timer_box(const std::string& uid, pugi::xml_node p) {
  visited_.insert(uid);
  if (const auto it = called_.find(uid); it != called_.end())
    return model::make_member(it->second, "Q", ctx_.where(p));
  const std::string name = attr(p, "Name");
  for (auto c : element_children(p)) {
    const auto k = local_name(c);
    if (k != "Instance" && !(k == "TemplateValue" && attr(c, "Name") == "time_type" &&
                             model::iequals(trim(c.text().get()), "Time"))) {
      fail(c, "<" + std::string(k) + "> on a " + name + " box");
      return nullptr;
    }
  }
  const auto inst = child(p, "Instance");
  std::vector<std::string> path;
  for (auto c : children(inst, "Component")) path.push_back(attr(c, "Name"));
  if (!inst || attr(inst, "Scope") != "LocalVariable" || path.size() != 1) {
    fail(p, "a " + name + " box whose instance is not a static member of the block (a " +
                "single-instance data block is not in the file)");
    return nullptr;
  }
  const auto* v = block_.pou().find_variable(path[0]);
  if (!v || v->type.kind != model::TypeKind::FunctionBlock ||
      model::to_string(v->type.fb) != name) {
    fail(inst, "the " + name + " box's instance '" + path[0] + "' is not a static " + name +
                   " member of the block");
    return nullptr;
  }
  const auto time = model::Type::time();
  auto in = input(uid, "IN", p);
  auto pt = operand(uid, "PT", p, &time);
  if (!in || !pt) return nullptr;
  called_[uid] = v->name;
  emit(model::make_fb_call(v->name, {{"IN", in}, {"PT", pt}}, ctx_.where(p)), p);
  return model::make_member(v->name, "Q", ctx_.where(p));
}

model::ExprPtr LadNetwork::read(bool& empty) {
  empty = false;
  if (!read_wires()) return nullptr;
  std::string coil;
  for (const auto& [uid, p] : parts_)
    if (attr(p, "Name") == coil_) {
      if (!coil.empty()) {
        fail(p, "a second " + coil_);
        return nullptr;
      }
      coil = uid;
    }
  if (coil.empty()) {
    ctx_.error(net_, "the LAD network of " + what_ + " has no " + coil_);
    return nullptr;
  }
  visited_.insert(coil);
  auto e = input(coil, "in", parts_.at(coil), false);
  if (!ok_) return nullptr;
  for (const auto& [uid, p] : parts_)
    if (!visited_.count(uid)) {
      fail(p, "part '" + attr(p, "Name") + "' (UId " + uid + ") not connected to the " + coil_);
      return nullptr;
    }
  if (!e) {
    if (parts_.size() != 1 || !access_.empty()) {
      fail(parts_.at(coil), "a " + coil_ + " without input");
      return nullptr;
    }
    empty = true;
  }
  return e;
}

model::ExprPtr LadNetwork::input(const std::string& uid, const std::string& pin,
                                 pugi::xml_node part, bool required) {
  const auto it = inputs_.find({uid, pin});
  if (it == inputs_.end()) {
    if (required) fail(part, "pin '" + pin + "' of part " + uid + " unconnected");
    return nullptr;
  }
  const Source& s = it->second;
  switch (s.kind) {
    case Source::Kind::Rail:
      return model::make_bool(true, ctx_.where(s.node));
    case Source::Kind::Pin:
      if (out_ && is_timer(s.uid) && s.pin == "Q") return timer_box(s.uid, parts_.at(s.uid));
      if (s.pin != "out") {
        fail(s.node, "power flow from pin '" + s.pin + "'");
        return nullptr;
      }
      return power(s.uid, s.node);
    case Source::Kind::Ident:
      break;
  }
  fail(s.node, "an operand wired into the power-flow pin '" + pin + "'");
  return nullptr;
}

model::ExprPtr LadNetwork::operand(const std::string& uid, const std::string& pin,
                                   pugi::xml_node part, const model::Type* type) {
  const auto it = inputs_.find({uid, pin});
  if (it == inputs_.end() || it->second.kind != Source::Kind::Ident) {
    fail(part, "pin '" + pin + "' of part " + uid + " is not wired to an operand");
    return nullptr;
  }
  const auto a = access_.find(it->second.uid);
  if (a == access_.end()) {
    fail(it->second.node, "operand UId " + it->second.uid + " is not an <Access>");
    return nullptr;
  }
  auto e = block_.access(a->second, type, what_);
  if (!e) ok_ = false;
  return e;
}

model::ExprPtr and_of(model::ExprPtr a, model::ExprPtr b) {
  if (a->kind == model::ExprKind::BoolConst && a->value == 1) return b;
  std::vector<model::ExprPtr> args;
  if (a->kind == model::ExprKind::And)
    args = a->args;
  else
    args.push_back(a);
  args.push_back(std::move(b));
  return model::make_nary(model::ExprKind::And, std::move(args), a->where);
}

model::ExprPtr LadNetwork::power(const std::string& uid, pugi::xml_node at) {
  const auto pit = parts_.find(uid);
  if (pit == parts_.end()) {
    fail(at, "power flow from UId " + uid + ", which is not a part");
    return nullptr;
  }
  const auto p = pit->second;
  if (visiting_.count(uid)) {
    fail(p, "a loop through part " + uid);
    return nullptr;
  }
  visiting_.insert(uid);
  visited_.insert(uid);
  const std::string name = attr(p, "Name");
  const auto where = ctx_.where(p);
  model::ExprPtr r;
  static const std::map<std::string, model::ExprKind> comparisons = {
      {"Eq", model::ExprKind::Eq}, {"Ne", model::ExprKind::Ne}, {"Gt", model::ExprKind::Gt},
      {"Ge", model::ExprKind::Ge}, {"Lt", model::ExprKind::Lt}, {"Le", model::ExprKind::Le}};
  for (auto c : element_children(p)) {
    const auto k = local_name(c);
    const bool negated_operand =
        k == "Negated" && name == "Contact" && attr(c, "Name") == "operand";
    const bool template_value = k == "TemplateValue" && (name == "O" || comparisons.count(name));
    if (!negated_operand && !template_value) {
      fail(c, "<" + std::string(k) + "> on part '" + name + "'");
      visiting_.erase(uid);
      return nullptr;
    }
  }
  if (name == "Contact") {
    const auto boolean = model::Type::boolean();
    auto in = input(uid, "in", p);
    auto op = operand(uid, "operand", p, &boolean);
    if (in && op) {
      const auto negated = child(p, "Negated");
      if (negated) op = model::make_unary(model::ExprKind::Not, op, where);
      r = and_of(in, op);
    }
  } else if (name == "O") {
    int card = 2;
    for (auto t : children(p, "TemplateValue"))
      if (attr(t, "Name") == "Card") card = std::atoi(trim(t.text().get()).c_str());
    if (card < 2 || card > 256) {
      fail(p, "an O box of cardinality " + std::to_string(card));
    } else {
      std::vector<model::ExprPtr> args;
      for (int i = 1; i <= card; ++i) {
        auto in = input(uid, "in" + std::to_string(i), p);
        if (!in) break;
        if (in->kind == model::ExprKind::Or)
          args.insert(args.end(), in->args.begin(), in->args.end());
        else
          args.push_back(in);
      }
      if (static_cast<int>(args.size()) >= card)
        r = model::make_nary(model::ExprKind::Or, std::move(args), where);
    }
  } else if (name == "Not") {
    if (auto in = input(uid, "in", p)) r = model::make_unary(model::ExprKind::Not, in, where);
  } else if (const auto cmp = comparisons.find(name); cmp != comparisons.end()) {
    // The compared type is the box's SrcType: it types the PLC tags it reads.
    std::optional<model::Type> type;
    for (auto t : children(p, "TemplateValue"))
      if (attr(t, "Name") == "SrcType") type = model::elementary_type(trim(t.text().get()));
    if (!type || type->kind == model::TypeKind::FunctionBlock) {
      fail(p, "comparison box '" + name + "' without an integer or TIME SrcType");
    } else {
      const std::string pre = inputs_.count({uid, "pre"}) ? "pre" : "in";
      auto in = input(uid, pre, p);
      auto a = operand(uid, "in1", p, &*type);
      auto b = operand(uid, "in2", p, &*type);
      if (in && a && b) r = and_of(in, model::make_binary(cmp->second, a, b, where));
    }
  } else {
    fail(p, "LAD part '" + name + "' (UId " + uid + ")");
  }
  visiting_.erase(uid);
  if (!r) ok_ = false;
  return r;
}

// ------------------------------------------------------------------------------ the block

model::ExprPtr GraphBlockReader::tag(const std::string& name, const model::Type& type,
                                     pugi::xml_node at) {
  if (!is_identifier(name)) {
    ctx_.error(at, "unsupported: PLC tag name '" + name + "' (not an IEC 61131-3 identifier)");
    return nullptr;
  }
  const std::string key = model::to_upper(name);
  if (const auto* v = pou_.find_variable(name)) {
    if (!scope_.tags.count(key)) {
      ctx_.error(at, "unsupported: PLC tag \"" + name + "\" has the name of the block's own '" +
                         v->name + "' (both would be one variable)");
      return nullptr;
    }
    if (!(v->type == type)) {
      ctx_.error(at, "PLC tag \"" + name + "\" used as " + type.name + " here and as " +
                         v->type.name + " before (its type is not in the file)");
      return nullptr;
    }
    return model::make_name(v->name, ctx_.where(at));
  }
  // PLC tags are not in the block's file: declared here, typed by their first use. One that
  // nothing in the block writes is read as an input (docs/semantics.md 1.8).
  model::Variable v;
  v.name = name;
  v.type = type;
  v.direction = model::VarDirection::Local;
  v.where = ctx_.where(at);
  scope_.tags[key] = name;
  pou_.variables.push_back(std::move(v));
  return model::make_name(name, ctx_.where(at));
}

model::ExprPtr GraphBlockReader::local(const std::string& name, pugi::xml_node at,
                                       const std::string& what) {
  const std::string key = model::to_upper(name);
  if (scope_.fb_parameters.count(key) || (!pou_.find_variable(name) && kFbParameters.count(key))) {
    ctx_.error(at, "unsupported: '" + name + "' in " + what +
                       " is a parameter of S7-GRAPH's sequencer control (operating modes, "
                       "INIT_SQ, ...), which is not modelled (the block is read in automatic "
                       "mode)");
    return nullptr;
  }
  const auto* v = pou_.find_variable(name);
  if (!v || scope_.tags.count(key)) {
    ctx_.error(at, "'" + name + "' in " + what + " is not a member of the block's interface");
    return nullptr;
  }
  return model::make_name(v->name, ctx_.where(at));
}

model::ExprPtr GraphBlockReader::access(pugi::xml_node a, const model::Type* type,
                                        const std::string& what) {
  const std::string scope = attr(a, "Scope");
  if (scope == "GlobalVariable" || scope == "LocalVariable") {
    std::vector<std::string> parts;
    for (auto c : children(child(a, "Symbol"), "Component")) {
      if (!element_children(c).empty()) {
        ctx_.error(c, "unsupported: an indexed or typed access in " + what);
        return nullptr;
      }
      parts.push_back(attr(c, "Name"));
    }
    if (parts.empty()) {
      ctx_.error(a, "unsupported: an <Access> without a symbol (absolute addresses) in " + what);
      return nullptr;
    }
    if (scope == "GlobalVariable") {
      if (parts.size() != 1) {
        ctx_.error(a, "unsupported: \"" + parts[0] + "\"." + parts[1] + " in " + what +
                          " (a member of a global data block, which is not in the file)");
        return nullptr;
      }
      if (!type) {
        ctx_.error(a, "unsupported: PLC tag \"" + parts[0] + "\" in " + what +
                          " where its type cannot be told");
        return nullptr;
      }
      return tag(parts[0], *type, a);
    }
    if (parts.size() == 2 && scope_.steps.count(model::to_upper(parts[0]))) {
      const std::string m = model::to_upper(parts[1]);
      if (m != "X" && m != "T") {
        ctx_.error(a, "unsupported: '" + parts[0] + "." + parts[1] + "' in " + what +
                          " (of a step's flags and times only .X, its activity, and .T, its "
                          "activation time, are read)");
        return nullptr;
      }
      return model::make_member(parts[0], m, ctx_.where(a));
    }
    if (parts.size() != 1) {
      ctx_.error(a, "unsupported: '" + parts[0] + "." + parts[1] + "' in " + what +
                        " (members of structures, transitions or unknown steps)");
      return nullptr;
    }
    return local(parts[0], a, what);
  }
  if (scope == "LiteralConstant" || scope == "TypedConstant") {
    const std::string v = trim(child(child(a, "Constant"), "ConstantValue").text().get());
    if (auto b = plcopen::parse_bool_literal(v)) return model::make_bool(*b, ctx_.where(a));
    if (auto t = plcopen::parse_time_literal(v); t.value)
      return model::make_time(*t.value, ctx_.where(a));
    if (auto i = plcopen::parse_int_literal(v); i.value)
      return model::make_int(*i.value, ctx_.where(a));
    ctx_.error(a, "unsupported: constant '" + v + "' in " + what);
    return nullptr;
  }
  ctx_.error(a, "unsupported: an access of scope '" + scope + "' in " + what);
  return nullptr;
}

void GraphBlockReader::read(pugi::xml_node fb) {
  pou_.name = block_attribute(fb, "Name");
  pou_.kind = model::PouKind::Program;
  pou_.where = ctx_.where(fb);
  scope_.pou = &pou_;
  if (!is_identifier(pou_.name)) {
    ctx_.error(fb, "unsupported: block name '" + pou_.name + "' (not an IEC identifier)");
    return;
  }
  if (project_.find_pou(pou_.name)) {
    ctx_.error(fb, "duplicate block '" + pou_.name + "'");
    return;
  }
  // Skip mode: a step whose transitions before and after hold together is passed in the
  // same cycle; sfcv's cycle fires one evolution (docs/semantics.md 1.13).
  if (model::iequals(block_attribute(fb, "SkipSteps"), "true"))
    ctx_.error(child(child(fb, "AttributeList"), "SkipSteps"),
               "unsupported: S7-GRAPH block '" + pou_.name +
                   "' with SkipSteps (a step is skipped when the transitions before and after it "
                   "hold together; sfcv fires one evolution per cycle)");
  lad_ = block_attribute(fb, "ProgrammingLanguage") == "LAD";
  interface(fb);
  if (lad_) {
    ladder(fb);
    return;
  }
  pugi::xml_node graph_node;
  for (auto cu : children(child(fb, "ObjectList"), "SW.Blocks.CompileUnit")) {
    const auto src = child(child(cu, "AttributeList"), "NetworkSource");
    for (auto g : element_children(src)) {
      if (local_name(g) != "Graph" || graph_node) {
        ctx_.error(g, "unsupported: <" + std::string(local_name(g)) +
                          "> in the network source of a GRAPH block (one <Graph> expected)");
        continue;
      }
      graph_node = g;
    }
  }
  if (!graph_node) {
    ctx_.error(fb, "GRAPH block '" + pou_.name + "' without a <Graph> network source");
    return;
  }
  chart_.name = pou_.name;
  chart_.where = ctx_.where(graph_node);
  graph(graph_node);
  if (model::has_errors(ctx_.diagnostics())) return;
  parallel_legs();
  check_operand_conflicts();
  ctx_.note(fb, "S7-GRAPH block '" + pou_.name +
                    "' read as a program run once per cycle in automatic mode; its sequencer "
                    "control parameters (INIT_SQ, OFF_SQ, SW_MAN, ...) are not modelled");
  pou_.charts.push_back(std::move(chart_));
  project_.pous.push_back(std::move(pou_));
}

// A LAD block (docs/semantics.md 1.13a): a PROGRAM whose body is its networks, one after the
// other in the order of its compile units.
void GraphBlockReader::ladder(pugi::xml_node fb) {
  for (auto cu : children(child(fb, "ObjectList"), "SW.Blocks.CompileUnit")) {
    ctx_.poll();
    const auto attrs = child(cu, "AttributeList");
    const std::string language = trim(child(attrs, "ProgrammingLanguage").text().get());
    const auto src = child(attrs, "NetworkSource");
    if (language != "LAD") {
      ctx_.error(cu, "unsupported: a network in " + language + " in LAD block '" + pou_.name +
                         "' (LAD networks are read)");
      continue;
    }
    const auto net = child(src, "FlgNet");
    if (!net) continue;  // an empty network
    LadNetwork lad(ctx_, *this, net, "", "network " + attr(cu, "ID") + " of " + pou_.name);
    lad.statements(pou_.body);
  }
  if (model::has_errors(ctx_.diagnostics())) return;
  ctx_.note(fb, "LAD block '" + pou_.name +
                    "' read as a program run once per cycle; PLC tags it names are declared by "
                    "their use (their table is not in the file)");
  project_.pous.push_back(std::move(pou_));
}

void GraphBlockReader::interface(pugi::xml_node fb) {
  const auto sections = child(child(child(fb, "AttributeList"), "Interface"), "Sections");
  for (auto s : children(sections, "Section")) {
    const std::string name = attr(s, "Name");
    model::VarDirection dir = model::VarDirection::Local;
    if (name == "Base") continue;  // GRAPH_BASE: the system's own
    if (name == "Return") {        // an FC's return value: read when it has none
      for (auto m : children(s, "Member"))
        if (!model::iequals(attr(m, "Datatype"), "Void"))
          ctx_.error(m, "unsupported: a function's return value (" + attr(m, "Datatype") + ")");
      continue;
    }
    if (name == "Input")
      dir = model::VarDirection::Input;
    else if (name == "Output")
      dir = model::VarDirection::Output;
    else if (name != "Static" && name != "Constant" && name != "Temp" && name != "InOut") {
      ctx_.error(s, "unsupported: interface section '" + name + "'");
      continue;
    }
    for (auto m : children(s, "Member")) member(m, dir, name);
  }
}

void GraphBlockReader::member(pugi::xml_node m, model::VarDirection dir,
                              const std::string& section) {
  ctx_.poll();
  const std::string name = attr(m, "Name");
  const std::string type = attr(m, "Datatype");
  const std::string key = model::to_upper(name);
  // The step and transition structures (G7_StepPlus_V6, G7_TransitionPlus_V6...) and the
  // sequencer's run-time data are the system's: the chart itself.
  if (type.rfind("G7_", 0) == 0) return;
  if ((section == "Input" || section == "Output") && kFbParameters.count(key)) {
    scope_.fb_parameters.insert(key);
    return;
  }
  if (section == "Temp" || section == "InOut") {
    ctx_.error(m, "unsupported: " + section + " member '" + name + "' of a GRAPH block");
    return;
  }
  // TIA Portal's IEC timers (TON_TIME, the TIME variant of TON, ...) are IEC 61131-3's TON,
  // TOF and TP; their members (PT, ET, IN, Q) are listed in the member's own Sections.
  if (section == "Static") {
    const auto u = model::to_upper(type);
    for (const char* fb : {"TON", "TOF", "TP"})
      if (u == fb || u == std::string(fb) + "_TIME") {
        if (!is_identifier(name) || pou_.find_variable(name)) {
          ctx_.error(m, "duplicate or unsupported member name '" + name + "'");
          return;
        }
        model::Variable v;
        v.name = name;
        v.type = model::Type::function_block(model::standard_fb(fb));
        v.where = ctx_.where(m);
        pou_.variables.push_back(std::move(v));
        return;
      }
  }
  const auto et = model::elementary_type(type);
  if (!et || et->kind == model::TypeKind::FunctionBlock || child(m, "Sections")) {
    ctx_.error(m, "unsupported: member '" + name + "' of type " + type);
    return;
  }
  if (!is_identifier(name) || pou_.find_variable(name)) {
    ctx_.error(m, is_identifier(name) ? "duplicate member '" + name + "'"
                                      : "unsupported: member name '" + name + "'");
    return;
  }
  model::Variable v;
  v.name = name;
  v.type = *et;
  v.direction = dir;
  v.constant = section == "Constant";
  v.where = ctx_.where(m);
  if (const auto sv = child(m, "StartValue")) {
    const std::string text = trim(sv.text().get());
    std::optional<std::int64_t> value;
    if (v.type.kind == model::TypeKind::Bool) {
      if (auto b = plcopen::parse_bool_literal(text)) value = *b ? 1 : 0;
    } else if (v.type.kind == model::TypeKind::Time) {
      value = plcopen::parse_time_literal(text).value;
    } else {
      value = plcopen::parse_int_literal(text).value;
    }
    if (!value ||
        (v.type.kind == model::TypeKind::Int && (*value < v.type.lo || *value > v.type.hi))) {
      ctx_.error(sv, "start value '" + text + "' of '" + name + "' not read as " + v.type.name);
      return;
    }
    v.initial = value;
  }
  pou_.variables.push_back(std::move(v));
}

void GraphBlockReader::graph(pugi::xml_node g) {
  const std::string ns = g.attribute("xmlns").value();
  if (!known_graph_namespace(ns))
    ctx_.error(g,
               "unsupported: Graph namespace '" + ns +
                   "' (TIA Portal V14 SP1 to V21, .../NetworkSource/Graph to Graph/v6, are read)");
  for (auto c : element_children(g)) {
    const auto k = local_name(c);
    if (k == "PreOperations")
      operations(c, "before");
    else if (k == "PostOperations")
      operations(c, "after");
    else if (k == "Sequence")
      sequences_.push_back(c);
    else if (k != "AlarmsSettings" && k != "Title" && k != "Comment")
      ctx_.error(c, "unsupported: <" + std::string(k) + "> in <Graph>");
  }
  if (sequences_.empty()) ctx_.error(g, "<Graph> without a <Sequence>");
  // Step names first: networks may read any step's flags.
  for (auto seq : sequences_)
    for (auto s : children(child(seq, "Steps"), "Step")) {
      const std::string number = attr(s, "Number");
      const std::string name = attr(s, "Name");
      if (!is_identifier(name)) {
        ctx_.error(s, "unsupported: step name '" + name + "' (not an IEC identifier)");
        continue;
      }
      if (step_nodes_.count(number) || scope_.steps.count(model::to_upper(name))) {
        ctx_.error(s, "duplicate step number " + number + " or name '" + name + "'");
        continue;
      }
      step_nodes_[number] = s;
      step_names_[number] = name;
      scope_.steps.insert(model::to_upper(name));
    }
  if (model::has_errors(ctx_.diagnostics())) return;
  for (auto seq : sequences_) sequence(seq);
  several_sequences_ = sequences_.size() > 1 || initial_steps_ > 1;
}

// Permanent instructions run before or after the sequencer in every cycle. The model's POU body
// runs before the chart: LAD ones before it are the body (docs/semantics.md 1.13a); after it
// the model runs nothing, so those are refused.
void GraphBlockReader::operations(pugi::xml_node ops, const char* when) {
  int n = 0;
  for (auto c : element_children(ops)) {
    const auto k = local_name(c);
    if (k == "Title" || k == "Comment") continue;
    ++n;
    if (std::string_view(when) == "before" && k == "PermanentOperation" &&
        attr(c, "ProgrammingLanguage") == "LAD" && child(c, "FlgNet")) {
      LadNetwork lad(ctx_, *this, child(c, "FlgNet"), "",
                     "permanent instruction " + std::to_string(n) + " before the sequencer");
      lad.statements(pou_.body);
      continue;
    }
    ctx_.error(c, std::string("unsupported: permanent instruction ") + when + " the sequencer (<" +
                      std::string(k) + ">, " + attr(c, "ProgrammingLanguage") +
                      "): S7-GRAPH runs it in every cycle " + when +
                      " the chart, which is not modelled");
  }
}

void GraphBlockReader::sequence(pugi::xml_node seq) {
  for (auto c : element_children(seq)) {
    const auto k = local_name(c);
    if (k != "Title" && k != "Comment" && k != "Steps" && k != "Transitions" && k != "Branches" &&
        k != "Connections")
      ctx_.error(c, "unsupported: <" + std::string(k) + "> in <Sequence>");
  }
  for (auto s : children(child(seq, "Steps"), "Step")) {
    ctx_.poll();
    const std::string name = step_names_[attr(s, "Number")];
    if (!name.empty()) step(s, name);
  }
  topology(seq);
}

void GraphBlockReader::step(pugi::xml_node s, const std::string& name) {
  model::Step st;
  st.name = name;
  st.initial = model::iequals(attr(s, "Init"), "true");
  st.where = ctx_.where(s);
  initial_steps_ += st.initial;
  for (const char* time : {"MaximumStepTime", "WarningTime"}) {
    const std::string t = attr(s, time);
    const auto ms = plcopen::parse_time_literal(t).value;
    if (!t.empty() && (!ms || *ms != 0))
      ctx_.error(s, std::string("unsupported: step '") + name + "' has a " + time + " of " + t +
                        " (S7-GRAPH's step time supervision is not modelled)");
  }
  for (auto c : element_children(s)) {
    const auto k = local_name(c);
    if (k == "Title" || k == "Comment") continue;
    if (k == "Actions") {
      int row = 0;
      for (auto a : element_children(c)) {
        const auto ak = local_name(a);
        if (ak == "Title" || ak == "Comment") continue;
        if (ak != "Action") {
          ctx_.error(
              a, "unsupported: <" + std::string(ak) + "> in the actions of step '" + name + "'");
          continue;
        }
        action(a, name, row++);
      }
    } else if (k == "Supervisions") {
      for (auto n : element_children(c)) guard_network(n, "supervision", "SvCoil", name, false);
    } else if (k == "Interlocks") {
      for (auto n : element_children(c)) guard_network(n, "interlock", "IlCoil", name, true);
    } else {
      ctx_.error(c, "unsupported: <" + std::string(k) + "> in step '" + name + "'");
    }
  }
  chart_.steps.push_back(std::move(st));
}

// True when `e` (contacts and comparisons over at most 16 atoms) has the value `value` whatever
// its atoms are: comparisons count as free atoms, so a `true` answer holds for every input.
bool GraphBlockReader::constant(const model::ExprPtr& e, bool value) {
  std::vector<std::string> atoms;
  std::function<void(const model::Expr&)> collect = [&](const model::Expr& x) {
    if (x.kind == model::ExprKind::And || x.kind == model::ExprKind::Or ||
        x.kind == model::ExprKind::Not) {
      for (const auto& a : x.args) collect(*a);
    } else if (x.kind != model::ExprKind::BoolConst) {
      const std::string s = model::to_st(x);
      if (std::find(atoms.begin(), atoms.end(), s) == atoms.end()) atoms.push_back(s);
    }
  };
  collect(*e);
  if (atoms.size() > 16) return false;
  for (std::uint32_t bits = 0; bits < (1u << atoms.size()); ++bits) {
    std::function<bool(const model::Expr&)> eval = [&](const model::Expr& x) -> bool {
      switch (x.kind) {
        case model::ExprKind::BoolConst:
          return x.value != 0;
        case model::ExprKind::Not:
          return !eval(*x.args[0]);
        case model::ExprKind::And:
          return std::all_of(x.args.begin(), x.args.end(), [&](const auto& a) { return eval(*a); });
        case model::ExprKind::Or:
          return std::any_of(x.args.begin(), x.args.end(), [&](const auto& a) { return eval(*a); });
        default:
          break;
      }
      const auto i = std::find(atoms.begin(), atoms.end(), model::to_st(x)) - atoms.begin();
      return (bits >> i) & 1u;
    };
    if (eval(*e) != value) return false;
  }
  return true;
}

// A supervision (SvCoil) stops the sequence at its step with an error, an interlock (IlCoil)
// disables the step's interlocked actions and marks it disturbed: neither is IEC 61131-3 SFC.
// One that can never act is read as absent: a supervision whose condition is false for every
// input (or empty), an interlock whose condition is true for every input (or empty).
void GraphBlockReader::guard_network(pugi::xml_node holder, const char* kind, const char* coil,
                                     const std::string& step, bool empty_is_true) {
  const std::string what = std::string("the ") + kind + " of step '" + step + "'";
  if (attr(holder, "ProgrammingLanguage") != "LAD") {
    ctx_.error(holder, "unsupported: " + what + " in " + attr(holder, "ProgrammingLanguage") +
                           " (LAD networks are read)");
    return;
  }
  const auto net = child(holder, "FlgNet");
  if (!net) return;  // no network: nothing programmed
  bool empty = false;
  LadNetwork lad(ctx_, *this, net, coil, what);
  const auto e = lad.read(empty);
  if (!e && !empty) return;  // the network's error is reported
  if (empty || constant(e, empty_is_true)) return;
  ctx_.error(holder,
             std::string("unsupported: ") + what + " (" + model::to_st(e) + "): " +
                 (empty_is_true ? "S7-GRAPH disables the step's interlocked actions and reports "
                                  "an error while it is not satisfied"
                                : "S7-GRAPH halts the sequence at the step with an error while "
                                  "it holds") +
                 ", which is not modelled");
}

void GraphBlockReader::action(pugi::xml_node a, const std::string& step, int row) {
  std::string text;
  for (auto c : element_children(a)) {
    if (local_name(c) != "Token") {
      ctx_.error(c, "unsupported: <" + std::string(local_name(c)) + "> in an action of step '" +
                        step + "'");
      return;
    }
    text += c.attribute("Text").value();
  }
  text = trim(text);
  for (auto at : a.attributes()) {
    const std::string n = at.name();
    if (n != "Qualifier" && !trim(at.value()).empty()) {
      ctx_.error(a, "unsupported: action '" + text + "' of step '" + step + "' with " + n + "='" +
                        at.value() +
                        "' (event-dependent actions and other attributes are not modelled)");
      return;
    }
  }
  const std::string q = attr(a, "Qualifier");
  if (text.empty() && q.empty()) return;  // the table's empty last row
  const std::string where = "action '" + q + " " + text + "' of step '" + step + "'";
  static const std::map<std::string, model::Qualifier> read = {{"N", model::Qualifier::N},
                                                               {"S", model::Qualifier::S},
                                                               {"R", model::Qualifier::R},
                                                               {"D", model::Qualifier::D},
                                                               {"L", model::Qualifier::L}};
  const auto qit = read.find(q);
  if (qit == read.end()) {
    ctx_.error(a, "unsupported: qualifier '" + q + "' in " + where +
                      " (N, S, R, D and L are read; interlocked qualifiers such as NC, event "
                      "actions, CALL, counters and timers are not)");
    return;
  }
  // Operand, then for D and L the time, separated by a comma outside quotes.
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : text) {
    if (c == '"') quoted = !quoted;
    if (c == ',' && !quoted)
      fields.emplace_back();
    else
      fields.back() += c;
  }
  for (auto& f : fields) f = trim(f);
  const bool timed = model::is_timed(qit->second);
  if (fields.size() != (timed ? 2u : 1u)) {
    ctx_.error(
        a, "unsupported: " + where +
               (timed ? " (an operand and a time expected)" : " (one Boolean operand expected)"));
    return;
  }
  const std::string& op = fields[0];
  model::ExprPtr var;
  if (op.size() > 2 && op.front() == '"' && op.back() == '"' && op.find('"', 1) == op.size() - 1) {
    var = tag(op.substr(1, op.size() - 2), model::Type::boolean(), a);
  } else if (op.size() > 1 && op[0] == '#' && is_identifier(op.substr(1))) {
    var = local(op.substr(1), a, where);
    if (var)
      if (const auto* v = pou_.find_variable(var->name);
          v && v->type.kind != model::TypeKind::Bool) {
        ctx_.error(
            a, "unsupported: " + where + ": '" + v->name + "' is " + v->type.name + ", not BOOL");
        var = nullptr;
      }
  } else {
    ctx_.error(a, "unsupported: operand '" + op + "' in " + where +
                      " (a PLC tag \"name\" or a member #name of the block is read)");
    return;
  }
  if (!var) return;
  model::ActionAssociation as;
  as.chart = chart_.name;
  as.step = step;
  as.action = var->name;
  as.qualifier = qit->second;
  as.where = ctx_.where(a);
  if (timed) {
    const std::string& t = fields[1];
    if (auto ms = plcopen::parse_time_literal(t); ms.value) {
      as.duration_ms = *ms.value;
    } else if (t.size() > 1 && t[0] == '#' && pou_.find_variable(t.substr(1)) &&
               !scope_.tags.count(model::to_upper(t.substr(1)))) {
      as.duration_variable = pou_.find_variable(t.substr(1))->name;
    } else {
      ctx_.error(a, "unsupported: time '" + t + "' in " + where +
                        " (sfcv needs a constant duration: a TIME literal or a member of the "
                        "block that nothing writes; a data block's member is not in the file)");
      return;
    }
  }
  if (!pou_.find_action(var->name)) {
    model::Action act;
    act.name = var->name;
    act.kind = model::ActionBodyKind::Variable;
    act.variable = var->name;
    act.where = as.where;
    pou_.actions.push_back(std::move(act));
  }
  uses_[model::to_upper(var->name)].push_back({step, qit->second, row, a});
  pou_.associations.push_back(std::move(as));
}

// S7-GRAPH runs the action rows of the active steps in order, each writing its operand: N, D
// and L write 1 while they act and reset the operand when their step is left, S and R set and
// reset it, and the last write wins. IEC 61131-3's action control gives one value per action
// (R dominant, N or stored). Both agree when (a) an operand is either only N/D/L or only S/R,
// (b) no S follows an R of its operand in one step, and (c) no two steps that may be active
// together act on one operand; otherwise the order of the writes decides: refused.
void GraphBlockReader::check_operand_conflicts() {
  for (const auto& [op, uses] : uses_) {
    bool stored = false, plain = false;
    for (const auto& u : uses)
      (u.q == model::Qualifier::S || u.q == model::Qualifier::R ? stored : plain) = true;
    const std::string name = pou_.find_action(op) ? pou_.find_action(op)->name : op;
    if (stored && plain) {
      ctx_.error(uses.back().node,
                 "unsupported: '" + name +
                     "' is the operand of N/D/L and of S/R actions (S7-GRAPH resets an N "
                     "operand when its step is left, even one an S set; IEC 61131-3 keeps it "
                     "stored): the result depends on S7-GRAPH's write order");
      continue;
    }
    std::set<std::string> steps;
    for (std::size_t i = 0; i < uses.size(); ++i) {
      steps.insert(uses[i].step);
      for (std::size_t j = i + 1; j < uses.size(); ++j)
        if (uses[i].step == uses[j].step && uses[i].q == model::Qualifier::R &&
            uses[j].q != model::Qualifier::R) {
          ctx_.error(uses[j].node, "unsupported: '" + name + "' is reset, then set in step '" +
                                       uses[j].step +
                                       "' (S7-GRAPH's last write wins, IEC 61131-3's R wins)");
          break;
        }
    }
    bool together = false;
    for (const auto& a : steps)
      for (const auto& b : steps) together = together || (a < b && concurrent(a, b));
    if (together)
      ctx_.error(uses.back().node,
                 "unsupported: '" + name +
                     "' is the operand of actions of steps that may be active together "
                     "(simultaneous branches or several sequences): S7-GRAPH's processing "
                     "order decides its value");
  }
}

// The steps of each leg of each simultaneous divergence: from the leg's first step, through
// every transition whose sources are all in the leg (nested branches included), never through
// the convergence that joins it with the other legs.
void GraphBlockReader::parallel_legs() {
  for (const auto& d : chart_.transitions) {
    if (d.targets.size() < 2) continue;
    std::vector<std::set<std::string>> legs;
    for (const auto& first : d.targets) {
      std::set<std::string> leg = {first};
      for (bool grew = true; grew;) {
        grew = false;
        for (const auto& t : chart_.transitions) {
          const bool inside = std::all_of(t.sources.begin(), t.sources.end(),
                                          [&](const auto& s) { return leg.count(s) > 0; });
          if (!inside) continue;
          for (const auto& s : t.targets) grew = leg.insert(s).second || grew;
        }
      }
      legs.push_back(std::move(leg));
    }
    legs_.push_back(std::move(legs));
  }
}

bool GraphBlockReader::concurrent(const std::string& a, const std::string& b) const {
  if (several_sequences_) return true;
  for (const auto& legs : legs_)
    for (std::size_t i = 0; i < legs.size(); ++i)
      for (std::size_t j = 0; j < legs.size(); ++j)
        if (i != j && legs[i].count(a) && legs[j].count(b)) return true;
  return false;
}

// ------------------------------------------------------------------------------ topology

void GraphBlockReader::topology(pugi::xml_node seq) {
  struct Branch {
    std::string type;
    pugi::xml_node node;
  };
  std::map<std::string, Branch> branches;
  for (auto b : children(child(seq, "Branches"), "Branch")) {
    const std::string type = attr(b, "Type");
    if (type != "AltBegin" && type != "AltEnd" && type != "SimBegin" && type != "SimEnd") {
      ctx_.error(b, "unsupported: branch of type '" + type + "'");
      continue;
    }
    branches[attr(b, "Number")] = {type, b};
  }
  std::map<std::string, pugi::xml_node> transitions;
  for (auto t : children(child(seq, "Transitions"), "Transition"))
    transitions[attr(t, "Number")] = t;
  // A node of the drawing: "S<n>", "T<n>", "B<n>:<pin>" (pin "i<k>" / "o<k>").
  struct Link {
    std::string to;
    bool jump = false;
    pugi::xml_node node;
  };
  std::map<std::string, std::vector<Link>> out, in;
  auto ref = [&](pugi::xml_node end, bool from, std::string& key) -> bool {
    const auto r = element_children(end);
    if (r.size() != 1) return false;
    const auto k = local_name(r[0]);
    const std::string n = attr(r[0], "Number");
    if (k == "StepRef" && step_names_.count(n)) {
      key = "S" + n;
    } else if (k == "TransitionRef" && transitions.count(n)) {
      key = "T" + n;
    } else if (k == "BranchRef" && branches.count(n)) {
      const std::string pin = attr(r[0], from ? "Out" : "In");
      if (pin.empty()) return false;
      key = "B" + n + (from ? ":o" : ":i") + pin;
    } else {
      return false;
    }
    return true;
  };
  for (auto c : children(child(seq, "Connections"), "Connection")) {
    std::string from, to;
    const std::string type = trim(child(c, "LinkType").text().get());
    if (!ref(child(c, "NodeFrom"), true, from) || !ref(child(c, "NodeTo"), false, to) ||
        (type != "Direct" && type != "Jump")) {
      ctx_.error(c, "unsupported: connection (an unknown node, pin or link type '" + type + "')");
      continue;
    }
    if (type == "Jump" && (from[0] != 'T' || to[0] != 'S')) {
      ctx_.error(c, "unsupported: a jump from " + from + " to " + to +
                        " (jumps lead from a transition to a step)");
      continue;
    }
    out[from].push_back({to, type == "Jump", c});
    in[to].push_back({from, type == "Jump", c});
  }
  if (model::has_errors(ctx_.diagnostics())) return;
  auto branch_of = [&](const std::string& key) -> const Branch& {
    return branches.at(key.substr(1, key.find(':') - 1));
  };
  // Pins of a branch: every connection into or out of it, keyed by the branch number.
  auto pins = [&](const std::string& key, const std::map<std::string, std::vector<Link>>& m,
                  const char* side) {
    std::vector<std::pair<int, std::string>> r;
    const std::string prefix = key.substr(0, key.find(':')) + side;
    for (auto it = m.lower_bound(prefix); it != m.end() && it->first.rfind(prefix, 0) == 0; ++it)
      r.emplace_back(std::atoi(it->first.c_str() + prefix.size()), it->first);
    std::sort(r.begin(), r.end());
    return r;
  };
  // The steps a transition leaves (walking its inputs back through an AltBegin or a SimEnd)
  // and enters (walking its outputs on through an AltEnd or a SimBegin).
  struct Side {
    const std::map<std::string, std::vector<Link>>& links;
    const char* pin;
    const char* alternative;   ///< one pin, followed
    const char* simultaneous;  ///< every pin, followed
  };
  const Side leaving{in, ":i", "AltBegin", "SimEnd"}, entering{out, ":o", "AltEnd", "SimBegin"};
  std::function<bool(const Side&, const std::string&, std::vector<std::string>&, int)> walk =
      [&](const Side& side, const std::string& key, std::vector<std::string>& r,
          int depth) -> bool {
    if (depth > model::kMaxNesting) return false;
    if (key[0] == 'S') {
      r.push_back(step_names_.at(key.substr(1)));
      return true;
    }
    if (key[0] != 'B') return false;
    const auto& b = branch_of(key);
    if (b.type == side.alternative) {
      const auto ps = pins(key, side.links, side.pin);
      if (ps.size() != 1 || side.links.at(ps[0].second).size() != 1) return false;
      return walk(side, side.links.at(ps[0].second)[0].to, r, depth + 1);
    }
    if (b.type == side.simultaneous) {
      for (const auto& [index, pin] : pins(key, side.links, side.pin))
        if (side.links.at(pin).size() != 1 || !walk(side, side.links.at(pin)[0].to, r, depth + 1))
          return false;
      return true;
    }
    return false;
  };
  const auto sources = [&](const std::string& key, std::vector<std::string>& r, int depth) {
    return walk(leaving, key, r, depth);
  };
  const auto targets = [&](const std::string& key, std::vector<std::string>& r, int depth) {
    return walk(entering, key, r, depth);
  };
  for (const auto& [key, links] : out)
    if (key[0] == 'S' && links.size() > 1)
      ctx_.error(links[1].node, "step '" + step_names_.at(key.substr(1)) +
                                    "' has several outgoing connections (alternatives are drawn "
                                    "with an AltBegin branch)");
  struct Read {
    model::Transition t;
    std::string branch;  ///< the AltBegin it leaves, if any
    int anchor = 0;      ///< its number, or the smallest number of its branch's transitions
    int leg = 0;
    int number = 0;
  };
  std::vector<Read> read;
  for (const auto& [number, node] : transitions) {
    ctx_.poll();
    const std::string key = "T" + number;
    Read r;
    r.t.name = attr(node, "Name");
    r.t.where = ctx_.where(node);
    r.number = std::atoi(number.c_str());
    if (!is_identifier(r.t.name)) {
      ctx_.error(node, "unsupported: transition name '" + r.t.name + "'");
      continue;
    }
    const auto& ins = in[key];
    const auto& outs = out[key];
    if (ins.size() != 1) {
      ctx_.error(node, "transition '" + r.t.name + "' has " + std::to_string(ins.size()) +
                           " incoming connections (one expected)");
      continue;
    }
    if (outs.empty()) {
      ctx_.error(node, "unsupported: transition '" + r.t.name +
                           "' ends in a branch stop (IEC 61131-3 transitions lead to steps)");
      continue;
    }
    if (outs.size() != 1) {
      ctx_.error(node, "transition '" + r.t.name + "' has " + std::to_string(outs.size()) +
                           " outgoing connections (one expected)");
      continue;
    }
    const std::string& before = ins[0].to;
    if (before[0] == 'B' && branch_of(before).type == "AltBegin") {
      r.leg = std::atoi(before.c_str() + before.find(":o") + 2);
      r.branch = before.substr(0, before.find(':'));
    }
    if (!sources(before, r.t.sources, 0) || !targets(outs[0].to, r.t.targets, 0)) {
      ctx_.error(node, "unsupported: the branches around transition '" + r.t.name +
                           "' are not drawn as S7-GRAPH draws them (a step before it, through "
                           "an AltBegin or a SimEnd; a step after it, through an AltEnd or a "
                           "SimBegin)");
      continue;
    }
    if (model::iequals(attr(node, "IsMissing"), "true") ||
        attr(node, "ProgrammingLanguage") != "LAD") {
      ctx_.error(node, "unsupported: transition '" + r.t.name + "' without a LAD condition");
      continue;
    }
    bool empty = false;
    LadNetwork lad(ctx_, *this, child(node, "FlgNet"), "TrCoil", "transition '" + r.t.name + "'");
    r.t.guard = lad.read(empty);
    if (empty)
      ctx_.error(node,
                 "transition '" + r.t.name + "' has an empty condition (its TrCoil has no input)");
    if (!r.t.guard) continue;
    read.push_back(std::move(r));
  }
  // An alternative branch's transitions are read left to right (Out 0 first), as drawn: the
  // model's document order, which decides when several hold (docs/semantics.md 1.13).
  std::map<std::string, int> first;
  for (const auto& r : read)
    if (!r.branch.empty())
      first[r.branch] = first.count(r.branch) ? std::min(first[r.branch], r.number) : r.number;
  for (auto& r : read) r.anchor = r.branch.empty() ? r.number : first[r.branch];
  std::sort(read.begin(), read.end(), [](const Read& a, const Read& b) {
    if (a.anchor != b.anchor) return a.anchor < b.anchor;
    return a.leg != b.leg ? a.leg < b.leg : a.number < b.number;
  });
  for (auto& r : read) {
    r.t.order = static_cast<int>(chart_.transitions.size());
    chart_.transitions.push_back(std::move(r.t));
  }
}

}  // namespace

LoadResult load_simatic_graph(std::string_view text, const std::string& file,
                              const model::Budget* budget) {
  model::Project project;
  project.source_format = "simaticml-graph";
  project.dialect = model::Dialect::Iec61131;
  project.where.file = file;
  model::Diagnostics diags;
  bool any_graph = false;
  {
    XmlContext ctx(file, text, diags, budget);
    pugi::xml_document doc;
    if (plcopen::load_document(doc, text, ctx)) {
      const auto root = doc.document_element();
      if (local_name(root) != "Document") {
        ctx.error(root, "not a SimaticML export: the root element is <" + std::string(root.name()) +
                            ">, not <Document>");
      } else {
        if (const std::string v = attr(child(root, "Engineering"), "version"); !v.empty())
          project.source_format += " " + v;
        for (auto b : element_children(root)) {
          ctx.poll();
          const std::string k(local_name(b));
          if (k == "Engineering" || k == "DocumentInfo") continue;
          const std::string language = block_attribute(b, "ProgrammingLanguage");
          const bool graph = k == "SW.Blocks.FB" && language == "GRAPH";
          const bool lad = (k == "SW.Blocks.FB" || k == "SW.Blocks.FC" || k == "SW.Blocks.OB") &&
                           language == "LAD";
          if (!graph && !lad) {
            ctx.error(b, "unsupported: Siemens TIA Portal SimaticML: <" + k + "> '" +
                             block_attribute(b, "Name") + "'" +
                             (language.empty() ? "" : " in " + language) +
                             " is not read (S7-GRAPH function blocks and LAD blocks are)");
            continue;
          }
          if (const std::string v = block_attribute(b, "GraphVersion"); !v.empty())
            project.source_format += " (GRAPH " + v + ")";
          any_graph = any_graph || graph;
          GraphBlockReader(ctx, project).read(b);
        }
      }
    }
  }
  if (project.pous.empty() && !model::has_errors(diags))
    diags.push_back(
        {model::Severity::Error, project.where, "no S7-GRAPH or LAD block in the file"});
  if (!project.pous.empty()) project.name = project.pous.front().name;
  if (!any_graph) project.source_format.replace(0, 15, "simaticml-lad");  // "simaticml-graph"
  if (!model::has_errors(diags)) model::lower_data_types(project, diags);
  LoadResult r;
  if (!model::has_errors(diags)) r.project = std::move(project);
  r.diagnostics = std::move(diags);
  return r;
}

}  // namespace sfcv::io
