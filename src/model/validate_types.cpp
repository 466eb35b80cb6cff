// Validation of expression types: value types, operators, and the resolution of names and
// members (variables, steps, function block members).

#include <algorithm>
#include <array>
#include <cctype>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "model/detail/validator.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"
#include "model/networks.hpp"
#include "model/suggest.hpp"

namespace sfcv::model::detail {

std::string ty_name(Ty t) {
  switch (t) {
    case Ty::Bool:
      return "BOOL";
    case Ty::Int:
    case Ty::Bit:
      return "integer";
    case Ty::Time:
      return "TIME";
    case Ty::Unknown:
      break;
  }
  return "unknown";
}

std::optional<Ty> value_type(const Type& t) {
  switch (t.kind) {
    case TypeKind::Bool:
      return Ty::Bool;
    case TypeKind::Int:
      return Ty::Int;
    case TypeKind::Time:
      return Ty::Time;
    case TypeKind::FunctionBlock:
      break;
  }
  return std::nullopt;  // a function block instance is not a value
}

bool clash(Ty a, Ty b) {
  if (a == Ty::Unknown || b == Ty::Unknown || a == b) return false;
  if (a == Ty::Bit) return b == Ty::Time;
  if (b == Ty::Bit) return a == Ty::Time;
  return true;
}

/// `Bit` read as a number.
Ty numeric(Ty t) {
  return t == Ty::Bit ? Ty::Int : t;
}

std::optional<FbMember> fb_member(StandardFb fb, std::string_view member) {
  struct Row {
    StandardFb fb;
    std::string_view name;
    Ty type;
    bool input;
  };
  static constexpr std::array<Row, 30> rows{{
      {StandardFb::TON, "IN", Ty::Bool, true},     {StandardFb::TON, "PT", Ty::Time, true},
      {StandardFb::TON, "Q", Ty::Bool, false},     {StandardFb::TON, "ET", Ty::Time, false},
      {StandardFb::TOF, "IN", Ty::Bool, true},     {StandardFb::TOF, "PT", Ty::Time, true},
      {StandardFb::TOF, "Q", Ty::Bool, false},     {StandardFb::TOF, "ET", Ty::Time, false},
      {StandardFb::TP, "IN", Ty::Bool, true},      {StandardFb::TP, "PT", Ty::Time, true},
      {StandardFb::TP, "Q", Ty::Bool, false},      {StandardFb::TP, "ET", Ty::Time, false},
      {StandardFb::R_TRIG, "CLK", Ty::Bool, true}, {StandardFb::R_TRIG, "Q", Ty::Bool, false},
      {StandardFb::F_TRIG, "CLK", Ty::Bool, true}, {StandardFb::F_TRIG, "Q", Ty::Bool, false},
      {StandardFb::SR, "S1", Ty::Bool, true},      {StandardFb::SR, "R", Ty::Bool, true},
      {StandardFb::SR, "Q1", Ty::Bool, false},     {StandardFb::RS, "S", Ty::Bool, true},
      {StandardFb::RS, "R1", Ty::Bool, true},      {StandardFb::RS, "Q1", Ty::Bool, false},
      {StandardFb::CTU, "CU", Ty::Bool, true},     {StandardFb::CTU, "R", Ty::Bool, true},
      {StandardFb::CTU, "PV", Ty::Int, true},      {StandardFb::CTU, "Q", Ty::Bool, false},
      {StandardFb::CTD, "CD", Ty::Bool, true},     {StandardFb::CTD, "LD", Ty::Bool, true},
      {StandardFb::CTD, "PV", Ty::Int, true},      {StandardFb::CTD, "Q", Ty::Bool, false},
  }};
  // CV is common to both counters; kept out of the table to keep it one row per member.
  if ((fb == StandardFb::CTU || fb == StandardFb::CTD) && iequals(member, "CV"))
    return FbMember{Ty::Int, false};
  // CODESYS and TwinCAT name the counters' reset and load inputs RESET and LOAD.
  if (fb == StandardFb::CTU && iequals(member, "RESET")) return FbMember{Ty::Bool, true};
  if (fb == StandardFb::CTD && iequals(member, "LOAD")) return FbMember{Ty::Bool, true};
  for (const auto& r : rows)
    if (r.fb == fb && iequals(r.name, member)) return FbMember{r.type, r.input};
  return std::nullopt;
}

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
}

