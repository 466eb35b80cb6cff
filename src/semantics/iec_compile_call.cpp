// The IEC compiler's function calls: user FUNCTIONs (iec_compile_function.cpp) and the
// standard functions (IEC 61131-3 table of standard functions: MAX, MIN,
// LIMIT, SEL, MUX, ABS, MOVE, GT..LT, ADD..MOD, NOT/AND/OR/XOR, *_TO_* conversions) and bit
// strings (BYTE/WORD/DWORD: bitwise AND/OR/XOR/NOT, SHL/SHR/ROL/ROR, bit access `w.3`), all
// into existing Program nodes plus Ite, RangeCheck and the bit-string operators.

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <vector>

#include "model/expr.hpp"
#include "model/names.hpp"
#include "model/types.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

namespace {

int width_of_range(std::int64_t lo, std::int64_t hi) {
  if (lo != 0) return -1;
  if (hi == 255) return 8;
  if (hi == 65535) return 16;
  if (hi == 4294967295LL) return 32;
  return -1;
}

/// The call with its formal arguments (`LIMIT(MN := 0, IN := x, MX := 9)`) put in the order of
/// the standard function's parameters (IEC 61131-3 2.5.1.5): IN1..INn for the extensible and
/// binary ones, G/IN0/IN1 for SEL, MN/IN/MX for LIMIT, K/IN0..INn for MUX, IN/N for the shifts,
/// IN for the unary ones. Null with `why` when they do not fit; EN is refused: in an expression
/// the result is undefined while it is FALSE.
model::ExprPtr in_parameter_order(const model::Expr& e, std::string& why) {
  const auto f = model::to_upper(e.name);
  const auto n = e.args.size();
  std::vector<std::string> order;
  if (f == "SEL") {
    order = {"G", "IN0", "IN1"};
  } else if (f == "LIMIT") {
    order = {"MN", "IN", "MX"};
  } else if (f == "MUX") {
    order = {"K"};
    for (std::size_t i = 0; i + 1 < n; ++i) order.push_back("IN" + std::to_string(i));
  } else if (f == "SHL" || f == "SHR" || f == "ROL" || f == "ROR") {
    order = {"IN", "N"};
  } else if (f == "NOT" || f == "ABS" || f == "MOVE" || f.find("_TO_") != std::string::npos) {
    order = {"IN"};
  } else {
    for (std::size_t i = 1; i <= n; ++i) order.push_back("IN" + std::to_string(i));
  }
  std::vector<model::ExprPtr> args(order.size());
  for (std::size_t a = 0; a < n; ++a) {
    const auto& name = e.arg_names[a];
    if (model::iequals(name, "EN")) {
      why =
          "EN of a standard function inside an expression (its result is undefined while EN "
          "is FALSE): write IF en THEN ... END_IF";
      return nullptr;
    }
    const auto at = std::find_if(order.begin(), order.end(),
                                 [&](const std::string& p) { return model::iequals(p, name); });
    if (at == order.end()) {
      std::string list;
      for (const auto& p : order) list += (list.empty() ? "" : ", ") + p;
      why = e.name + " has no parameter '" + name + "'" +
            (list.empty() ? "" : " (its parameters here: " + list + ")");
      return nullptr;
    }
    auto& slot = args[static_cast<std::size_t>(at - order.begin())];
    if (slot) {
      why = "parameter '" + name + "' is given twice";
      return nullptr;
    }
    slot = e.args[a];
  }
  for (std::size_t i = 0; i < order.size(); ++i)
    if (!args[i]) {
      why = "parameter '" + order[i] + "' of " + e.name + " is not given";
      return nullptr;
    }
  return model::make_call(e.name, std::move(args), e.where);
}

bool all_digits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c));
  });
}

}  // namespace

bool Compiler::is_bit_access(const model::Expr& e) {
  return e.kind == ExprKind::Member && all_digits(e.member);
}

