#include "io/iec_text_writer.hpp"

#include <algorithm>
#include <cctype>
#include <numeric>
#include <stdexcept>

#include "io/st_names.hpp"
#include "io/st_parser.hpp"
#include "model/errors.hpp"
#include "model/names.hpp"
#include "model/types.hpp"

namespace sfcv::io {

namespace {

using model::ExprKind;

[[noreturn]] void cannot_print(const std::string& what) {
  throw UnsupportedConstruct("cannot print as IEC 61131-3 text: " + what);
}

bool is_identifier(std::string_view s) {
  return is_st_identifier(s);
}

const std::string& ident(const std::string& s, std::string_view role) {
  if (!is_identifier(s)) cannot_print(std::string(role) + " '" + s + "' is not an IEC identifier");
  return s;
}

/// A directly represented variable (`%IX0.1`, `%QW4`, `%MD*`): '%' then letters, digits, '.'
/// and '*' only, so that it cannot end the declaration.
const std::string& address(const std::string& s) {
  const bool ok = s.size() > 1 && s[0] == '%' &&
                  s.find_first_not_of(
                      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                      "0123456789.*",
                      1) == std::string::npos;
  if (!ok) cannot_print("address '" + s + "' is not a directly represented variable");
  return s;
}

/// `ACT` or `inst.ACT` (an action of a function block instance): identifiers joined by dots.
const std::string& action_ident(const std::string& s) {
  for (std::size_t from = 0;;) {
    const auto dot = s.find('.', from);
    const auto part = s.substr(from, dot == std::string::npos ? dot : dot - from);
    if (!is_identifier(part)) cannot_print("action name '" + s + "' is not an IEC identifier");
    if (dot == std::string::npos) return s;
    from = dot + 1;
  }
}

void check_printable(const model::StmtList& body, const std::string& where) {
  if (auto why = st_text_obstacle(body, where); !why.empty()) cannot_print(why);
}

std::string type_text(const model::Type& t) {
  switch (t.kind) {
    case model::TypeKind::Bool:
      return "BOOL";
    case model::TypeKind::Time:
      return "TIME";
    case model::TypeKind::FunctionBlock:  // a user function block keeps its declared name
      return t.fb == model::StandardFb::None ? ident(t.name, "function block type")
                                             : std::string(model::to_string(t.fb));
    case model::TypeKind::Int:
      break;
  }
  const std::string base = model::to_upper(t.name.substr(0, t.name.find('(')));
  auto elementary = model::elementary_type(base);
  if (elementary && elementary->kind == model::TypeKind::Int) {
    if (elementary->lo == t.lo && elementary->hi == t.hi) return base;
    if (elementary->lo <= t.lo && t.hi <= elementary->hi)
      return base + "(" + std::to_string(t.lo) + ".." + std::to_string(t.hi) + ")";
  }
  return "LINT(" + std::to_string(t.lo) + ".." + std::to_string(t.hi) + ")";
}

std::string section_word(model::VarDirection d) {
  switch (d) {
    case model::VarDirection::Input:
      return "VAR_INPUT";
    case model::VarDirection::Output:
      return "VAR_OUTPUT";
    case model::VarDirection::InOut:
      return "VAR_IN_OUT";
    case model::VarDirection::Global:
      return "VAR_GLOBAL";
    case model::VarDirection::External:
      return "VAR_EXTERNAL";
    case model::VarDirection::Local:
      break;
  }
  return "VAR";
}

class Writer {
 public:
  explicit Writer(const model::Pou& pou) : pou_(pou), printed_(pou.associations.size(), false) {}

