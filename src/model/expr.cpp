#include "model/expr.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

#include "model/names.hpp"

namespace sfcv::model {

namespace {
ExprPtr make(ExprKind kind, SourceLocation where) {
  auto e = std::make_shared<Expr>();
  e->kind = kind;
  e->where = std::move(where);
  return e;
}

int precedence(ExprKind k) {
  switch (k) {
    case ExprKind::Or:
      return 1;
    case ExprKind::Xor:
      return 2;
    case ExprKind::And:
      return 3;
    case ExprKind::Eq:
    case ExprKind::Ne:
      return 4;
    case ExprKind::Lt:
    case ExprKind::Le:
    case ExprKind::Gt:
    case ExprKind::Ge:
      return 5;
    case ExprKind::Add:
    case ExprKind::Sub:
      return 6;
    case ExprKind::Mul:
    case ExprKind::Div:
    case ExprKind::Mod:
      return 7;
    case ExprKind::Not:
    case ExprKind::Neg:
    case ExprKind::Rising:
    case ExprKind::Falling:
      return 8;
    default:
      return 9;
  }
}

const char* op_text(ExprKind k) {
  switch (k) {
    case ExprKind::And:
      return " AND ";
    case ExprKind::Or:
      return " OR ";
    case ExprKind::Xor:
      return " XOR ";
    case ExprKind::Add:
      return " + ";
    case ExprKind::Sub:
      return " - ";
    case ExprKind::Mul:
      return " * ";
    case ExprKind::Div:
      return " / ";
    case ExprKind::Mod:
      return " MOD ";
    case ExprKind::Eq:
      return " = ";
    case ExprKind::Ne:
      return " <> ";
    case ExprKind::Lt:
      return " < ";
    case ExprKind::Le:
      return " <= ";
    case ExprKind::Gt:
      return " > ";
    case ExprKind::Ge:
      return " >= ";
    default:
      return " ? ";
  }
}

void set_height(Expr& e) {
  std::uint32_t h = 0;
  for (const auto& a : e.args) h = std::max(h, a->height);
  e.height = h + 1;
}

std::string time_literal(std::int64_t ms) {
  if (ms % 1000 == 0) return "T#" + std::to_string(ms / 1000) + "s";
  return "T#" + std::to_string(ms) + "ms";
}

std::string print(const Expr& e, int parent_prec, bool right_operand) {
  const int p = precedence(e.kind);
  std::string s;
  switch (e.kind) {
    case ExprKind::BoolConst:
      return e.value ? "TRUE" : "FALSE";
    case ExprKind::IntConst:
      return std::to_string(e.value);
    case ExprKind::TimeConst:
      return time_literal(e.value);
    case ExprKind::Name:
      return e.name;
    case ExprKind::Member:
      return e.name + "." + e.member;
    case ExprKind::Not:
      s = "NOT " + print(*e.args[0], p, false);
      break;
    case ExprKind::Neg:
      s = "-" + print(*e.args[0], p, false);
      break;
    case ExprKind::Rising:
      s = "RE " + print(*e.args[0], p, false);
      break;
    case ExprKind::Falling:
      s = "FE " + print(*e.args[0], p, false);
      break;
    case ExprKind::Call:
      s = e.name + "(";
      for (std::size_t i = 0; i < e.args.size(); ++i)
        s += (i ? ", " : "") + (i < e.arg_names.size() ? e.arg_names[i] + " := " : "") +
             print(*e.args[i], 0, false);
      return s + ")";
    case ExprKind::UnmodelledConst:
      return e.name;
    case ExprKind::StringConst: {
      std::string q = "'";
      for (const char ch : e.name) {
        if (ch == '\n')
          q += "$N";
        else if (ch == '\r')
          q += "$R";
        else if (ch == '\t')
          q += "$T";
        else if (ch == '\f')
          q += "$P";
        else
          q += (ch == '\'' || ch == '$') ? std::string("$") + ch : std::string(1, ch);
      }
      return q + "'";
    }
    case ExprKind::Index: {
      std::string indices;
      for (std::size_t i = 0; i < e.args.size(); ++i)
        indices += (i ? ", " : "") + print(*e.args[i], 0, false);
      std::string path = e.name;
      if (const auto at = path.find("[*]"); at != std::string::npos)
        path.replace(at, 3, "[" + indices + "]");
      return path;
    }
    case ExprKind::Delay:
      return time_literal(e.value) + "/" + print(*e.args[0], 9, false) + "/" +
             time_literal(e.value2);
    default:
      for (std::size_t i = 0; i < e.args.size(); ++i) {
        if (i) s += op_text(e.kind);
        s += print(*e.args[i], p, i > 0);
      }
  }
  // Binary operators are printed left-associative: a right operand of equal precedence needs
  // parentheses (a - (b - c)); so do comparisons, which IEC does not chain.
  const bool needs = p < parent_prec || (p == parent_prec && right_operand && p < 8) ||
                     (p == parent_prec && (p == 4 || p == 5));
  return needs ? "(" + s + ")" : s;
}
}  // namespace

ExprPtr make_bool(bool v, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(ExprKind::BoolConst, std::move(where)));
  e->value = v ? 1 : 0;
  return e;
}
ExprPtr make_int(std::int64_t v, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(ExprKind::IntConst, std::move(where)));
  e->value = v;
  return e;
}
ExprPtr make_time(std::int64_t ms, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(ExprKind::TimeConst, std::move(where)));
  e->value = ms;
  return e;
}
ExprPtr make_name(std::string name, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(ExprKind::Name, std::move(where)));
  e->name = std::move(name);
  return e;
}
ExprPtr make_member(std::string name, std::string member, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(ExprKind::Member, std::move(where)));
  e->name = std::move(name);
  e->member = std::move(member);
  return e;
}
ExprPtr make_unary(ExprKind kind, ExprPtr arg, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(kind, std::move(where)));
  e->args.push_back(std::move(arg));
  set_height(*e);
  return e;
}
ExprPtr make_binary(ExprKind kind, ExprPtr lhs, ExprPtr rhs, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(kind, std::move(where)));
  e->args.push_back(std::move(lhs));
  e->args.push_back(std::move(rhs));
  set_height(*e);
  return e;
}
ExprPtr make_nary(ExprKind kind, std::vector<ExprPtr> args, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(kind, std::move(where)));
  e->args = std::move(args);
  set_height(*e);
  return e;
}
namespace {
/// A node naming something (a function, an array) with operands: calls and indexed reads.
ExprPtr make_named(ExprKind kind, std::string name, std::vector<ExprPtr> args,
                   SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(kind, std::move(where)));
  e->name = std::move(name);
  e->args = std::move(args);
  set_height(*e);
  return e;
}
}  // namespace