int Compiler::bit_width(const PouScope& sc, const model::Expr& e) const {
  switch (e.kind) {
    case ExprKind::IntConst:
      return 0;
    case ExprKind::Name: {
      auto it = sc.names.find(model::to_upper(e.name));
      if (it == sc.names.end() || it->second.is_bool) return -1;
      if (it->second.kind == Ref::Field)
        return width_of_range(p.field_lo[it->second.index], p.field_hi[it->second.index]);
      if (it->second.kind == Ref::Input) {
        const auto& t = p.inputs[it->second.index].type;
        return width_of_range(t.lo, t.hi);
      }
      return -1;
    }
    case ExprKind::Not:
    case ExprKind::And:
    case ExprKind::Or:
    case ExprKind::Xor: {
      int w = 0;
      for (const auto& a : e.args) {
        const int aw = bit_width(sc, *a);
        if (aw < 0) return -1;
        w = std::max(w, aw);
      }
      return w;
    }
    case ExprKind::Call: {
      if (const auto* user = project.find_pou(e.name);
          user && user->kind == model::PouKind::Function) {
        const auto* result = user->find_variable(user->name);
        return result && result->type.kind == model::TypeKind::Int
                   ? width_of_range(result->type.lo, result->type.hi)
                   : -1;
      }
      const auto f = model::to_upper(e.name);
      if ((f == "SHL" || f == "SHR" || f == "ROL" || f == "ROR") && !e.args.empty())
        return bit_width(sc, *e.args[0]);
      return -1;
    }
    default:
      return -1;
  }
}

std::uint32_t Compiler::bitwise(const PouScope& sc, const model::Expr& e, int context, VT& type) {
  type = VT::Int;
  const int w = bit_width(sc, e);
  if (w <= 0) {
    error(e.where, "'" + model::to_st(e) +
                       "': bitwise operation on operands that are not all BYTE, WORD or DWORD "
                       "(or of the same width)");
    return constant(0);
  }
  std::vector<std::uint32_t> kids;
  for (const auto& a : e.args) {
    VT t;
    kids.push_back(expr(sc, *a, context, t));
  }
  Node n;
  n.op = e.kind == ExprKind::Not   ? Op::BitNot
         : e.kind == ExprKind::And ? Op::BitAnd
         : e.kind == ExprKind::Or  ? Op::BitOr
                                   : Op::BitXor;
  n.k = w;
  return node(n, std::move(kids));
}

std::uint32_t Compiler::bit_access(const PouScope& sc, const model::Expr& e, int context,
                                   VT& type) {
  type = VT::Bool;
  const auto base = model::make_name(e.name, e.where);
  const int w = bit_width(sc, *base);
  const auto bit = e.member.size() > 2 ? 99 : std::stoi(e.member);
  if (w <= 0 || bit >= w) {
    error(e.where, "'" + model::to_st(e) +
                       "': bit access needs a BYTE, WORD or DWORD variable "
                       "and a bit number below its width");
    return constant(0);
  }
  VT t;
  const auto x = expr(sc, *base, context, t);
  Node shr;
  shr.op = Op::Shr;
  shr.k = w;
  const auto shifted = node(shr, {x, constant(bit)});
  Node mask;
  mask.op = Op::BitAnd;
  mask.k = w;
  return node(mask, {shifted, constant(1)});
}

