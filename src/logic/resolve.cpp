#include "logic/resolve.hpp"

#include <algorithm>

#include "logic/formula.hpp"
#include "model/names.hpp"

namespace sfcv::logic {

namespace {

FormulaPtr bind(const FormulaPtr& f, const semantics::TransitionSystem& ts,
                const std::string& source, model::Diagnostics& diags) {
  auto error = [&](std::string message) {
    model::Diagnostic d;
    d.where.file = source;
    d.where.line = f->line;
    d.where.column = f->column;
    d.message = std::move(message);
    diags.push_back(std::move(d));
    return f;
  };
  if (f->op == Op::Atom || f->op == Op::Compare) {
    std::string why;
    const auto index = semantics::find_observable(ts, f->name, &why);
    if (!index) {
      for (const auto& in : ts.inputs())
        if (model::iequals(in.name, f->name))
          return error("'" + f->name +
                       "' is an input: properties talk about the state (steps, actions, "
                       "variables); constrain inputs with --assume");
      return error(why);
    }
    const auto& obs = ts.observables()[*index];
    if (f->op == Op::Atom && obs.type.kind != model::TypeKind::Bool)
      return error("'" + f->name + "' is an integer (" + obs.type.name +
                   "): compare it with a constant, e.g. '" + f->name + " > 0'");
    std::int64_t value = f->value;
    if (f->op == Op::Compare && !f->value_name.empty()) {
      const auto& es = obs.type.enumerators;
      const auto it = std::find_if(es.begin(), es.end(), [&](const auto& e) {
        return model::iequals(e.first, f->value_name) ||
               model::iequals(obs.type.name + "#" + e.first, f->value_name);
      });
      if (it == es.end())
        return error("'" + f->value_name + "' is no enumerator of '" + f->name + "' (" +
                     obs.type.name + ")");
      value = it->second;
    }
    // prev(x): the observable that keeps x's previous value (logic::history_system_for).
    auto bound = *index;
    for (std::uint32_t d = 0; d < f->prev; ++d) {
      const auto previous = ts.previous_observable(bound);
      if (!previous)
        return error("prev(" + f->name +
                     "): this system does not keep previous values "
                     "(resolve against logic::history_system_for)");
      bound = *previous;
    }
    if (value == f->value) return with_observable(*f, static_cast<std::int32_t>(bound));
    Formula valued = *f;
    valued.value = value;
    return with_observable(valued, static_cast<std::int32_t>(bound));
  }
  if (f->args.empty()) return f;
  std::vector<FormulaPtr> args;
  args.reserve(f->args.size());
  for (const auto& a : f->args) args.push_back(bind(a, ts, source, diags));
  return make_op(f->op, std::move(args), f->line, f->column);
}

}  // namespace

ResolvedFormula resolve(const FormulaPtr& f, const semantics::TransitionSystem& ts,
                        const std::string& source) {
  ResolvedFormula out;
  auto bound = bind(f, ts, source, out.diagnostics);
  if (!model::has_errors(out.diagnostics)) out.formula = std::move(bound);
  return out;
}

}  // namespace sfcv::logic
