// The native Grafcet text format (.g7): lexer, recursive-descent parser and name checks.
// The grammar is documented in docs/formats.md; g7_writer.cpp prints the same syntax.

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "io/g7_lexicon.hpp"
#include "io/load.hpp"
#include "model/literal.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"

namespace sfcv::io {

// The .g7 text's own lexer and parser, named apart from the ST ones of the same layer.
namespace g7_syntax {
namespace {

using model::ExprKind;
using model::ExprPtr;
using model::SourceLocation;

enum class Tok { End, Ident, Number, Time, String, Punct };

struct Token {
  Tok kind = Tok::End;
  std::string text;        ///< identifier / string contents / punctuation / number digits
  std::int64_t value = 0;  ///< Number: the value; Time: milliseconds
  /// Number: 2^63, LINT's smallest value once negated (value holds it); out of range otherwise.
  bool negation_only = false;
  int line = 0, col = 0;
};

struct ParseError {
  int line, col;
  std::string message;
};

// ------------------------------------------------------------------------------------ lexer

class Lexer {
 public:
  Lexer(std::string_view text, const model::Budget* budget) : text_(text), poll_(budget, 4096) {}

  /// Tokens up to End; a lexical error is thrown as ParseError.
  std::vector<Token> run() {
    std::vector<Token> out;
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") advance(3);
    for (;;) {
      poll_.tick_or_throw("reading the model");
      skip_space_and_comments();
      Token t;
      t.line = line_;
      t.col = col_;
      if (pos_ >= text_.size()) {
        out.push_back(t);
        return out;
      }
      const auto c = static_cast<unsigned char>(text_[pos_]);
      if (std::isalpha(c) || c == '_') {
        const std::size_t b = pos_;
        while (pos_ < text_.size() &&
               (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
          advance(1);
        t.kind = Tok::Ident;
        t.text = std::string(text_.substr(b, pos_ - b));
      } else if (std::isdigit(c)) {
        lex_number(t);
      } else if (c == '"') {
        lex_string(t);
      } else if (text_.substr(pos_, 3) == "\xE2\x86\x91" ||
                 text_.substr(pos_, 3) == "\xE2\x86\x93") {
        t.kind = Tok::Punct;
        t.text = text_[pos_ + 2] == '\x91' ? "RE" : "FE";  // ↑ and ↓
        advance(3);
      } else {
        static constexpr std::string_view kTwo[] = {
            "->", ":=", "..", "==", "!=", "<>", "<=", ">=", "&&", "||"};
        static constexpr std::string_view kOne = "{}(),;:&|!^+-*/=<>";
        t.kind = Tok::Punct;
        for (auto two : kTwo)
          if (text_.substr(pos_, 2) == two) t.text = std::string(two);
        if (t.text.empty() && kOne.find(static_cast<char>(c)) != std::string_view::npos)
          t.text = std::string(1, static_cast<char>(c));
        if (t.text.empty())
          throw ParseError{line_, col_, "unexpected character " + describe_char()};
        advance(t.text.size());
      }
      out.push_back(std::move(t));
    }
  }

 private:
  void advance(std::size_t n) {
    for (std::size_t i = 0; i < n && pos_ < text_.size(); ++i, ++pos_) {
      const auto c = static_cast<unsigned char>(text_[pos_]);
      if (c == '\n') {
        ++line_;
        col_ = 1;
      } else if ((c & 0xC0) != 0x80) {
        ++col_;  // columns count characters, not UTF-8 continuation bytes
      }
    }
  }

  void skip_space_and_comments() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        advance(1);
      } else if (c == '#' || text_.substr(pos_, 2) == "//") {
        while (pos_ < text_.size() && text_[pos_] != '\n') advance(1);
      } else {
        return;
      }
    }
  }

  std::string describe_char() const {
    const auto c = static_cast<unsigned char>(text_[pos_]);
    if (c >= 0x20 && c < 0x7F) return std::string("'") + static_cast<char>(c) + "'";
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", c);
    return buf;
  }

