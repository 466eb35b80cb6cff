#include "io/g7_writer.hpp"

#include <string>

#include "io/g7_lexicon.hpp"
#include "model/names.hpp"

namespace sfcv::io {

namespace {

using model::Expr;
using model::ExprKind;

// Every name of the file goes through here: a plain name bare, any other in double quotes with
// '"' and '\\' escaped (g7::quote_name). A quoted name cannot span lines or be empty in the
// reader, so such a name is refused rather than written as something else.
std::string quoted(std::string_view n, bool in_expression) {
  if (n.empty()) throw G7WriteError(".g7 has no empty names");
  if (n.find_first_of("\r\n") != std::string_view::npos)
    throw G7WriteError("name '" + std::string(n.substr(0, n.find_first_of("\r\n"))) +
                       "...' holds a line break: .g7 names are on one line");
  return g7::quote_name(n, in_expression);
}

// Binding strength, as in the reader's grammar: | ^ & comparisons + * unary primary.
int level(const Expr& e) {
  switch (e.kind) {
    case ExprKind::Or:
      return 1;
    case ExprKind::Xor:
      return 2;
    case ExprKind::And:
      return 3;
    case ExprKind::Eq:
    case ExprKind::Ne:
    case ExprKind::Lt:
    case ExprKind::Le:
    case ExprKind::Gt:
    case ExprKind::Ge:
      return 4;
    case ExprKind::Add:
    case ExprKind::Sub:
      return 5;
    case ExprKind::Mul:
    case ExprKind::Div:
    case ExprKind::Mod:
      return 6;
    case ExprKind::Not:
    case ExprKind::Neg:
    case ExprKind::Rising:
    case ExprKind::Falling:
      return 7;
    case ExprKind::IntConst:
      return e.value < 0 ? 7 : 8;
    default:
      return 8;
  }
}

std::string expr(const Expr& e);

std::string wrap(const Expr& e, bool parens) {
  return parens ? "(" + expr(e) + ")" : expr(e);
}

const char* op_text(ExprKind k) {
  switch (k) {
    case ExprKind::Or:
      return " | ";
    case ExprKind::Xor:
      return " ^ ";
    case ExprKind::And:
      return " & ";
    case ExprKind::Eq:
      return " = ";
    case ExprKind::Ne:
      return " <> ";
    case ExprKind::Lt:
      return " < ";
    case ExprKind::Le:
      return " <= ";
    case ExprKind::Gt:
      return " > ";
    case ExprKind::Ge:
      return " >= ";
    case ExprKind::Add:
      return " + ";
    case ExprKind::Sub:
      return " - ";
    case ExprKind::Mul:
      return " * ";
    case ExprKind::Div:
      return " / ";
    case ExprKind::Mod:
      return " mod ";
    default:
      return " ? ";
  }
}

std::string expr(const Expr& e) {
  const int p = level(e);
  switch (e.kind) {
    case ExprKind::BoolConst:
      return e.value ? "true" : "false";
    case ExprKind::IntConst:
      return std::to_string(e.value);
    case ExprKind::TimeConst:
      return g7::duration(e.value);
    case ExprKind::Name:
      return quoted(e.name, true);
    case ExprKind::Member:
      throw G7WriteError("the .g7 format has no member access ('" + e.name + "." + e.member + "')");
    case ExprKind::Not:
      return "!" + wrap(*e.args[0], level(*e.args[0]) < 7);
    case ExprKind::Neg:
      // "-3" would read back as the constant -3, not as the negation of 3.
      return "-" + wrap(*e.args[0], level(*e.args[0]) < 7 || e.args[0]->kind == ExprKind::IntConst);
    case ExprKind::Rising:
      return "RE " + wrap(*e.args[0], level(*e.args[0]) < 7);
    case ExprKind::Falling:
      return "FE " + wrap(*e.args[0], level(*e.args[0]) < 7);
    case ExprKind::Delay:
      return g7::duration(e.value) + "/" + wrap(*e.args[0], level(*e.args[0]) < 7) + "/" +
             g7::duration(e.value2);
    case ExprKind::Or:
    case ExprKind::Xor:
    case ExprKind::And: {
      // Nested operators of the same kind keep their parentheses: the reader builds one n-ary
      // node per parenthesis level.
      std::string s;
      for (std::size_t i = 0; i < e.args.size(); ++i) {
        if (i) s += op_text(e.kind);
        s += wrap(*e.args[i], level(*e.args[i]) <= p);
      }
      return s;
    }
    case ExprKind::Eq:
    case ExprKind::Ne:
    case ExprKind::Lt:
    case ExprKind::Le:
    case ExprKind::Gt:
    case ExprKind::Ge:
      return wrap(*e.args[0], level(*e.args[0]) <= p) + op_text(e.kind) +
             wrap(*e.args[1], level(*e.args[1]) <= p);
    default: {
      // Left-associative binary arithmetic. A duration left of '/' would read as a delay.
      const bool left_parens = level(*e.args[0]) < p ||
                               (e.kind == ExprKind::Div && e.args[0]->kind == ExprKind::TimeConst);
      return wrap(*e.args[0], left_parens) + op_text(e.kind) +
             wrap(*e.args[1], level(*e.args[1]) <= p);
    }
  }
}

std::string expr(const model::ExprPtr& e) {
  return e ? expr(*e) : "true";
}

std::string name(std::string_view n) {
  return quoted(n, false);
}

std::string step_set(const std::vector<std::string>& steps) {
  if (steps.size() == 1) return name(steps[0]);
  std::string s = "{";
  for (std::size_t i = 0; i < steps.size(); ++i) s += (i ? ", " : "") + name(steps[i]);
  return s + "}";
}

std::string where(const model::SourceLocation& l) {
  return l.known() ? " (" + l.str() + ")" : std::string();
}

void write_variable(std::string& out, const model::Variable& v) {
  switch (v.direction) {
    case model::VarDirection::Input:
      out += "input ";
      break;
    case model::VarDirection::Output:
      out += "output ";
      break;
    case model::VarDirection::Local:
      out += "internal ";
      break;
    default:
      throw G7WriteError("variable '" + v.name + "'" + where(v.where) +
                         ": .g7 has only input, output and internal variables");
  }
  out += quoted(v.name, true);
  if (v.type.kind == model::TypeKind::Int) {
    out += " : " + std::to_string(v.type.lo) + ".." + std::to_string(v.type.hi);
  } else if (v.type.kind != model::TypeKind::Bool) {
    throw G7WriteError("variable '" + v.name + "'" + where(v.where) + " of type " + v.type.name +
                       ": .g7 has only BOOL and bounded integers");
  }
  if (v.initial) {
    if (v.type.kind == model::TypeKind::Bool)
      out += *v.initial ? " := true" : " := false";
    else
      out += " := " + std::to_string(*v.initial);
  }
  out += ";\n";
}

void write_chart(std::string& out, const model::Pou& pou, const model::Chart& c) {
  if (!c.parent_action.empty())
    throw G7WriteError("chart '" + c.name + "' is the body of action '" + c.parent_action +
                       "': .g7 has no nested SFC actions");
  out += "grafcet " + name(c.name) + " {\n";
  for (const auto& s : c.steps) {
    out += "  step " + name(s.name);
    if (s.initial) out += " initial";
    if (s.activation_link) out += " linked";
    if (!c.macro_entry.empty() && c.macro_entry == s.name) out += " entry";
    if (!c.macro_exit.empty() && c.macro_exit == s.name) out += " exit";
    if (s.kind == model::StepKind::MacroStep) out += " macro " + name(s.expansion);
    if (s.kind == model::StepKind::Enclosing) {
      out += " encloses " + step_set(s.enclosed);
    }
    out += ";\n";
  }
  for (const auto& t : c.transitions) {
    if (t.priority)
      throw G7WriteError("transition '" + t.name + "' of '" + c.name +
                         "' has a priority: .g7 has none (Grafcet clears all clearable "
                         "transitions)");
    out += "  transition ";
    if (!t.name.empty()) out += name(t.name) + ": ";
    out += step_set(t.sources) + " -> " + step_set(t.targets);
    const bool always = !t.guard || (t.guard->kind == ExprKind::BoolConst && t.guard->value == 1);
    if (!always) out += " when " + expr(t.guard);
    out += ";\n";
  }
  for (const auto& a : pou.associations) {
    if (a.chart != c.name) continue;
    const model::Action* act = pou.find_action(a.action);
    const bool plain_variable = act && act->kind == model::ActionBodyKind::Variable &&
                                model::iequals(act->variable, act->name);
    if (a.qualifier != model::Qualifier::N || a.duration_ms || !a.duration_variable.empty() ||
        !a.indicator.empty() || !plain_variable)
      throw G7WriteError("action '" + a.action + "' of step '" + a.step + "'" + where(a.where) +
                         ": .g7 has only continuous actions on a Boolean variable");
    out += "  action " + name(a.step) + ": " + quoted(a.action, true);
    if (a.condition) out += " if " + expr(a.condition);
    out += ";\n";
  }
  for (const auto& sa : pou.stored_actions) {
    if (sa.chart != c.name) continue;
    out += "  action " + name(sa.step);
    switch (sa.when) {
      case model::StoredWhen::Activation:
        out += " on_enter";
        break;
      case model::StoredWhen::Deactivation:
        out += " on_exit";
        break;
      case model::StoredWhen::Event:
        out += " on " + expr(sa.event);
        break;
    }
    out += ": " + quoted(sa.variable, true) + " := " + expr(sa.value) + ";\n";
  }
  for (const auto& fo : pou.forcing_orders) {
    if (fo.chart != c.name) continue;
    out += "  action " + name(fo.step) + ": " + name(fo.target) + "{";
    switch (fo.kind) {
      case model::ForcingKind::Current:
        out += "*";
        break;
      case model::ForcingKind::Initial:
        out += "INIT";
        break;
      case model::ForcingKind::Empty:
        break;
      case model::ForcingKind::Situation:
        for (std::size_t i = 0; i < fo.situation.size(); ++i)  // a step named INIT is quoted
          out += (i ? ", " : "") + (model::iequals(fo.situation[i], "INIT")
                                        ? quoted(fo.situation[i], true)
                                        : name(fo.situation[i]));
        break;
    }
    out += "};\n";
  }
  out += "}\n";
}

}  // namespace

std::string write_g7(const model::Project& project) {
  if (project.pous.size() != 1)
    throw G7WriteError("a .g7 file holds one grafcet; this project has " +
                       std::to_string(project.pous.size()) + " POUs");
  const model::Pou& pou = project.pous[0];
  if (!pou.body.empty())
    throw G7WriteError("POU '" + pou.name + "' has an ST body: .g7 cannot write it");
  auto belongs = [&](const std::string& chart) { return pou.find_chart(chart) != nullptr; };
  for (const auto& a : pou.associations)
    if (!belongs(a.chart)) throw G7WriteError("action of step '" + a.step + "' names no chart");
  for (const auto& a : pou.stored_actions)
    if (!belongs(a.chart))
      throw G7WriteError("stored action of step '" + a.step + "' names no chart");
  for (const auto& a : pou.forcing_orders)
    if (!belongs(a.chart))
      throw G7WriteError("forcing order of step '" + a.step + "' names no chart");

  std::string out = "# Grafcet (IEC 60848) in the sfcv native format, see docs/formats.md\n";
  out += "project " + name(project.name) + ";\n\n";
  for (const auto& v : pou.variables) write_variable(out, v);
  for (const auto& c : pou.charts) {
    out += "\n";
    write_chart(out, pou, c);
  }
  return out;
}

}  // namespace sfcv::io
