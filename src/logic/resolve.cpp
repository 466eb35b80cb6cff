#include "logic/resolve.hpp"

#include <algorithm>
#include <limits>

#include "logic/formula.hpp"
#include "model/names.hpp"

namespace sfcv::logic {

namespace {

__extension__ using Wide = __int128;  // exact ranges of 64-bit terms

// What a term is, for the type rule of comparisons (docs/properties.md): integers of any
// width compare with each other, a Boolean with a Boolean, an enumeration with its own type;
// a literal with an integer or an enumeration, TRUE/FALSE with a Boolean.
struct TermType {
  enum Kind { Bool, Int, Enum, Literal, BoolLiteral } kind = Int;
  std::string name;     ///< the type's name (for Enum and messages)
  Wide lo = 0, hi = 0;  ///< the values the term may take (exact, no wrap-around)
};

class Binder {
 public:
  Binder(const semantics::TransitionSystem& ts, const std::string& source, model::Diagnostics& d)
      : ts_(ts), source_(source), diags_(d) {}

  FormulaPtr bind(const FormulaPtr& f) {
    if (names_observable(f->op)) return bind_name(f);
    if (f->op == Op::Relation) return bind_relation(f);
    if (f->args.empty()) return f;
    std::vector<FormulaPtr> args;
    args.reserve(f->args.size());
    for (const auto& a : f->args) args.push_back(bind(a));
    return copy_with(f, std::move(args));
  }

 private:
  static FormulaPtr copy_with(const FormulaPtr& f, std::vector<FormulaPtr> args) {
    auto r = std::make_shared<Formula>(*make_op(f->op, std::move(args), f->line, f->column));
    r->cmp = f->cmp;
    r->value = f->value;
    r->value_name = f->value_name;
    return r;
  }
  FormulaPtr error(const Formula& at, std::string message) {
    model::Diagnostic d;
    d.where.file = source_;
    d.where.line = at.line;
    d.where.column = at.column;
    d.message = std::move(message);
    diags_.push_back(std::move(d));
    failed_ = true;
    return nullptr;
  }
  std::optional<std::uint32_t> find(const Formula& f, const std::string& name) {
    std::string why;
    const auto index = semantics::find_observable(ts_, name, &why);
    if (index) return index;
    for (const auto& in : ts_.inputs())
      if (model::iequals(in.name, name)) {
        error(f, "'" + name +
                     "' is an input: properties talk about the state (steps, actions, "
                     "variables); constrain inputs with --assume");
        return std::nullopt;
      }
    error(f, why);
    return std::nullopt;
  }
  // prev(x): the observable that keeps x's previous value (logic::history_system_for).
  std::optional<std::uint32_t> previous(const Formula& f, std::uint32_t bound) {
    for (std::uint32_t d = 0; d < f.prev; ++d) {
      const auto p = ts_.previous_observable(bound);
      if (!p) {
        error(f, "prev(" + f.name +
                     "): this system does not keep previous values "
                     "(resolve against logic::history_system_for)");
        return std::nullopt;
      }
      bound = *p;
    }
    return bound;
  }

  FormulaPtr bind_name(const FormulaPtr& f) {
    const auto index = find(*f, f->name);
    if (!index) return f;
    const auto& obs = ts_.observables()[*index];
    if (f->op == Op::Atom && obs.type.kind != model::TypeKind::Bool)
      return error(*f, "'" + f->name + "' is an integer (" + obs.type.name +
                           "): compare it with a constant, e.g. '" + f->name + " > 0'"),
             f;
    std::int64_t value = f->value;
    if (f->op == Op::Compare && !f->value_name.empty()) {
      const auto& es = obs.type.enumerators;
      const auto it = std::find_if(es.begin(), es.end(), [&](const auto& e) {
        return model::iequals(e.first, f->value_name) ||
               model::iequals(obs.type.name + "#" + e.first, f->value_name);
      });
      if (it == es.end()) return as_relation(f, obs);
      value = it->second;
    }
    const auto bound = previous(*f, *index);
    if (!bound) return f;
    Formula valued = *f;
    valued.value = value;
    return with_observable(valued, static_cast<std::int32_t>(*bound));
  }
  // `a = b` where b is no enumerator of a's type: b is a variable (docs/properties.md).
  FormulaPtr as_relation(const FormulaPtr& f, const semantics::Observable& obs) {
    std::string why;
    if (!semantics::find_observable(ts_, f->value_name, &why)) {
      bool input = false;
      for (const auto& in : ts_.inputs()) input = input || model::iequals(in.name, f->value_name);
      if (!obs.type.enumerators.empty() && !input)
        return error(*f, "'" + f->value_name + "' is no enumerator of '" + f->name + "' (" +
                             obs.type.name + ") nor a variable"),
               f;
    }
    auto lhs = std::make_shared<Formula>(*f);
    lhs->op = Op::Value;
    lhs->value_name.clear();
    auto rhs = std::make_shared<Formula>(*make_atom(f->value_name, f->line, f->column));
    rhs->op = Op::Value;
    auto rel = std::make_shared<Formula>(*make_op(Op::Relation, {lhs, rhs}, f->line, f->column));
    rel->cmp = f->cmp;
    return bind_relation(rel);
  }

  static constexpr Wide kMin = std::numeric_limits<std::int64_t>::min();
  static constexpr Wide kMax = std::numeric_limits<std::int64_t>::max();

