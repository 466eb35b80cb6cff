#include "logic/pattern.hpp"

#include <cctype>
#include <map>

#include "logic/formula.hpp"
#include "logic/parser.hpp"
#include "model/literal.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"

namespace sfcv::logic {

namespace {

// A bounded response nests three operators per cycle (S | (EX TRUE & AX ...)); formulas stay
// below model::kMaxNesting, which every recursive pass relies on.
constexpr std::int64_t kMaxBoundCycles = 60;

enum class ScopeKind { Global, Before, After, Between, AfterUntil };

const std::vector<PatternInfo> kCatalogue = {
    {"always", "A", "{A} is true at the end of every cycle", "AG A", false, false},
    {"never", "A", "{A} is never true at the end of a cycle", "AG !A", false, false},
    {"implies", "A, B",
     "if {A} is true at the end of a cycle, {B} is true at the end of the same cycle",
     "AG (A -> B)", false, false},
    {"next_cycle", "A, B",
     "if {A} is true at the end of a cycle, {B} is true at the end of the next cycle",
     "AG (A -> AX B)", false, false},
    {"between_cycles", "A, B, C",
     "if {A} is true at the end of a cycle and {B} at the end of the next, {C} is true at the "
     "end of that next cycle",
     "AG (A -> AX (B -> C))", false, false},
    {"statechange_duringcycle", "A, B",
     "if {A} is true at the beginning of a cycle, {B} is true at the end of the same cycle",
     "AG AX (prev(A) -> B)", false, false},
    {"leadsto", "A, B",
     "if {A} is true at the end of a cycle, {B} was true at the end of an earlier cycle",
     "AX !E[!B U A]", false, false},
    {"infinitely_often", "A", "{A} is true at the end of infinitely many cycles of every run",
     "AG AF A", false, false},
    {"never_before", "A, B", "{A} is never true before {B} is", "A[!A W B]", false, false},
    {"reachable", "A", "{A} can be true at the end of some cycle", "EF A", false, false},
    {"repeatable", "A", "from every reachable state, {A} can be true again", "AG EF A", false,
     false},
    {"absence", "P", "{P} is never true", "AG !P", true, false},
    {"universality", "P", "{P} is always true", "AG P", true, false},
    {"existence", "P", "{P} becomes true", "AF P", true, false},
    {"precedence", "S, P", "{P} is never true before {S} is", "A[!P W S]", true, false},
    {"response", "P, S", "whenever {P} is true, {S} is true then or later", "AG (P -> AF S)", true,
     true},
};

// --- building CTL ---

FormulaPtr op1(Op op, FormulaPtr a) {
  return make_op(op, {std::move(a)});
}
FormulaPtr op2(Op op, FormulaPtr a, FormulaPtr b) {
  return make_op(op, {std::move(a), std::move(b)});
}
// !!x is x: the formulas stay as readable as the mappings they come from.
FormulaPtr neg(FormulaPtr a) {
  return a->op == Op::Not ? a->args[0] : op1(Op::Not, std::move(a));
}
FormulaPtr conj(FormulaPtr a, FormulaPtr b) {
  return op2(Op::And, std::move(a), std::move(b));
}
FormulaPtr disj(FormulaPtr a, FormulaPtr b) {
  return op2(Op::Or, std::move(a), std::move(b));
}
FormulaPtr imp(FormulaPtr a, FormulaPtr b) {
  return op2(Op::Implies, std::move(a), std::move(b));
}
FormulaPtr AG(FormulaPtr a) {
  return op1(Op::AG, std::move(a));
}
FormulaPtr AF(FormulaPtr a) {
  return op1(Op::AF, std::move(a));
}
FormulaPtr AX(FormulaPtr a) {
  return op1(Op::AX, std::move(a));
}
FormulaPtr AU(FormulaPtr a, FormulaPtr b) {
  return op2(Op::AU, std::move(a), std::move(b));
}
// A[x W y] = (x U y) | G x on every path = !E[!y U (!x & !y)].
FormulaPtr AW(const FormulaPtr& x, const FormulaPtr& y) {
  return neg(op2(Op::EU, neg(y), conj(neg(x), neg(y))));
}

struct Scope {
  ScopeKind kind = ScopeKind::Global;
  FormulaPtr q, r;
};

// Dwyer, Avrunin, Corbett's CTL mappings (patterns.projects.cs.ksu.edu), with the weak until
// their "before R" scopes need (a run that never reaches R is not constrained).
FormulaPtr dwyer(std::string_view name, const std::vector<FormulaPtr>& a, const Scope& s) {
  const auto& Q = s.q;
  const auto& R = s.r;
  // The property inside a scope that ends at R, if R comes (before R, between Q and R).
  auto up_to_r = [&](const FormulaPtr& P, const FormulaPtr& S) -> FormulaPtr {
    const auto never_r = AG(neg(R));
    if (name == "absence") return AW(disj(neg(P), never_r), R);
    if (name == "universality") return AW(disj(P, never_r), R);
    if (name == "existence") return AW(neg(R), conj(P, neg(R)));
    if (name == "precedence") return AW(disj(neg(P), never_r), disj(S, R));
    return AW(disj(imp(P, AU(neg(R), conj(S, neg(R)))), never_r), R);  // response
  };
  // The property from a state on, until R or for ever (after Q until R).
  auto until_r = [&](const FormulaPtr& P, const FormulaPtr& S) -> FormulaPtr {
    if (name == "absence") return AW(neg(P), R);
    if (name == "universality") return AW(P, R);
    if (name == "existence") return AU(neg(R), conj(P, neg(R)));
    if (name == "precedence") return AW(neg(P), disj(S, R));
    return AW(imp(P, AU(neg(R), conj(S, neg(R)))), R);  // response
  };
  auto global = [&](const FormulaPtr& P, const FormulaPtr& S) -> FormulaPtr {
    if (name == "absence") return AG(neg(P));
    if (name == "universality") return AG(P);
    if (name == "existence") return AF(P);
    if (name == "precedence") return AW(neg(P), S);
    return AG(imp(P, AF(S)));  // response
  };
  // Argument order: precedence(S, P) ("S precedes P"), response(P, S) ("S responds to P").
  const FormulaPtr P = name == "precedence" ? a[1] : a[0];
  const FormulaPtr S = name == "precedence" ? a[0] : (a.size() > 1 ? a[1] : nullptr);
  switch (s.kind) {
    case ScopeKind::Global:
      return global(P, S);
    case ScopeKind::Before:
      return up_to_r(P, S);
    case ScopeKind::After:
      // From the first Q on. For absence and universality, from every Q is the same.
      if (name == "absence" || name == "universality") return AG(imp(Q, global(P, S)));
      return AW(neg(Q), conj(Q, global(P, S)));
    case ScopeKind::Between:
      return AG(imp(conj(Q, neg(R)), up_to_r(P, S)));
    case ScopeKind::AfterUntil:
      return AG(imp(conj(Q, neg(R)), until_r(P, S)));
  }
  return nullptr;
}

FormulaPtr cycle_template(std::string_view name, const std::vector<FormulaPtr>& a) {
  if (name == "always") return AG(a[0]);
  if (name == "never") return AG(neg(a[0]));
  if (name == "implies") return AG(imp(a[0], a[1]));
  if (name == "next_cycle") return AG(imp(a[0], AX(a[1])));
  if (name == "between_cycles") return AG(imp(a[0], AX(imp(a[1], a[2]))));
  // The beginning of a cycle is the state the previous cycle left (docs/semantics.md): A is
  // judged on the previous values, B on the new ones, for every cycle (every edge: AG AX).
  if (name == "statechange_duringcycle") return AG(AX(imp(shifted_back(a[0]), a[1])));
  // Past time without past operators: a violation is a run whose cycles end without B up to
  // one that ends with A, E[!B U A], from the end of the first cycle on (AX: the initial
  // state ends no cycle).
  if (name == "leadsto") return AX(neg(op2(Op::EU, neg(a[1]), a[0])));
  if (name == "infinitely_often") return AG(AF(a[0]));
  if (name == "never_before") return AW(neg(a[0]), a[1]);
  if (name == "reachable") return op1(Op::EF, a[0]);
  return AG(op1(Op::EF, a[0]));  // repeatable
}

// S then, or a next cycle exists and S holds within n - 1 cycles after it. The next cycle is
// required (like AF, unlike a bare AX): a run that stops before S does not meet the bound.
FormulaPtr within(const FormulaPtr& S, std::int64_t n) {
  if (n == 0) return S;
  return disj(S, conj(op1(Op::EX, make_const(true)), AX(within(S, n - 1))));
}

// --- scanning the text ---

bool ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
}

struct Piece {
  std::size_t begin = 0, end = 0;  ///< offsets into the text
};

class PatternReader {
 public:
  PatternReader(std::string_view text, std::string source, const PatternOptions& options, int line,
                int column)
      : text_(blank_comments(text)),
        source_(std::move(source)),
        options_(options),
        line_(line),
        column_(column) {}