std::uint32_t Compiler::call(const PouScope& sc, const model::Expr& e, int context, VT& type) {
  if (const auto* user = project.find_pou(e.name); user && user->kind == model::PouKind::Function)
    return function_call(sc, e, *user, context, type);
  const auto f = model::to_upper(e.name);
  const auto n_args = e.args.size();
  type = VT::Int;
  auto fail = [&](const std::string& why) {
    error(e.where, "'" + model::to_st(e) + "': " + why);
    return constant(0);
  };
  auto args = [&](std::vector<VT>& types) {
    std::vector<std::uint32_t> out;
    for (const auto& a : e.args) {
      VT t;
      out.push_back(expr(sc, *a, context, t));
      types.push_back(t);
    }
    return out;
  };
  auto op_node = [&](Op op, std::vector<std::uint32_t> kids) {
    return node(Node{op, Op::Eq, false, 0, 0, 0, 0}, std::move(kids));
  };
  auto ite = [&](std::uint32_t c, std::uint32_t t, std::uint32_t el) {
    return op_node(Op::Ite, {c, t, el});
  };
  auto all_int = [&](const std::vector<VT>& ts) {
    return std::all_of(ts.begin(), ts.end(), [](VT t) { return t == VT::Int; });
  };
  if (!e.arg_names.empty()) {
    std::string why;
    const auto in_order = in_parameter_order(e, why);
    if (!in_order) return fail(why);
    return call(sc, *in_order, context, type);
  }

  // Comparisons, extensible: GT(a, b, c) = a > b AND b > c.
  static constexpr std::array<std::pair<const char*, ExprKind>, 6> kCompare{{{"GT", ExprKind::Gt},
                                                                             {"GE", ExprKind::Ge},
                                                                             {"EQ", ExprKind::Eq},
                                                                             {"NE", ExprKind::Ne},
                                                                             {"LE", ExprKind::Le},
                                                                             {"LT", ExprKind::Lt}}};
  for (const auto& [name, kind] : kCompare)
    if (f == name) {
      if (n_args < 2 || (kind == ExprKind::Ne && n_args != 2))
        return fail(std::string(name) + " needs " + (kind == ExprKind::Ne ? "two" : "two or more") +
                    " arguments");
      std::vector<model::ExprPtr> pairs;
      for (std::size_t i = 0; i + 1 < n_args; ++i)
        pairs.push_back(model::make_binary(kind, e.args[i], e.args[i + 1], e.where));
      const auto whole =
          pairs.size() == 1 ? pairs[0] : model::make_nary(ExprKind::And, pairs, e.where);
      return expr(sc, *whole, context, type);
    }
  // Arithmetic and logic as functions: rewritten to the operators.
  static constexpr std::array<std::pair<const char*, ExprKind>, 9> kOps{{{"ADD", ExprKind::Add},
                                                                         {"MUL", ExprKind::Mul},
                                                                         {"SUB", ExprKind::Sub},
                                                                         {"DIV", ExprKind::Div},
                                                                         {"MOD", ExprKind::Mod},
                                                                         {"AND", ExprKind::And},
                                                                         {"OR", ExprKind::Or},
                                                                         {"XOR", ExprKind::Xor},
                                                                         {"NOT", ExprKind::Not}}};
  for (const auto& [name, kind] : kOps)
    if (f == name) {
      const bool binary = kind == ExprKind::Sub || kind == ExprKind::Div || kind == ExprKind::Mod;
      const bool unary = kind == ExprKind::Not;
      if (unary ? n_args != 1 : binary ? n_args != 2 : n_args < 2)
        return fail(std::string(name) + " needs " +
                    (unary    ? "one argument"
                     : binary ? "two arguments"
                              : "two or more arguments"));
      model::ExprPtr whole;
      if (unary) {
        whole = model::make_unary(kind, e.args[0], e.where);
      } else if (kind == ExprKind::And || kind == ExprKind::Or || kind == ExprKind::Xor) {
        whole = model::make_nary(kind, e.args, e.where);
      } else {
        whole = e.args[0];
        for (std::size_t i = 1; i < n_args; ++i)
          whole = model::make_binary(kind, whole, e.args[i], e.where);
      }
      return expr(sc, *whole, context, type);
    }
  if (f == "MOVE") {
    if (n_args != 1) return fail("MOVE needs one argument");
    return expr(sc, *e.args[0], context, type);
  }
  if (f == "MAX" || f == "MIN") {
    if (n_args < 2) return fail(f + " needs two or more arguments");
    std::vector<VT> ts;
    const auto kids = args(ts);
    if (!all_int(ts)) return fail(f + " of BOOL values");
    auto acc = kids[0];
    for (std::size_t i = 1; i < kids.size(); ++i) {
      const auto lt = op_node(Op::Lt, {acc, kids[i]});
      acc = f == "MAX" ? ite(lt, kids[i], acc) : ite(lt, acc, kids[i]);
    }
    return acc;
  }
  if (f == "LIMIT") {  // LIMIT(MN, IN, MX) = MIN(MAX(IN, MN), MX)
    if (n_args != 3) return fail("LIMIT needs three arguments (MN, IN, MX)");
    std::vector<VT> ts;
    const auto k = args(ts);
    if (!all_int(ts)) return fail("LIMIT of BOOL values");
    const auto lo = ite(op_node(Op::Lt, {k[1], k[0]}), k[0], k[1]);
    return ite(op_node(Op::Lt, {k[2], lo}), k[2], lo);
  }
  if (f == "ABS") {
    if (n_args != 1) return fail("ABS needs one argument");
    std::vector<VT> ts;
    const auto k = args(ts);
    if (!all_int(ts)) return fail("ABS of a BOOL");
    return ite(op_node(Op::Lt, {k[0], constant(0)}), op_node(Op::Neg, {k[0]}), k[0]);
  }
  if (f == "SEL") {  // SEL(G, IN0, IN1)
    if (n_args != 3) return fail("SEL needs three arguments (G, IN0, IN1)");
    std::vector<VT> ts;
    const auto k = args(ts);
    ts[0] = bool_if_literal(*e.args[0], ts[0]);
    if (ts[0] != VT::Bool) return fail("SEL's selector G is not Boolean");
    if (ts[1] != ts[2]) return fail("SEL's inputs have different types");
    type = ts[1];
    return ite(k[0], k[2], k[1]);
  }
  if (f == "MUX") {  // MUX(K, IN0, ..., INn): K out of 0..n is a range error
    if (n_args < 2) return fail("MUX needs a selector and at least one input");
    std::vector<VT> ts;
    const auto k = args(ts);
    if (ts[0] != VT::Int) return fail("MUX's selector K is not an integer");
    for (std::size_t i = 2; i < ts.size(); ++i)
      if (ts[i] != ts[1]) return fail("MUX's inputs have different types");
    type = ts[1];
    const auto inputs = static_cast<std::int64_t>(n_args - 1);
    const auto checked = op_node(Op::RangeCheck, {k[0], constant(0), constant(inputs - 1)});
    auto acc = k[n_args - 1];
    for (auto i = inputs - 2; i >= 0; --i)
      acc = ite(op_node(Op::Eq, {checked, constant(i)}), k[static_cast<std::size_t>(i) + 1], acc);
    return acc;
  }
  if (f == "SHL" || f == "SHR" || f == "ROL" || f == "ROR") {
    if (n_args != 2) return fail(f + " needs two arguments (IN, N)");
    const int w = bit_width(sc, *e.args[0]);
    if (w <= 0) return fail(f + " needs a BYTE, WORD or DWORD first argument");
    std::vector<VT> ts;
    const auto k = args(ts);
    if (ts[1] != VT::Int) return fail(f + "'s count N is not an integer");
    Node n;
    n.op = f == "SHL" ? Op::Shl : f == "SHR" ? Op::Shr : f == "ROL" ? Op::Rol : Op::Ror;
    n.k = w;
    return node(n, k);
  }
  // Type conversions SRC_TO_DST among BOOL and the modelled integer types.
  if (const auto to = f.find("_TO_"); to != std::string::npos) {
    const auto src_name = f.substr(0, to), dst_name = f.substr(to + 4);
    const auto src = model::elementary_type(src_name), dst = model::elementary_type(dst_name);
    auto modelled = [](const std::optional<model::Type>& t) {
      return t && (t->kind == model::TypeKind::Bool || t->kind == model::TypeKind::Int);
    };
    if (!modelled(src) || !modelled(dst))
      return fail("conversion " + f + " is not modelled (only between BOOL and the integer types)");
    if (n_args != 1) return fail(f + " needs one argument");
    std::vector<VT> ts;
    const auto k = args(ts);
    const bool src_bool = src->kind == model::TypeKind::Bool;
    if (src_bool) ts[0] = bool_if_literal(*e.args[0], ts[0]);
    if ((ts[0] == VT::Bool) != src_bool) return fail("the argument is not of type " + src_name);
    if (dst->kind == model::TypeKind::Bool) {
      type = VT::Bool;
      return src_bool ? k[0] : op_node(Op::Ne, {k[0], constant(0)});
    }
    type = VT::Int;
    if (src_bool) return k[0];
    return op_node(Op::RangeCheck, {k[0], constant(dst->lo), constant(dst->hi)});
  }
  if (model::standard_fb(f) != model::StandardFb::None)
    return fail(e.name + " is a function block; call an instance of it");
  return fail("call of function '" + e.name +
              "', which is neither a modelled standard function nor a FUNCTION of this project");
}

}  // namespace sfcv::semantics::iec::detail