const SourceLocation& at(const SourceLocation& own, const SourceLocation& fallback) {
  return own.known() ? own : fallback;
}

/// `loc` for a message about an element at `here`: "12:5" in the same file, else the full form.
std::string place(const SourceLocation& loc, const SourceLocation& here) {
  if (loc.line > 0 && loc.file == here.file)
    return "line " + std::to_string(loc.line) +
           (loc.column > 0 ? ":" + std::to_string(loc.column) : std::string());
  return loc.str();
}

std::string quoted(std::string_view s) {
  return "'" + std::string(s) + "'";
}

void Validator::expect_bool(const ExprPtr& e, const SourceLocation& fallback,
                            std::string_view what) {
  if (!e) return;
  const Ty t = type_of(*e, fallback);
  if (clash(t, Ty::Bool))
    error(at(e->where, fallback),
          std::string(what) + " has type " + ty_name(t) + ", expected BOOL");
}

Ty Validator::type_of(const Expr& e, const SourceLocation& fallback) {
  const auto& here = at(e.where, fallback);
  auto arg = [&](std::size_t i) -> Ty {
    if (i >= e.args.size() || !e.args[i]) return Ty::Unknown;
    return type_of(*e.args[i], here);
  };
  auto op = [&] { return to_st(e); };
  switch (e.kind) {
    case ExprKind::BoolConst:
      return Ty::Bool;
    case ExprKind::IntConst:
      return e.value == 0 || e.value == 1 ? Ty::Bit : Ty::Int;
    case ExprKind::TimeConst:
      return Ty::Time;
    case ExprKind::StringConst:
      error(here, "unsupported: STRING literal in '" + op() + "'");
      return Ty::Unknown;
    case ExprKind::UnmodelledConst:
      error(at(e.where, here), "unsupported: literal " + e.name);
      return Ty::Unknown;
    case ExprKind::Index:
      // The readers lower arrays (model::lower_data_types); an index left is not modelled.
      error(here, "unsupported: array index in '" + op() + "'");
      return Ty::Unknown;
    case ExprKind::Name:
      return resolve_name(e, here);
    case ExprKind::Member:
      return resolve_member(e, here);
    case ExprKind::Not: {
      const Ty a = arg(0);
      if (a == Ty::Time) {
        error(here, "NOT of a TIME value in " + op());
        return Ty::Unknown;
      }
      return a;
    }
    case ExprKind::Neg: {
      const Ty a = arg(0);
      if (a == Ty::Bool) {
        error(here, "arithmetic negation of a BOOL value in " + op());
        return Ty::Unknown;
      }
      return numeric(a);
    }
    case ExprKind::And:
    case ExprKind::Or:
    case ExprKind::Xor: {
      // Boolean, or bitwise on integers; never mixed.
      std::optional<Ty> kind;
      bool unknown = false;
      for (std::size_t i = 0; i < e.args.size(); ++i) {
        const Ty a = arg(i);
        if (a == Ty::Unknown) {
          unknown = true;
          continue;
        }
        if (a == Ty::Bit) continue;  // fits BOOL and integer operands alike
        if (a == Ty::Time) {
          error(here, "logical operation on a TIME value in " + op());
          return Ty::Unknown;
        }
        if (kind && *kind != a) {
          error(here, "logical operation mixes BOOL and integer operands in " + op());
          return Ty::Unknown;
        }
        kind = a;
      }
      if (unknown) return Ty::Unknown;
      return kind ? *kind : Ty::Bit;
    }
    case ExprKind::Add:
    case ExprKind::Sub:
    case ExprKind::Mul:
    case ExprKind::Div:
    case ExprKind::Mod:
      return arithmetic(e.kind, arg(0), arg(1), here, op());
    case ExprKind::Eq:
    case ExprKind::Ne:
    case ExprKind::Lt:
    case ExprKind::Le:
    case ExprKind::Gt:
    case ExprKind::Ge: {
      const Ty a = arg(0), b = arg(1);
      if (clash(a, b))
        error(here, "comparison of " + ty_name(a) + " with " + ty_name(b) + " in " + op());
      return Ty::Bool;
    }
    case ExprKind::Call: {
      // Standard functions: the IEC compiler checks their arguments (iec_compile_call.cpp).
      for (std::size_t i = 0; i < e.args.size(); ++i) (void)arg(i);
      const std::string f = to_upper(e.name);
      if (f == "GT" || f == "GE" || f == "EQ" || f == "NE" || f == "LE" || f == "LT" ||
          (f.size() > 8 && f.ends_with("_TO_BOOL")))
        return Ty::Bool;
      return Ty::Unknown;
    }
    case ExprKind::Rising:
    case ExprKind::Falling:
    case ExprKind::Delay: {
      const Ty a = arg(0);
      if (clash(a, Ty::Bool))
        error(here, std::string(e.kind == ExprKind::Delay ? "time delay" : "edge") + " of a " +
                        ty_name(a) + " value in " + op() + " (expected BOOL)");
      return Ty::Bool;
    }
  }
  return Ty::Unknown;
}

