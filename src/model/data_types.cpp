#include "model/data_types.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "model/names.hpp"

namespace sfcv::model {

namespace {

/// Elements of one project, all aggregates together: beyond this the model is not one a
/// verifier can explore, and a typo in a bound (ARRAY[0..100000]) should not exhaust memory.
constexpr std::size_t kMaxElements = 100000;
/// Elements one variable index may choose among (the MUX or CASE built for it).
constexpr std::size_t kMaxIndexChoices = 4096;
/// Nesting of STRUCT/ARRAY/alias types: deeper is a type that contains itself.
constexpr int kMaxTypeDepth = 32;

struct LoweringError {
  SourceLocation where;
  std::string message;
};

/// What lowering knows of one POU's variables, by upper-case path.
struct Scope {
  std::set<std::string> leaves;                               ///< element variables
  std::set<std::string> strings;                              ///< leaves of type STRING
  std::map<std::string, std::string> instances;               ///< leaf -> user FB type (upper)
  std::map<std::string, std::vector<ArrayDimension>> arrays;  ///< path of an array -> bounds
  bool globals = false;                                       ///< holds VAR_GLOBAL variables
};

std::string index_text(const std::vector<std::int64_t>& k) {
  std::string s = "[";
  for (std::size_t i = 0; i < k.size(); ++i) s += (i ? "," : "") + std::to_string(k[i]);
  return s + "]";
}

class Lowering {
 public:
  Lowering(Project& project, Diagnostics& diags) : project_(project), diags_(diags) {}

  void run() {
    for (const auto& t : project_.data_types) {
      const std::string key = to_upper(t.name);
      if (types_.count(key)) {
        error(t.where, "type '" + t.name + "' is declared twice");
        continue;
      }
      types_[key] = &t;
      if (t.kind != DataTypeKind::Enumeration) continue;
      for (const auto& [name, value] : t.enumerators) {
        qualified_[key + "#" + to_upper(name)] = value;
        const auto [it, fresh] = enumerators_.emplace(to_upper(name), value);
        if (!fresh && it->second != value) ambiguous_.insert(to_upper(name));
      }
    }
    collect_strings();
    bool any = !project_.data_types.empty() || string_codes_.size() > 1;
    // Declarations first (every POU's scope is needed to resolve `inst.arr[i]`), then uses.
    for (auto& pou : project_.pous) {
      Scope& sc = scopes_[to_upper(pou.name)];
      std::vector<Variable> lowered;
      for (const auto& v : pou.variables) {
        any = any || !v.dimensions.empty() || v.declared_initial || v.type.is_string();
        try {
          expand(v, v.declared_initial, lowered, sc, 0);
        } catch (const LoweringError& e) {
          error(e.where, e.message);
        }
      }
      pou.variables = std::move(lowered);
    }
    give_strings_their_range();
    if (!any) return;
    project_.data_types_lowered = true;
    for (auto& pou : project_.pous) {
      pou_ = &pou;
      try {
        pou.body = statements(pou.body);
        for (auto& a : pou.actions) a.body = statements(a.body);
        for (auto& c : pou.charts)
          for (auto& t : c.transitions)
            if (t.guard) {
              check_strings(*t.guard);
              t.guard = expression(t.guard);
            }
        for (auto& a : pou.associations)
          if (a.condition) a.condition = expression(a.condition);
      } catch (const LoweringError& e) {
        error(e.where, e.message);
      }
    }
  }

 private:
  void error(const SourceLocation& where, std::string message) {
    diags_.push_back({Severity::Error, where, std::move(message)});
  }
  [[noreturn]] static void fail(const SourceLocation& where, std::string message) {
    throw LoweringError{where, std::move(message)};
  }

  const DataType* user_type(const Type& t) const {
    if (t.kind != TypeKind::FunctionBlock || t.fb != StandardFb::None) return nullptr;
    const auto it = types_.find(to_upper(t.name));
    return it == types_.end() ? nullptr : it->second;
  }

  // ------------------------------------------------------------------------------ declarations

