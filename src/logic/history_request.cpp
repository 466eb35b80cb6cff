// Which inputs and previous values the properties read (check_inputs.hpp: history_system_for).

#include <deque>
#include <map>

#include "logic/check_inputs.hpp"
#include "logic/formula.hpp"
#include "model/names.hpp"
#include "semantics/history_system.hpp"

namespace sfcv::logic {

namespace {

struct Use {
  const Formula* atom;
  std::string source;
};

void collect(const FormulaPtr& f, const std::string& source, std::vector<Use>& out,
             std::deque<Formula>& names) {
  if (names_observable(f->op)) out.push_back({f.get(), source});
  // `a = b`: b may be a variable or an input rather than an enumerator (resolve.hpp).
  if (f->op == Op::Compare && !f->value_name.empty()) {
    Formula& rhs = names.emplace_back();
    rhs.op = Op::Value;
    rhs.name = f->value_name;
    rhs.line = f->line;
    rhs.column = f->column;
    out.push_back({&rhs, source});
  }
  for (const auto& a : f->args) collect(a, source, out, names);
}

std::optional<std::uint32_t> input_named(const semantics::TransitionSystem& ts,
                                         const std::string& name) {
  for (std::uint32_t i = 0; i < ts.inputs().size(); ++i)
    if (!ts.inputs()[i].pseudo && model::iequals(ts.inputs()[i].name, name)) return i;
  return std::nullopt;
}

}  // namespace

semantics::TransitionSystemPtr history_system_for(const Spec& spec,
                                                  const semantics::TransitionSystem& ts,
                                                  model::Diagnostics& diagnostics) {
  std::vector<Use> uses;
  std::deque<Formula> names;
  for (const auto& p : spec.properties)
    collect(p.formula, property_source(p.name, p.where), uses, names);
  for (const auto& f : spec.fairness)
    collect(f.formula, f.where.file.empty() ? "--fair" : f.where.file, uses, names);

  auto error = [&](const Use& u, std::string message) {
    model::Diagnostic d;
    d.where.file = u.source;
    d.where.line = u.atom->line;
    d.where.column = u.atom->column;
    d.message = std::move(message);
    diagnostics.push_back(std::move(d));
  };
  semantics::HistoryRequest request;
  bool failed = false;
  // Pass 1: the inputs to record (their observables follow the base ones).
  for (const auto& u : uses) {
    if (semantics::find_observable(ts, u.atom->name)) continue;
    const auto input = input_named(ts, u.atom->name);
    if (!input) continue;  // resolve() reports the unknown name
    const auto& in = ts.inputs()[*input];
    if (ts.kind() == semantics::SemanticsKind::Grafcet) {
      error(u, "'" + u.atom->name +
                   "' is an input this grafcet does not keep in its situations: "
                   "it is read only as a level and --multi-input-change drops the input memory; "
                   "without it every input the grafcet reads is part of the situation");
      failed = true;
    } else if (in.type.kind != model::TypeKind::Bool) {
      error(u, "'" + u.atom->name + "' is an integer input (" + in.type.name +
                   "): properties can name Boolean inputs only; compare it in the chart and "
                   "name that variable");
      failed = true;
    } else if (std::find(request.inputs.begin(), request.inputs.end(), *input) ==
               request.inputs.end()) {
      request.inputs.push_back(*input);
    }
  }
  if (failed) return nullptr;
  const auto num_base = static_cast<std::uint32_t>(ts.observables().size());
  // Pass 2: previous values, prev(prev(x)) after prev(x).
  std::map<std::uint32_t, std::uint32_t> previous_of;
  for (const auto& u : uses) {
    if (u.atom->prev == 0) continue;
    std::optional<std::uint32_t> index = semantics::find_observable(ts, u.atom->name);
    if (!index) {
      const auto input = input_named(ts, u.atom->name);
      if (!input) continue;
      const auto k =
          std::find(request.inputs.begin(), request.inputs.end(), *input) - request.inputs.begin();
      index = num_base + static_cast<std::uint32_t>(k);
    }
    std::uint32_t cur = *index;
    for (std::uint32_t d = 0; d < u.atom->prev; ++d) {
      auto it = previous_of.find(cur);
      if (it == previous_of.end()) {
        const auto next =
            num_base + static_cast<std::uint32_t>(request.inputs.size() + request.previous.size());
        request.previous.push_back(cur);
        it = previous_of.emplace(cur, next).first;
      }
      cur = it->second;
    }
  }
  if (request.inputs.empty() && request.previous.empty()) return nullptr;
  try {
    return std::make_unique<semantics::HistorySystem>(ts, std::move(request));
  } catch (const std::invalid_argument& e) {
    model::Diagnostic d;
    d.where.file = uses.front().source;
    d.message = e.what();
    diagnostics.push_back(std::move(d));
    return nullptr;
  }
}

}  // namespace sfcv::logic