Ty Validator::arithmetic(ExprKind kind, Ty a, Ty b, const SourceLocation& here,
                         const std::string& op) {
  if (a == Ty::Unknown || b == Ty::Unknown) return Ty::Unknown;
  a = numeric(a);
  b = numeric(b);
  if (a == Ty::Int && b == Ty::Int) return Ty::Int;
  if ((kind == ExprKind::Add || kind == ExprKind::Sub) && a == Ty::Time && b == Ty::Time)
    return Ty::Time;
  if (kind == ExprKind::Mul && ((a == Ty::Time && b == Ty::Int) || (a == Ty::Int && b == Ty::Time)))
    return Ty::Time;
  if (kind == ExprKind::Div && a == Ty::Time && b == Ty::Int) return Ty::Time;
  error(here, "arithmetic on " + ty_name(a) + " and " + ty_name(b) + " in " + op);
  return Ty::Unknown;
}

Ty Validator::resolve_name(const Expr& e, const SourceLocation& here) {
  if (const Variable* v = pou_->find_variable(e.name)) {
    if (auto t = value_type(v->type)) return *t;
    error(here, "function block instance " + quoted(e.name) +
                    " used as a value (name one of its outputs, e.g. " + e.name + ".Q)");
    return Ty::Unknown;
  }
  if (const Variable* g = grafcet() ? nullptr : project_global(e.name)) {
    if (auto t = value_type(g->type)) return *t;
  }
  if (step_exists(e.name)) return Ty::Bool;  // a step used as a Boolean: its activity
  // A chain kept as one name (`GVL.IsSFCResetting` in a TwinCAT condition network): resolved
  // as the member chain it is.
  if (!grafcet() && e.name.find('.') != std::string::npos)
    return resolve_path(split_path(e.name), *pou_, true, here, e.name);
  // IEC 60848 step variable: X12 is the activity of step 12.
  if (grafcet() && e.name.size() > 1 && (e.name[0] == 'X' || e.name[0] == 'x') &&
      step_exists(std::string_view(e.name).substr(1)))
    return Ty::Bool;
  // A typo ("Boing" for "Boin") gets the closest name of the POU, its globals and steps.
  std::vector<std::string> known;
  for (const auto& v : pou_->variables) known.push_back(v.name);
  for (const auto& q : project_.pous)
    for (const auto& v : q.variables)
      if (v.direction == VarDirection::Global) known.push_back(v.name);
  for (const auto& c : pou_->charts)
    for (const auto& s : c.steps) known.push_back(s.name);
  error(here, "unknown name " + quoted(e.name) + " (not a variable" +
                  (grafcet() ? ", step or step variable Xi)" : " or step)") +
                  did_you_mean(e.name, known));
  return Ty::Unknown;
}