  void lex_number(Token& t) {
    const std::size_t b = pos_;
    while (pos_ < text_.size() && std::isalnum(static_cast<unsigned char>(text_[pos_]))) advance(1);
    const std::string word(text_.substr(b, pos_ - b));
    std::size_t digits = 0;
    while (digits < word.size() && std::isdigit(static_cast<unsigned char>(word[digits]))) ++digits;
    // The one checked conversion (model/literal.hpp): numbers up to 2^63 (negated: LINT's
    // smallest value), durations within TIME's range.
    const std::string digit_text = word.substr(0, digits);
    const std::string unit = word.substr(digits);
    t.text = digit_text;
    if (unit.empty()) {
      const auto magnitude = model::literal_magnitude(digit_text, 10, word);
      if (!magnitude) throw ParseError{t.line, t.col, magnitude.error};
      t.kind = Tok::Number;
      t.negation_only = *magnitude == model::kMaxLiteralMagnitude;
      t.value = t.negation_only ? std::numeric_limits<std::int64_t>::min()
                                : static_cast<std::int64_t>(*magnitude);
      return;
    }
    std::int64_t unit_ns = 0;
    if (unit == "ms")
      unit_ns = 1000000;
    else if (unit == "s")
      unit_ns = 1000000000;
    else if (unit == "min")
      unit_ns = 60000000000;
    else if (unit == "h")
      unit_ns = 3600000000000;
    if (unit_ns == 0)
      throw ParseError{t.line, t.col,
                       "invalid number '" + word +
                           "' (durations end in ms, s, min or h; quote "
                           "names that start with a digit)"};
    model::DurationLiteral d("'" + word + "'");
    const auto ms = d.add(digit_text, "", unit_ns) ? d.milliseconds(false)
                                                   : model::Converted<std::int64_t>{{}, d.error()};
    if (!ms) throw ParseError{t.line, t.col, "duration " + ms.error};
    t.kind = Tok::Time;
    t.value = *ms;
  }

  void lex_string(Token& t) {
    advance(1);
    t.kind = Tok::String;
    while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n') {
      if (text_[pos_] == '\\' && pos_ + 1 < text_.size() && text_[pos_ + 1] != '\n') advance(1);
      t.text += text_[pos_];
      advance(1);
    }
    if (pos_ >= text_.size() || text_[pos_] != '"')
      throw ParseError{t.line, t.col, "unterminated quoted name"};
    advance(1);
    if (t.text.empty()) throw ParseError{t.line, t.col, "empty quoted name"};
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1, col_ = 1;
  model::BudgetPoll poll_;
};

// ----------------------------------------------------------------------------------- parser

/// A reference to a step or chart by name, kept with its place for the checks after parsing.
struct NameRef {
  std::string name;
  SourceLocation where;
};

class Parser {
 public:
  Parser(std::vector<Token> tokens, std::string file, model::Diagnostics& diags,
         const model::Budget* budget)
      : toks_(std::move(tokens)), file_(std::move(file)), diags_(diags), poll_(budget, 4096) {}

  model::Project run() {
    model::Project project;
    project.dialect = model::Dialect::Grafcet;
    project.source_format = "g7";
    project.name = std::filesystem::path(file_).stem().string();
    if (project.name.empty()) project.name = "grafcet";
    project.where = loc(toks_.front());
    pou_.kind = model::PouKind::Program;
    pou_.where = project.where;
    while (peek().kind != Tok::End) {
      try {
        top_statement(project);
      } catch (const ParseError& e) {
        error(e.line, e.col, e.message);
        recover();
      }
      if (errors_ >= kMaxErrors) break;
    }
    pou_.name = project.name;
    check();
    project.pous.push_back(std::move(pou_));
    return project;
  }

 private:
  static constexpr int kMaxErrors = 50;

  // ---- token helpers
  const Token& peek(std::size_t k = 0) const { return toks_[std::min(pos_ + k, toks_.size() - 1)]; }
  const Token& next() {
    poll_.tick_or_throw("reading the model");
    const Token& t = peek();
    if (pos_ + 1 < toks_.size()) ++pos_;
    return t;
  }
  bool is_punct(std::string_view p, std::size_t k = 0) const {
    return peek(k).kind == Tok::Punct && peek(k).text == p;
  }
  bool is_word(std::string_view w, std::size_t k = 0) const {
    return peek(k).kind == Tok::Ident && peek(k).text == w;
  }
  bool accept(std::string_view p) {
    if (!is_punct(p)) return false;
    next();
    return true;
  }
  [[noreturn]] void fail(const Token& t, const std::string& message) const {
    throw ParseError{t.line, t.col, message};
  }
  static std::string show(const Token& t) {
    switch (t.kind) {
      case Tok::End:
        return "end of file";
      case Tok::String:
        return "\"" + t.text + "\"";
      case Tok::Time:
        return "duration";
      default:
        return "'" + t.text + "'";
    }
  }
  void expect(std::string_view p, std::string_view what = {}) {
    if (!accept(p))
      fail(peek(), "expected '" + std::string(p) + "'" +
                       (what.empty() ? "" : " " + std::string(what)) + ", found " + show(peek()));
  }
  SourceLocation loc(const Token& t) const {
    SourceLocation l;
    l.file = file_;
    l.line = t.line;
    l.column = t.col;
    return l;
  }
  void error(int line, int col, std::string message) {
    SourceLocation l;
    l.file = file_;
    l.line = line;
    l.column = col;
    diags_.push_back({model::Severity::Error, l, std::move(message)});
    ++errors_;
  }
  void error(const SourceLocation& l, std::string message) {
    diags_.push_back({model::Severity::Error, l, std::move(message)});
    ++errors_;
  }
  void note(const SourceLocation& l, model::Severity s, std::string message) {
    diags_.push_back({s, l, std::move(message)});
  }
  /// Skips to just after the next ';' (or to a '}' closing the current block).
  void recover() {
    while (peek().kind != Tok::End) {
      if (is_punct(";")) {
        next();
        return;
      }
      if (is_punct("}")) return;
      next();
    }
  }

