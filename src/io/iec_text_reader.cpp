// IEC 61131-3 textual SFC (IEC 61131-3 2.6 textual form): PROGRAM / FUNCTION_BLOCK with VAR
// sections, INITIAL_STEP / STEP with action associations, TRANSITION ... FROM ... TO ...,
// ACTION bodies in ST or as nested SFC.
//
// Syntax errors are reported here with file:line:col; semantic defects (duplicate steps,
// transitions to undeclared steps, ...) are kept in the model for model validation to report.

#include <memory>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "io/st_lexer.hpp"
#include "io/st_parser.hpp"
#include "model/data_types.hpp"
#include "model/names.hpp"

namespace sfcv::io {

namespace {

using st::ParseError;
using st::Parser;
using st::Token;
using st::TokenKind;

constexpr std::size_t kMaxErrors = 50;

class IecTextReader {
 public:
  IecTextReader(std::string_view text, const std::string& file, const model::Budget* budget)
      : file_(file) {
    model::SourceLocation start;
    start.file = file;
    start.line = 1;
    start.column = 1;
    st::Locator locator(start);
    auto tokens = st::tokenize(text, locator, diags_, budget);
    parser_ = std::make_unique<Parser>(std::move(tokens), locator, budget);
  }

  LoadResult run() {
    model::Project project;
    project.source_format = "iec-text";
    project.dialect = model::Dialect::Iec61131;
    project.where.file = file_;
    Parser& p = *parser_;
    // After a lexical error the token stream has a hole; parsing it would mostly report
    // consequences of the same mistake.
    if (model::has_errors(diags_)) return LoadResult{std::nullopt, std::move(diags_)};
    while (!p.at(TokenKind::End) && diags_.size() < kMaxErrors) {
      try {
        if (p.at_word("PROGRAM") || p.at_word("FUNCTION_BLOCK") || p.at_word("FUNCTION")) {
          project.pous.push_back(parse_pou());
        } else if (p.at_word("CONFIGURATION")) {
          skip_block("CONFIGURATION", "END_CONFIGURATION", "tasks and resources are not modelled");
        } else if (p.at_word("TYPE")) {
          p.type_declarations(project.data_types);
        } else {
          p.fail_unexpected("PROGRAM, FUNCTION_BLOCK, FUNCTION, CONFIGURATION or TYPE");
        }
      } catch (const ParseError& e) {
        error(e);
        // Resynchronise on the next declaration at file level.
        while (!p.at(TokenKind::End) && !p.at_word("PROGRAM") && !p.at_word("FUNCTION_BLOCK") &&
               !p.at_word("FUNCTION") && !p.at_word("CONFIGURATION") && !p.at_word("TYPE"))
          p.next();
      }
    }
    if (project.pous.empty() && !model::has_errors(diags_)) {
      model::SourceLocation where;
      where.file = file_;
      diags_.push_back(
          {model::Severity::Error, where, "no PROGRAM, FUNCTION_BLOCK or FUNCTION in the file"});
    }
    // Named after its first program or function block (functions usually come first).
    for (const auto& pou : project.pous)
      if (project.name.empty() && pou.kind != model::PouKind::Function) project.name = pou.name;
    if (project.name.empty() && !project.pous.empty()) project.name = project.pous.front().name;
    if (!model::has_errors(diags_)) model::lower_data_types(project, diags_);
    LoadResult r;
    if (!model::has_errors(diags_)) r.project = std::move(project);
    r.diagnostics = std::move(diags_);
    return r;
  }

 private:
  void error(const ParseError& e) { diags_.push_back({model::Severity::Error, e.where, e.what()}); }

  // Skips `begin name ... end` (FUNCTION, CONFIGURATION, TYPE) with a note.
  void skip_block(std::string_view begin, std::string_view end, std::string_view why) {
    Parser& p = *parser_;
    const Token& kw = p.next();
    std::string name = p.at(TokenKind::Identifier) ? p.peek().text : "";
    while (!p.at(TokenKind::End) && !p.at_word(end)) p.next();
    if (p.at(TokenKind::End)) p.fail_unexpected(end);
    p.next();
    diags_.push_back({model::Severity::Note, p.where(kw),
                      std::string(begin) + (name.empty() ? "" : " '" + name + "'") +
                          " skipped: " + std::string(why)});
  }