  /// Appends to `out` the elements of `v` (declared with initial value `init`, or none).
  void expand(const Variable& v, const ExprPtr& init, std::vector<Variable>& out, Scope& sc,
              int depth) {
    if (depth > kMaxTypeDepth)
      fail(v.where, "type of '" + v.name + "' contains itself (nested deeper than " +
                        std::to_string(kMaxTypeDepth) + " levels)");
    if (!v.dimensions.empty()) {
      expand_array(v, init, out, sc, depth);
      return;
    }
    if (const DataType* t = user_type(v.type)) {
      switch (t->kind) {
        case DataTypeKind::Enumeration: {
          Variable e = v;
          std::int64_t lo = t->enumerators.front().second, hi = lo;
          for (const auto& en : t->enumerators) {
            lo = std::min(lo, en.second);
            hi = std::max(hi, en.second);
          }
          e.type = Type::integer(t->name, lo, hi);
          e.type.enumerators = t->enumerators;
          e.initial = init ? constant(init, v.name) : t->enumerators.front().second;
          e.declared_initial = nullptr;
          leaf(std::move(e), out, sc);
          return;
        }
        case DataTypeKind::Structure: {
          std::map<std::string, ExprPtr> field_init;
          if (init) {
            if (init->kind != ExprKind::Call || init->name != "(")
              fail(init->where, "initial value of STRUCT '" + v.name +
                                    "' is not a structure initialiser (x := ..., ...)");
            for (std::size_t i = 0; i < init->args.size(); ++i) {
              const bool known = std::any_of(
                  t->fields.begin(), t->fields.end(),
                  [&](const Variable& f) { return iequals(f.name, init->arg_names[i]); });
              if (!known)
                fail(init->args[i]->where,
                     "'" + init->arg_names[i] + "' is no field of " + t->name);
              field_init[to_upper(init->arg_names[i])] = init->args[i];
            }
          }
          for (const auto& f : t->fields) {
            Variable e = f;
            e.name = v.name + "." + f.name;
            e.direction = v.direction;
            e.constant = v.constant;
            e.address.clear();
            e.where = v.where;
            const auto fi = field_init.find(to_upper(f.name));
            expand(e, fi != field_init.end() ? fi->second : f.declared_initial, out, sc, depth + 1);
          }
          return;
        }
        case DataTypeKind::Alias: {
          Variable e = t->fields.front();
          e.name = v.name;
          e.direction = v.direction;
          e.constant = v.constant;
          e.address = v.address;
          e.where = v.where;
          if (!init && v.initial) {
            e.initial = v.initial;
            e.declared_initial = nullptr;
          }
          expand(e, init ? init : e.declared_initial, out, sc, depth + 1);
          return;
        }
      }
    }
    Variable e = v;
    if (init) e.initial = constant(init, v.name);
    e.declared_initial = nullptr;
    if (e.initial && e.type.kind == TypeKind::Int && !e.type.is_string() &&
        (*e.initial < e.type.lo || *e.initial > e.type.hi))
      fail(init ? init->where : v.where, "initial value " + std::to_string(*e.initial) + " of '" +
                                             e.name + "' is outside " + e.type.name);
    leaf(std::move(e), out, sc);
  }

