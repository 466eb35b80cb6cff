#include "model/chart.hpp"

#include <array>
#include <cctype>

#include "model/names.hpp"

namespace sfcv::model {

namespace {
constexpr std::array<std::pair<Qualifier, std::string_view>, 12> kQualifiers{{
    {Qualifier::N, "N"},
    {Qualifier::R, "R"},
    {Qualifier::S, "S"},
    {Qualifier::P, "P"},
    {Qualifier::P0, "P0"},
    {Qualifier::P1, "P1"},
    {Qualifier::L, "L"},
    {Qualifier::D, "D"},
    {Qualifier::SD, "SD"},
    {Qualifier::DS, "DS"},
    {Qualifier::SL, "SL"},
    {Qualifier::DL, "DL"},
}};

template <typename T>
int index_of(const std::vector<T>& v, std::string_view name) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (iequals(v[i].name, name)) return static_cast<int>(i);
  return -1;
}
template <typename T>
const T* find(const std::vector<T>& v, std::string_view name) {
  const int i = index_of(v, name);
  return i < 0 ? nullptr : &v[static_cast<std::size_t>(i)];
}
}  // namespace

std::string_view to_string(Qualifier q) {
  for (const auto& [k, s] : kQualifiers)
    if (k == q) return s;
  return "?";
}

std::optional<Qualifier> parse_qualifier(std::string_view s) {
  for (const auto& [k, text] : kQualifiers)
    if (iequals(text, s)) return k;
  return std::nullopt;
}

bool is_timed(Qualifier q) {
  return q == Qualifier::L || q == Qualifier::D || q == Qualifier::SD || q == Qualifier::DS ||
         q == Qualifier::SL || q == Qualifier::DL;
}

const Step* Chart::find_step(std::string_view n) const {
  return find(steps, n);
}
int Chart::step_index(std::string_view n) const {
  return index_of(steps, n);
}

const Variable* Pou::find_variable(std::string_view n) const {
  return find(variables, n);
}
const Action* Pou::find_action(std::string_view n) const {
  return find(actions, n);
}
const std::string& Pou::assigned_variable(const ActionAssociation& as) const {
  const Action* a = find_action(as.action);
  return a ? a->variable : as.action;
}
const Chart* Pou::find_chart(std::string_view n) const {
  return find(charts, n);
}
int Pou::chart_index(std::string_view n) const {
  return index_of(charts, n);
}

std::string vendor_of(const Project& project) {
  if (!project.vendor.empty()) {
    std::string vendor = project.vendor;
    for (auto& c : vendor) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return vendor;
  }
  const auto format = to_upper(project.source_format);
  if (format.find("TWINCAT") != std::string::npos) return "twincat";
  if (format.find("CODESYS") != std::string::npos) return "codesys";
  // The readers append the tool's version ("simaticml-graph V20 (GRAPH 6.0)").
  if (format.rfind("SIMATICML", 0) == 0) return "siemens";
  if (format.rfind("ROCKWELL-L5X", 0) == 0) return "rockwell";
  return "";
}

const Pou* Project::find_pou(std::string_view n) const {
  return find(pous, n);
}

void add_boolean_variable_actions(Pou& pou) {
  for (const auto& as : pou.associations) {
    if (pou.find_action(as.action)) continue;
    const auto* var = pou.find_variable(as.action);
    if (!var || var->type.kind != TypeKind::Bool) continue;
    Action act;
    act.name = var->name;
    act.kind = ActionBodyKind::Variable;
    act.variable = var->name;
    act.where = var->where;
    pou.actions.push_back(std::move(act));
  }
}

std::size_t count_steps(const Project& p) {
  std::size_t n = 0;
  for (const auto& pou : p.pous)
    for (const auto& c : pou.charts) n += c.steps.size();
  return n;
}

std::size_t count_transitions(const Project& p) {
  std::size_t n = 0;
  for (const auto& pou : p.pous)
    for (const auto& c : pou.charts) n += c.transitions.size();
  return n;
}

std::vector<std::string> in_out_bindings(const Project* project, std::string_view pou,
                                         const Stmt& call) {
  std::vector<std::string> bound;
  if (!project) return bound;
  auto bind = [&](const Pou& callee, const std::string& param, const ExprPtr& value) {
    const Variable* m = callee.find_variable(param);
    if (!m || m->direction != VarDirection::InOut || !value) return;
    if (value->kind == ExprKind::Name) bound.push_back(value->name);
    if (value->kind == ExprKind::Member) bound.push_back(value->name + "." + value->member);
  };
  // `y := F(io := v)`, `F(io := v);`: a user function's VAR_IN_OUT (a formal call).
  const Pou* caller = project->find_pou(pou);
  const Pou* function = nullptr;
  if (call.kind == StmtKind::Assign && call.value && call.value->kind == ExprKind::Call)
    function = project->find_pou(call.value->name);
  else if (call.kind == StmtKind::FbCall && !(caller && caller->find_variable(call.target)))
    function = project->find_pou(call.target);
  if (function && function->kind == PouKind::Function) {
    if (call.kind == StmtKind::Assign) {
      for (std::size_t a = 0; a < call.value->arg_names.size(); ++a)
        bind(*function, call.value->arg_names[a], call.value->args[a]);
    } else {
      for (const auto& [param, value] : call.arguments) bind(*function, param, value);
    }
    return bound;
  }
  if (call.kind != StmtKind::FbCall || call.arguments.empty()) return bound;
  const Pou* type = caller;
  const auto parts = split_path(call.target);
  for (std::size_t i = 0; type && i < parts.size(); ++i) {
    const Variable* v = type->find_variable(parts[i]);
    if (!v && i == 0 && parts.size() > 1) {  // `Main.inst(...)`: an instance of a program
      type = project->find_pou(parts[0]);
      continue;
    }
    type = v && v->type.kind == TypeKind::FunctionBlock ? project->find_pou(v->type.name) : nullptr;
  }
  if (!type || type->kind != PouKind::FunctionBlock) return bound;
  for (const auto& [param, value] : call.arguments) bind(*type, param, value);
  return bound;
}

}  // namespace sfcv::model