  ParsedPattern read() {
    ParsedPattern out;
    try {
      out = translate();
    } catch (const Failure&) {
      out.formula.reset();
    }
    out.diagnostics = std::move(diagnostics_);
    return out;
  }

 private:
  struct Failure {};

  static std::string blank_comments(std::string_view s) {
    std::string out(s);
    for (std::size_t i = 0; i + 1 < out.size(); ++i)
      if ((out[i] == '-' && out[i + 1] == '-') || (out[i] == '/' && out[i + 1] == '/'))
        for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
    return out;
  }

  std::pair<int, int> position(std::size_t offset) const {
    int line = line_, column = column_;
    for (std::size_t i = 0; i < offset && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    return {line, column};
  }

  [[noreturn]] void fail(std::size_t offset, std::string message) {
    const auto [line, column] = position(offset);
    model::Diagnostic d;
    d.where.file = source_;
    d.where.line = line;
    d.where.column = column;
    d.message = std::move(message);
    diagnostics_.push_back(std::move(d));
    throw Failure{};
  }

  std::size_t skip_space(std::size_t i) const {
    while (i < text_.size() && std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
    return i;
  }
  Piece trimmed(Piece p) const {
    p.begin = skip_space(p.begin);
    while (p.end > p.begin && std::isspace(static_cast<unsigned char>(text_[p.end - 1]))) --p.end;
    return p;
  }
  std::string_view view(Piece p) const {
    return std::string_view(text_).substr(p.begin, p.end - p.begin);
  }

  // The first word of `p` if it is one of the scope or bound keywords and something follows it
  // (`globally` stands alone); else empty.
  std::string_view keyword(Piece p) const {
    std::size_t i = p.begin;
    while (i < p.end && ident_char(text_[i])) ++i;
    const auto word = std::string_view(text_).substr(p.begin, i - p.begin);
    for (const char* k : {"before", "after", "between", "within"})
      if (word == k && i < p.end && std::isspace(static_cast<unsigned char>(text_[i]))) return word;
    if (word == "globally" && i == p.end) return word;
    return {};
  }

  // The first `word` in `p` outside parentheses and brackets, as a whole word.
  std::optional<Piece> find_word(Piece p, std::string_view word) const {
    int depth = 0;
    for (std::size_t i = p.begin; i < p.end; ++i) {
      const char c = text_[i];
      if (c == '(' || c == '[') ++depth;
      if (c == ')' || c == ']') --depth;
      if (depth != 0 || (i > p.begin && ident_char(text_[i - 1]))) continue;
      if (view({i, p.end}).starts_with(word) &&
          (i + word.size() == p.end || !ident_char(text_[i + word.size()])))
        return Piece{i, i + word.size()};
    }
    return std::nullopt;
  }

  // A propositional argument, parsed by the formula parser at its place in the source.
  FormulaPtr expression(Piece p, std::string_view what) {
    p = trimmed(p);
    if (p.begin == p.end) fail(p.begin, "expected " + std::string(what) + ", found nothing");
    const auto [line, column] = position(p.begin);
    std::string placed(static_cast<std::size_t>(line - 1), '\n');
    placed.append(static_cast<std::size_t>(column - 1), ' ');
    placed += view(p);
    auto parsed = parse_formula(placed, source_);
    if (!parsed.ok()) {
      diagnostics_.insert(diagnostics_.end(), parsed.diagnostics.begin(), parsed.diagnostics.end());
      throw Failure{};
    }
    if (!is_propositional(*parsed.formula))
      fail(p.begin, "a pattern's arguments are propositional formulas (no temporal operator): " +
                        std::string(view(p)));
    return parsed.formula;
  }

  ParsedPattern translate() {
    // name ( argument, ... )
    std::size_t i = skip_space(0);
    const std::size_t name_at = i;
    while (i < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[i])) || text_[i] == '_'))
      ++i;
    const std::string name(view({name_at, i}));
    if (name.empty()) fail(name_at, "expected a pattern name, e.g. 'response(start, V1)'");
    const PatternInfo* info = nullptr;
    for (const auto& p : kCatalogue)
      if (model::iequals(p.name, name)) info = &p;
    if (!info) {
      std::string known;
      for (const auto& p : kCatalogue) known += (known.empty() ? "" : ", ") + std::string(p.name);
      fail(name_at, "unknown pattern '" + name + "' (known: " + known + ")");
    }
    i = skip_space(i);
    if (i >= text_.size() || text_[i] != '(')
      fail(i, "expected '(' after the pattern name '" + name + "'");
    std::vector<Piece> args;
    int depth = 0;
    std::size_t start = ++i;
    for (;; ++i) {
      if (i >= text_.size()) fail(i, "expected ')' at the end of the pattern");
      const char c = text_[i];
      if (c == '(' || c == '[') ++depth;
      if ((c == ')' || c == ']') && depth > 0) {
        --depth;
        continue;
      }
      if (depth == 0 && (c == ',' || c == ')')) {
        args.push_back({start, i});
        start = i + 1;
        if (c == ')') break;
      }
    }
    i = skip_space(i + 1);
    if (i < text_.size() && text_[i] == ';') i = skip_space(i + 1);
    if (i < text_.size())
      fail(i, "unexpected '" + std::string(1, text_[i]) + "' after the pattern");
    if (args.size() == 1 && trimmed(args[0]).begin == trimmed(args[0]).end) args.clear();