  /// A step, transition or chart name: identifier, number or quoted string.
  NameRef name(std::string_view what) {
    const Token& t = peek();
    if (t.kind == Tok::Ident || t.kind == Tok::Number || t.kind == Tok::String) {
      next();
      return {t.text, loc(t)};
    }
    fail(t, "expected " + std::string(what) + ", found " + show(t));
  }
  /// A variable name: identifier or quoted string.
  NameRef var_name() {
    const Token& t = peek();
    if (t.kind == Tok::Ident || t.kind == Tok::String) {
      next();
      return {t.text, loc(t)};
    }
    fail(t, "expected a variable name, found " + show(t));
  }
  /// A Number token's value, negated after a unary minus (model::signed_literal: 2^63 only
  /// as LINT's smallest value).
  std::int64_t number_value(const Token& t, bool negated) const {
    const std::uint64_t magnitude =
        t.negation_only ? model::kMaxLiteralMagnitude : static_cast<std::uint64_t>(t.value);
    const auto v = model::signed_literal(negated, magnitude, (negated ? "-" : "") + t.text);
    if (!v) fail(t, v.error);
    return *v;
  }
  std::int64_t signed_number() {
    const bool neg = accept("-");
    const Token& t = peek();
    if (t.kind != Tok::Number) fail(t, "expected an integer, found " + show(t));
    next();
    return number_value(t, neg);
  }

  // ---- top level
  void top_statement(model::Project& project) {
    const Token& t = peek();
    if (is_word("project")) {
      next();
      project.name = name("a project name").name;
      expect(";");
    } else if (is_word("input") || is_word("output") || is_word("internal")) {
      declaration();
    } else if (is_word("grafcet")) {
      grafcet_block();
    } else {
      fail(t, "expected 'project', 'input', 'output', 'internal' or 'grafcet', found " + show(t));
    }
  }

  void declaration() {
    const Token& kw = next();
    const auto dir = kw.text == "input"    ? model::VarDirection::Input
                     : kw.text == "output" ? model::VarDirection::Output
                                           : model::VarDirection::Local;
    std::vector<NameRef> names{var_name()};
    while (accept(",")) names.push_back(var_name());
    model::Type type = model::Type::boolean();
    if (accept(":")) {
      if (peek().kind == Tok::Ident && model::iequals(peek().text, "bool")) {
        next();
      } else {
        const Token& at = peek();
        const std::int64_t lo = signed_number();
        expect("..", "in an integer range lo..hi");
        const std::int64_t hi = signed_number();
        if (lo > hi)
          fail(at, "empty integer range " + std::to_string(lo) + ".." + std::to_string(hi));
        type = model::Type::integer(g7::range_type_name(lo, hi), lo, hi);
      }
    }
    std::optional<std::int64_t> initial;
    if (accept(":=")) {
      const Token& at = peek();
      if (at.kind == Tok::Ident &&
          (model::iequals(at.text, "true") || model::iequals(at.text, "false"))) {
        initial = model::iequals(next().text, "true") ? 1 : 0;
      } else {
        initial = signed_number();
      }
      const bool fits = type.kind == model::TypeKind::Bool
                            ? (*initial == 0 || *initial == 1)
                            : (*initial >= type.lo && *initial <= type.hi);
      if (!fits)
        fail(at, "initial value " + std::to_string(*initial) + " is outside " +
                     (type.kind == model::TypeKind::Bool ? std::string("BOOL (0..1)")
                                                         : model::range_text(type)));
    }
    expect(";");
    for (auto& n : names) {
      if (pou_.find_variable(n.name)) {
        error(n.where, "variable '" + n.name + "' is declared twice");
        continue;
      }
      model::Variable v;
      v.name = n.name;
      v.direction = dir;
      v.type = type;
      v.initial = initial;
      v.where = n.where;
      pou_.variables.push_back(std::move(v));
    }
  }