Ty Validator::resolve_member(const Expr& e, const SourceLocation& here) {
  // Importers may keep a chain a.b.c as name "a.b", member "c".
  const std::string full = e.name + "." + e.member;
  return resolve_path(split_path(full), *pou_, true, here, full);
}

Ty Validator::resolve_path(const std::vector<std::string>& parts, const Pou& scope, bool top,
                           const SourceLocation& here, const std::string& full) {
  const std::string& base = parts[0];
  const std::string& member = parts[1];
  const bool simple = parts.size() == 2;
  if (const Variable* v = scope.find_variable(base)) {
    if (v->type.kind == TypeKind::FunctionBlock && v->type.fb == StandardFb::None) {
      // An instance of a user function block: its member, in the FB's own declarations (a
      // type this model does not hold is the compiler's error, with its location).
      const Pou* type = project_.find_pou(v->type.name);
      if (!type) return Ty::Unknown;
      const std::vector<std::string> rest(parts.begin() + 1, parts.end());
      if (!simple) return resolve_path(rest, *type, false, here, full);
      const Variable* m = type->find_variable(member);
      if (!m) {
        error(here, "function block " + type->name + " declares no variable " + quoted(member) +
                        " (in " + full + ")");
        return Ty::Unknown;
      }
      if (auto t = value_type(m->type)) return *t;
      error(here, "function block instance " + quoted(full) + " used as a value");
      return Ty::Unknown;
    }
    if (v->type.kind == TypeKind::FunctionBlock) {
      if (auto m = fb_member(v->type.fb, member); m && simple) return m->type;
      error(here, "function block " + v->type.name + " has no member " + quoted(member) + " (in " +
                      full + ")");
      return Ty::Unknown;
    }
    if (v->type.kind == TypeKind::Int && simple && all_digits(member)) return Ty::Bool;  // bit
    error(here, "variable " + quoted(base) + " of type " + v->type.name + " has no member " +
                    quoted(member) + " (in " + full + ")");
    return Ty::Unknown;
  }
  if (top && simple && step_exists(base)) {
    if (iequals(member, "X")) return Ty::Bool;
    if (iequals(member, "T")) return Ty::Time;
    error(here,
          "step " + quoted(base) + " has no member " + quoted(member) + " (a step has X and T)");
    return Ty::Unknown;
  }
  if (top && simple && pou_->find_action(base)) {
    // IEC 61131-3 ed. 3 action control: A.A (active) and A.Q.
    if (iequals(member, "A") || iequals(member, "Q") || iequals(member, "X")) return Ty::Bool;
    error(here, "action " + quoted(base) + " has no member " + quoted(member) +
                    " (an action has A and Q)");
    return Ty::Unknown;
  }
  if (top) {
    if (const Pou* other = project_.find_pou(base)) {
      // A program's variable read from elsewhere: Main.x.
      const std::vector<std::string> rest(parts.begin() + 1, parts.end());
      if (rest.size() >= 2) return resolve_path(rest, *other, false, here, full);
      const Variable* v = other->find_variable(member);
      if (!v) {
        error(here, "POU " + quoted(other->name) + " declares no variable " + quoted(member));
        return Ty::Unknown;
      }
      if (auto t = value_type(v->type)) return *t;
      error(here, "function block instance " + quoted(full) + " used as a value");
      return Ty::Unknown;
    }
    // S.X / S.T on an undeclared step is a typo, not an outside reference.
    if (simple && (iequals(member, "X") || iequals(member, "T"))) {
      error(here, "unknown step " + quoted(base) + " in " + full);
      return Ty::Unknown;
    }
  }
  outside_model(here, full, top ? base : full.substr(0, full.rfind('.')));
  return Ty::Unknown;
}

}  // namespace sfcv::model::detail