    // The last argument may be a scope or a bound.
    std::optional<Piece> modifier;
    if (!args.empty() && !keyword(trimmed(args.back())).empty()) {
      modifier = trimmed(args.back());
      args.pop_back();
    }
    for (const auto& a : args)
      if (!keyword(trimmed(a)).empty())
        fail(trimmed(a).begin, "a scope or bound ('" + std::string(keyword(trimmed(a))) +
                                   " ...') must be the last argument of a pattern");
    const std::string letters(info->arguments);
    const std::size_t arity = (letters.size() + 2) / 3;  // "A", "A, B", "A, B, C"
    const std::string usage = name + "(" + letters +
                              (info->scoped && info->bounded ? "[, scope | within N cycles]"
                               : info->scoped                ? "[, scope]"
                                                             : "") +
                              ")";
    if (args.size() != arity)
      fail(args.size() > arity ? trimmed(args[arity]).begin : name_at,
           "pattern '" + std::string(info->name) + "' takes " + std::to_string(arity) +
               (arity == 1 ? " argument" : " arguments") + ", found " +
               std::to_string(args.size()) + ": " + usage);
    std::vector<FormulaPtr> values;
    for (std::size_t k = 0; k < args.size(); ++k)
      values.push_back(expression(args[k], "the argument " + std::string(1, letters[3 * k])));