ExprPtr make_call(std::string function, std::vector<ExprPtr> args, SourceLocation where) {
  return make_named(ExprKind::Call, std::move(function), std::move(args), std::move(where));
}
ExprPtr make_formal_call(std::string function, std::vector<std::string> names,
                         std::vector<ExprPtr> args, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make_call(std::move(function), std::move(args), where));
  e->arg_names = std::move(names);
  return e;
}
ExprPtr make_index(std::string path, std::vector<ExprPtr> indices, SourceLocation where) {
  return make_named(ExprKind::Index, std::move(path), std::move(indices), std::move(where));
}
ExprPtr make_string(std::string characters, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(ExprKind::StringConst, std::move(where)));
  e->name = std::move(characters);
  return e;
}
ExprPtr make_unmodelled_literal(std::string text, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(ExprKind::UnmodelledConst, std::move(where)));
  e->name = std::move(text);
  return e;
}
ExprPtr make_delay(std::int64_t t1_ms, ExprPtr arg, std::int64_t t2_ms, SourceLocation where) {
  auto e = std::const_pointer_cast<Expr>(make(ExprKind::Delay, std::move(where)));
  e->value = t1_ms;
  e->value2 = t2_ms;
  e->args.push_back(std::move(arg));
  set_height(*e);
  return e;
}

bool reads(const Expr& e, std::string_view variable) {
  switch (e.kind) {
    case ExprKind::Name:
      if (iequals(e.name, variable)) return true;
      break;
    case ExprKind::Member:
      if (iequals(e.name, variable) || iequals(e.name + "." + e.member, variable)) return true;
      break;
    case ExprKind::Index:
      if (iequals(std::string_view(e.name).substr(0, e.name.find('[')), variable)) return true;
      break;
    default:
      break;
  }
  return std::any_of(e.args.begin(), e.args.end(),
                     [&](const ExprPtr& a) { return a && reads(*a, variable); });
}

bool equal(const Expr& a, const Expr& b) {
  if (a.kind != b.kind || a.value != b.value || a.value2 != b.value2 ||
      a.args.size() != b.args.size())
    return false;
  if (a.kind == ExprKind::StringConst || a.kind == ExprKind::UnmodelledConst)
    return a.name == b.name;
  if (a.kind == ExprKind::Name || a.kind == ExprKind::Member || a.kind == ExprKind::Call ||
      a.kind == ExprKind::Index) {
    // Identifiers are case-insensitive.
    auto ieq = [](const std::string& x, const std::string& y) {
      if (x.size() != y.size()) return false;
      for (std::size_t i = 0; i < x.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(x[i])) !=
            std::toupper(static_cast<unsigned char>(y[i])))
          return false;
      return true;
    };
    if (!ieq(a.name, b.name) || !ieq(a.member, b.member)) return false;
    if (a.arg_names.size() != b.arg_names.size()) return false;
    for (std::size_t i = 0; i < a.arg_names.size(); ++i)
      if (!ieq(a.arg_names[i], b.arg_names[i])) return false;
  }
  for (std::size_t i = 0; i < a.args.size(); ++i)
    if (!equal(a.args[i], b.args[i])) return false;
  return true;
}

bool equal(const ExprPtr& a, const ExprPtr& b) {
  if (!a || !b) return !a && !b;
  return equal(*a, *b);
}

std::string to_st(const Expr& e) {
  return print(e, 0, false);
}
std::string to_st(const ExprPtr& e) {
  return e ? to_st(*e) : "TRUE";
}

}  // namespace sfcv::model