  void write(std::string& out) {
    if (pou_.body_unsupported)
      cannot_print("POU '" + pou_.name + "', whose body sfcv does not model");
    if (!pou_.stored_actions.empty())
      cannot_print("Grafcet stored actions (POU '" + pou_.name + "')");
    if (!pou_.forcing_orders.empty())
      cannot_print("Grafcet forcing orders (POU '" + pou_.name + "')");
    const bool program = pou_.kind == model::PouKind::Program;
    const bool function = pou_.kind == model::PouKind::Function;
    const std::string kind = program ? "PROGRAM" : function ? "FUNCTION" : "FUNCTION_BLOCK";
    out += kind + " " + ident(pou_.name, "POU name");
    if (function) {
      // The result is the variable named like the function (model::PouKind).
      const auto* result = pou_.find_variable(pou_.name);
      if (!result || result->direction != model::VarDirection::Output)
        cannot_print("FUNCTION '" + pou_.name + "' without a result");
      out += " : " + type_text(result->type);
    }
    out += "\n";
    variables(out);
    std::vector<std::size_t> top;
    for (std::size_t i = 0; i < pou_.charts.size(); ++i)
      if (pou_.charts[i].parent_action.empty()) top.push_back(i);
    if (top.size() > 1) cannot_print("POU '" + pou_.name + "' has several top-level charts");
    if (!top.empty() && !pou_.body.empty())
      cannot_print("POU '" + pou_.name + "' has both an SFC and an ST body");
    if (!pou_.body.empty()) {
      check_printable(pou_.body, "the body of '" + pou_.name + "'");
      out += "\n" + model::to_st(pou_.body, 2);
    }
    std::vector<bool> chart_printed(pou_.charts.size(), false);
    if (!top.empty()) {
      chart(top[0], 2, out);
      chart_printed[top[0]] = true;
    }
    for (const auto& a : pou_.actions) action(a, chart_printed, out);
    for (std::size_t i = 0; i < pou_.charts.size(); ++i)
      if (!chart_printed[i])
        cannot_print("chart '" + pou_.charts[i].name + "' is the body of no action");
    for (std::size_t i = 0; i < printed_.size(); ++i)
      if (!printed_[i]) {
        const auto& a = pou_.associations[i];
        cannot_print("association of action '" + a.action + "' to step '" + a.step +
                     "' of chart '" + a.chart + "', which does not exist");
      }
    out += "END_" + kind + "\n";
  }

 private:
  void variables(std::string& out) {
    // A function's result is declared by its header.
    auto declared = [&](const model::Variable& v) {
      return pou_.kind != model::PouKind::Function || !model::iequals(v.name, pou_.name);
    };
    std::vector<const model::Variable*> vars;
    for (const auto& v : pou_.variables)
      if (declared(v)) vars.push_back(&v);
    std::size_t i = 0;
    while (i < vars.size()) {
      const auto dir = vars[i]->direction;
      const bool constant = vars[i]->constant;
      out += "  " + section_word(dir) + (constant ? " CONSTANT" : "") + "\n";
      for (; i < vars.size() && vars[i]->direction == dir && vars[i]->constant == constant; ++i) {
        const auto& v = *vars[i];
        out += "    " + ident(v.name, "variable name");
        if (!v.address.empty()) out += " AT " + address(v.address);
        out += " : " + type_text(v.type);
        if (v.initial) {
          if (v.type.kind == model::TypeKind::FunctionBlock)
            cannot_print("initial value of FB instance '" + v.name + "'");
          out += " := ";
          if (v.type.kind == model::TypeKind::Bool)
            out += *v.initial ? "TRUE" : "FALSE";
          else if (v.type.kind == model::TypeKind::Time)
            out += model::to_st(model::make_time(*v.initial));
          else
            out += std::to_string(*v.initial);
        }
        out += ";\n";
      }
      out += "  END_VAR\n";
    }
  }

  void chart(std::size_t index, int indent, std::string& out) {
    const model::Chart& c = pou_.charts[index];
    const std::string pad(static_cast<std::size_t>(indent), ' ');
    for (std::size_t i = 0; i < c.steps.size(); ++i) {
      const auto& s = c.steps[i];
      if (s.kind != model::StepKind::Normal)
        cannot_print("Grafcet macro-step or enclosing step '" + s.name + "'");
      out +=
          "\n" + pad + (s.initial ? "INITIAL_STEP " : "STEP ") + ident(s.name, "step name") + ":\n";
      // Associations name a step, not one of several steps of that name: print them once, under
      // the first.
      bool first = true;
      for (std::size_t k = 0; k < i; ++k)
        if (model::iequals(c.steps[k].name, s.name)) first = false;
      if (first)
        for (std::size_t k = 0; k < pou_.associations.size(); ++k) {
          const auto& a = pou_.associations[k];
          if (!model::iequals(a.chart, c.name) || !model::iequals(a.step, s.name)) continue;
          out += pad + "  " + association(a) + "\n";
          printed_[k] = true;
        }
      out += pad + "END_STEP\n";
    }
    std::vector<std::size_t> order(c.transitions.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return c.transitions[x].order < c.transitions[y].order;
    });
    for (std::size_t i : order) transition(c.transitions[i], pad, out);
  }