  // ---- grafcet blocks
  void grafcet_block() {
    next();
    NameRef n = name("a partial grafcet name");
    // A duplicate is reported, and its block still parsed, so that later errors stay precise.
    if (chart_named(n.name)) error(n.where, "partial grafcet '" + n.name + "' is declared twice");
    model::Chart chart;
    chart.name = n.name;
    chart.where = n.where;
    chart_by_name_.emplace(model::to_upper(n.name), pou_.charts.size());
    pou_.charts.push_back(std::move(chart));
    steps_of_chart_.emplace_back();
    transitions_of_chart_.emplace_back();
    chart_ = static_cast<int>(pou_.charts.size()) - 1;
    expect("{", "after the partial grafcet name");
    while (!is_punct("}")) {
      if (peek().kind == Tok::End) fail(peek(), "missing '}' closing grafcet '" + n.name + "'");
      try {
        chart_statement();
      } catch (const ParseError& e) {
        error(e.line, e.col, e.message);
        recover();
      }
      if (errors_ >= kMaxErrors) return;
    }
    next();
  }

  model::Chart& chart() { return pou_.charts[static_cast<std::size_t>(chart_)]; }

  void chart_statement() {
    const Token& t = peek();
    if (is_word("step"))
      step_statement();
    else if (is_word("transition"))
      transition_statement();
    else if (is_word("action"))
      action_statement();
    else
      fail(t, "expected 'step', 'transition', 'action' or '}', found " + show(t));
  }

  void step_statement() {
    next();
    std::vector<NameRef> names{name("a step name")};
    while (accept(",")) names.push_back(name("a step name"));
    model::Step proto;
    bool entry = false, exit = false;
    while (!is_punct(";")) {
      const Token& m = peek();
      if (is_word("initial")) {
        next();
        proto.initial = true;
      } else if (is_word("linked") || is_punct("*")) {
        next();
        proto.activation_link = true;
      } else if (is_word("entry")) {
        next();
        entry = true;
      } else if (is_word("exit")) {
        next();
        exit = true;
      } else if (is_word("macro")) {
        next();
        if (proto.kind != model::StepKind::Normal)
          fail(m, "a step is a macro-step or an enclosing step, not both");
        proto.kind = model::StepKind::MacroStep;
        NameRef e = name("the name of the macro-step's expansion");
        proto.expansion = e.name;
        chart_refs_.push_back(std::move(e));
      } else if (is_word("encloses")) {
        next();
        if (proto.kind != model::StepKind::Normal)
          fail(m, "a step is a macro-step or an enclosing step, not both");
        proto.kind = model::StepKind::Enclosing;
        for (auto& e : name_set("the name of an enclosed partial grafcet")) {
          proto.enclosed.push_back(e.name);
          chart_refs_.push_back(std::move(e));
        }
      } else {
        fail(m,
             "expected 'initial', 'linked', 'entry', 'exit', 'macro', 'encloses' or ';', found " +
                 show(m));
      }
    }
    next();
    if (names.size() > 1 && (entry || exit || proto.kind != model::StepKind::Normal))
      fail(toks_[pos_ - 1], "'entry', 'exit', 'macro' and 'encloses' apply to one step at a time");
    for (auto& n : names) {
      const std::string upper = model::to_upper(n.name);
      if (!steps_of_chart_[static_cast<std::size_t>(chart_)].insert(upper).second) {
        error(n.where, "step '" + n.name + "' is declared twice in grafcet '" + chart().name + "'");
        continue;
      }
      ++charts_with_step_[upper];
      if (entry) set_once(chart().macro_entry, n, "an entry step");
      if (exit) set_once(chart().macro_exit, n, "an exit step");
      model::Step s = proto;
      s.name = n.name;
      s.where = n.where;
      chart().steps.push_back(std::move(s));
    }
  }

