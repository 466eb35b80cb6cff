#include "logic/push_negation.hpp"

#include "logic/formula.hpp"

namespace sfcv::logic {

FormulaPtr push_negation(const FormulaPtr& f) {
  const int l = f->line, c = f->column;
  const auto& a = f->args;
  switch (f->op) {
    case Op::True:
      return make_const(false, l, c);
    case Op::False:
      return make_const(true, l, c);
    case Op::Not:
      return a[0];
    case Op::And:
      return make_op(Op::Or, {make_not(a[0]), make_not(a[1])}, l, c);
    case Op::Or:
      return make_op(Op::And, {make_not(a[0]), make_not(a[1])}, l, c);
    case Op::Implies:
      return make_op(Op::And, {a[0], make_not(a[1])}, l, c);
    case Op::Iff:
      return make_op(Op::Xor, {a[0], a[1]}, l, c);
    case Op::Xor:
      return make_op(Op::Iff, {a[0], a[1]}, l, c);
    case Op::EX:
      return make_op(Op::AX, {make_not(a[0])}, l, c);
    case Op::AX:
      return make_op(Op::EX, {make_not(a[0])}, l, c);
    case Op::EF:
      return make_op(Op::AG, {make_not(a[0])}, l, c);
    case Op::AG:
      return make_op(Op::EF, {make_not(a[0])}, l, c);
    case Op::AF:
      return make_op(Op::EG, {make_not(a[0])}, l, c);
    case Op::EG:
      return make_op(Op::AF, {make_not(a[0])}, l, c);
    case Op::AU: {
      auto nq = make_not(a[1]);
      auto eu = make_op(Op::EU, {nq, make_and(make_not(a[0]), nq)}, l, c);
      return make_op(Op::Or, {eu, make_op(Op::EG, {nq}, l, c)}, l, c);
    }
    default:
      return make_not(f);  // atoms, comparisons, E[p U q]: no simpler dual here
  }
}

}  // namespace sfcv::logic