    Scope scope;
    std::optional<std::int64_t> bound_cycles;
    std::string bound_english;
    if (modifier) {
      const auto word = keyword(*modifier);
      if (word == "within" ? !info->bounded : !info->scoped)
        fail(modifier->begin, "pattern '" + std::string(info->name) + "' takes no " +
                                  (word == "within" ? "bound" : "scope") + ": " + usage);
      const Piece rest{modifier->begin + word.size(), modifier->end};
      if (word == "within") {
        read_bound(trimmed(rest), bound_cycles, bound_english);
      } else if (word == "before") {
        scope.kind = ScopeKind::Before;
        scope.r = expression(rest, "the end of the scope R");
      } else if (word == "between") {
        const auto and_word = find_word(rest, "and");
        if (!and_word) fail(rest.end, "expected 'between Q and R'");
        scope.kind = ScopeKind::Between;
        scope.q = expression({rest.begin, and_word->begin}, "the start of the scope Q");
        scope.r = expression({and_word->end, rest.end}, "the end of the scope R");
      } else if (word == "after") {
        const auto until_word = find_word(rest, "until");
        scope.kind = until_word ? ScopeKind::AfterUntil : ScopeKind::After;
        scope.q = expression({rest.begin, until_word ? until_word->begin : rest.end},
                             "the start of the scope Q");
        if (until_word) scope.r = expression({until_word->end, rest.end}, "the end of the scope R");
      }
    }