  void set_once(std::string& slot, const NameRef& n, const char* what) {
    if (!slot.empty())
      error(n.where, "grafcet '" + chart().name + "' already has " + what + " ('" + slot + "')");
    else
      slot = n.name;
  }

  /// `name` or `{}` or `{name, name...}`.
  std::vector<NameRef> name_set(std::string_view what) {
    std::vector<NameRef> out;
    if (accept("{")) {
      if (accept("}")) return out;
      do out.push_back(name(what));
      while (accept(","));
      expect("}", "closing the set");
      return out;
    }
    out.push_back(name(std::string(what) + " or a set {a, b}"));
    return out;
  }
  std::vector<NameRef> step_set() { return name_set("a step name"); }

  void transition_statement() {
    const Token& kw = next();
    model::Transition tr;
    tr.where = loc(kw);
    tr.order = static_cast<int>(chart().transitions.size());
    std::vector<NameRef> sources;
    if (!is_punct("{") && is_punct(":", 1)) {
      tr.name = name("a transition name").name;
      next();
    }
    sources = step_set();
    expect("->", "between the upstream and downstream steps");
    std::vector<NameRef> targets = step_set();
    if (is_word("when")) {
      next();
      tr.guard = condition();
    } else {
      tr.guard = model::make_bool(true, tr.where);
    }
    expect(";", "at the end of the transition");
    if (!tr.name.empty() &&
        !transitions_of_chart_[static_cast<std::size_t>(chart_)].insert(tr.name).second)
      error(tr.where,
            "transition '" + tr.name + "' is declared twice in grafcet '" + chart().name + "'");
    for (auto& s : sources) tr.sources.push_back(s.name);
    for (auto& s : targets) tr.targets.push_back(s.name);
    step_refs_.push_back({chart_, std::move(sources)});
    step_refs_.push_back({chart_, std::move(targets)});
    chart().transitions.push_back(std::move(tr));
  }

  void action_statement() {
    const Token& kw = next();
    NameRef step = name("a step name");
    step_refs_.push_back({chart_, {step}});
    if (is_punct(":")) {
      next();
      continuous_or_forcing(kw, step);
      return;
    }
    model::StoredAction sa;
    sa.chart = chart().name;
    sa.step = step.name;
    sa.where = loc(kw);
    if (is_word("on_enter")) {
      next();
      sa.when = model::StoredWhen::Activation;
    } else if (is_word("on_exit")) {
      next();
      sa.when = model::StoredWhen::Deactivation;
    } else if (is_word("on")) {
      next();
      sa.when = model::StoredWhen::Event;
      sa.event = condition();
    } else {
      fail(peek(),
           "expected ':', 'on_enter', 'on_exit' or 'on' after the step, found " + show(peek()));
    }
    expect(":");
    NameRef v = var_name();
    expect(":=", "in the stored action");
    sa.variable = v.name;
    sa.value = expression();
    expect(";", "at the end of the action");
    var_refs_.push_back({v, true});
    pou_.stored_actions.push_back(std::move(sa));
  }

  void continuous_or_forcing(const Token& kw, const NameRef& step) {
    if (peek().kind != Tok::String && peek().kind != Tok::Ident && peek().kind != Tok::Number)
      fail(peek(), "expected a variable or a forcing order G{...}, found " + show(peek()));
    if (is_punct("{", 1)) {
      model::ForcingOrder fo;
      fo.chart = chart().name;
      fo.step = step.name;
      fo.where = loc(kw);
      NameRef target = name("a partial grafcet name");
      fo.target = target.name;
      chart_refs_.push_back(target);
      next();  // {
      std::vector<NameRef> situation;
      if (is_punct("*")) {
        next();
        fo.kind = model::ForcingKind::Current;
      } else if (peek().kind == Tok::Ident && model::iequals(peek().text, "INIT")) {
        next();
        fo.kind = model::ForcingKind::Initial;
      } else if (is_punct("}")) {
        fo.kind = model::ForcingKind::Empty;
      } else {
        fo.kind = model::ForcingKind::Situation;
        do situation.push_back(name("a step of the forced grafcet"));
        while (accept(","));
      }
      expect("}", "closing the forced situation");
      expect(";", "at the end of the action");
      for (const auto& s : situation) fo.situation.push_back(s.name);
      forced_refs_.push_back({static_cast<int>(pou_.forcing_orders.size()), std::move(situation)});
      pou_.forcing_orders.push_back(std::move(fo));
      return;
    }
    NameRef v = var_name();
    model::ActionAssociation a;
    a.chart = chart().name;
    a.step = step.name;
    a.action = v.name;
    a.qualifier = model::Qualifier::N;
    a.where = loc(kw);
    if (is_word("if")) {
      next();
      a.condition = condition();
    }
    expect(";", "at the end of the action");
    var_refs_.push_back({v, false});
    if (!pou_.find_action(v.name)) {
      model::Action act;
      act.name = v.name;
      act.kind = model::ActionBodyKind::Variable;
      act.variable = v.name;
      act.where = v.where;
      pou_.actions.push_back(std::move(act));
    }
    pou_.associations.push_back(std::move(a));
  }