  void expand_array(const Variable& v, const ExprPtr& init, std::vector<Variable>& out, Scope& sc,
                    int depth) {
    std::size_t count = 1;
    for (const auto& d : v.dimensions) {
      if (d.lo > d.hi)
        fail(v.where, "array '" + v.name + "' has an empty dimension [" + std::to_string(d.lo) +
                          ".." + std::to_string(d.hi) + "]");
      // hi - lo + 1 without overflow: bounds wider than kMaxElements are refused first.
      if (d.lo < -(std::int64_t{1} << 62) || d.hi > (std::int64_t{1} << 62) ||
          d.hi - d.lo >= static_cast<std::int64_t>(kMaxElements))
        fail(v.where,
             "array '" + v.name + "' has more than " + std::to_string(kMaxElements) + " elements");
      const auto n = static_cast<std::size_t>(d.hi - d.lo + 1);
      if (count * n > kMaxElements)
        fail(v.where,
             "array '" + v.name + "' has more than " + std::to_string(kMaxElements) + " elements");
      count *= static_cast<std::size_t>(n);
    }
    elements_ += count;
    if (elements_ > kMaxElements)
      fail(v.where,
           "the project's arrays have more than " + std::to_string(kMaxElements) + " elements");
    // `[1, 2, 3(0)]`: the readers expand repetitions, so one argument per element, in order.
    std::vector<ExprPtr> inits;
    if (init) {
      if (init->kind != ExprKind::Call || init->name != "[")
        fail(init->where, "initial value of ARRAY '" + v.name + "' is not an array initialiser");
      if (init->args.size() > count)
        fail(init->where, "array '" + v.name + "' has " + std::to_string(count) + " elements and " +
                              std::to_string(init->args.size()) + " initial values");
      inits = init->args;
    }
    sc.arrays[to_upper(v.name)] = v.dimensions;
    std::vector<std::int64_t> k;
    for (const auto& d : v.dimensions) k.push_back(d.lo);
    for (std::size_t i = 0; i < count; ++i) {
      Variable e = v;
      e.dimensions.clear();
      e.name = v.name + index_text(k);
      e.declared_initial = nullptr;
      e.address.clear();
      expand(e, i < inits.size() ? inits[i] : nullptr, out, sc, depth + 1);
      for (std::size_t j = k.size(); j-- > 0;) {  // row-major: the last index runs fastest
        if (k[j] < v.dimensions[j].hi) {
          ++k[j];
          break;
        }
        k[j] = v.dimensions[j].lo;
      }
    }
  }

  void leaf(Variable v, std::vector<Variable>& out, Scope& sc) {
    const std::string key = to_upper(v.name);
    sc.leaves.insert(key);
    if (v.type.is_string()) {
      sc.strings.insert(key);
      if (!v.initial) v.initial = string_codes_.at("");
    }
    if (v.direction == VarDirection::Global) sc.globals = true;
    if (v.type.kind == TypeKind::FunctionBlock && v.type.fb == StandardFb::None)
      sc.instances[key] = to_upper(v.type.name);
    out.push_back(std::move(v));
  }

  /// The value of an initial value written as a literal or an enumerator.
  std::int64_t constant(const ExprPtr& e, const std::string& variable) const {
    switch (e->kind) {
      case ExprKind::BoolConst:
      case ExprKind::IntConst:
      case ExprKind::TimeConst:
        return e->value;
      case ExprKind::StringConst:
        return string_codes_.at(e->name);
      case ExprKind::Neg:
        if (e->args[0]->kind == ExprKind::IntConst) return -e->args[0]->value;
        break;
      case ExprKind::Name:
      case ExprKind::Member:
        if (const auto v = enumerator(*e)) return *v;
        break;
      default:
        break;
    }
    fail(e->where, "unsupported: initial value '" + to_st(e) + "' of '" + variable +
                       "' (a literal or an enumerator)");
  }

  // ------------------------------------------------------------------------------------ names

  /// The value of `e` if it names an enumerator: `Red` (when no variable is so named and only
  /// one type has it), `Color#Red`, `Color.Red`.
  std::optional<std::int64_t> enumerator(const Expr& e) const {
    std::string key;
    if (e.kind == ExprKind::Name) {
      const auto hash = e.name.find('#');
      if (hash != std::string::npos) {
        key = to_upper(e.name);
      } else {
        const std::string n = to_upper(e.name);
        if (!enumerators_.count(n)) return std::nullopt;
        if (ambiguous_.count(n))
          fail(e.where, "enumerator '" + e.name +
                            "' has different values in several types: write Type#" + e.name);
        return enumerators_.at(n);
      }
    } else if (e.kind == ExprKind::Member) {
      key = to_upper(e.name) + "#" + to_upper(e.member);
    } else {
      return std::nullopt;
    }
    const auto it = qualified_.find(key);
    if (it == qualified_.end()) return std::nullopt;
    return it->second;
  }

