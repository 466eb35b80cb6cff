#include <CLI/CLI.hpp>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "cli/run_guard.hpp"
#include "model/names.hpp"
#include "model/networks.hpp"
#include "report/text_encoding.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::cli {

namespace {
struct InfoOptions {
  std::string model;
  std::string format = "auto";
  bool json = false;
  bool quiet = false;
  LimitOptions limits;
};

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

/// The variables that the run (default options: every PROGRAM) reads and no POU of it writes,
/// read as inputs (docs/semantics.md 1.8); null when the semantics cannot model the project.
ordered_json unwritten_info(const model::Project& p, const model::Budget& budget) {
  model::Diagnostics ignored;  // `sfcv lint` reports them
  semantics::Iec61131Options options;
  options.deadline = budget.deadline;
  const auto system = semantics::make_iec61131_system(p, options, ignored);
  if (!system) return nullptr;
  auto list = ordered_json::array();
  for (const auto& u : semantics::unwritten_variables(*system)) {
    ordered_json j;
    j["name"] = u.name;
    j["type"] = u.type.name;
    j["declared"] = u.declared.str();
    j["read_in"] = u.read_in;
    j["read_line"] = u.read_at.line;
    list.push_back(j);
  }
  return list;
}

/// `stopped`: set when a limit left the unwritten variables out (then null).
ordered_json project_info(const std::string& file, const model::Project& p, const RunGuard& guard,
                          std::optional<LimitReached>& stopped) {
  ordered_json j;
  j["model"] = file;
  j["format"] = p.source_format;
  j["dialect"] = p.dialect == model::Dialect::Grafcet ? "grafcet" : "iec61131";
  j["steps"] = model::count_steps(p);
  j["transitions"] = model::count_transitions(p);
  auto pous = ordered_json::array();
  for (const auto& pou : p.pous) pous.push_back(pou_info(pou));
  j["pous"] = pous;
  try {
    j["unwritten"] = p.dialect == model::Dialect::Grafcet ? ordered_json::array()
                                                          : unwritten_info(p, guard.budget());
    guard.check("finding the unwritten variables");
  } catch (const LimitReached& e) {
    j["unwritten"] = nullptr;
    stopped = guard.reason(e);
  }
  return j;
}

/// "N 3, S 1" from a map of counts, leaving out the zeros; "none" when all are zero.
std::string nonzero(const ordered_json& counts) {
  std::string s;
  for (const auto& [k, v] : counts.items())
    if (v.get<int>() != 0) s += (s.empty() ? "" : ", ") + k + " " + std::to_string(v.get<int>());
  return s.empty() ? "none" : s;
}

void print_text(const ordered_json& j, std::ostream& out, bool stopped) {
  const bool grafcet = j["dialect"] == "grafcet";
  out << "model: " << j["model"].get<std::string>() << " (" << j["format"].get<std::string>()
      << ", " << (grafcet ? "Grafcet, IEC 60848" : "SFC, IEC 61131-3") << ")\n";
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
}  // namespace

void add_info_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<InfoOptions>();
  auto* sub =
      app.add_subcommand("info", "Summarise a chart: POUs, steps, transitions, actions, variables");
  sub->add_option("model", opts->model, "Chart file (PLCopen XML, IEC text, .g7, AGRAFE .grafcet)")
      ->required();
  sub->add_option("--format", opts->format, "Input format: auto, xml, iec, g7, agrafe");
  sub->add_flag("--json", opts->json, "Print the summary as JSON (schema: docs/formats.md)");
  add_limit_options(*sub, opts->limits, "what is not counted is left out (exit 3)");
  sub->callback([opts, &selected] {
    selected = [opts] {
      return run_limited(opts->limits, [&](const RunGuard& guard) {
        const auto project =
            load_model_or_throw(opts->model, parse_format(opts->format), false, &guard.budget());
        std::optional<LimitReached> stopped;
        auto info = project_info(opts->model, project, guard, stopped);
        report::make_valid_utf8(info);  // names are bytes; the JSON is UTF-8
        if (opts->json)
          std::cout << info.dump(2) << "\n";
        else
          print_text(info, std::cout, stopped.has_value());
        return stopped ? report_limit(*stopped) : kHolds;
      });
    };
  });
}

}  // namespace sfcv::cli