  // ---- expressions
  ExprPtr condition() { return boolify(expression()); }

  ExprPtr expression() { return parse_or(); }

  ExprPtr nary(ExprKind kind, std::vector<ExprPtr> args, const SourceLocation& where) {
    if (args.size() == 1) return args[0];
    return model::make_nary(kind, std::move(args), where);
  }
  ExprPtr parse_or() {
    const SourceLocation at = loc(peek());
    std::vector<ExprPtr> args{parse_xor()};
    while (accept("|") || accept("||")) args.push_back(parse_xor());
    return nary(ExprKind::Or, std::move(args), at);
  }
  ExprPtr parse_xor() {
    const SourceLocation at = loc(peek());
    std::vector<ExprPtr> args{parse_and()};
    while (accept("^")) args.push_back(parse_and());
    return nary(ExprKind::Xor, std::move(args), at);
  }
  ExprPtr parse_and() {
    const SourceLocation at = loc(peek());
    std::vector<ExprPtr> args{parse_cmp()};
    while (accept("&") || accept("&&")) args.push_back(parse_cmp());
    return nary(ExprKind::And, std::move(args), at);
  }
  ExprPtr parse_cmp() {
    const SourceLocation at = loc(peek());
    ExprPtr lhs = parse_add();
    static const std::pair<std::string_view, ExprKind> kOps[] = {
        {"=", ExprKind::Eq}, {"==", ExprKind::Eq}, {"<>", ExprKind::Ne}, {"!=", ExprKind::Ne},
        {"<", ExprKind::Lt}, {"<=", ExprKind::Le}, {">", ExprKind::Gt},  {">=", ExprKind::Ge}};
    for (const auto& [text, kind] : kOps) {
      if (is_punct(text)) {
        next();
        ExprPtr rhs = parse_add();
        for (const auto& op : kOps)
          if (is_punct(op.first)) fail(peek(), "comparisons do not chain: add parentheses");
        return model::make_binary(kind, std::move(lhs), std::move(rhs), at);
      }
    }
    return lhs;
  }
  // `a + b + c ...` is built by a loop: bound the height of the tree it makes, too.
  void bound_height(const ExprPtr& e) const {
    if (e->height > static_cast<std::uint32_t>(model::kMaxNesting))
      fail(peek(),
           "expression nested deeper than " + std::to_string(model::kMaxNesting) + " levels");
  }
  ExprPtr parse_add() {
    const SourceLocation at = loc(peek());
    ExprPtr e = parse_mul();
    for (;;) {
      if (accept("+"))
        e = model::make_binary(ExprKind::Add, e, parse_mul(), at);
      else if (accept("-"))
        e = model::make_binary(ExprKind::Sub, e, parse_mul(), at);
      else
        return e;
      bound_height(e);
    }
  }
  ExprPtr parse_mul() {
    const SourceLocation at = loc(peek());
    ExprPtr e = parse_unary();
    for (;;) {
      if (accept("*"))
        e = model::make_binary(ExprKind::Mul, e, parse_unary(), at);
      else if (accept("/"))
        e = model::make_binary(ExprKind::Div, e, parse_unary(), at);
      else if (is_word("mod") || is_word("MOD")) {
        next();
        e = model::make_binary(ExprKind::Mod, e, parse_unary(), at);
      } else
        return e;
      bound_height(e);
    }
  }
  // Every recursion of the expression grammar passes here (operators and parentheses).
  ExprPtr parse_unary() {
    const Token& t = peek();
    const SourceLocation at = loc(t);
    const model::NestingLevel level(depth_);
    if (level.too_deep())
      fail(t, "expression nested deeper than " + std::to_string(model::kMaxNesting) + " levels");
    if (accept("!")) return model::make_unary(ExprKind::Not, parse_unary(), at);
    if (is_punct("-")) {
      next();
      if (peek().kind == Tok::Number) return model::make_int(number_value(next(), true), at);
      return model::make_unary(ExprKind::Neg, parse_unary(), at);
    }
    if (is_punct("RE") || is_word("RE")) {
      next();
      return model::make_unary(ExprKind::Rising, parse_unary(), at);
    }
    if (is_punct("FE") || is_word("FE")) {
      next();
      return model::make_unary(ExprKind::Falling, parse_unary(), at);
    }
    return parse_primary();
  }
  ExprPtr parse_primary() {
    const Token& t = next();
    const SourceLocation at = loc(t);
    switch (t.kind) {
      case Tok::Number:
        return model::make_int(number_value(t, false), at);
      case Tok::Time: {
        if (!accept("/")) return model::make_time(t.value, at);
        ExprPtr inner = boolify(parse_unary());
        std::int64_t t2 = 0;
        if (is_punct("/") && peek(1).kind == Tok::Time) {
          next();
          t2 = next().value;
        }
        return model::make_delay(t.value, std::move(inner), t2, at);
      }
      case Tok::String: {
        ExprPtr e = model::make_name(t.text, at);
        names_.push_back({t.text, at});
        return e;
      }
      case Tok::Ident: {
        if (model::iequals(t.text, "true")) return model::make_bool(true, at);
        if (model::iequals(t.text, "false")) return model::make_bool(false, at);
        if (g7::is_reserved_in_expression(t.text))
          fail(t, "'" + t.text + "' is a reserved word: quote a variable of that name (\"" +
                      t.text + "\")");
        names_.push_back({t.text, at});
        return model::make_name(t.text, at);
      }
      case Tok::Punct:
        if (t.text == "(") {
          ExprPtr e = expression();
          expect(")", "closing the parenthesis");
          return e;
        }
        break;
      case Tok::End:
        break;
    }
    fail(t, "expected an expression, found " + show(t));
  }