  model::Pou parse_pou() {
    Parser& p = *parser_;
    const Token& kw = p.next();
    model::Pou pou;
    const bool program = model::iequals(kw.text, "PROGRAM");
    const bool function = model::iequals(kw.text, "FUNCTION");
    pou.kind = program    ? model::PouKind::Program
               : function ? model::PouKind::Function
                          : model::PouKind::FunctionBlock;
    const std::string end = program    ? "END_PROGRAM"
                            : function ? "END_FUNCTION"
                                       : "END_FUNCTION_BLOCK";
    pou.where = p.where(kw);
    pou.name = p.identifier(program    ? "a program name"
                            : function ? "a function name"
                                       : "a function block name");
    if (function) {
      // `FUNCTION f : INT`: the result is the variable named like the function.
      p.expect(TokenKind::Colon, "':' and the function's result type");
      model::Variable result;
      result.name = pou.name;
      result.direction = model::VarDirection::Output;
      result.where = pou.where;
      result.type = p.var_type();
      pou.variables.push_back(std::move(result));
    }
    if (p.at_word("EXTENDS") || p.at_word("IMPLEMENTS"))
      p.fail(p.peek(), "unsupported: " + model::to_upper(p.peek().text) +
                           " (object-oriented function blocks)");
    while (p.at_var_section()) {
      guarded("END_VAR", end, [&] { p.var_section(pou.variables); });
    }
    if (at_sfc_element()) {
      model::Chart chart;
      chart.name = pou.name;
      chart.where = p.where(p.peek());
      pou.charts.push_back(std::move(chart));
      sfc_elements(pou, 0, end);
      // Only ACTION declarations: there is no top-level chart after all.
      if (pou.charts[0].steps.empty() && pou.charts[0].transitions.empty()) {
        pou.charts.erase(pou.charts.begin());
        for (auto& a : pou.actions)
          if (a.kind == model::ActionBodyKind::Chart) --a.chart;
      }
    } else {
      guarded(end, end, [&] {
        pou.body = p.statements();
        if (!p.at_word(end)) p.fail_unexpected("a statement or " + end);
      });
    }
    if (!p.accept_word(end)) p.fail_unexpected(end);
    resolve_variable_actions(pou);
    return pou;
  }

  bool at_sfc_element() const {
    const Parser& p = *parser_;
    return p.at_word("STEP") || p.at_word("INITIAL_STEP") || p.at_word("TRANSITION") ||
           p.at_word("ACTION");
  }

  // Runs `f`; on a syntax error, records it and skips to just after `element_end`, or to
  // `block_end` (left for the caller) when the element is not closed.
  template <typename F>
  void guarded(std::string_view element_end, std::string_view block_end, F&& f) {
    Parser& p = *parser_;
    try {
      f();
    } catch (const ParseError& e) {
      error(e);
      while (!p.at(TokenKind::End) && !p.at_word(element_end) && !p.at_word(block_end)) p.next();
      if (p.at_word(element_end) && element_end != block_end) p.next();
    }
  }

  // Steps, transitions and actions of chart `ci` up to `end` (not consumed).
  void sfc_elements(model::Pou& pou, int ci, std::string_view end) {
    Parser& p = *parser_;
    while (!p.at_word(end) && !p.at(TokenKind::End) && diags_.size() < kMaxErrors) {
      if (p.at_word("STEP") || p.at_word("INITIAL_STEP")) {
        guarded("END_STEP", end, [&] { parse_step(pou, ci); });
      } else if (p.at_word("TRANSITION")) {
        guarded("END_TRANSITION", end, [&] { parse_transition(pou, ci); });
      } else if (p.at_word("ACTION")) {
        guarded("END_ACTION", end, [&] { parse_action(pou); });
      } else {
        const std::string expected =
            "STEP, INITIAL_STEP, TRANSITION, ACTION or " + std::string(end);
        guarded(end, end, [&] { p.fail_unexpected(expected); });
      }
    }
  }

