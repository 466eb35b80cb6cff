#include "logic/query_compile.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "model/input_file.hpp"
#include "model/names.hpp"

namespace sfcv::logic {

std::string to_string(Sort s) {
  switch (s) {
    case Sort::States:
      return "a set of situations";
    case Sort::Evolutions:
      return "a set of evolutions";
    case Sort::Steps:
      return "a set of steps";
    case Sort::Empty:
      return "the empty set";
    case Sort::Bool:
      return "a test";
    case Sort::Int:
      return "a number";
  }
  return "?";
}

bool compare(CmpOp op, std::int64_t a, std::int64_t b) {
  switch (op) {
    case CmpOp::Eq:
      return a == b;
    case CmpOp::Ne:
      return a != b;
    case CmpOp::Lt:
      return a < b;
    case CmpOp::Le:
      return a <= b;
    case CmpOp::Gt:
      return a > b;
    case CmpOp::Ge:
      return a >= b;
  }
  return false;
}

namespace {

std::string lower(std::string_view s) {
  std::string r(s);
  for (auto& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

enum class Builtin { None, Int, Ext, Amont, Aval, Succ, Pred, Act, Des, Nec, Emis };

Builtin builtin(std::string_view name) {
  const auto n = lower(name);
  if (n == "int") return Builtin::Int;
  if (n == "ext") return Builtin::Ext;
  if (n == "amont" || n == "upstream") return Builtin::Amont;
  if (n == "aval" || n == "downstream") return Builtin::Aval;
  if (n == "succ") return Builtin::Succ;
  if (n == "pred") return Builtin::Pred;
  if (n == "act") return Builtin::Act;
  if (n == "des") return Builtin::Des;
  if (n == "nec") return Builtin::Nec;
  if (n == "emis") return Builtin::Emis;
  return Builtin::None;
}

bool is_constant(std::string_view n) {
  return n == "Y" || n == "T" || n == "Y0" || n == "Steps" || n == "Tclear";
}

bool is_set(Sort s) {
  return s == Sort::States || s == Sort::Evolutions || s == Sort::Steps || s == Sort::Empty;
}

CmpOp cmp_of(NodeKind k) {
  switch (k) {
    case NodeKind::Ne:
      return CmpOp::Ne;
    case NodeKind::Lt:
      return CmpOp::Lt;
    case NodeKind::Le:
      return CmpOp::Le;
    case NodeKind::Gt:
      return CmpOp::Gt;
    case NodeKind::Ge:
      return CmpOp::Ge;
    default:
      return CmpOp::Eq;
  }
}

CmpOp flip(CmpOp op) {
  switch (op) {
    case CmpOp::Lt:
      return CmpOp::Gt;
    case CmpOp::Le:
      return CmpOp::Ge;
    case CmpOp::Gt:
      return CmpOp::Lt;
    case CmpOp::Ge:
      return CmpOp::Le;
    default:
      return op;
  }
}

const char* op_symbol(NodeKind k) {
  switch (k) {
    case NodeKind::Union:
      return "+";
    case NodeKind::Inter:
      return "*";
    case NodeKind::Diff:
      return "-";
    case NodeKind::And:
      return "&";
    case NodeKind::Or:
      return "|";
    case NodeKind::Not:
      return "!";
    case NodeKind::Eq:
      return "=";
    case NodeKind::Ne:
      return "!=";
    case NodeKind::Lt:
      return "<";
    case NodeKind::Le:
      return "<=";
    case NodeKind::Gt:
      return ">";
    case NodeKind::Ge:
      return ">=";
    default:
      return "?";
  }
}

/// Lexical environment: let bindings and definition parameters are closures (the expression and
/// the environment it was written in), compiled where they are used, so that `mutex(V1, V2)`
/// passes names that become outputs inside Emis; set-builder variables are slots.
struct Env;
using EnvPtr = std::shared_ptr<const Env>;
struct Env {
  std::string name;
  bool step_var = false;
  std::uint32_t slot = 0;
  NodePtr node;
  EnvPtr node_env;
  EnvPtr parent;
};

const Env* lookup(const EnvPtr& env, const std::string& name) {
  for (const Env* e = env.get(); e; e = e->parent.get())
    if (e->name == name) return e;
  return nullptr;
}

enum class Mode { Value, Steps, SignalNec, SignalEmis };

class Compiler {
 public:
  Compiler(const QueryLibrary& lib, const semantics::TransitionSystem& ts) : lib_(lib), ts_(ts) {}

  std::uint32_t slots() const { return slots_; }

  Term value(const Node& n, const EnvPtr& env) {
    count_expansion(n);
    switch (n.kind) {
      case NodeKind::Name:
        return value_name(n, env);
      case NodeKind::Integer: {
        Term t = leaf(Term::Op::Number, Sort::Int, n);
        t.value = n.value;
        return t;
      }
      case NodeKind::EmptySet:
        return leaf(Term::Op::Empty, Sort::Empty, n);
      case NodeKind::StepList:
        return steps(n, env);
      case NodeKind::SetBuilder: {
        Term domain = steps(*n.args[0], env);
        auto bound = std::make_shared<Env>();
        bound->name = n.name;
        bound->step_var = true;
        bound->slot = slots_++;
        bound->parent = env;
        Term body = value(*n.args[1], bound);
        if (body.sort != Sort::Bool)
          throw QueryError(n.args[1]->pos,
                           "the condition of a set of steps must be a test (e.g. "
                           "'... != {}'), not " +
                               to_string(body.sort));
        Term t = leaf(Term::Op::SetBuilder, Sort::Steps, n);
        t.slot = bound->slot;
        t.args = {std::move(domain), std::move(body)};
        return t;
      }
      case NodeKind::Call:
        return call(n, env, Mode::Value).first;
      case NodeKind::Let:
        return value(*n.args[1], bind(n, env));
      case NodeKind::Union:
        return set_binary(Term::Op::Union, n, env);
      case NodeKind::Inter:
        return set_binary(Term::Op::Inter, n, env);
      case NodeKind::Diff:
        return set_binary(Term::Op::Diff, n, env);
      case NodeKind::And:
      case NodeKind::Or: {
        Term a = value(*n.args[0], env), b = value(*n.args[1], env);
        if (a.sort != Sort::Bool || b.sort != Sort::Bool)
          throw QueryError(n.pos, std::string("'") + op_symbol(n.kind) +
                                      "' combines tests (or input/output expressions inside Nec "
                                      "and Emis), not " +
                                      to_string(a.sort != Sort::Bool ? a.sort : b.sort) +
                                      (n.kind == NodeKind::And ? ": for an intersection write '*'"
                                                               : ": for a union write '+'"));
        Term t = leaf(n.kind == NodeKind::And ? Term::Op::And : Term::Op::Or, Sort::Bool, n);
        t.args = {std::move(a), std::move(b)};
        return t;
      }
      case NodeKind::Not: {
        Term a = value(*n.args[0], env);
        if (a.sort != Sort::Bool)
          throw QueryError(n.pos,
                           "'!' negates a test (or an input/output expression inside Nec "
                           "and Emis), not " +
                               to_string(a.sort) + ": for a complement write 'Y - A' or 'T - A'");
        Term t = leaf(Term::Op::Not, Sort::Bool, n);
        t.args = {std::move(a)};
        return t;
      }
      case NodeKind::Count: {
        Term a = value(*n.args[0], env);
        if (!is_set(a.sort))
          throw QueryError(n.pos, "'#' counts the elements of a set, not of " + to_string(a.sort));
        Term t = leaf(Term::Op::Count, Sort::Int, n);
        t.args = {std::move(a)};
        return t;
      }
      case NodeKind::Eq:
      case NodeKind::Ne:
      case NodeKind::Lt:
      case NodeKind::Le:
      case NodeKind::Gt:
      case NodeKind::Ge: {
        Term a = value(*n.args[0], env), b = value(*n.args[1], env);
        Term t = leaf(Term::Op::IntCmp, Sort::Bool, n);
        t.cmp = cmp_of(n.kind);
        if (a.sort == Sort::Int && b.sort == Sort::Int) {
          t.args = {std::move(a), std::move(b)};
          return t;
        }
        if (is_set(a.sort) && is_set(b.sort) &&
            (n.kind == NodeKind::Eq || n.kind == NodeKind::Ne)) {
          unify(a, b, n, "=");
          t.op = Term::Op::SetCmp;
          t.args = {std::move(a), std::move(b)};
          return t;
        }
        if (is_set(a.sort) && is_set(b.sort))
          throw QueryError(n.pos, std::string("'") + op_symbol(n.kind) +
                                      "' compares numbers; compare sets with '=' or '!=', or "
                                      "their sizes with '#'");
        throw QueryError(n.pos, std::string("cannot compare ") + to_string(a.sort) + " with " +
                                    to_string(b.sort) +
                                    " (test emptiness with '= {}', count with '#')");
      }
    }
    throw QueryError(n.pos, "unsupported expression");
  }

  /// A set of steps: `{1, X3}`, `10`, `X3`, `e` (set-builder variable), or any step-set term.
  Term steps(const Node& n, const EnvPtr& env) {
    count_expansion(n);
    switch (n.kind) {
      case NodeKind::Integer:
        return step_literal({resolve_step_number(n)}, n);
      case NodeKind::Name: {
        if (const Env* b = lookup(env, n.name)) {
          if (b->step_var) return step_var(*b, n);
          return steps(*b->node, b->node_env);
        }
        if (n.name == "Steps") return leaf(Term::Op::AllSteps, Sort::Steps, n);
        if (is_constant(n.name) || lib_.find(n.name)) return expect_steps(value(n, env), n);
        return step_literal({resolve_step_name(n)}, n);
      }
      case NodeKind::StepList: {
        std::vector<std::uint32_t> lits;
        std::vector<Term> vars;
        for (const auto& e : n.args) {
          if (e->kind == NodeKind::Integer) {
            lits.push_back(resolve_step_number(*e));
          } else if (const Env* b = lookup(env, e->name)) {
            vars.push_back(b->step_var ? step_var(*b, *e) : steps(*b->node, b->node_env));
          } else {
            lits.push_back(resolve_step_name(*e));
          }
        }
        Term t = step_literal(std::move(lits), n);
        for (auto& v : vars) {
          if (t.steps.empty() && t.op == Term::Op::StepLiteral) {
            t = std::move(v);
            continue;
          }
          Term u = leaf(Term::Op::Union, Sort::Steps, n);
          u.args = {std::move(t), std::move(v)};
          t = std::move(u);
        }
        return t;
      }
      case NodeKind::Let:
        return steps(*n.args[1], bind(n, env));
      case NodeKind::Call:
        if (builtin(n.name) == Builtin::None) return call(n, env, Mode::Steps).first;
        [[fallthrough]];
      default:
        return expect_steps(value(n, env), n);
    }
  }

  Signal signal(const Node& n, const EnvPtr& env, Mode mode) {
    count_expansion(n);
    switch (n.kind) {
      case NodeKind::Name: {
        if (const Env* b = lookup(env, n.name)) {
          if (b->step_var) {
            Signal s;
            s.op = Signal::Op::StepVar;
            s.index = b->slot;
            return s;
          }
          return signal(*b->node, b->node_env, mode);
        }
        if (model::iequals(n.name, "TRUE") || model::iequals(n.name, "FALSE")) {
          Signal s;
          s.value = model::iequals(n.name, "TRUE") ? 1 : 0;
          return s;
        }
        if (const Definition* d = lib_.find(n.name); d && d->params.empty())
          return expand(*d, n, {}, env,
                        [&](const Node& body, const EnvPtr& e) { return signal(body, e, mode); });
        return signal_name(n, mode);
      }
      case NodeKind::Integer: {
        Signal s;
        s.is_int = true;
        s.value = n.value;
        return s;
      }
      case NodeKind::Let:
        return signal(*n.args[1], bind(n, env), mode);
      case NodeKind::Call:
        if (builtin(n.name) == Builtin::None) {
          const Definition* d = find_def(n);
          return expand(*d, n, n.args, env,
                        [&](const Node& body, const EnvPtr& e) { return signal(body, e, mode); });
        }
        throw QueryError(n.pos, "'" + n.name + "(...)' is a set; inside " +
                                    (mode == Mode::SignalNec ? "Nec" : "Emis") +
                                    " write an expression over inputs, outputs and steps");
      case NodeKind::Not: {
        Signal s;
        s.op = Signal::Op::Not;
        s.args = {bool_signal(*n.args[0], env, mode, "!")};
        return s;
      }
      case NodeKind::And:
      case NodeKind::Or: {
        Signal s;
        s.op = n.kind == NodeKind::And ? Signal::Op::And : Signal::Op::Or;
        s.args = {bool_signal(*n.args[0], env, mode, op_symbol(n.kind)),
                  bool_signal(*n.args[1], env, mode, op_symbol(n.kind))};
        return s;
      }
      case NodeKind::Eq:
      case NodeKind::Ne:
      case NodeKind::Lt:
      case NodeKind::Le:
      case NodeKind::Gt:
      case NodeKind::Ge: {
        Signal a = signal(*n.args[0], env, mode), b = signal(*n.args[1], env, mode);
        CmpOp op = cmp_of(n.kind);
        if (a.is_int != b.is_int)
          throw QueryError(
              n.pos, std::string("'") + op_symbol(n.kind) + "' compares a Boolean with a number");
        if (!a.is_int && n.kind != NodeKind::Eq && n.kind != NodeKind::Ne)
          throw QueryError(n.pos, std::string("'") + op_symbol(n.kind) + "' needs numbers");
        if (mentions_input(a) || mentions_input(b)) {
          // Nec decides implication by splitting each input's range at the constants it is
          // compared with, so an input may only be compared with a number.
          if (b.op == Signal::Op::Input) {
            std::swap(a, b);
            op = flip(op);
          }
          if (a.op != Signal::Op::Input || b.op != Signal::Op::Const)
            throw QueryError(n.pos,
                             "inside Nec an input may only be compared with a number "
                             "(e.g. 'level > 3')");
        }
        Signal s;
        s.op = Signal::Op::Cmp;
        s.cmp = op;
        s.args = {std::move(a), std::move(b)};
        return s;
      }
      case NodeKind::Union:
      case NodeKind::Inter:
      case NodeKind::Diff:
        throw QueryError(n.pos, std::string("'") + op_symbol(n.kind) +
                                    "' is a set operator; inside Nec and Emis use '&', '|' and "
                                    "'!' (arithmetic is not supported)");
      default:
        throw QueryError(n.pos, "expected an expression over inputs, outputs and steps");
    }
  }

  /// A call of a built-in operator or a library definition.
  std::pair<Term, bool> call(const Node& n, const EnvPtr& env, Mode mode) {
    const auto b = builtin(n.name);
    if (b == Builtin::None) {
      const Definition* d = find_def(n);
      return {expand(*d, n, n.args, env,
                     [&](const Node& body, const EnvPtr& e) {
                       return mode == Mode::Steps ? steps(body, e) : value(body, e);
                     }),
              true};
    }
    auto arity = [&](std::size_t k, const char* shape) {
      if (n.args.size() != k)
        throw QueryError(n.pos, "'" + n.name + "' takes " + std::to_string(k) +
                                    (k == 1 ? " argument" : " arguments") + ": " + shape);
    };
    Term t = leaf(Term::Op::Empty, Sort::States, n);
    switch (b) {
      case Builtin::Int:
      case Builtin::Ext:
        arity(1, "a set of situations");
        t.op = b == Builtin::Int ? Term::Op::Int : Term::Op::Ext;
        t.sort = Sort::Evolutions;
        t.args = {expect(value(*n.args[0], env), Sort::States, *n.args[0], n.name)};
        break;
      case Builtin::Amont:
      case Builtin::Aval:
        arity(1, "a set of evolutions");
        t.op = b == Builtin::Amont ? Term::Op::Amont : Term::Op::Aval;
        t.args = {expect(value(*n.args[0], env), Sort::Evolutions, *n.args[0], n.name)};
        break;
      case Builtin::Succ:
      case Builtin::Pred:
        arity(2, "a set of situations and a set of evolutions");
        t.op = b == Builtin::Succ ? Term::Op::Succ : Term::Op::Pred;
        t.args = {expect(value(*n.args[0], env), Sort::States, *n.args[0], n.name),
                  expect(value(*n.args[1], env), Sort::Evolutions, *n.args[1], n.name)};
        break;
      case Builtin::Act:
      case Builtin::Des:
        arity(1, "a set of steps such as {1, 10}");
        t.op = b == Builtin::Act ? Term::Op::Act : Term::Op::Des;
        t.args = {steps(*n.args[0], env)};
        break;
      case Builtin::Nec:
        arity(1, "an expression over inputs");
        t.op = Term::Op::Nec;
        t.sort = Sort::Evolutions;
        t.signal = bool_signal(*n.args[0], env, Mode::SignalNec, "Nec");
        break;
      case Builtin::Emis:
        arity(1, "an expression over outputs and steps");
        t.op = Term::Op::Emis;
        t.signal = bool_signal(*n.args[0], env, Mode::SignalEmis, "Emis");
        break;
      case Builtin::None:
        break;
    }
    return {std::move(t), false};
  }

 private:
  static Term leaf(Term::Op op, Sort sort, const Node& n) {
    Term t;
    t.op = op;
    t.sort = sort;
    t.pos = n.pos;
    return t;
  }

  /// Each use of a let name or a definition is compiled where it is used, so a chain such as
  /// `let a1 = a0 + a0; let a2 = a1 + a1; ...` doubles at every line: past this many compiled
  /// nodes the query is refused where the count ran out, instead of growing without bound.
  static constexpr std::size_t kMaxExpandedNodes = 1'000'000;
  void count_expansion(const Node& n) {
    if (++expanded_ > kMaxExpandedNodes)
      throw QueryError(n.pos, "the query expands to more than " +
                                  std::to_string(kMaxExpandedNodes) +
                                  " nodes (each use of a let name or a definition is expanded "
                                  "where it is used); share less, or split the query");
  }

  EnvPtr bind(const Node& let, const EnvPtr& env) {
    if (is_constant(let.name) || is_builtin_name(let.name))
      throw QueryError(let.pos, "'" + let.name + "' is predefined and cannot be redefined by let");
    auto e = std::make_shared<Env>();
    e->name = let.name;
    e->node = let.args[0];
    e->node_env = env;
    e->parent = env;
    return e;
  }

  const Definition* find_def(const Node& n) {
    const Definition* d = lib_.find(n.name);
    if (!d) throw QueryError(n.pos, "unknown operator or definition '" + n.name + "'");
    return d;
  }

  template <class F>
  auto expand(const Definition& d, const Node& call_node, const std::vector<NodePtr>& args,
              const EnvPtr& env, F&& compile_body) -> decltype(compile_body(*d.body, env)) {
    if (args.size() != d.params.size())
      throw QueryError(call_node.pos, "'" + d.name + "' takes " + std::to_string(d.params.size()) +
                                          " argument(s), " + std::to_string(args.size()) +
                                          " given (defined at " + d.pos.str() + ")");
    if (++depth_ > 64)
      throw QueryError(call_node.pos,
                       "definitions nested more than 64 deep (is '" + d.name + "' recursive?)");
    EnvPtr body_env;  // definitions see only their parameters
    for (std::size_t i = 0; i < args.size(); ++i) {
      auto e = std::make_shared<Env>();
      e->name = d.params[i];
      e->node = args[i];
      e->node_env = env;
      e->parent = body_env;
      body_env = e;
    }
    try {
      auto r = compile_body(*d.body, body_env);
      --depth_;
      return r;
    } catch (const QueryError& err) {
      --depth_;
      if (err.pos().source == call_node.pos.source) throw;
      throw QueryError(
          err.pos(), err.message() + " (in '" + d.name + "' used at " + call_node.pos.str() + ")");
    }
  }

  Term value_name(const Node& n, const EnvPtr& env) {
    if (const Env* b = lookup(env, n.name)) {
      if (b->step_var) return step_var(*b, n);
      return value(*b->node, b->node_env);
    }
    if (n.name == "Y") return leaf(Term::Op::AllStates, Sort::States, n);
    if (n.name == "T") return leaf(Term::Op::AllEvolutions, Sort::Evolutions, n);
    if (n.name == "Y0") return leaf(Term::Op::Initial, Sort::States, n);
    if (n.name == "Tclear") return leaf(Term::Op::Clearing, Sort::Evolutions, n);
    if (n.name == "Steps") return leaf(Term::Op::AllSteps, Sort::Steps, n);
    if (const Definition* d = lib_.find(n.name); d && d->params.empty())
      return expand(*d, n, {}, env,
                    [&](const Node& body, const EnvPtr& e) { return value(body, e); });
    std::string err;
    if (auto o = semantics::find_observable(ts_, n.name, &err)) {
      const auto& obs = ts_.observables()[*o];
      if (obs.kind == semantics::ObservableKind::Step)
        throw QueryError(n.pos, "'" + n.name + "' is a step: write {" + n.name +
                                    "} for the set of steps, Act({" + n.name +
                                    "}) for the situations where it is active");
      throw QueryError(
          n.pos, "'" + n.name + "' is " + (obs.is_output ? "an output" : "a variable") +
                     ", not a set: " + "write Emis(" + n.name + ") for the situations emitting it");
    }
    if (find_input(n.name))
      throw QueryError(n.pos, "'" + n.name + "' is an input, not a set: write Nec(" + n.name +
                                  ") for the evolutions that need it");
    throw QueryError(n.pos, "unknown name '" + n.name + "'");
  }

  std::optional<std::uint32_t> find_input(std::string_view name) const {
    const auto& in = ts_.inputs();
    for (std::uint32_t i = 0; i < in.size(); ++i)
      if (model::iequals(in[i].name, name)) return i;
    return std::nullopt;
  }

  Signal signal_name(const Node& n, Mode mode) {
    std::string err;
    const auto input = find_input(n.name);
    if (mode == Mode::SignalNec && input) {
      Signal s;
      s.op = Signal::Op::Input;
      s.index = *input;
      s.is_int = ts_.inputs()[*input].type.kind != model::TypeKind::Bool;
      return s;
    }
    if (auto o = semantics::find_observable(ts_, n.name, &err)) {
      Signal s;
      s.op = Signal::Op::Observable;
      s.index = *o;
      s.is_int = ts_.observables()[*o].type.kind != model::TypeKind::Bool;
      return s;
    }
    if (input)
      throw QueryError(n.pos, "'" + n.name +
                                  "' is an input: Emis talks about outputs and steps "
                                  "(use Nec for conditions on inputs)");
    throw QueryError(n.pos, err);
  }

  Signal bool_signal(const Node& n, const EnvPtr& env, Mode mode, const std::string& what) {
    Signal s = signal(n, env, mode);
    if (s.is_int)
      throw QueryError(n.pos, "'" + what + "' needs a Boolean expression, not a number");
    return s;
  }

  static bool mentions_input(const Signal& s) {
    if (s.op == Signal::Op::Input) return true;
    for (const auto& a : s.args)
      if (mentions_input(a)) return true;
    return false;
  }

  Term step_var(const Env& b, const Node& n) {
    Term t = leaf(Term::Op::StepVar, Sort::Steps, n);
    t.slot = b.slot;
    return t;
  }

  Term step_literal(std::vector<std::uint32_t> s, const Node& n) {
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    Term t = leaf(Term::Op::StepLiteral, Sort::Steps, n);
    t.steps = std::move(s);
    return t;
  }

  std::uint32_t check_step(std::uint32_t o, const Node& n) {
    const auto& obs = ts_.observables()[o];
    if (obs.kind != semantics::ObservableKind::Step)
      throw QueryError(
          n.pos, "'" + n.name + "' is not a step (it is " +
                     (obs.kind == semantics::ObservableKind::Action ? "an action" : "a variable") +
                     ")");
    return o;
  }

  std::uint32_t resolve_step_name(const Node& n) {
    std::string err;
    if (auto o = semantics::find_observable(ts_, n.name, &err)) return check_step(*o, n);
    throw QueryError(n.pos, err.empty() ? "unknown step '" + n.name + "'" : err);
  }

  std::uint32_t resolve_step_number(const Node& n) {
    // Grafcet steps are numbered: "10" is the step whose activity is X10.
    const std::string num = std::to_string(n.value);
    for (const auto& cand : {num, "X" + num}) {
      std::string err;
      if (auto o = semantics::find_observable(ts_, cand, &err)) {
        if (ts_.observables()[*o].kind == semantics::ObservableKind::Step) return *o;
      }
    }
    throw QueryError(n.pos, "no step numbered " + num);
  }

  Term expect_steps(Term t, const Node& n) {
    if (t.sort == Sort::Empty) retag(t, Sort::Steps);
    if (t.sort != Sort::Steps)
      throw QueryError(n.pos, "expected a set of steps, found " + to_string(t.sort));
    return t;
  }

  static Term expect(Term t, Sort s, const Node& n, const std::string& op) {
    if (t.sort == Sort::Empty) retag(t, s);
    if (t.sort != s)
      throw QueryError(n.pos, "the argument of '" + op + "' must be " + to_string(s) + ", not " +
                                  to_string(t.sort));
    return t;
  }

  /// Gives `{}` (and unions/intersections of `{}`) the sort of the set it meets.
  static void retag(Term& t, Sort s) {
    if (t.sort != Sort::Empty) return;
    t.sort = s;
    for (auto& a : t.args) retag(a, s);
  }

  static void unify(Term& a, Term& b, const Node& n, const char* op) {
    if (a.sort == Sort::Empty) retag(a, b.sort);
    if (b.sort == Sort::Empty) retag(b, a.sort);
    if (a.sort != b.sort)
      throw QueryError(n.pos, std::string("the operands of '") + op +
                                  "' must have the same sort: the left one is " +
                                  to_string(a.sort) + ", the right one " + to_string(b.sort));
  }

  Term set_binary(Term::Op op, const Node& n, const EnvPtr& env) {
    Term a = value(*n.args[0], env), b = value(*n.args[1], env);
    const char* sym = op_symbol(n.kind);
    for (const Term* x : {&a, &b})
      if (!is_set(x->sort))
        throw QueryError(n.pos, std::string("'") + sym + "' combines sets, but its " +
                                    (x == &a ? "left" : "right") + " operand is " +
                                    to_string(x->sort) +
                                    (x->sort == Sort::Bool ? " (inside Nec and Emis, write '&' "
                                                             "and '|')"
                                                           : ""));
    unify(a, b, n, sym);
    Term t = leaf(op, a.sort, n);
    t.args = {std::move(a), std::move(b)};
    return t;
  }

  const QueryLibrary& lib_;
  const semantics::TransitionSystem& ts_;
  std::uint32_t slots_ = 0;
  int depth_ = 0;
  std::size_t expanded_ = 0;
};

}  // namespace

bool is_builtin_name(std::string_view name) {
  return builtin(name) != Builtin::None || is_constant(name) || name == "let" || name == "def" ||
         name == "in";
}

void QueryLibrary::add(Definition d) {
  if (is_builtin_name(d.name))
    throw QueryError(d.pos, "'" + d.name + "' is predefined and cannot be redefined");
  defs_[lower(d.name)] = std::move(d);
}

void QueryLibrary::add_text(std::string_view text, const std::string& source_name) {
  auto defs = parse_library(text, source_name);
  std::map<std::string, QueryPos> seen;
  for (auto& d : defs) {
    const auto key = lower(d.name);
    if (auto it = seen.find(key); it != seen.end())
      throw QueryError(d.pos, "'" + d.name + "' is already defined at " + it->second.str());
    seen.emplace(key, d.pos);
  }
  for (auto& d : defs) add(std::move(d));
}

void QueryLibrary::add_file(const std::string& path) {
  std::string text;
  if (auto reason = model::try_read_input_file(path, "the library file", text)) {
    QueryPos pos{std::make_shared<const std::string>(path), 0, 0};
    throw QueryError(pos, *reason);
  }
  add_text(text, path);
}

const Definition* QueryLibrary::find(std::string_view name) const {
  auto it = defs_.find(lower(name));
  return it == defs_.end() ? nullptr : &it->second;
}

const Term* emptiness_tested_set(const Term& t) {
  if (t.op != Term::Op::SetCmp) return nullptr;
  const bool left_empty = t.args[0].op == Term::Op::Empty;
  const bool right_empty = t.args[1].op == Term::Op::Empty;
  if (left_empty == right_empty) return nullptr;
  return left_empty ? &t.args[1] : &t.args[0];
}

CompiledQuery compile_query(const NodePtr& query, const QueryLibrary& library,
                            const semantics::TransitionSystem& ts) {
  Compiler c(library, ts);
  CompiledQuery q;
  q.text = to_string(*query);
  q.root = c.value(*query, nullptr);
  q.slots = c.slots();
  return q;
}

CompiledQuery compile_query(std::string_view text, const QueryLibrary& library,
                            const semantics::TransitionSystem& ts, const std::string& source_name) {
  auto q = compile_query(parse_query(text, source_name), library, ts);
  q.text = std::string(text);
  return q;
}

}  // namespace sfcv::logic
