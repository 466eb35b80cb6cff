#include "logic/formula.hpp"

#include <algorithm>
#include <stdexcept>

namespace sfcv::logic {

namespace {
std::shared_ptr<Formula> node(Op op, int line, int column) {
  auto f = std::make_shared<Formula>();
  f->op = op;
  f->line = line;
  f->column = column;
  return f;
}

// Binding strength for printing (NuSMV: <-> weakest, then ->, | xor, &, unary).
int precedence(Op op) {
  switch (op) {
    case Op::Iff:
      return 1;
    case Op::Implies:
      return 2;
    case Op::Or:
    case Op::Xor:
      return 3;
    case Op::And:
      return 4;
    case Op::Compare:
    case Op::Relation:
      return 5;
    case Op::Not:
    case Op::EX:
    case Op::AX:
    case Op::EF:
    case Op::AF:
    case Op::EG:
    case Op::AG:
    case Op::X:
    case Op::F:
    case Op::G:
      return 6;
    default:
      return 7;
  }
}

std::string_view op_text(Op op) {
  switch (op) {
    case Op::Not:
      return "!";
    case Op::And:
      return " & ";
    case Op::Or:
      return " | ";
    case Op::Implies:
      return " -> ";
    case Op::Iff:
      return " <-> ";
    case Op::Xor:
      return " xor ";
    case Op::EX:
      return "EX ";
    case Op::AX:
      return "AX ";
    case Op::EF:
      return "EF ";
    case Op::AF:
      return "AF ";
    case Op::EG:
      return "EG ";
    case Op::AG:
      return "AG ";
    case Op::X:
      return "X ";
    case Op::F:
      return "F ";
    case Op::G:
      return "G ";
    case Op::U:
      return " U ";
    case Op::R:
      return " R ";
    case Op::W:
      return " W ";
    default:
      return "";
  }
}

void print_name(const Formula& f, std::string& out) {
  for (std::uint32_t k = 0; k < f.prev; ++k) out += "prev(";
  out += f.name;
  out.append(f.prev, ')');
}

// Terms: + - weakest, then * / mod, then unary minus.
int term_precedence(Op op) {
  switch (op) {
    case Op::Add:
    case Op::Sub:
      return 1;
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
      return 2;
    case Op::Neg:
      return 3;
    default:
      return 4;
  }
}

void print_term(const Formula& t, int context, std::string& out) {
  const int p = term_precedence(t.op);
  const bool parens = p < context;
  if (parens) out += '(';
  switch (t.op) {
    case Op::Value:
      print_name(t, out);
      break;
    case Op::Number:
      out += t.value_name.empty() ? std::to_string(t.value) : t.value_name;
      break;
    case Op::Neg:
      out += '-';
      print_term(*t.args[0], p, out);
      break;
    default: {
      const char* text = t.op == Op::Add   ? " + "
                         : t.op == Op::Sub ? " - "
                         : t.op == Op::Mul ? " * "
                         : t.op == Op::Div ? " / "
                                           : " mod ";
      print_term(*t.args[0], p, out);  // left associative
      out += text;
      print_term(*t.args[1], p + 1, out);
      break;
    }
  }
  if (parens) out += ')';
}

void print(const Formula& f, int context, std::string& out) {
  if (is_term(f.op)) return print_term(f, 0, out);
  const int p = precedence(f.op);
  const bool parens = p < context;
  if (parens) out += '(';
  switch (f.op) {
    case Op::True:
      out += "TRUE";
      break;
    case Op::False:
      out += "FALSE";
      break;
    case Op::Atom:
      print_name(f, out);
      break;
    case Op::Compare:
      print_name(f, out);
      out += ' ';
      out += to_string(f.cmp);
      out += ' ';
      out += f.value_name.empty() ? std::to_string(f.value) : f.value_name;
      break;
    case Op::Relation:
      print_term(*f.args[0], 1, out);
      out += ' ';
      out += to_string(f.cmp);
      out += ' ';
      print_term(*f.args[1], 1, out);
      break;
    case Op::Not:
    case Op::EX:
    case Op::AX:
    case Op::EF:
    case Op::AF:
    case Op::EG:
    case Op::AG:
    case Op::X:
    case Op::F:
    case Op::G:
      out += op_text(f.op);
      print(*f.args[0], p, out);
      break;
    case Op::U:
    case Op::R:
    case Op::W:  // always parenthesised: (p U q)
      out += '(';
      print(*f.args[0], 0, out);
      out += op_text(f.op);
      print(*f.args[1], 0, out);
      out += ')';
      break;
    case Op::EU:
    case Op::AU:
      out += f.op == Op::EU ? "E[" : "A[";
      print(*f.args[0], 0, out);
      out += " U ";
      print(*f.args[1], 0, out);
      out += ']';
      break;
    case Op::Implies:  // right associative
      print(*f.args[0], p + 1, out);
      out += op_text(f.op);
      print(*f.args[1], p, out);
      break;
    default:  // And, Or, Xor, Iff: left associative
      print(*f.args[0], p, out);
      out += op_text(f.op);
      print(*f.args[1], p + 1, out);
      break;
  }
  if (parens) out += ')';
}

void collect_names(const Formula& f, std::vector<std::string>& out) {
  if (names_observable(f.op)) {
    if (std::find(out.begin(), out.end(), f.name) == out.end()) out.push_back(f.name);
  }
  for (const auto& a : f.args) collect_names(*a, out);
}

void collect_observables(const Formula& f, std::vector<std::uint32_t>& out) {
  if (names_observable(f.op) && f.observable >= 0)
    out.push_back(static_cast<std::uint32_t>(f.observable));
  for (const auto& a : f.args) collect_observables(*a, out);
}
}  // namespace

FormulaPtr make_const(bool v, int line, int column) {
  return node(v ? Op::True : Op::False, line, column);
}

FormulaPtr make_atom(std::string name, int line, int column) {
  auto f = node(Op::Atom, line, column);
  f->name = std::move(name);
  return f;
}

FormulaPtr make_compare(std::string name, CompareOp cmp, std::int64_t value, int line, int column) {
  auto f = node(Op::Compare, line, column);
  f->name = std::move(name);
  f->cmp = cmp;
  f->value = value;
  return f;
}

FormulaPtr make_op(Op op, std::vector<FormulaPtr> args, int line, int column) {
  auto f = node(op, line, column);
  f->args = std::move(args);
  for (const auto& a : f->args) f->height = std::max(f->height, a->height + 1);
  return f;
}

FormulaPtr make_not(FormulaPtr f) {
  const int l = f->line, c = f->column;
  return make_op(Op::Not, {std::move(f)}, l, c);
}
FormulaPtr make_and(FormulaPtr a, FormulaPtr b) {
  const int l = a->line, c = a->column;
  return make_op(Op::And, {std::move(a), std::move(b)}, l, c);
}
FormulaPtr make_or(FormulaPtr a, FormulaPtr b) {
  const int l = a->line, c = a->column;
  return make_op(Op::Or, {std::move(a), std::move(b)}, l, c);
}

FormulaPtr with_observable(const Formula& f, std::int32_t index) {
  auto copy = std::make_shared<Formula>(f);
  copy->observable = index;
  return copy;
}

FormulaPtr shifted_back(const FormulaPtr& f, std::uint32_t n) {
  if (names_observable(f->op)) {
    auto copy = std::make_shared<Formula>(*f);
    copy->prev += n;
    return copy;
  }
  if (f->args.empty()) return f;
  std::vector<FormulaPtr> args;
  for (const auto& a : f->args) args.push_back(shifted_back(a, n));
  return make_op(f->op, std::move(args), f->line, f->column);
}

FormulaPtr make_rise(const FormulaPtr& p, int line, int column) {
  return make_op(Op::And, {p, make_op(Op::Not, {shifted_back(p)}, line, column)}, line, column);
}

FormulaPtr make_fall(const FormulaPtr& p, int line, int column) {
  return make_op(Op::And, {make_op(Op::Not, {p}, line, column), shifted_back(p)}, line, column);
}

bool reads_previous(const Formula& f) {
  if (names_observable(f.op) && f.prev > 0) return true;
  return std::any_of(f.args.begin(), f.args.end(),
                     [](const FormulaPtr& a) { return reads_previous(*a); });
}

bool is_term(Op op) {
  switch (op) {
    case Op::Value:
    case Op::Number:
    case Op::Neg:
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
      return true;
    default:
      return false;
  }
}

bool names_observable(Op op) {
  return op == Op::Atom || op == Op::Compare || op == Op::Value;
}

std::int64_t evaluate_term(const Formula& t,
                           const std::function<std::int64_t(std::uint32_t)>& observe) {
  auto arg = [&](std::size_t i) { return evaluate_term(*t.args[i], observe); };
  switch (t.op) {
    case Op::Value:
      return observe(static_cast<std::uint32_t>(t.observable));
    case Op::Number:
      return t.value;
    case Op::Neg:
      return -arg(0);
    case Op::Add:
      return arg(0) + arg(1);
    case Op::Sub:
      return arg(0) - arg(1);
    case Op::Mul:
      return arg(0) * arg(1);
    case Op::Div:
      return arg(0) / arg(1);  // C++ truncates toward zero, as IEC 61131-3 does
    case Op::Mod:
      return arg(0) % arg(1);  // the sign of the dividend, as IEC 61131-3 MOD
    default:
      throw std::invalid_argument("evaluate_term: not a term: " + to_string(t));
  }
}

bool relation_holds(const Formula& f, const std::function<std::int64_t(std::uint32_t)>& observe) {
  return compare(f.cmp, evaluate_term(*f.args[0], observe), evaluate_term(*f.args[1], observe));
}

bool is_temporal(Op op) {
  switch (op) {
    case Op::EX:
    case Op::AX:
    case Op::EF:
    case Op::AF:
    case Op::EG:
    case Op::AG:
    case Op::EU:
    case Op::AU:
      return true;
    default:
      return is_ltl_op(op);
  }
}

bool is_ltl_op(Op op) {
  switch (op) {
    case Op::X:
    case Op::F:
    case Op::G:
    case Op::U:
    case Op::R:
    case Op::W:
      return true;
    default:
      return false;
  }
}

bool is_ltl(const Formula& f) {
  if (is_ltl_op(f.op)) return true;
  return std::any_of(f.args.begin(), f.args.end(), [](const FormulaPtr& a) { return is_ltl(*a); });
}

bool is_propositional(const Formula& f) {
  if (is_temporal(f.op)) return false;
  return std::all_of(f.args.begin(), f.args.end(),
                     [](const FormulaPtr& a) { return is_propositional(*a); });
}

std::vector<std::string> atom_names(const Formula& f) {
  std::vector<std::string> out;
  collect_names(f, out);
  return out;
}

std::vector<std::uint32_t> atom_observables(const Formula& f) {
  std::vector<std::uint32_t> out;
  collect_observables(f, out);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string to_string(const Formula& f) {
  std::string out;
  print(f, 0, out);
  return out;
}
std::string to_string(const FormulaPtr& f) {
  return f ? to_string(*f) : "<null>";
}

std::string_view to_string(CompareOp c) {
  switch (c) {
    case CompareOp::Eq:
      return "=";
    case CompareOp::Ne:
      return "!=";
    case CompareOp::Lt:
      return "<";
    case CompareOp::Le:
      return "<=";
    case CompareOp::Gt:
      return ">";
    case CompareOp::Ge:
      return ">=";
  }
  return "?";
}

bool compare(CompareOp c, std::int64_t lhs, std::int64_t rhs) {
  switch (c) {
    case CompareOp::Eq:
      return lhs == rhs;
    case CompareOp::Ne:
      return lhs != rhs;
    case CompareOp::Lt:
      return lhs < rhs;
    case CompareOp::Le:
      return lhs <= rhs;
    case CompareOp::Gt:
      return lhs > rhs;
    case CompareOp::Ge:
      return lhs >= rhs;
  }
  return false;
}

}  // namespace sfcv::logic