  static std::string association(const model::ActionAssociation& a) {
    if (a.condition) cannot_print("assignment condition of action '" + a.action + "'");
    std::string s = action_ident(a.action) + "(" + std::string(model::to_string(a.qualifier));
    if (model::is_timed(a.qualifier)) {
      if (a.duration_ms)
        s += ", " + model::to_st(model::make_time(*a.duration_ms));
      else if (!a.duration_variable.empty())
        s += ", " + ident(a.duration_variable, "duration variable");
      else
        cannot_print("timed qualifier " + std::string(model::to_string(a.qualifier)) +
                     " of action '" + a.action + "' without a duration");
    } else if (a.duration_ms || !a.duration_variable.empty()) {
      cannot_print("duration on qualifier " + std::string(model::to_string(a.qualifier)) +
                   " of action '" + a.action + "'");
    }
    if (!a.indicator.empty()) s += ", " + ident(a.indicator, "indicator variable");
    return s + ");";
  }

  static void transition(const model::Transition& t, const std::string& pad, std::string& out) {
    auto list = [](const std::vector<std::string>& v) {
      if (v.empty()) cannot_print("transition without source or target steps");
      std::string r;
      for (const auto& x : v) r += (r.empty() ? "" : ", ") + ident(x, "step name");
      return v.size() == 1 ? r : "(" + r + ")";
    };
    out += "\n" + pad + "TRANSITION";
    if (!t.name.empty()) out += " " + ident(t.name, "transition name");
    if (t.priority) {
      if (*t.priority < 0) cannot_print("negative transition priority");
      out += " (PRIORITY := " + std::to_string(*t.priority) + ")";
    }
    if (auto why = st_text_obstacle(t.guard, "a transition condition"); !why.empty())
      cannot_print(why);
    out += " FROM " + list(t.sources) + " TO " + list(t.targets) + "\n";
    out += pad + "  := " + model::to_st(t.guard) + ";\n";
    out += pad + "END_TRANSITION\n";
  }

  void action(const model::Action& a, std::vector<bool>& chart_printed, std::string& out) {
    switch (a.kind) {
      case model::ActionBodyKind::Variable:
        // Re-created on loading from the association naming the variable.
        if (!model::iequals(a.name, a.variable) || !pou_.find_variable(a.variable) ||
            std::none_of(pou_.associations.begin(), pou_.associations.end(),
                         [&](const auto& x) { return model::iequals(x.action, a.name); }))
          cannot_print("action '" + a.name + "' standing for variable '" + a.variable + "'");
        return;
      case model::ActionBodyKind::Statements:
        if (a.body_unsupported)
          cannot_print("action '" + a.name + "', whose body sfcv does not model");
        check_printable(a.body, "action '" + a.name + "'");
        out += "\n  ACTION " + ident(a.name, "action name") + ":\n" + model::to_st(a.body, 4) +
               "  END_ACTION\n";
        return;
      case model::ActionBodyKind::Chart: {
        if (a.chart < 0 || static_cast<std::size_t>(a.chart) >= pou_.charts.size())
          cannot_print("action '" + a.name + "' without its chart");
        const auto index = static_cast<std::size_t>(a.chart);
        if (chart_printed[index])
          cannot_print("chart '" + pou_.charts[index].name + "' used twice");
        chart_printed[index] = true;
        out += "\n  ACTION " + ident(a.name, "action name") + ":";
        chart(index, 4, out);
        out += "  END_ACTION\n";
        return;
      }
    }
  }

  const model::Pou& pou_;
  std::vector<bool> printed_;
};

}  // namespace

std::string write_iec_text(const model::Project& project) {
  if (project.dialect == model::Dialect::Grafcet)
    cannot_print("a Grafcet (IEC 60848) project; print it in the native Grafcet format");
  if (project.data_types_lowered)
    cannot_print(
        "a project with user data types (ARRAY, STRUCT, enumerations): sfcv models them "
        "element by element and does not print them back as declared");
  std::string out;
  for (std::size_t i = 0; i < project.pous.size(); ++i) {
    if (i) out += "\n";
    Writer(project.pous[i]).write(out);
  }
  return out;
}

}  // namespace sfcv::io