  /// The scope where `path` (upper case) is declared, with the part of it that is local there,
  /// following instances of user FBs (`fb.arr` -> FB's scope, "ARR") and global lists
  /// (`GVL.x`). `prefix` receives the instance path, "" when the path is local.
  const Scope* locate(const std::string& path, std::string& local, std::string& prefix) const {
    const Scope& own = scopes_.at(to_upper(pou_->name));
    const auto is_declared = [&](const Scope& s, const std::string& p) {
      return s.leaves.count(p) || s.arrays.count(p);
    };
    if (is_declared(own, path)) {
      local = path;
      prefix.clear();
      return &own;
    }
    for (const auto& [name, s] : scopes_)
      if (s.globals && is_declared(s, path)) {
        local = path;
        prefix.clear();
        return &s;
      }
    // `inst.rest`: the longest instance prefix declared here.
    for (std::size_t dot = path.find('.'); dot != std::string::npos;
         dot = path.find('.', dot + 1)) {
      const std::string head = path.substr(0, dot), rest = path.substr(dot + 1);
      const Scope* s = nullptr;
      std::string type;
      if (const auto it = own.instances.find(head); it != own.instances.end()) type = it->second;
      if (type.empty() && scopes_.count(head) && scopes_.at(head).globals) {
        // `GVL.rest`: a global of that list.
        s = &scopes_.at(head);
        if (is_declared(*s, rest)) {
          local = rest;
          prefix.clear();
          return s;
        }
        continue;
      }
      if (type.empty() || !scopes_.count(type)) continue;
      s = &scopes_.at(type);
      if (is_declared(*s, rest)) {
        local = rest;
        prefix = head;
        return s;
      }
    }
    return nullptr;
  }

  /// The expression designating the element at `path` as written (`a[2].x`, `fb.s.y`).
  ExprPtr designate(const std::string& path, const SourceLocation& where) const {
    std::string local, prefix;
    const Scope* s = locate(to_upper(path), local, prefix);
    if (s && s->leaves.count(local)) {
      if (prefix.empty()) return make_name(path, where);
      // Written case of the instance part, then the FB's element as one member name.
      return make_member(path.substr(0, prefix.size()), path.substr(prefix.size() + 1), where);
    }
    // A member of an element that is a standard FB instance or an instance (`t[2].Q`).
    const auto dot = path.rfind('.');
    if (dot != std::string::npos) {
      const std::string head = path.substr(0, dot);
      if (locate(to_upper(head), local, prefix))
        return make_member(head, path.substr(dot + 1), where);
    }
    fail(where, "'" + path + "' is no element of a declared array or structure");
  }

  // ------------------------------------------------------------------------------ expressions

  ExprPtr expression(const ExprPtr& e) {
    switch (e->kind) {
      case ExprKind::Name: {
        std::string local, prefix;
        if (locate(to_upper(e->name), local, prefix)) return e;
        if (const auto v = enumerator(*e)) return make_int(*v, e->where);
        if (e->name.find('[') != std::string::npos) return designate(e->name, e->where);
        return e;
      }
      case ExprKind::Member: {
        const std::string full = e->name + "." + e->member;
        std::string local, prefix;
        if (locate(to_upper(full), local, prefix)) return designate(full, e->where);
        if (const auto v = enumerator(*e)) return make_int(*v, e->where);
        if (full.find('[') != std::string::npos) return designate(full, e->where);
        return e;
      }
      case ExprKind::Index:
        return index(*e);
      case ExprKind::StringConst:
        return make_int(string_codes_.at(e->name), e->where);
      default:
        break;
    }
    if (e->args.empty()) return e;
    auto copy = std::make_shared<Expr>(*e);
    for (auto& a : copy->args) a = expression(a);
    return copy;
  }

  /// The bounds of the array that `path`'s "[*]" indexes.
  std::vector<ArrayDimension> bounds(const std::string& path, std::size_t indices,
                                     const SourceLocation& where) const {
    const std::string array = path.substr(0, path.find("[*]"));
    std::string local, prefix;
    const Scope* s = locate(to_upper(array), local, prefix);
    if (!s || !s->arrays.count(local)) fail(where, "'" + array + "' is not an array");
    const auto& dims = s->arrays.at(local);
    if (dims.size() != indices)
      fail(where, "array '" + array + "' has " + std::to_string(dims.size()) +
                      " dimension(s), indexed with " + std::to_string(indices));
    std::size_t choices = 1;
    for (const auto& d : dims) choices *= static_cast<std::size_t>(d.hi - d.lo + 1);
    if (choices > kMaxIndexChoices)
      fail(where, "unsupported: a variable index into '" + array + "', which has more than " +
                      std::to_string(kMaxIndexChoices) + " elements");
    return dims;
  }