  /// In a condition, the constants 1 and 0 are true and false.
  ExprPtr boolify(const ExprPtr& e) {
    switch (e->kind) {
      case ExprKind::IntConst:
        if (e->value == 0 || e->value == 1) return model::make_bool(e->value == 1, e->where);
        throw ParseError{e->where.line, e->where.column,
                         "the integer " + std::to_string(e->value) + " is not a condition"};
      case ExprKind::Not:
      case ExprKind::And:
      case ExprKind::Or:
      case ExprKind::Xor:
      case ExprKind::Rising:
      case ExprKind::Falling: {
        bool changed = false;
        std::vector<ExprPtr> args;
        for (const auto& a : e->args) {
          args.push_back(boolify(a));
          changed = changed || args.back() != a;
        }
        if (!changed) return e;
        auto copy = std::make_shared<model::Expr>(*e);
        copy->args = std::move(args);
        return copy;
      }
      default:
        return e;
    }
  }

  // ---- checks after parsing: every name refers to something declared
  struct VarRef {
    NameRef var;
    bool stored;
  };

  int charts_with_step(std::string_view step) const {
    const auto it = charts_with_step_.find(model::to_upper(step));
    return it == charts_with_step_.end() ? 0 : it->second;
  }
  bool chart_has_step(std::size_t chart, std::string_view step) const {
    return steps_of_chart_[chart].count(model::to_upper(step)) > 0;
  }

