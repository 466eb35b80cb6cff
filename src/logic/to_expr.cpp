#include "logic/to_expr.hpp"

#include <stdexcept>

#include "logic/formula.hpp"

namespace sfcv::logic {

model::ExprPtr to_expr(const Formula& f, const std::string& file) {
  using model::ExprKind;
  model::SourceLocation where;
  where.file = file;
  where.line = f.line;
  where.column = f.column;
  auto name = [&]() -> model::ExprPtr {
    const auto dot = f.name.rfind('.');
    if (dot == std::string::npos) return model::make_name(f.name, where);
    return model::make_member(f.name.substr(0, dot), f.name.substr(dot + 1), where);
  };
  auto arg = [&](std::size_t i) { return to_expr(*f.args[i], file); };
  switch (f.op) {
    case Op::True:
      return model::make_bool(true, where);
    case Op::False:
      return model::make_bool(false, where);
    case Op::Atom:
      return name();
    case Op::Compare: {
      static constexpr ExprKind kinds[] = {ExprKind::Eq, ExprKind::Ne, ExprKind::Lt,
                                           ExprKind::Le, ExprKind::Gt, ExprKind::Ge};
      return model::make_binary(kinds[static_cast<int>(f.cmp)], name(),
                                model::make_int(f.value, where), where);
    }
    case Op::Relation: {
      static constexpr ExprKind kinds[] = {ExprKind::Eq, ExprKind::Ne, ExprKind::Lt,
                                           ExprKind::Le, ExprKind::Gt, ExprKind::Ge};
      return model::make_binary(kinds[static_cast<int>(f.cmp)], arg(0), arg(1), where);
    }
    case Op::Value:
      return name();
    case Op::Number:
      return model::make_int(f.value, where);
    case Op::Neg:
      return model::make_unary(ExprKind::Neg, arg(0), where);
    case Op::Add:
      return model::make_binary(ExprKind::Add, arg(0), arg(1), where);
    case Op::Sub:
      return model::make_binary(ExprKind::Sub, arg(0), arg(1), where);
    case Op::Mul:
      return model::make_binary(ExprKind::Mul, arg(0), arg(1), where);
    case Op::Div:
      return model::make_binary(ExprKind::Div, arg(0), arg(1), where);
    case Op::Mod:
      return model::make_binary(ExprKind::Mod, arg(0), arg(1), where);
    case Op::Not:
      return model::make_unary(ExprKind::Not, arg(0), where);
    case Op::And:
      return model::make_nary(ExprKind::And, {arg(0), arg(1)}, where);
    case Op::Or:
      return model::make_nary(ExprKind::Or, {arg(0), arg(1)}, where);
    case Op::Xor:
      return model::make_nary(ExprKind::Xor, {arg(0), arg(1)}, where);
    case Op::Implies:
      return model::make_nary(ExprKind::Or,
                              {model::make_unary(ExprKind::Not, arg(0), where), arg(1)}, where);
    case Op::Iff:
      return model::make_binary(ExprKind::Eq, arg(0), arg(1), where);
    default:
      throw std::invalid_argument("to_expr: temporal operator in '" + to_string(f) + "'");
  }
}

}  // namespace sfcv::logic