  /// The path with its "[*]" replaced by the constant indices `k`.
  static std::string element_path(const std::string& path, const std::vector<std::int64_t>& k) {
    std::string p = path;
    p.replace(p.find("[*]"), 3, index_text(k));
    return p;
  }

  /// The selector of dimension `d` counted from 0: MUX's K.
  ExprPtr offset(const ExprPtr& index, const ArrayDimension& d) {
    const ExprPtr i = expression(index);
    return d.lo == 0 ? i : make_binary(ExprKind::Sub, i, make_int(d.lo, i->where), i->where);
  }

  /// Walks the index tuples of `dims` depth first: `element(k)` is the result for the element
  /// `k`, `level(depth, children)` combines the results for the values of dimension `depth`.
  /// Reads (MUX) and writes (CASE) of a variable index are both this walk.
  template <class Result, class Element, class Level>
  static Result over_index_tuples(const std::vector<ArrayDimension>& dims,
                                  std::vector<std::int64_t>& k, const Element& element,
                                  const Level& level) {
    if (k.size() == dims.size()) return element(k);
    const std::size_t depth = k.size();
    std::vector<Result> children;
    for (std::int64_t v = dims[depth].lo; v <= dims[depth].hi; ++v) {
      k.push_back(v);
      children.push_back(over_index_tuples<Result>(dims, k, element, level));
      k.pop_back();
    }
    return level(depth, std::move(children));
  }

  /// `a[i, j]` -> MUX(i - lo1, MUX(j - lo2, a[lo1,lo2], ...), ...): an index outside the bounds
  /// is MUX's range error.
  ExprPtr index(const Expr& e) {
    const auto dims = bounds(e.name, e.args.size(), e.where);
    std::vector<std::int64_t> k;
    return over_index_tuples<ExprPtr>(
        dims, k,
        [&](const std::vector<std::int64_t>& at) {
          return expression(designate(element_path(e.name, at), e.where));
        },
        [&](std::size_t depth, std::vector<ExprPtr> elements) {
          std::vector<ExprPtr> args{offset(e.args[depth], dims[depth])};
          for (auto& x : elements) args.push_back(std::move(x));
          return make_call("MUX", std::move(args), e.where);
        });
  }

  // ------------------------------------------------------------------------------- statements

  StmtList statements(const StmtList& body) {
    StmtList out;
    out.reserve(body.size());
    for (const auto& s : body) out.push_back(statement(*s));
    return out;
  }

  StmtPtr statement(const Stmt& s) {
    check_strings(s);
    auto c = std::make_shared<Stmt>(s);
    if (c->value) c->value = expression(c->value);
    if (c->limit) c->limit = expression(c->limit);
    if (c->step) c->step = expression(c->step);
    for (auto& e : c->conditions) e = expression(e);
    for (auto& b : c->bodies) b = statements(b);
    c->else_body = statements(c->else_body);
    for (auto& a : c->arguments) a.second = expression(a.second);
    for (auto& labels : c->labels)
      for (auto& l : labels) {
        if (!l.lo_name.empty()) l.lo = label(l.lo_name, s.where);
        if (!l.hi_name.empty()) l.hi = label(l.hi_name, s.where);
        l.lo_name.clear();
        l.hi_name.clear();
      }
    if (c->kind == StmtKind::FbCall && !c->target_indices.empty())
      fail(s.where, "unsupported: a call of an instance chosen by a variable index ('" +
                        to_st(make_index(s.target, s.target_indices)) + "')");
    if (c->kind == StmtKind::Assign) {
      if (!c->target_indices.empty()) return indexed_assignment(*c);
      c->target = target(c->target, s.where);
    }
    return c;
  }

  /// A target as the semantics names it: `s.x` stays, an element of a structure inside an
  /// instance is refused (the semantics reads `a.b.x` as nested instances).
  std::string target(const std::string& path, const SourceLocation& where) const {
    if (path.find('.') == std::string::npos && path.find('[') == std::string::npos) return path;
    std::string local, prefix;
    const Scope* s = locate(to_upper(path), local, prefix);
    if (!s && path.find('[') != std::string::npos)
      fail(where, "'" + path + "' is no element of a declared array or structure");
    if (!s) return path;  // an instance's input (`fb.IN`): the semantics resolves it
    if (!prefix.empty() && local.find_first_of(".[") != std::string::npos)
      fail(where, "unsupported: assignment to '" + path +
                      "', an element of a structure or array inside an instance");
    return path;
  }

