#include "logic/check_inputs.hpp"

#include "logic/formula.hpp"
#include "logic/parser.hpp"
#include "logic/resolve.hpp"
#include "logic/to_expr.hpp"

namespace sfcv::logic {

namespace {
// A diagnostic names the option and its text; a hostile text of 100 KB is cut short.
std::string option_source(const char* option, const std::string& text) {
  constexpr std::size_t kShown = 60;
  return std::string(option) + " '" +
         (text.size() <= kShown ? text : text.substr(0, kShown) + "...") + "'";
}
}  // namespace

ParsedInputs parse_check_inputs(const CheckInputs& in) {
  ParsedInputs out;
  auto append = [&](model::Diagnostics d) {
    out.diagnostics.insert(out.diagnostics.end(), d.begin(), d.end());
  };
  if (!in.spec_text.empty()) {
    auto r = parse_spec(in.spec_text, in.spec_file.empty() ? "<spec>" : in.spec_file,
                        in.pattern_options);
    append(std::move(r.diagnostics));
    out.spec = std::move(r.spec);
  }
  for (const auto& text : in.ctl) {
    auto r = parse_formula(text, option_source("--ctl", text));
    append(std::move(r.diagnostics));
    if (r.formula) {
      NamedFormula nf{text, r.formula, {}, {}, {}};
      nf.where.file = "--ctl";
      out.spec.properties.push_back(std::move(nf));
    }
  }
  for (const auto& text : in.ltl) {
    auto r = parse_ltl(text, option_source("--ltl", text));
    append(std::move(r.diagnostics));
    if (r.formula) {
      NamedFormula nf{text, r.formula, {}, {}, {}};
      nf.where.file = "--ltl";
      out.spec.properties.push_back(std::move(nf));
    }
  }
  for (const auto& text : in.patterns) {
    auto r = parse_pattern(text, option_source("--pattern", text), in.pattern_options);
    append(std::move(r.diagnostics));
    if (r.ok()) {
      NamedFormula nf{text, r.formula, {}, r.english, {}};
      nf.where.file = "--pattern";
      out.spec.properties.push_back(std::move(nf));
    }
  }
  for (const auto& text : in.fair) {
    auto r = parse_propositional(text, option_source("--fair", text));
    append(std::move(r.diagnostics));
    if (r.formula) out.spec.fairness.push_back({"", r.formula, {}, {}, {}});
  }
  for (const auto& text : in.assume) {
    auto r = parse_propositional(text, option_source("--assume", text));
    append(std::move(r.diagnostics));
    if (r.formula && reads_previous(*r.formula)) {
      model::Diagnostic d;
      d.where.file = "--assume '" + text + "'";
      d.where.line = r.formula->line;
      d.where.column = r.formula->column;
      d.message =
          "prev(), rise() and fall() are not allowed in an assumption: it constrains "
          "one cycle's inputs and state";
      out.diagnostics.push_back(std::move(d));
      continue;
    }
    if (r.formula) out.spec.assumptions.push_back({"", r.formula, {}, {}, {}});
  }
  return out;
}

std::vector<model::ExprPtr> assumption_exprs(const Spec& spec) {
  std::vector<model::ExprPtr> out;
  for (const auto& a : spec.assumptions) out.push_back(to_expr(*a.formula, a.where.file));
  return out;
}

std::string property_source(const std::string& name, const model::SourceLocation& where) {
  if (where.file.empty() || where.file == "--ctl") return "--ctl '" + name + "'";
  if (where.file == "--pattern") return "--pattern '" + name + "'";
  if (where.file == "--ltl") return "--ltl '" + name + "'";
  return where.file;
}

void describe_results(CheckReport& report, const Spec& spec) {
  for (auto& r : report.results) {
    if (!r.check.empty()) continue;
    for (const auto& p : spec.properties)
      if (p.name == r.name && (!p.description.empty() || !p.justification.empty())) {
        r.description = p.description;
        r.justification = p.justification;
        break;
      }
  }
}

void resolve_into(const Spec& spec, const semantics::TransitionSystem& ts, CheckTask& task,
                  model::Diagnostics& diagnostics) {
  for (const auto& p : spec.properties) {
    auto r = resolve(p.formula, ts, property_source(p.name, p.where));
    diagnostics.insert(diagnostics.end(), r.diagnostics.begin(), r.diagnostics.end());
    if (r.formula) task.properties.push_back(Property{p.name, r.formula, p.where});
  }
  for (const auto& f : spec.fairness) {
    auto r = resolve(f.formula, ts, f.where.file.empty() ? "--fair" : f.where.file);
    diagnostics.insert(diagnostics.end(), r.diagnostics.begin(), r.diagnostics.end());
    if (r.formula) task.fairness.push_back(r.formula);
  }
}

}  // namespace sfcv::logic