  // Binds a term and computes its type and range; null on error (reported).
  FormulaPtr bind_term(const FormulaPtr& t, TermType& type) {
    switch (t->op) {
      case Op::Value: {
        const auto index = find(*t, t->name);
        if (!index) return nullptr;
        const auto& ty = ts_.observables()[*index].type;
        type.name = ty.name;
        if (ty.kind == model::TypeKind::Bool) {
          type.kind = TermType::Bool;
          type.lo = 0;
          type.hi = 1;
        } else {
          type.kind = ty.enumerators.empty() ? TermType::Int : TermType::Enum;
          type.lo = ty.lo;
          type.hi = ty.hi;
        }
        const auto bound = previous(*t, *index);
        if (!bound) return nullptr;
        return with_observable(*t, static_cast<std::int32_t>(*bound));
      }
      case Op::Number:
        type.kind = t->value_name.empty() ? TermType::Literal : TermType::BoolLiteral;
        type.name = t->value_name.empty() ? "a literal" : "BOOL";
        type.lo = type.hi = t->value;
        return t;
      default:
        break;
    }
    std::vector<FormulaPtr> args;
    std::vector<TermType> types(t->args.size());
    for (std::size_t i = 0; i < t->args.size(); ++i) {
      auto a = bind_term(t->args[i], types[i]);
      if (!a) return nullptr;
      if (types[i].kind != TermType::Int && types[i].kind != TermType::Literal)
        return error(*t, "arithmetic on " + types[i].name + " in '" + to_string(*t) +
                             "': + - * / MOD take integers");
      args.push_back(std::move(a));
    }
    type.kind = std::all_of(types.begin(), types.end(),
                            [](const TermType& x) { return x.kind == TermType::Literal; })
                    ? TermType::Literal
                    : TermType::Int;
    type.name = "an integer";
    const auto& x = types[0];
    auto constant = [&](std::size_t i) {
      return t->args[i]->op == Op::Number ? std::optional<std::int64_t>(t->args[i]->value)
                                          : std::nullopt;
    };
    switch (t->op) {
      case Op::Neg:
        type.lo = -x.hi;
        type.hi = -x.lo;
        break;
      case Op::Add:
        type.lo = x.lo + types[1].lo;
        type.hi = x.hi + types[1].hi;
        break;
      case Op::Sub:
        type.lo = x.lo - types[1].hi;
        type.hi = x.hi - types[1].lo;
        break;
      case Op::Mul: {
        // As the scan cycle's circuit: a product needs a constant factor.
        if (!constant(0) && !constant(1))
          return error(*t, "'" + to_string(*t) +
                               "': a product of two variables is not modelled; one factor must "
                               "be a constant");
        const Wide c[] = {x.lo * types[1].lo, x.lo * types[1].hi, x.hi * types[1].lo,
                          x.hi * types[1].hi};
        type.lo = *std::min_element(std::begin(c), std::end(c));
        type.hi = *std::max_element(std::begin(c), std::end(c));
        break;
      }
      case Op::Div:
      case Op::Mod: {
        const auto k = constant(1);
        if (!k || *k == 0)
          return error(*t, "'" + to_string(*t) + "': the divisor of " +
                               (t->op == Op::Div ? "/" : "MOD") +
                               " must be a non-zero integer constant");
        const Wide m = *k < 0 ? -static_cast<Wide>(*k) : *k;
        if (t->op == Op::Mod) {
          type.lo = x.lo < 0 ? -(m - 1) : 0;
          type.hi = x.hi > 0 ? m - 1 : 0;
        } else {
          const Wide a = x.lo / *k, b = x.hi / *k;
          type.lo = std::min(a, b);
          type.hi = std::max(a, b);
        }
        break;
      }
      default:
        return error(*t, "not a term: '" + to_string(*t) + "'");
    }
    if (type.lo < kMin || type.hi > kMax)
      return error(*t, "'" + to_string(*t) +
                           "' may leave the 64-bit integers; sfcv compares exact values only");
    return copy_with(t, std::move(args));
  }

  static bool compatible(const TermType& a, const TermType& b) {
    using K = TermType;
    auto numeric = [](K::Kind k) { return k == K::Int || k == K::Literal; };
    if (numeric(a.kind) && numeric(b.kind)) return true;
    auto truth = [](K::Kind k) { return k == K::Bool || k == K::BoolLiteral; };
    if (truth(a.kind) && truth(b.kind)) return true;
    if (a.kind == K::Enum && b.kind == K::Enum) return model::iequals(a.name, b.name);
    return (a.kind == K::Enum && b.kind == K::Literal) ||
           (a.kind == K::Literal && b.kind == K::Enum);
  }

  FormulaPtr bind_relation(const FormulaPtr& f) {
    TermType a, b;
    auto lhs = bind_term(f->args[0], a);
    auto rhs = lhs ? bind_term(f->args[1], b) : nullptr;
    if (!lhs || !rhs) return f;
    if (!compatible(a, b))
      return error(*f, "'" + to_string(*f) + "' compares " + a.name + " with " + b.name +
                           ": the two sides must have compatible types"),
             f;
    if ((a.kind == TermType::Bool || b.kind == TermType::Bool) && f->cmp != CompareOp::Eq &&
        f->cmp != CompareOp::Ne)
      return error(*f, "'" + to_string(*f) + "': truth values compare with = and <> only"), f;
    return copy_with(f, {lhs, rhs});
  }

  const semantics::TransitionSystem& ts_;
  const std::string& source_;
  model::Diagnostics& diags_;

 public:
  bool failed_ = false;
};

}  // namespace

ResolvedFormula resolve(const FormulaPtr& f, const semantics::TransitionSystem& ts,
                        const std::string& source) {
  ResolvedFormula out;
  Binder binder(ts, source, out.diagnostics);
  auto bound = binder.bind(f);
  if (!binder.failed_ && !model::has_errors(out.diagnostics)) out.formula = std::move(bound);
  return out;
}

}  // namespace sfcv::logic