  void check() {
    for (const auto& [ci, refs] : step_refs_) {
      const auto& c = pou_.charts[static_cast<std::size_t>(ci)];
      for (const auto& r : refs)
        if (!chart_has_step(static_cast<std::size_t>(ci), r.name))
          error(r.where, "undeclared step '" + r.name + "' in grafcet '" + c.name + "'");
    }
    for (const auto& r : chart_refs_)
      if (!chart_named(r.name)) error(r.where, "undeclared partial grafcet '" + r.name + "'");
    for (const auto& [oi, refs] : forced_refs_) {
      const auto& fo = pou_.forcing_orders[static_cast<std::size_t>(oi)];
      const model::Chart* target = chart_named(fo.target);
      if (!target) continue;
      const auto target_index = static_cast<std::size_t>(target - pou_.charts.data());
      for (const auto& r : refs)
        if (!chart_has_step(target_index, r.name))
          error(r.where,
                "forced step '" + r.name + "' is not a step of grafcet '" + target->name + "'");
    }
    for (const auto& c : pou_.charts) {
      for (const auto& s : c.steps)
        if (s.kind == model::StepKind::Enclosing && s.enclosed.empty())
          note(s.where, model::Severity::Warning,
               "enclosing step '" + s.name + "' encloses no partial grafcet");
      for (const auto& s : c.steps)
        if (s.kind == model::StepKind::MacroStep)
          if (const model::Chart* e = chart_named(s.expansion))
            if (e->macro_entry.empty() || e->macro_exit.empty())
              error(s.where, "the expansion '" + e->name + "' of macro-step '" + s.name +
                                 "' needs an entry step and an exit step");
      for (const auto& t : c.transitions) {
        if (t.sources.empty())
          note(t.where, model::Severity::Note, "source transition (no upstream step)");
        if (t.targets.empty())
          note(t.where, model::Severity::Note, "sink transition (no downstream step)");
      }
    }
    for (const auto& r : names_) {
      if (pou_.find_variable(r.name)) continue;
      const int steps = r.name.size() > 1 && (r.name[0] == 'X' || r.name[0] == 'x')
                            ? charts_with_step(std::string_view(r.name).substr(1))
                            : 0;
      if (steps == 1) continue;
      if (steps > 1) {
        error(r.where, "step variable '" + r.name +
                           "' is ambiguous: several partial grafcets have a step '" +
                           r.name.substr(1) + "'");
        continue;
      }
      error(r.where,
            "unknown name '" + r.name + "' (not a declared variable nor a step variable X<step>)");
    }
    for (const auto& [v, stored] : var_refs_) {
      const model::Variable* var = pou_.find_variable(v.name);
      if (!var) {
        error(v.where, "undeclared variable '" + v.name + "'");
      } else if (var->direction == model::VarDirection::Input) {
        error(v.where, "the input '" + v.name + "' cannot be assigned by an action");
      } else if (!stored && var->type.kind != model::TypeKind::Bool) {
        error(v.where, "the continuous action '" + v.name + "' needs a Boolean variable");
      }
    }
    // Stored actions on Boolean variables hold Boolean constants.
    for (auto& sa : pou_.stored_actions) {
      const model::Variable* var = pou_.find_variable(sa.variable);
      if (!var || var->type.kind != model::TypeKind::Bool) continue;
      try {
        sa.value = boolify(sa.value);
      } catch (const ParseError& e) {
        error(e.line, e.col,
              "Boolean variable '" + sa.variable + "' takes 0, 1, true, false or a condition");
      }
    }
  }

  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  int depth_ = 0;  ///< expression nesting (model::kMaxNesting)
  std::string file_;
  model::Diagnostics& diags_;
  model::BudgetPoll poll_;
  int errors_ = 0;
  model::Pou pou_;
  /// Upper-cased partial grafcet name -> its first chart: thousands of charts are looked up by
  /// name without a linear search each.
  std::unordered_map<std::string, std::size_t> chart_by_name_;
  /// Per chart (as pou_.charts), the upper-cased names of its steps (and the names of its
  /// transitions, compared as written, as before); and per upper-cased step
  /// name, how many charts declare it: every reference is checked without a linear search.
  std::vector<std::unordered_set<std::string>> steps_of_chart_;
  std::vector<std::unordered_set<std::string>> transitions_of_chart_;  ///< names, as written
  std::unordered_map<std::string, int> charts_with_step_;
  const model::Chart* chart_named(std::string_view name) const {
    const auto it = chart_by_name_.find(model::to_upper(name));
    return it == chart_by_name_.end() ? nullptr : &pou_.charts[it->second];
  }
  int chart_ = -1;
  std::vector<std::pair<int, std::vector<NameRef>>> step_refs_;
  std::vector<NameRef> chart_refs_;
  std::vector<std::pair<int, std::vector<NameRef>>> forced_refs_;
  std::vector<NameRef> names_;
  std::vector<VarRef> var_refs_;
};

}  // namespace
}  // namespace g7_syntax

LoadResult load_g7(std::string_view text, const std::string& file, const model::Budget* budget) {
  LoadResult r;
  std::vector<g7_syntax::Token> tokens;
  try {
    tokens = g7_syntax::Lexer(text, budget).run();
  } catch (const g7_syntax::ParseError& e) {
    model::SourceLocation l;
    l.file = file;
    l.line = e.line;
    l.column = e.col;
    r.diagnostics.push_back({model::Severity::Error, l, e.message});
    return r;
  }
  model::Project p = g7_syntax::Parser(std::move(tokens), file, r.diagnostics, budget).run();
  if (!model::has_errors(r.diagnostics)) r.project = std::move(p);
  return r;
}

}  // namespace sfcv::io