    // The sentence: the arguments as formulas in the template, then the scope.
    std::map<char, std::string> text_of;
    for (std::size_t k = 0; k < values.size(); ++k) text_of[letters[3 * k]] = to_string(values[k]);
    std::string sentence;
    const std::string_view templ =
        bound_cycles ? std::string_view("whenever {P} is true, {S} is true then or")
                     : info->english;
    for (std::size_t k = 0; k < templ.size(); ++k) {
      if (templ[k] == '{' && k + 2 < templ.size() && templ[k + 2] == '}') {
        sentence += text_of[templ[k + 1]];
        k += 2;
      } else {
        sentence += templ[k];
      }
    }
    if (bound_cycles) sentence += " " + bound_english;
    const std::string q = scope.q ? to_string(scope.q) : "", r = scope.r ? to_string(scope.r) : "";
    switch (scope.kind) {
      case ScopeKind::Global:
        break;
      case ScopeKind::Before:
        sentence = "before the first " + r + " (if " + r + " comes), " + sentence;
        break;
      case ScopeKind::After:
        sentence = "from the first " + q + " on, " + sentence;
        break;
      case ScopeKind::Between:
        sentence = "from each " + q + " up to the next " + r + " (if " + r + " comes), " + sentence;
        break;
      case ScopeKind::AfterUntil:
        sentence = "from each " + q + " up to the next " + r + " (or for ever if no " + r +
                   " comes), " + sentence;
        break;
    }
    // A sentence that starts with a word starts with a capital; one that starts with a name not.
    if (!sentence.empty() && !(scope.kind == ScopeKind::Global && templ.starts_with("{")))
      sentence[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(sentence[0])));
    sentence += ".";

    ParsedPattern out;
    out.english = std::move(sentence);
    if (bound_cycles)
      out.formula = AG(imp(values[0], within(values[1], *bound_cycles)));
    else if (info->scoped)
      out.formula = dwyer(info->name, values, scope);
    else
      out.formula = cycle_template(info->name, values);
    return out;
  }

  // `N cycles` | `N cycle` | `N ms` | `N s`: a count of cycles (time needs the cycle time).
  void read_bound(Piece p, std::optional<std::int64_t>& cycles, std::string& english) {
    std::size_t i = p.begin;
    while (i < p.end && std::isdigit(static_cast<unsigned char>(text_[i]))) ++i;
    if (i == p.begin)
      fail(p.begin, "expected a number after 'within', e.g. 'within 5 cycles' or 'within 2 s'");
    // The one checked conversion (model/literal.hpp): a count, or a duration within TIME's
    // range (`n * 1000` once wrapped around and slipped under the bound on cycles).
    const std::string_view digits = std::string_view(text_).substr(p.begin, i - p.begin);
    const auto unit = view(trimmed({i, p.end}));
    const auto magnitude = model::literal_magnitude(digits, 10, digits);
    const auto value = magnitude ? model::signed_literal(false, *magnitude, digits)
                                 : model::Converted<std::int64_t>{{}, magnitude.error};
    if (!value) fail(p.begin, value.error);
    const std::int64_t n = *value;
    std::int64_t count = n;
    if (unit == "cycle" || unit == "cycles") {
      english =
          n == 1 ? "within the next cycle" : "within the next " + std::to_string(n) + " cycles";
    } else if (unit == "ms" || unit == "s") {
      model::DurationLiteral d(std::string(digits) + " " + std::string(unit));
      const auto converted = d.add(digits, "", unit == "s" ? 1000000000 : 1000000)
                                 ? d.milliseconds(false)
                                 : model::Converted<std::int64_t>{{}, d.error()};
      if (!converted) fail(p.begin, converted.error);
      const std::int64_t ms = *converted;
      if (!options_.cycle_ms || *options_.cycle_ms <= 0)
        fail(p.begin,
             "a bound in time needs a cycle time: use --time discrete (and --cycle, "
             "10ms by default), or give the bound in cycles ('within N cycles')");
      count = ms / *options_.cycle_ms;
      english = "within " + std::to_string(n) + " " + std::string(unit) + " (the next " +
                std::to_string(count) + (count == 1 ? " cycle" : " cycles") + " of " +
                std::to_string(*options_.cycle_ms) + " ms)";
    } else {
      fail(trimmed({i, p.end}).begin,
           "expected 'cycles', 'ms' or 's' after the number in 'within'");
    }
    if (count > kMaxBoundCycles)
      fail(p.begin, "a bounded response is checked for at most " + std::to_string(kMaxBoundCycles) +
                        " cycles; this bound is " + std::to_string(count) + " cycles");
    cycles = count;
  }

  std::string text_;
  std::string source_;
  PatternOptions options_;
  int line_, column_;
  model::Diagnostics diagnostics_;
};

}  // namespace

const std::vector<PatternInfo>& pattern_catalogue() {
  return kCatalogue;
}

ParsedPattern parse_pattern(std::string_view text, std::string source,
                            const PatternOptions& options, int line, int column) {
  return PatternReader(text, std::move(source), options, line, column).read();
}

}  // namespace sfcv::logic