  std::int64_t label(const std::string& name, const SourceLocation& where) const {
    Expr e;
    const auto dot = name.find('.');
    if (dot != std::string::npos) {
      e.kind = ExprKind::Member;
      e.name = name.substr(0, dot);
      e.member = name.substr(dot + 1);
    } else {
      e.kind = ExprKind::Name;
      e.name = name;
    }
    e.where = where;
    if (const auto v = enumerator(e)) return *v;
    fail(where, "CASE label '" + name + "' is no enumerator");
  }

  /// `a[i] := v` -> CASE i OF lo: a[lo] := v; ... ELSE a[lo] := MUX(i - lo, a[lo], ...) END_CASE:
  /// the ELSE branch runs only for an index outside the bounds, where the MUX is a range error.
  StmtPtr indexed_assignment(const Stmt& s) {
    const auto dims = bounds(s.target, s.target_indices.size(), s.where);
    std::vector<std::int64_t> first;
    for (const auto& d : dims) first.push_back(d.lo);
    const std::string first_path = element_path(s.target, first);
    std::vector<std::int64_t> k;
    return over_index_tuples<StmtPtr>(
        dims, k,
        [&](const std::vector<std::int64_t>& at) {
          return make_assign(target(element_path(s.target, at), s.where), s.value, s.where);
        },
        [&](std::size_t depth, std::vector<StmtPtr> assignments) {
          const auto& d = dims[depth];
          auto c = std::make_shared<Stmt>();
          c->kind = StmtKind::Case;
          c->where = s.where;
          c->value = expression(s.target_indices[depth]);
          for (std::int64_t v = d.lo; v <= d.hi; ++v) {
            c->labels.push_back({CaseLabel{v, v, {}, {}}});
            c->bodies.push_back({std::move(assignments[static_cast<std::size_t>(v - d.lo)])});
          }
          // ELSE: a range error, by a MUX whose selector is out of its bounds here.
          std::vector<ExprPtr> mux{offset(s.target_indices[depth], d)};
          for (std::int64_t v = d.lo; v <= d.hi; ++v) mux.push_back(s.value);
          c->else_body.push_back(make_assign(target(first_path, s.where),
                                             make_call("MUX", std::move(mux), s.where), s.where));
          return StmtPtr(c);
        });
  }

  // ---------------------------------------------------------------------------------- STRING

  /// Every STRING literal of the project gets a code (in sorted order, '' included); a STRING
  /// variable holds a code. = and <> compare codes, which is exact for literals. A STRING input
  /// can hold any string: the codes after the literals' stand for strings no literal spells,
  /// one per STRING input, so that any pattern of equalities between inputs is a state.
  void collect_strings() {
    std::set<std::string> literals{""};
    std::function<void(const ExprPtr&)> in_expr = [&](const ExprPtr& e) {
      if (!e) return;
      if (e->kind == ExprKind::StringConst) literals.insert(e->name);
      for (const auto& a : e->args) in_expr(a);
    };
    std::function<void(const StmtList&)> in_body = [&](const StmtList& body) {
      for (const auto& st : body) {
        in_expr(st->value);
        in_expr(st->limit);
        in_expr(st->step);
        for (const auto& c : st->conditions) in_expr(c);
        for (const auto& a : st->arguments) in_expr(a.second);
        for (const auto& b : st->bodies) in_body(b);
        in_body(st->else_body);
      }
    };
    for (const auto& t : project_.data_types)
      for (const auto& f : t.fields) in_expr(f.declared_initial);
    for (const auto& pou : project_.pous) {
      for (const auto& v : pou.variables) in_expr(v.declared_initial);
      in_body(pou.body);
      for (const auto& a : pou.actions) in_body(a.body);
      for (const auto& c : pou.charts)
        for (const auto& t : c.transitions) in_expr(t.guard);
    }
    std::int64_t code = 0;
    for (const auto& l : literals) string_codes_[l] = code++;
  }

