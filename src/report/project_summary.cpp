#include "report/project_summary.hpp"

#include <map>
#include <string>

#include "model/names.hpp"
#include "model/networks.hpp"

namespace sfcv::report {

namespace {

using nlohmann::ordered_json;

const char* pou_kind(model::PouKind k) {
  switch (k) {
    case model::PouKind::Program:
      return "program";
    case model::PouKind::FunctionBlock:
      return "function_block";
    case model::PouKind::Function:
      return "function";
  }
  return "program";
}

const char* direction(model::VarDirection d) {
  switch (d) {
    case model::VarDirection::Input:
      return "input";
    case model::VarDirection::Output:
      return "output";
    case model::VarDirection::InOut:
      return "in_out";
    case model::VarDirection::Local:
      return "local";
    case model::VarDirection::Global:
      return "global";
    case model::VarDirection::External:
      return "external";
  }
  return "local";
}

constexpr model::VarDirection kDirections[] = {
    model::VarDirection::Input, model::VarDirection::Output, model::VarDirection::InOut,
    model::VarDirection::Local, model::VarDirection::Global, model::VarDirection::External};
constexpr model::Qualifier kQualifiers[] = {
    model::Qualifier::N,  model::Qualifier::R,  model::Qualifier::S,  model::Qualifier::P,
    model::Qualifier::P0, model::Qualifier::P1, model::Qualifier::L,  model::Qualifier::D,
    model::Qualifier::SD, model::Qualifier::DS, model::Qualifier::SL, model::Qualifier::DL};

ordered_json chart_info(const model::Chart& c) {
  ordered_json j;
  j["name"] = c.name;
  j["parent_action"] =
      c.parent_action.empty() ? ordered_json(nullptr) : ordered_json(c.parent_action);
  j["steps"] = c.steps.size();
  auto initial = ordered_json::array();
  for (const auto& s : c.steps)
    if (s.initial) initial.push_back(s.name);
  j["initial_steps"] = initial;
  j["transitions"] = c.transitions.size();
  j["networks"] = model::count_networks(c);
  return j;
}

ordered_json pou_info(const model::Pou& pou) {
  ordered_json j;
  j["name"] = pou.name;
  j["kind"] = pou_kind(pou.kind);
  std::size_t steps = 0, transitions = 0;
  auto charts = ordered_json::array();
  for (const auto& c : pou.charts) {
    steps += c.steps.size();
    transitions += c.transitions.size();
    charts.push_back(chart_info(c));
  }
  j["steps"] = steps;
  j["transitions"] = transitions;
  j["charts"] = charts;

  ordered_json by_kind{{"variable", 0}, {"statements", 0}, {"chart", 0}};
  for (const auto& a : pou.actions) {
    const char* k = a.kind == model::ActionBodyKind::Variable     ? "variable"
                    : a.kind == model::ActionBodyKind::Statements ? "statements"
                                                                  : "chart";
    by_kind[k] = by_kind[k].get<int>() + 1;
  }
  j["actions"] = ordered_json{{"total", pou.actions.size()}, {"by_kind", by_kind}};

  ordered_json by_qualifier;
  for (auto q : kQualifiers) by_qualifier[std::string(model::to_string(q))] = 0;
  for (const auto& as : pou.associations) {
    const std::string q(model::to_string(as.qualifier));
    by_qualifier[q] = by_qualifier[q].get<int>() + 1;
  }
  j["associations"] =
      ordered_json{{"total", pou.associations.size()}, {"by_qualifier", by_qualifier}};

  ordered_json by_direction, by_type = ordered_json::object();
  for (auto d : kDirections) by_direction[direction(d)] = 0;
  std::map<std::string, int> types;  // sorted keys: stable output
  for (const auto& v : pou.variables) {
    by_direction[direction(v.direction)] = by_direction[direction(v.direction)].get<int>() + 1;
    ++types[model::to_upper(v.type.name)];
  }
  for (const auto& [name, n] : types) by_type[name] = n;
  j["variables"] = ordered_json{
      {"total", pou.variables.size()}, {"by_direction", by_direction}, {"by_type", by_type}};
  j["stored_actions"] = pou.stored_actions.size();
  j["forcing_orders"] = pou.forcing_orders.size();
  return j;
}

/// "N 3, S 1" from a map of counts, leaving out the zeros; "none" when all are zero.
std::string nonzero(const ordered_json& counts) {
  std::string s;
  for (const auto& [k, v] : counts.items())
    if (v.get<int>() != 0) s += (s.empty() ? "" : ", ") + k + " " + std::to_string(v.get<int>());
  return s.empty() ? "none" : s;
}

std::string_view severity_name(model::Severity s) {
  switch (s) {
    case model::Severity::Error:
      return "error";
    case model::Severity::Warning:
      return "warning";
    case model::Severity::Note:
      break;
  }
  return "note";
}

std::string plural(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

ordered_json project_summary_json(
    const std::string& file, const model::Project& p,
    const std::optional<std::vector<semantics::UnwrittenVariable>>& unwritten) {
  ordered_json j;
  j["schema_version"] = kSummaryJsonSchemaVersion;
  j["model"] = file;
  j["format"] = p.source_format;
  j["dialect"] = p.dialect == model::Dialect::Grafcet ? "grafcet" : "iec61131";
  // The vendor whose reading --dialect takes by default (docs/semantics.md 1.4a).
  if (p.dialect == model::Dialect::Grafcet) {
    j["vendor_dialect"] = nullptr;
  } else {
    const auto vendor = model::vendor_of(p);
    j["vendor_dialect"] = vendor.empty() ? "iec" : vendor;
  }
  j["steps"] = model::count_steps(p);
  j["transitions"] = model::count_transitions(p);
  auto pous = ordered_json::array();
  for (const auto& pou : p.pous) pous.push_back(pou_info(pou));
  j["pous"] = pous;
  if (p.dialect == model::Dialect::Grafcet) {
    j["unwritten"] = ordered_json::array();
  } else if (!unwritten) {
    j["unwritten"] = nullptr;
  } else {
    auto list = ordered_json::array();
    for (const auto& u : *unwritten) {
      ordered_json v;
      v["name"] = u.name;
      v["type"] = u.type.name;
      v["declared"] = u.declared.str();
      v["read_in"] = u.read_in;
      v["read_line"] = u.read_at.line;
      list.push_back(v);
    }
    j["unwritten"] = list;
  }
  return j;
}

void print_project_summary(const ordered_json& j, std::ostream& out, bool stopped) {
  const bool grafcet = j["dialect"] == "grafcet";
  out << "model: " << j["model"].get<std::string>() << " (" << j["format"].get<std::string>()
      << ", "
      << (grafcet                     ? "Grafcet, IEC 60848"
          : j["steps"].get<int>() > 0 ? "SFC, IEC 61131-3"
                                      : "IEC 61131-3");
  if (j["vendor_dialect"].is_string() && j["vendor_dialect"] != "iec")
    out << ", read in " << j["vendor_dialect"].get<std::string>() << "'s dialect";
  out << ")\n";
  out << "steps: " << j["steps"] << ", transitions: " << j["transitions"] << "\n";
  for (const auto& pou : j["pous"]) {
    out << "\n"
        << model::to_upper(pou["kind"].get<std::string>()) << " " << pou["name"].get<std::string>()
        << ": " << pou["steps"] << " steps, " << pou["transitions"] << " transitions\n";
    for (const auto& c : pou["charts"]) {
      out << "  chart "
          << (c["name"].get<std::string>().empty() ? "(unnamed)" : c["name"].get<std::string>());
      if (!c["parent_action"].is_null())
        out << " (body of action " << c["parent_action"].get<std::string>() << ")";
      out << ": " << c["steps"] << " steps, " << c["transitions"] << " transitions, "
          << c["networks"] << (c["networks"] == 1 ? " network" : " networks") << "; initial:";
      if (c["initial_steps"].empty()) out << " none";
      for (const auto& s : c["initial_steps"]) out << " " << s.get<std::string>();
      out << "\n";
    }
    const auto& a = pou["actions"];
    out << "  actions: " << a["total"] << " (" << nonzero(a["by_kind"]) << ")\n";
    const auto& as = pou["associations"];
    out << "  action associations: " << as["total"]
        << " (by qualifier: " << nonzero(as["by_qualifier"]) << ")\n";
    const auto& v = pou["variables"];
    out << "  variables: " << v["total"] << " (" << nonzero(v["by_direction"])
        << "; by type: " << nonzero(v["by_type"]) << ")\n";
    if (grafcet || pou["stored_actions"] != 0 || pou["forcing_orders"] != 0)
      out << "  stored actions: " << pou["stored_actions"]
          << ", forcing orders: " << pou["forcing_orders"] << "\n";
  }
  if (grafcet) return;
  const auto& u = j["unwritten"];
  out << "\n";
  if (u.is_null() && stopped) {
    out << "unwritten variables: not computed (a limit was reached)\n";
    return;
  }
  if (u.is_null()) {
    out << "unwritten variables: not computed (the IEC 61131-3 semantics cannot model this "
           "project as a whole: see sfcv lint)\n";
    return;
  }
  out << "unwritten variables (read as inputs, free each cycle; --unwritten keep holds them): "
      << u.size() << "\n";
  for (const auto& v : u) {
    out << "  " << v["name"].get<std::string>() << " : " << v["type"].get<std::string>()
        << " (read in " << v["read_in"].get<std::string>();
    if (v["read_line"].get<int>() > 0) out << ", line " << v["read_line"].get<int>();
    out << ")\n";
  }
}

ordered_json diagnostics_json(const model::Diagnostics& diagnostics, std::size_t errors,
                              std::size_t warnings) {
  ordered_json j;
  j["schema_version"] = kSummaryJsonSchemaVersion;
  auto list = ordered_json::array();
  for (const auto& d : diagnostics) {
    ordered_json e;
    e["file"] = d.where.file;
    e["line"] = d.where.line;
    e["column"] = d.where.column;
    e["element_path"] = d.where.element_path;
    e["severity"] = severity_name(d.severity);
    e["message"] = d.message;
    list.push_back(e);
  }
  j["diagnostics"] = list;
  j["errors"] = errors;
  j["warnings"] = warnings;
  return j;
}

void print_diagnostics(const model::Diagnostics& diagnostics, std::size_t errors,
                       std::size_t warnings, std::ostream& out) {
  for (const auto& d : diagnostics) out << d.str() << "\n";
  out << plural(errors, "error") << ", " << plural(warnings, "warning") << "\n";
}

}  // namespace sfcv::report