  model::Chart& chart_at(model::Pou& pou, int ci) {
    return pou.charts[static_cast<std::size_t>(ci)];
  }

  void parse_step(model::Pou& pou, int ci) {
    Parser& p = *parser_;
    const Token& kw = p.next();
    model::Step s;
    s.initial = model::iequals(kw.text, "INITIAL_STEP");
    s.where = p.where(kw);
    s.name = p.identifier("a step name");
    p.expect(TokenKind::Colon, "':' after the step name");
    while (!p.at_word("END_STEP")) {
      if (p.accept(TokenKind::Semicolon)) continue;
      pou.associations.push_back(parse_association(chart_at(pou, ci).name, s.name));
    }
    p.next();
    p.accept(TokenKind::Semicolon);
    chart_at(pou, ci).steps.push_back(std::move(s));
  }

  // action_name [ '(' [qualifier [, duration]] {, indicator} ')' ] ';'
  model::ActionAssociation parse_association(const std::string& chart_name,
                                             const std::string& step) {
    Parser& p = *parser_;
    model::ActionAssociation a;
    a.chart = chart_name;
    a.step = step;
    a.where = p.where(p.peek());
    a.action = p.identifier("an action association or END_STEP");
    // `inst.ACT`: an action of a function block instance (TwinCAT, CODESYS).
    while (p.accept(TokenKind::Dot)) a.action += "." + p.identifier("an action name after '.'");
    if (p.accept(TokenKind::LParen)) {
      if (p.at(TokenKind::Identifier)) {
        const Token& q = p.next();
        const auto qualifier = model::parse_qualifier(q.text);
        if (!qualifier)
          p.fail(q,
                 "expected an action qualifier (N, R, S, P, P0, P1, L, D, SD, DS, SL, DL), "
                 "found '" +
                     q.text + "'");
        a.qualifier = *qualifier;
        if (model::is_timed(a.qualifier)) {
          if (!p.accept(TokenKind::Comma))
            p.fail(q, "qualifier " + model::to_upper(q.text) + " needs a duration");
          const Token& d = p.peek();
          if (d.kind == TokenKind::Time) {
            if (d.value < 0) p.fail(d, "negative duration");
            a.duration_ms = d.value;
          } else if (d.kind == TokenKind::Identifier && !st::is_reserved(d.text)) {
            a.duration_variable = d.text;
          } else {
            p.fail_unexpected("a TIME literal or a TIME variable as duration");
          }
          p.next();
        } else if (p.at(TokenKind::Comma) && p.at(TokenKind::Time, 1)) {
          p.fail(p.peek(1), "qualifier " + model::to_upper(q.text) + " takes no duration");
        }
      }
      // Indicator variables: IEC allows several; the model keeps the first.
      while (p.accept(TokenKind::Comma)) {
        std::string indicator = p.identifier("an indicator variable");
        if (a.indicator.empty()) a.indicator = std::move(indicator);
      }
      p.expect(TokenKind::RParen, "')' after the action qualifier");
    }
    p.expect(TokenKind::Semicolon, "';' after the action association");
    return a;
  }

  std::vector<std::string> step_list(std::string_view what) {
    Parser& p = *parser_;
    std::vector<std::string> steps;
    if (p.accept(TokenKind::LParen)) {
      do steps.push_back(p.identifier("a step name"));
      while (p.accept(TokenKind::Comma));
      p.expect(TokenKind::RParen, "',' or ')' in the step list");
    } else {
      steps.push_back(p.identifier(what));
    }
    return steps;
  }