  void give_strings_their_range() {
    std::int64_t inputs = 0;
    for (const auto& pou : project_.pous)
      for (const auto& v : pou.variables)
        if (v.type.is_string() &&
            (v.direction == VarDirection::Input || v.address.starts_with("%I")))
          ++inputs;
    const auto hi = static_cast<std::int64_t>(string_codes_.size()) + inputs - 1;
    for (auto& pou : project_.pous)
      for (auto& v : pou.variables)
        if (v.type.is_string()) v.type.hi = hi;
  }

  /// Whether `e` is a STRING: a literal or a STRING variable (before lowering).
  bool is_string(const Expr& e) const {
    if (e.kind == ExprKind::StringConst) return true;
    std::string path;
    if (e.kind == ExprKind::Name)
      path = e.name;
    else if (e.kind == ExprKind::Member)
      path = e.name + "." + e.member;
    else
      return false;
    std::string local, prefix;
    const Scope* s = locate(to_upper(path), local, prefix);
    return s && s->strings.count(local);
  }

  /// STRINGs are compared with = and <> and assigned, nothing else (1.7a).
  void check_strings(const Expr& e) const {
    const bool compare = e.kind == ExprKind::Eq || e.kind == ExprKind::Ne;
    if (compare && e.args.size() == 2 && is_string(*e.args[0]) != is_string(*e.args[1]))
      fail(e.where, "comparison of a STRING with a value that is not one in '" + to_st(e) + "'");
    if (!compare)
      for (const auto& a : e.args)
        if (a && is_string(*a))
          fail(a->where, "unsupported: '" + to_st(e) +
                             "' uses a STRING (sfcv compares STRINGs with = and <> and assigns "
                             "them, nothing else)");
    for (const auto& a : e.args)
      if (a) check_strings(*a);
  }
  void check_strings(const Stmt& s) const {
    for (const auto* e : {&s.value, &s.limit, &s.step})
      if (*e) check_strings(**e);
    for (const auto& c : s.conditions) check_strings(*c);
    for (const auto& a : s.arguments) check_strings(*a.second);
    if (s.kind == StmtKind::Case && s.value && is_string(*s.value))
      fail(s.where, "unsupported: CASE on a STRING");
    if (s.kind == StmtKind::Assign && s.value && s.target_indices.empty())
      check_string_transfer(s.target, *s.value, s.where);
    // An FB call passes its arguments to the instance's inputs and copies outputs out: the same
    // rule as an assignment, so a literal's code never lands in an integer input.
    if (s.kind == StmtKind::FbCall) {
      for (const auto& [input, value] : s.arguments)
        if (value) check_string_transfer(s.target + "." + input, *value, value->where);
      for (const auto& [output, variable] : s.outputs)
        check_string_transfer(variable, *variable_expr(s.target + "." + output), s.where);
    }
  }

  static ExprPtr variable_expr(const std::string& path) {
    const auto dot = path.rfind('.');
    return dot == std::string::npos ? make_name(path)
                                    : make_member(path.substr(0, dot), path.substr(dot + 1));
  }

  /// `target := value`: both are STRINGs or neither is.
  void check_string_transfer(const std::string& target, const Expr& value,
                             const SourceLocation& where) const {
    const bool to_string = is_string(*variable_expr(target)), of_string = is_string(value);
    if (to_string != of_string)
      fail(where, std::string(of_string ? "assignment of a STRING to '"
                                        : "assignment of a value that is no STRING to '") +
                      target + "'" + (to_string ? ", a STRING" : ""));
  }

  Project& project_;
  Diagnostics& diags_;
  std::map<std::string, std::int64_t> string_codes_;
  std::map<std::string, const DataType*> types_;
  std::map<std::string, std::int64_t> enumerators_, qualified_;
  std::set<std::string> ambiguous_;
  std::map<std::string, Scope> scopes_;
  std::size_t elements_ = 0;
  const Pou* pou_ = nullptr;
};

}  // namespace

void lower_data_types(Project& project, Diagnostics& diags) {
  Lowering(project, diags).run();
}

}  // namespace sfcv::model
