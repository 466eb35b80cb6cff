#include "io/plcopen_network.hpp"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include "io/plcopen_st.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"
#include "model/types.hpp"

namespace sfcv::io::plcopen {

namespace {
using model::ExprKind;
using model::ExprPtr;

bool is_true_const(const ExprPtr& e) {
  return e && e->kind == ExprKind::BoolConst && e->value == 1;
}

ExprPtr negate_if(bool negated, ExprPtr e) {
  if (!negated || !e) return e;
  auto where = e->where;
  return model::make_unary(ExprKind::Not, std::move(e), std::move(where));
}

// Functions of the standard library the model can express.
/// User: a FUNCTION of the project, called with the block's formal parameters.
// Standard: the other standard functions the semantics models (MAX, MIN, LIMIT, SEL, MUX, ABS,
// the shifts and rotations, *_TO_* conversions), read as a formal call with the block's
// parameter names, which the semantics puts in the standard's order.
enum class Fn { None, And, Or, Xor, Not, Move, Cmp, Add, Mul, Sub, Div, Mod, Standard, User };

Fn function_of(std::string_view type, ExprKind& cmp) {
  const std::string t = model::to_upper(type);
  if (t == "AND") return Fn::And;
  if (t == "OR") return Fn::Or;
  if (t == "XOR") return Fn::Xor;
  if (t == "NOT") return Fn::Not;
  if (t == "MOVE") return Fn::Move;
  if (t == "ADD") return Fn::Add;
  if (t == "MUL") return Fn::Mul;
  if (t == "SUB") return Fn::Sub;
  if (t == "DIV") return Fn::Div;
  if (t == "MOD") return Fn::Mod;
  static const std::pair<const char*, ExprKind> cmps[] = {
      {"GT", ExprKind::Gt}, {"GE", ExprKind::Ge}, {"EQ", ExprKind::Eq},
      {"NE", ExprKind::Ne}, {"LT", ExprKind::Lt}, {"LE", ExprKind::Le}};
  for (const auto& [name, kind] : cmps)
    if (t == name) {
      cmp = kind;
      return Fn::Cmp;
    }
  static const char* const standard[] = {"MAX", "MIN", "LIMIT", "SEL", "MUX",
                                         "ABS", "SHL", "SHR",   "ROL", "ROR"};
  for (const char* name : standard)
    if (t == name) return Fn::Standard;
  if (t.find("_TO_") != std::string::npos) return Fn::Standard;
  return Fn::None;
}

bool is_output_element(std::string_view n) {
  return n == "outVariable" || n == "inOutVariable" || n == "coil";
}
}  // namespace

model::StmtPtr make_if_assign(model::ExprPtr cond, std::string target, model::ExprPtr value,
                              model::SourceLocation where) {
  auto s = std::make_shared<model::Stmt>();
  s->kind = model::StmtKind::If;
  s->where = where;
  s->conditions.push_back(std::move(cond));
  s->bodies.push_back({model::make_assign(std::move(target), std::move(value), where)});
  return s;
}

namespace {

/// Every `connection` element under `n`, at any depth.
void for_each_connection(pugi::xml_node n, const std::function<void(pugi::xml_node)>& f) {
  std::vector<pugi::xml_node> stack{n};
  while (!stack.empty()) {
    const auto e = stack.back();
    stack.pop_back();
    for (auto c : element_children(e)) {
      if (local_name(c) == "connection") f(c);
      stack.push_back(c);
    }
  }
}

bool has_connected_enable(pugi::xml_node block) {
  if (local_name(block) != "block") return false;
  for (auto v : children(child(block, "inputVariables"), "variable"))
    if (model::iequals(v.attribute("formalParameter").value(), "EN"))
      if (const auto cpi = child(v, "connectionPointIn"); cpi && child(cpi, "connection"))
        return true;
  return false;
}

bool is_leaf(const model::Expr& e) {
  switch (e.kind) {
    case ExprKind::BoolConst:
    case ExprKind::IntConst:
    case ExprKind::TimeConst:
    case ExprKind::Name:
    case ExprKind::Member:
      return true;
    default:
      return false;
  }
}

/// The size of `e` as a tree (shared nodes counted at each use), saturated above `cap`.
std::uint64_t unfolded_size(const model::Expr& e, std::uint64_t cap,
                            std::unordered_map<const model::Expr*, std::uint64_t>& known) {
  if (const auto it = known.find(&e); it != known.end()) return it->second;
  std::uint64_t n = 1;
  for (const auto& a : e.args) {
    if (a) n += unfolded_size(*a, cap, known);
    if (n > cap) {
      n = cap + 1;
      break;
    }
  }
  known.emplace(&e, n);
  return n;
}

}  // namespace

Network::Network(pugi::xml_node container, const XmlContext& ctx, model::Diagnostics& problems,
                 std::string edge_prefix, const std::vector<model::Variable>* declared)
    : ctx_(ctx), problems_(problems), edge_prefix_(std::move(edge_prefix)), container_(container) {
  if (declared)
    for (const auto& v : *declared) declared_types_.emplace(model::to_upper(v.name), v.type);
  std::map<std::string, int> continuations;  // connector name -> continuations reading it
  for (auto n : element_children(container)) {
    ctx_.poll();
    if (const auto id = n.attribute("localId")) by_id_.emplace(id.value(), n);
    if (local_name(n) == "connector")
      connectors_.emplace(model::to_upper(n.attribute("name").value()), n);
    if (local_name(n) == "continuation")
      ++continuations[model::to_upper(n.attribute("name").value())];
  }
  for_each_connection(container,
                      [&](pugi::xml_node c) { ++fan_out_[c.attribute("refLocalId").value()]; });
  // Each continuation reads what feeds its connector once more.
  for (const auto& [name, count] : continuations)
    if (const auto it = connectors_.find(name); it != connectors_.end() && count > 1)
      for_each_connection(it->second, [&, count = count](pugi::xml_node c) {
        fan_out_[c.attribute("refLocalId").value()] += count - 1;
      });
}

ExprPtr Network::fail(pugi::xml_node node, std::string message) {
  problems_.push_back({model::Severity::Error, ctx_.where(node), std::move(message)});
  return nullptr;
}

model::StmtList Network::take_calls() {
  return std::exchange(calls_, {});
}

std::vector<model::Variable> Network::take_edge_instances() {
  return std::exchange(edge_instances_, {});
}

// IEC 61131-3 (4.2.3, 4.2.4): a positive/negative transition-sensing contact or coil passes
// power for one evaluation when its operand rises/falls: an R_TRIG/F_TRIG of the operand,
// called where the element is evaluated.
ExprPtr Network::edge_of(pugi::xml_node node, const std::string& edge, ExprPtr value) {
  if (edge != "rising" && edge != "falling")
    return fail(node,
                "unsupported: " + std::string(local_name(node)) + " with edge '" + edge + "'");
  const std::string name = "SFCV_EDGE_" + (edge_prefix_.empty() ? "" : edge_prefix_ + "_") +
                           node.attribute("localId").value();
  // A contact read by several outputs is one element, evaluated once per cycle: the later
  // statements read the Q of the first one's call (a second R_TRIG would also clash by name).
  if (!edges_.insert(name).second) return model::make_member(name, "Q", ctx_.where(node));
  model::Variable v;
  v.name = name;
  v.direction = model::VarDirection::Local;
  v.type = model::Type::function_block(edge == "rising" ? model::StandardFb::R_TRIG
                                                        : model::StandardFb::F_TRIG);
  v.where = ctx_.where(node);
  declared_types_.emplace(model::to_upper(name), v.type);
  edge_instances_.push_back(std::move(v));
  calls_.push_back(model::make_fb_call(name, {{"CLK", std::move(value)}}, ctx_.where(node)));
  return model::make_member(name, "Q", ctx_.where(node));
}

ExprPtr Network::input(pugi::xml_node cpi, pugi::xml_node owner) {
  const auto connections = children(cpi, "connection");
  if (connections.empty()) {
    const auto at = owner ? owner : cpi ? cpi.parent() : container_;
    return fail(at, std::string(local_name(at)) + ": input is not connected");
  }
  std::vector<ExprPtr> alternatives;
  for (auto c : connections) {
    auto v = value(c);
    if (!v) return nullptr;
    alternatives.push_back(std::move(v));
  }
  if (alternatives.size() == 1) return alternatives.front();
  // LD parallel branches; a branch straight from the power rail makes the whole OR true.
  for (const auto& a : alternatives)
    if (is_true_const(a)) return a;
  return model::make_nary(ExprKind::Or, std::move(alternatives), ctx_.where(cpi));
}

ExprPtr Network::value(pugi::xml_node connection) {
  const std::string ref = connection.attribute("refLocalId").value();
  const auto it = by_id_.find(ref);
  if (ref.empty() || it == by_id_.end())
    return fail(connection, "connection to unknown localId '" + ref + "'");
  const std::string pin = connection.attribute("formalParameter").value();
  const auto node = it->second;
  // A function with EN is modelled only where its result goes straight to one variable.
  if (fan_out_[ref] < 2 || has_connected_enable(node)) return node_value(node, pin);
  const std::string key = ref + "/" + pin;
  if (const auto m = memo_.find(key); m != memo_.end()) return m->second;
  auto v = node_value(node, pin);
  if (!v) return nullptr;
  v = shared(node, pin, std::move(v));
  if (v) memo_.emplace(key, v);
  return v;
}

ExprPtr Network::shared(pugi::xml_node node, const std::string& pin, ExprPtr v) {
  // Small values stay written out (the body reads as the network does); past kHoistedSize a
  // value is shared, so no chain of shared elements doubles more than a few levels.
  constexpr std::uint64_t kHoistedSize = 16;
  std::unordered_map<const model::Expr*, std::uint64_t> known;
  if (!hoist_ || is_leaf(*v) || unfolded_size(*v, kHoistedSize, known) <= kHoistedSize ||
      !is_boolean(*v))
    return v;
  // One evaluation per element (IEC 61131-3 FBD: an element's outputs are evaluated once its
  // inputs are), held in a hidden temporary the body assigns before the first reader.
  const std::string name = "SFCV_NET_" + (edge_prefix_.empty() ? "" : edge_prefix_ + "_") +
                           node.attribute("localId").value() + (pin.empty() ? "" : "_" + pin);
  const auto where = ctx_.where(node);
  if (std::find(temporaries_.begin(), temporaries_.end(), name) == temporaries_.end()) {
    model::Variable t;
    t.name = name;
    t.direction = model::VarDirection::Local;
    t.type = model::Type::boolean();
    t.initial = 0;
    t.where = where;
    declared_types_.emplace(model::to_upper(name), t.type);
    edge_instances_.push_back(std::move(t));
    temporaries_.push_back(name);
  }
  calls_.push_back(model::make_assign(name, std::move(v), where));
  return model::make_name(name, where);
}

std::optional<model::Type> Network::declared_type(const std::string& name) const {
  const auto it = declared_types_.find(model::to_upper(name));
  if (it == declared_types_.end()) return std::nullopt;
  return it->second;
}

bool Network::is_boolean(const model::Expr& e) const {
  switch (e.kind) {
    case ExprKind::BoolConst:
    case ExprKind::Eq:
    case ExprKind::Ne:
    case ExprKind::Lt:
    case ExprKind::Le:
    case ExprKind::Gt:
    case ExprKind::Ge:
      return true;
    case ExprKind::Not:
    case ExprKind::And:
    case ExprKind::Or:
    case ExprKind::Xor:
      return std::all_of(e.args.begin(), e.args.end(),
                         [&](const ExprPtr& a) { return a && is_boolean(*a); });
    case ExprKind::Name: {
      const auto t = declared_type(e.name);
      return t && t->kind == model::TypeKind::Bool;
    }
    case ExprKind::Member: {
      // The Boolean outputs of the standard function blocks.
      const auto t = declared_type(e.name);
      return t && t->kind == model::TypeKind::FunctionBlock && t->fb != model::StandardFb::None &&
             (model::iequals(e.member, "Q") || model::iequals(e.member, "Q1") ||
              model::iequals(e.member, "QU") || model::iequals(e.member, "QD"));
    }
    default:
      return false;
  }
}

bool Network::within_unfolded_bound(const ExprPtr& v, pugi::xml_node at) {
  std::unordered_map<const model::Expr*, std::uint64_t> known;
  if (unfolded_size(*v, kMaxUnfoldedOperations, known) <= kMaxUnfoldedOperations) return true;
  fail(at, "unsupported: this value of the network unfolds into more than " +
               std::to_string(kMaxUnfoldedOperations) +
               " operations (elements whose output feeds several inputs, nested); a shared "
               "non-Boolean value is not modelled at that size");
  return false;
}

ExprPtr Network::condition(pugi::xml_node connection_point_in) {
  auto v = input(connection_point_in);
  if (v && !within_unfolded_bound(v, connection_point_in)) return nullptr;
  return v;
}

ExprPtr Network::text_value(pugi::xml_node holder, pugi::xml_node text_element) {
  if (!text_element) return fail(holder, std::string(local_name(holder)) + " has no expression");
  const auto text = body_text(text_element, ctx_);
  if (trim(text.text).empty())
    return fail(holder, std::string(local_name(holder)) + " has an empty expression");
  return parse_expression_text(text, problems_);
}

ExprPtr Network::node_value(pugi::xml_node node, const std::string& pin) {
  const std::string id = node.attribute("localId").value();
  const auto kind = local_name(node);
  // The evaluation path is the recursion depth (and the height of the expression it builds).
  if (visiting_.size() >= static_cast<std::size_t>(model::kMaxNesting))
    return fail(node, "the network is wired deeper than " + std::to_string(model::kMaxNesting) +
                          " elements from this value: not modelled");
  if (kind == "block") return block_value(node, pin);
  if (visiting_.count(id))
    return fail(node, "feedback loop through " + std::string(kind) +
                          " without a function block: the value is not defined");
  visiting_.insert(id);
  struct Leave {
    std::set<std::string>& s;
    std::string id;
    ~Leave() { s.erase(id); }
  } leave{visiting_, id};

  if (kind == "leftPowerRail") return model::make_bool(true, ctx_.where(node));
  if (kind == "inVariable" || kind == "inOutVariable")
    return negate_if(attribute_true(node, "negated"), text_value(node, child(node, "expression")));
  if (kind == "contact") {
    auto var = text_value(node, child(node, "variable"));
    if (!var) return nullptr;
    var = negate_if(attribute_true(node, "negated"), var);
    if (const auto edge = std::string(node.attribute("edge").value());
        !edge.empty() && edge != "none") {
      var = edge_of(node, edge, var);
      if (!var) return nullptr;
    }
    auto in = input(child(node, "connectionPointIn"), node);
    if (!in) return nullptr;
    if (is_true_const(in)) return var;
    return model::make_nary(ExprKind::And, {in, var}, ctx_.where(node));
  }
  if (kind == "coil") return input(child(node, "connectionPointIn"), node);  // power flows through
  if (kind == "continuation") {
    const auto it = connectors_.find(model::to_upper(node.attribute("name").value()));
    if (it == connectors_.end())
      return fail(node, std::string("continuation '") + node.attribute("name").value() +
                            "' has no connector of that name");
    return input(child(it->second, "connectionPointIn"), it->second);
  }
  return fail(node, "unsupported: a " + std::string(kind) + " cannot be used as a value here");
}

ExprPtr Network::in_out_variable(pugi::xml_node block, pugi::xml_node pin) {
  const std::string f = pin.attribute("formalParameter").value();
  const std::string what =
      "in/out parameter " + f + " of block " + std::string(block.attribute("typeName").value());
  const auto cpi = child(pin, "connectionPointIn");
  if (!cpi || !child(cpi, "connection"))
    return fail(pin, what + " is not connected (IEC 61131-3 requires a variable there)");
  if (attribute_true(pin, "negated") || (!std::string(pin.attribute("edge").value()).empty() &&
                                         std::string(pin.attribute("edge").value()) != "none"))
    return fail(pin, "unsupported: negated or edge " + what);
  auto bound = input(cpi);
  if (!bound) return nullptr;
  if (bound->kind != ExprKind::Name && bound->kind != ExprKind::Member)
    return fail(pin, what + " is wired to '" + model::to_st(*bound) + "', which is no variable");
  return bound;
}

ExprPtr Network::block_value(pugi::xml_node block, const std::string& pin) {
  const std::string type = block.attribute("typeName").value();
  const std::string instance = block.attribute("instanceName").value();
  const auto outputs = children(child(block, "outputVariables"), "variable");
  const bool user_function =
      instance.empty() && ctx_.user_functions.count(model::to_upper(type)) > 0;
  if (!pin.empty() && (!instance.empty() || user_function))
    for (auto io : children(child(block, "inOutVariables"), "variable"))
      if (model::iequals(io.attribute("formalParameter").value(), pin)) {
        // The output side of a VAR_IN_OUT pin: the bound variable, after the call (of a
        // function: run as a statement, so its result may not be read as well).
        if (user_function && evaluated_.count(block.attribute("localId").value()))
          return fail(block, "unsupported: function " + type +
                                 " with both its result and an in/out parameter read");
        if (!call_block(block)) return nullptr;
        return in_out_variable(block, io);
      }
  if (model::iequals(pin, "ENO")) {
    // ENO is EN where nothing can clear it: a standard FB instance (called here), a standard
    // function (an error inside it is a range error of the cycle, not an ENO), and a user FB
    // or function whose POU never names ENO. One that names it may clear it: refused.
    ExprKind cmp = ExprKind::Eq;
    const auto upper = model::to_upper(type);
    const bool quiet = !ctx_.pous_naming_eno.count(upper);
    const bool function = instance.empty() && (function_of(type, cmp) != Fn::None ||
                                               (quiet && ctx_.user_functions.count(upper)));
    const bool fb_instance =
        !instance.empty() && (model::standard_fb(type) != model::StandardFb::None ||
                              (quiet && ctx_.user_function_blocks.count(upper)));
    if (!function && !fb_instance)
      return fail(block, "unsupported: ENO output of block " + type +
                             (ctx_.pous_naming_eno.count(upper) ? " (its body names ENO)" : ""));
    if (fb_instance && !call_block(block)) return nullptr;
    return enable_of(block);
  }
  bool out_negated = false;
  std::string out_pin = pin;
  for (auto o : outputs) {
    const std::string f = o.attribute("formalParameter").value();
    if (pin.empty() || model::iequals(f, pin)) {
      out_negated = attribute_true(o, "negated");
      if (out_pin.empty()) out_pin = f;
      break;
    }
  }

  if (!instance.empty() && (model::standard_fb(type) != model::StandardFb::None ||
                            ctx_.user_function_blocks.count(model::to_upper(type)))) {
    // A standard or user FB instance: called once where the network first needs it, its
    // output read as a member (`inst.Q`, which the semantics resolves for either kind).
    if (!call_block(block)) return nullptr;
    if (out_pin.empty()) return fail(block, "block " + instance + " has no output");
    return negate_if(out_negated, model::make_member(instance, out_pin, ctx_.where(block)));
  }

  ExprKind cmp = ExprKind::Eq;
  Fn fn = function_of(type, cmp);
  if (fn == Fn::None && instance.empty() && ctx_.user_functions.count(model::to_upper(type)))
    fn = Fn::User;
  if (fn == Fn::None) {
    if (!instance.empty())
      return fail(block, "unsupported: function block " + type + " (instance " + instance +
                             "): neither a standard function block (R_TRIG, F_TRIG, SR, RS, "
                             "TON, TOF, TP, CTU, CTD) nor one of this project");
    return fail(block, "unsupported: function " + type +
                           " (modelled: AND, OR, XOR, NOT, MOVE, the comparisons, ADD, SUB, MUL, "
                           "DIV, MOD, MAX, MIN, LIMIT, SEL, MUX, ABS, the shifts, *_TO_* "
                           "conversions and the project's functions)");
  }

  const std::string id = block.attribute("localId").value();
  if (visiting_.count(id))
    return fail(block, "feedback loop through function " + type + ": the value is not defined");
  visiting_.insert(id);
  struct Leave {
    std::set<std::string>& s;
    std::string id;
    ~Leave() { s.erase(id); }
  } leave{visiting_, id};

  std::vector<ExprPtr> args;
  std::vector<std::string> names;  // Fn::User: the formal parameters
  for (auto v : children(child(block, "inputVariables"), "variable")) {
    const std::string f = v.attribute("formalParameter").value();
    const auto cpi = child(v, "connectionPointIn");
    if (model::iequals(f, "EN")) {
      if (!cpi || !child(cpi, "connection")) continue;
      // With EN FALSE a function is not executed and its result is not defined: modelled only
      // where the result is assigned straight to a variable, which then keeps its value.
      if (id != enabled_function_)
        return fail(v, "unsupported: EN input of block " + type +
                           " whose result is not assigned straight to a variable");
      enabled_function_.clear();
      enable_ = enable_of(block);
      if (!enable_) return nullptr;
      continue;
    }
    if (const auto edge = std::string(v.attribute("edge").value()); !edge.empty() && edge != "none")
      return fail(v, "unsupported: " + edge + " edge input of block " + type);
    // An unconnected input of a user function has its initial value (a formal call omits it).
    if (fn == Fn::User && (!cpi || !child(cpi, "connection"))) continue;
    auto a = input(cpi, v);
    if (!a) return nullptr;
    args.push_back(negate_if(attribute_true(v, "negated"), std::move(a)));
    names.push_back(f);
  }
  const auto where = ctx_.where(block);
  auto arity = [&](std::size_t lo, std::size_t hi) {
    return args.size() >= lo && args.size() <= hi;
  };
  ExprPtr r;
  switch (fn) {
    case Fn::And:
    case Fn::Or:
    case Fn::Xor: {
      if (!arity(1, 1000)) return fail(block, type + " block without inputs");
      const auto k = fn == Fn::And ? ExprKind::And : fn == Fn::Or ? ExprKind::Or : ExprKind::Xor;
      r = args.size() == 1 ? args[0] : model::make_nary(k, args, where);
      break;
    }
    case Fn::Not:
    case Fn::Move:
      if (!arity(1, 1)) return fail(block, type + " block needs exactly one input");
      r = fn == Fn::Not ? model::make_unary(ExprKind::Not, args[0], where) : args[0];
      break;
    case Fn::Cmp: {
      if (!arity(2, 1000)) return fail(block, type + " block needs at least two inputs");
      // GT(a, b, c) is a > b AND b > c.
      std::vector<ExprPtr> parts;
      for (std::size_t i = 0; i + 1 < args.size(); ++i)
        parts.push_back(model::make_binary(cmp, args[i], args[i + 1], where));
      r = parts.size() == 1 ? parts[0] : model::make_nary(ExprKind::And, parts, where);
      break;
    }
    case Fn::Add:
    case Fn::Mul: {
      if (!arity(2, 1000)) return fail(block, type + " block needs at least two inputs");
      r = args[0];
      for (std::size_t i = 1; i < args.size(); ++i)
        r = model::make_binary(fn == Fn::Add ? ExprKind::Add : ExprKind::Mul, r, args[i], where);
      break;
    }
    case Fn::Sub:
    case Fn::Div:
    case Fn::Mod: {
      if (!arity(2, 2)) return fail(block, type + " block needs exactly two inputs");
      const auto k = fn == Fn::Sub ? ExprKind::Sub : fn == Fn::Div ? ExprKind::Div : ExprKind::Mod;
      r = model::make_binary(k, args[0], args[1], where);
      break;
    }
    case Fn::Standard:
      if (args.empty()) return fail(block, type + " block without inputs");
      r = model::make_formal_call(type, std::move(names), std::move(args), where);
      break;
    case Fn::User:
      if (outputs.size() > 1 || !children(child(block, "inOutVariables"), "variable").empty())
        return fail(block, "unsupported: function " + type +
                               (children(child(block, "inOutVariables"), "variable").empty()
                                    ? " with outputs besides its result"
                                    : " with both its result and an in/out parameter read"));
      evaluated_.insert(id);
      r = model::make_formal_call(type, std::move(names), std::move(args), where);
      break;
    case Fn::None:
      break;
  }
  return negate_if(out_negated, r);
}

bool Network::call_block(pugi::xml_node block) {
  const std::string id = block.attribute("localId").value();
  // Already called, or being called (a feedback loop: the output of the previous call is read).
  if (called_.count(id)) return true;
  called_.insert(id);
  const std::string type = block.attribute("typeName").value();
  std::vector<std::pair<std::string, ExprPtr>> args;
  ExprPtr enable;  // EN: the instance is called only when it is TRUE (IEC 61131-3 2.5.1.2)
  for (auto v : children(child(block, "inputVariables"), "variable")) {
    const std::string f = v.attribute("formalParameter").value();
    const auto cpi = child(v, "connectionPointIn");
    if (!cpi || !child(cpi, "connection")) continue;  // unconnected input keeps its value
    if (const auto edge = std::string(v.attribute("edge").value());
        !edge.empty() && edge != "none") {
      fail(v, "unsupported: " + edge + " edge input of block " + type);
      return false;
    }
    auto a = input(cpi);
    if (!a) return false;
    a = negate_if(attribute_true(v, "negated"), std::move(a));
    if (model::iequals(f, "EN"))
      enable = std::move(a);
    else
      args.emplace_back(f, std::move(a));
  }
  // A VAR_IN_OUT pin binds the variable wired to it (docs/semantics.md 1.3c); its output side
  // reads that variable after the call (block_value).
  for (auto v : children(child(block, "inOutVariables"), "variable")) {
    const std::string f = v.attribute("formalParameter").value();
    auto bound = in_out_variable(block, v);
    if (!bound) return false;
    args.emplace_back(f, std::move(bound));
  }
  // An instance, or a user function run for its effects (its in/out parameters, the globals it
  // writes) where nothing reads its result: `F(x := a, io := v);` (docs/semantics.md 1.9.1).
  const std::string instance = block.attribute("instanceName").value();
  auto call =
      model::make_fb_call(instance.empty() ? type : instance, std::move(args), ctx_.where(block));
  if (!enable) {
    calls_.push_back(std::move(call));
    return true;
  }
  // With EN FALSE the instance is not called: its outputs keep their values.
  auto guarded = std::make_shared<model::Stmt>();
  guarded->kind = model::StmtKind::If;
  guarded->where = call->where;
  guarded->conditions.push_back(std::move(enable));
  guarded->bodies.push_back({std::move(call)});
  calls_.push_back(std::move(guarded));
  return true;
}

std::string Network::straight_function(pugi::xml_node cpi) const {
  const auto connections = children(cpi, "connection");
  if (connections.size() != 1) return {};
  const auto it = by_id_.find(connections.front().attribute("refLocalId").value());
  if (it == by_id_.end() || local_name(it->second) != "block" ||
      *it->second.attribute("instanceName").value())
    return {};
  return it->second.attribute("localId").value();
}

ExprPtr Network::enable_of(pugi::xml_node block) {
  for (auto v : children(child(block, "inputVariables"), "variable")) {
    const auto cpi = child(v, "connectionPointIn");
    if (!model::iequals(v.attribute("formalParameter").value(), "EN") || !cpi ||
        !child(cpi, "connection"))
      continue;
    if (const auto edge = std::string(v.attribute("edge").value()); !edge.empty() && edge != "none")
      return fail(v, "unsupported: " + edge + " edge input of block " +
                         block.attribute("typeName").value());
    auto enable = input(cpi);
    return enable ? negate_if(attribute_true(v, "negated"), std::move(enable)) : nullptr;
  }
  return model::make_bool(true, ctx_.where(block));
}

ExprPtr Network::output_named(std::string_view name, bool& found) {
  found = false;
  for (auto n : element_children(container_)) {
    const auto kind = local_name(n);
    pugi::xml_node text;
    if (kind == "outVariable" || kind == "inOutVariable")
      text = child(n, "expression");
    else if (kind == "coil")
      text = child(n, "variable");
    else
      continue;
    if (!model::iequals(trim(body_text(text, ctx_).text), name)) continue;
    found = true;
    auto v = input(child(n, "connectionPointIn"), n);
    if (v && !within_unfolded_bound(v, n)) return nullptr;
    return negate_if(attribute_true(n, "negated"), v);
  }
  return nullptr;
}

std::vector<std::size_t> Network::variables_read(pugi::xml_node output,
                                                 const std::map<std::string, std::size_t>& at) {
  std::vector<std::size_t> out;
  std::set<std::string> seen;
  std::vector<pugi::xml_node> stack{output};
  while (!stack.empty()) {
    const auto n = stack.back();
    stack.pop_back();
    // Every connection under n (its inputs, a block's input variables), then what feeds them.
    std::vector<pugi::xml_node> walk{n};
    while (!walk.empty()) {
      const auto e = walk.back();
      walk.pop_back();
      for (auto c : element_children(e)) {
        if (local_name(c) != "connection") {
          walk.push_back(c);
          continue;
        }
        const std::string ref = c.attribute("refLocalId").value();
        if (!seen.insert(ref).second) continue;
        const auto it = by_id_.find(ref);
        if (it == by_id_.end()) continue;
        const auto from = it->second;
        const auto kind = local_name(from);
        if (kind == "inOutVariable") {  // read as the variable: stop here
          if (const auto k = at.find(ref); k != at.end()) out.push_back(k->second);
          continue;
        }
        if (kind == "continuation") {
          const auto con = connectors_.find(model::to_upper(from.attribute("name").value()));
          if (con != connectors_.end()) stack.push_back(con->second);
          continue;
        }
        stack.push_back(from);
      }
    }
  }
  return out;
}

bool Network::in_data_flow_order(std::vector<pugi::xml_node>& outputs) {
  // Without an execution order, an element reading a variable that the network assigns through
  // an inOutVariable runs after that assignment (IEC 61131-3 FBD: an element is evaluated once
  // its inputs are; Beremiz's `first_steps` CounterFBD reads `Cnt` for OUT after assigning it).
  // Otherwise document order.
  std::map<std::string, std::size_t> at;  // localId of an assigned inOutVariable -> position
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if (local_name(outputs[i]) == "inOutVariable")
      at.emplace(outputs[i].attribute("localId").value(), i);
  if (at.empty()) return true;
  std::vector<std::vector<std::size_t>> after(outputs.size());  // after[j]: the readers of j
  std::vector<std::size_t> waiting(outputs.size(), 0);
  for (std::size_t i = 0; i < outputs.size(); ++i)
    for (const auto j : variables_read(outputs[i], at))
      if (j != i) {  // an element reading its own variable reads the value before it (feedback)
        after[j].push_back(i);
        ++waiting[i];
      }
  std::vector<pugi::xml_node> order;
  std::vector<bool> done(outputs.size(), false);
  while (order.size() < outputs.size()) {
    std::size_t next = outputs.size();
    for (std::size_t i = 0; i < outputs.size() && next == outputs.size(); ++i)
      if (!done[i] && waiting[i] == 0) next = i;
    if (next == outputs.size()) {
      for (std::size_t i = 0; i < outputs.size(); ++i)
        if (!done[i]) {
          fail(outputs[i],
               "unsupported: variables of the network read each other in a cycle and no "
               "execution order is given (executionOrderId), so the order of their assignments "
               "is not defined");
          return false;
        }
    }
    done[next] = true;
    order.push_back(outputs[next]);
    for (const auto k : after[next]) --waiting[k];
  }
  outputs = std::move(order);
  return true;
}

std::optional<model::StmtList> Network::statements() {
  std::vector<pugi::xml_node> outputs;
  for (auto n : element_children(container_)) {
    const auto kind = local_name(n);
    if (kind == "rung") {
      // ESBMC's LD benchmarks list contacts and coils inside <rung>: no TC6 element, and
      // skipping it would leave an empty body (every invariant on its coils would "hold").
      fail(n,
           "unsupported: <rung> (ESBMC's LD rung shorthand) is not a PLCopen TC6 element: "
           "TC6 LD wires contacts, coils and blocks by localId and connectionPointIn");
      return std::nullopt;
    }
    if (!is_output_element(kind)) continue;
    const auto cpi = child(n, "connectionPointIn");
    if (!cpi || !child(cpi, "connection")) continue;
    outputs.push_back(n);
  }
  // FBD execution order, when the tool gave one to every output. Read through the one checked
  // conversion: an id that wrapped around would reorder the network's assignments.
  std::map<const void*, std::int64_t> order_id;
  bool ordered = !outputs.empty();
  for (auto n : outputs) {
    const std::string written = trim(n.attribute("executionOrderId").value());
    const auto id = parse_int_literal(written);
    if (!written.empty() && !id) {
      fail(n, "executionOrderId '" + written + "': " + id.error);
      return std::nullopt;
    }
    order_id[n.internal_object()] = id ? *id : 0;
    ordered = ordered && id && *id > 0;
  }
  if (ordered)
    std::stable_sort(outputs.begin(), outputs.end(), [&](auto a, auto b) {
      return order_id[a.internal_object()] < order_id[b.internal_object()];
    });
  else if (!in_data_flow_order(outputs))
    return std::nullopt;

  model::StmtList body;
  hoist_ = true;
  for (auto n : outputs) {
    // Shared elements are evaluated once per statement: across statements, each reads the
    // variables as the assignments before it left them.
    memo_.clear();
    const auto kind = local_name(n);
    const auto where = ctx_.where(n);
    const auto text = body_text(child(n, kind == "coil" ? "variable" : "expression"), ctx_);
    const std::string target = trim(text.text);
    if (target.empty()) {
      fail(n, std::string(kind) + " has no variable");
      return std::nullopt;
    }
    const auto cpi = child(n, "connectionPointIn");
    enabled_function_ = straight_function(cpi);
    enable_ = nullptr;
    auto v = input(cpi);
    enabled_function_.clear();
    if (!v || !within_unfolded_bound(v, n)) return std::nullopt;
    for (auto& c : take_calls()) body.push_back(std::move(c));
    const bool negated = attribute_true(n, "negated");
    const std::string storage = n.attribute("storage").value();
    const std::string edge = kind == "coil" ? n.attribute("edge").value() : "";
    if (enable_ && !edge.empty() && edge != "none") {
      fail(n, "unsupported: " + edge + " edge coil fed by a function with EN");
      return std::nullopt;
    }
    if (!edge.empty() && edge != "none") {
      v = edge_of(n, edge, v);
      if (!v) return std::nullopt;
      for (auto& c : take_calls()) body.push_back(std::move(c));
    }
    model::StmtPtr assignment =
        kind == "coil" && (storage == "set" || storage == "reset")
            ? make_if_assign(negate_if(negated, v), target,
                             model::make_bool(storage == "set", where), where)
            : model::make_assign(target, negate_if(negated, v), where);
    if (enable_) {
      // EN FALSE: the function does not run, the variable keeps its value.
      auto guarded = std::make_shared<model::Stmt>();
      guarded->kind = model::StmtKind::If;
      guarded->where = where;
      guarded->conditions.push_back(std::move(enable_));
      guarded->bodies.push_back({std::move(assignment)});
      assignment = std::move(guarded);
    }
    body.push_back(std::move(assignment));
  }
  // A user function whose result nobody reads still runs, as a statement, at the end (it may
  // write its in/out parameters or globals, or meet a range error).
  for (auto n : element_children(container_))
    if (local_name(n) == "block" && !*n.attribute("instanceName").value() &&
        ctx_.user_functions.count(model::to_upper(n.attribute("typeName").value())) &&
        !evaluated_.count(n.attribute("localId").value()) &&
        !called_.count(n.attribute("localId").value())) {
      if (children(child(n, "outputVariables"), "variable").size() > 1) {
        fail(n, std::string("unsupported: function ") + n.attribute("typeName").value() +
                    " with outputs besides its result");
        return std::nullopt;
      }
      if (!call_block(n)) return std::nullopt;
      for (auto& c : take_calls()) body.push_back(std::move(c));
    }
  // Function blocks whose outputs nobody reads still run.
  memo_.clear();
  for (auto n : element_children(container_)) {
    if (local_name(n) != "block" || !*n.attribute("instanceName").value()) continue;
    if (called_.count(n.attribute("localId").value())) continue;
    if (model::standard_fb(n.attribute("typeName").value()) == model::StandardFb::None &&
        !ctx_.user_function_blocks.count(model::to_upper(n.attribute("typeName").value()))) {
      fail(n, std::string("unsupported: function block ") + n.attribute("typeName").value() +
                  " (instance " + n.attribute("instanceName").value() +
                  "): not a function block of this project");
      return std::nullopt;
    }
    if (!call_block(n)) return std::nullopt;
    for (auto& c : take_calls()) body.push_back(std::move(c));
  }
  // The temporaries hold nothing between cycles (a state they kept would multiply the states).
  for (const auto& t : temporaries_)
    body.push_back(model::make_assign(t, model::make_bool(false, ctx_.where(container_)),
                                      ctx_.where(container_)));
  return body;
}

}  // namespace sfcv::io::plcopen