  void parse_transition(model::Pou& pou, int ci) {
    Parser& p = *parser_;
    const Token& kw = p.next();
    model::Transition t;
    t.where = p.where(kw);
    // The name is optional and may itself be FROM; it is a name when FROM does not start the
    // source list here.
    const bool priority_follows =
        p.at(TokenKind::LParen, 1) && p.at_word("PRIORITY", 2) && p.at(TokenKind::Assign, 3);
    if (p.at(TokenKind::Identifier) &&
        (!p.at_word("FROM") || p.at_word("FROM", 1) || priority_follows))
      t.name = p.identifier("a transition name or FROM");
    if (p.at(TokenKind::LParen)) {
      p.next();
      p.expect_word("PRIORITY");
      p.expect(TokenKind::Assign, "':=' after PRIORITY");
      const Token& n = p.expect(TokenKind::Integer, "an integer priority");
      if (n.negation_only || n.value > 1000000) p.fail(n, "priority too large");
      t.priority = static_cast<int>(n.value);
      p.expect(TokenKind::RParen, "')' after the priority");
    }
    p.expect_word("FROM");
    t.sources = step_list("a step name or '(' after FROM");
    p.expect_word("TO");
    t.targets = step_list("a step name or '(' after TO");
    if (p.accept(TokenKind::Assign)) {
      t.guard = p.expression();
      p.accept(TokenKind::Semicolon);
    } else if (p.at(TokenKind::Colon)) {
      const Token& colon = p.next();
      model::StmtList body = p.statements();
      // `T := F(x, q => z);` would copy q into z: a condition has no outputs to bind.
      if (body.size() != 1 || body[0]->kind != model::StmtKind::Assign || t.name.empty() ||
          !model::iequals(body[0]->target, t.name) || !body[0]->outputs.empty())
        p.fail(colon,
               "unsupported: transition body other than '<transition name> := <condition>;'");
      t.guard = body[0]->value;
    } else {
      p.fail_unexpected("':=' and the transition condition");
    }
    p.expect_word("END_TRANSITION");
    p.accept(TokenKind::Semicolon);
    auto& c = chart_at(pou, ci);
    t.order = static_cast<int>(c.transitions.size());
    c.transitions.push_back(std::move(t));
  }

  void parse_action(model::Pou& pou) {
    Parser& p = *parser_;
    const Token& kw = p.next();
    model::Action a;
    a.where = p.where(kw);
    a.name = p.identifier("an action name");
    p.expect(TokenKind::Colon, "':' after the action name");
    if (at_sfc_element()) {
      // An action body that is itself an SFC: a nested chart (hierarchy).
      model::Chart nested;
      nested.name = a.name;
      nested.parent_action = a.name;
      nested.where = p.where(p.peek());
      pou.charts.push_back(std::move(nested));
      a.kind = model::ActionBodyKind::Chart;
      a.chart = static_cast<int>(pou.charts.size()) - 1;
      sfc_elements(pou, a.chart, "END_ACTION");
    } else {
      a.kind = model::ActionBodyKind::Statements;
      a.body = p.statements();
    }
    p.expect_word("END_ACTION");
    p.accept(TokenKind::Semicolon);
    pou.actions.push_back(std::move(a));
  }

  // An action named in a step but never declared is the Boolean variable of that name, if there
  // is one; otherwise it stays unresolved for validation to report.
  static void resolve_variable_actions(model::Pou& pou) {
    for (const auto& assoc : pou.associations) {
      if (pou.find_action(assoc.action)) continue;
      const model::Variable* v = pou.find_variable(assoc.action);
      if (!v) continue;
      model::Action a;
      a.name = assoc.action;
      a.kind = model::ActionBodyKind::Variable;
      a.variable = v->name;
      a.where = assoc.where;
      pou.actions.push_back(std::move(a));
    }
  }

  std::string file_;
  model::Diagnostics diags_;
  std::unique_ptr<Parser> parser_;
};

}  // namespace

LoadResult load_iec_text(std::string_view text, const std::string& file,
                         const model::Budget* budget) {
  return IecTextReader(text, file, budget).run();
}

}  // namespace sfcv::io
