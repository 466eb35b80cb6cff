// sfcv rsg: builds the reachable situations graph (Grafcet) or the cycle-level state graph
// (IEC 61131-3) and prints its size, its listing, a Graphviz or a JSON rendering.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "cli/progress_line.hpp"
#include "cli/run_limits.hpp"
#include "cli/system_options.hpp"
#include "engine/bdd/condition_simplifier.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "model/names.hpp"
#include "report/situation_graph_dot.hpp"
#include "semantics/grafcet_system.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::cli {

namespace {

struct RsgOptions {
  std::string model;
  std::string format = "auto";
  SystemOptions system;
  bool list = false;
  std::string dot, dot_states;
  std::size_t max_nodes = report::SituationGraphOptions{}.max_nodes;
  bool json = false;
  LimitOptions limits;
};

/// "{1,10} x y" -> ("{1,10}", "x y"): the situation and what it emits.
std::pair<std::string, std::string> split_description(const std::string& d) {
  const auto close = d.find('}');
  if (d.empty() || d[0] != '{' || close == std::string::npos) return {d, ""};
  std::string rest = d.substr(close + 1);
  while (!rest.empty() && rest.front() == ' ') rest.erase(rest.begin());
  return {d.substr(0, close + 1), rest};
}

std::string inputs_of(const semantics::TransitionSystem& ts, semantics::StateView s) {
  std::string out;
  for (std::uint32_t i = 0; i < ts.observables().size(); ++i) {
    const auto& o = ts.observables()[i];
    if (o.kind != semantics::ObservableKind::Variable || o.is_output) continue;
    bool is_input = false;
    for (const auto& in : ts.inputs())
      if (in.name == o.name) is_input = true;
    if (!is_input) continue;
    const auto v = ts.observe(s, i);
    if (!out.empty()) out += " ";
    out += o.type.kind == model::TypeKind::Bool ? (v ? "" : "!") + o.name
                                                : o.name + "=" + std::to_string(v);
  }
  return out;
}

/// Under the single-input-change rule: which input changed between two nodes ("a rises",
/// "n: 0 -> 5"), or "a delay elapses" when none did.
std::string event_of(const semantics::TransitionSystem& ts, semantics::StateView from,
                     semantics::StateView to) {
  for (std::uint32_t i = 0; i < ts.observables().size(); ++i) {
    const auto& o = ts.observables()[i];
    if (o.kind != semantics::ObservableKind::Variable || o.is_output) continue;
    bool is_input = false;
    for (const auto& in : ts.inputs())
      if (in.name == o.name && !in.pseudo) is_input = true;
    if (!is_input) continue;
    const auto a = ts.observe(from, i), b = ts.observe(to, i);
    if (a == b) continue;
    if (o.type.kind == model::TypeKind::Bool) return o.name + (b ? " rises" : " falls");
    return o.name + ": " + std::to_string(a) + " -> " + std::to_string(b);
  }
  return "a delay elapses";
}

std::string dot_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

int run_rsg(const RsgOptions& o) {
  const model::Budget budget = make_budget(o.limits);  // one deadline for every phase
  ProgressLine progress(!global_options().quiet);
  progress.phase("load");
  const model::Project project = load_model_or_throw(o.model, parse_format(o.format));
  budget.check_time("loading the model");
  progress.phase("build");
  const auto built = build_system(project, o.system, {}, "sfcv rsg", semantics::ActionOrder::Declaration,
                                  &budget);
  budget.check_time("building the system");
  const auto& ts = built.system;
  const std::string& sem = built.semantics;

  progress.phase("explore");
  engine::ExplorationOptions eo;
  eo.max_states = budget.max_states;
  eo.deadline = budget.deadline;
  if (auto report = progress.callback())
    eo.progress = [report](const engine::ExplorationProgress& p) {
      model::Progress q;
      q.phase = "explore";
      q.states = p.states;
      q.edges = p.edges;
      q.depth = p.depth;
      q.seconds = p.seconds;
      report(q);
    };
  eo.progress_interval = 4096;
  const auto g = engine::build_reachable_situation_graph(*ts, eo);
  progress.phase("render");
  const auto& inputs = ts->inputs();
  auto state = [&g](std::uint32_t s) { return g.states().at(s); };
  auto condition = [&](std::uint64_t e) {
    return engine::simplify(g.condition(e), inputs).to_string(inputs);
  };

  // Distinct step situations: the states projected on the step fields (the seed's RSG nodes
  // do not hold the input values).
  std::set<std::vector<std::int64_t>> situations;
  std::set<std::pair<std::vector<std::int64_t>, std::vector<std::int64_t>>> moves;
  const auto& layout = ts->layout();
  auto project_steps = [&](std::uint32_t s) {
    std::vector<std::int64_t> v;
    for (std::uint32_t f = 0; f < layout.fields().size(); ++f) {
      const auto k = layout.fields()[f].kind;
      if (k == semantics::FieldKind::StepActive || k == semantics::FieldKind::StepReady ||
          false)
        v.push_back(layout.get(state(s), f));
    }
    return v;
  };
  for (std::uint32_t s = 0; s < g.num_states(); ++s) {
    const auto p = project_steps(s);
    situations.insert(p);
    for (auto e = g.edges_begin(s); g.expanded(s) && e < g.edges_end(s); ++e) {
      const auto q = project_steps(g.target(e));
      if (q != p) moves.insert({p, q});
    }
  }

  const bool single = sem == "grafcet" && !o.system.multi_input_change;
  // A graph written to stdout is the whole output (dot reads it from a pipe).
  const bool dot_to_stdout = o.dot == "-" || o.dot_states == "-";
  if (o.json) {
    nlohmann::json j;
    j["semantics"] = sem;
    if (sem == "grafcet") j["single_input_change"] = single;
    j["complete"] = g.complete();
    if (!g.complete()) j["limit"] = g.limit_reached();
    j["build_seconds"] = g.build_seconds();
    j["inputs"] = nlohmann::json::array();
    for (const auto& in : inputs) j["inputs"].push_back({{"name", in.name}, {"pseudo", in.pseudo}});
    j["states"] = nlohmann::json::array();
    std::vector<bool> initial(g.num_states(), false);
    for (auto s : g.initial_states()) initial[s] = true;
    for (std::uint32_t s = 0; s < g.num_states(); ++s) {
      const auto [sit, out] = split_description(ts->describe(state(s)));
      j["states"].push_back({{"id", s}, {"situation", sit}, {"outputs", out},
                             {"inputs", inputs_of(*ts, state(s))}, {"initial", bool(initial[s])},
                             {"expanded", g.expanded(s)}});
    }
    j["edges"] = nlohmann::json::array();
    for (std::uint32_t s = 0; s < g.num_states(); ++s)
      for (auto e = g.edges_begin(s); g.expanded(s) && e < g.edges_end(s); ++e) {
        nlohmann::json fired = nlohmann::json::array();
        for (auto t : g.fired(e)) fired.push_back(ts->transitions()[t].name);
        j["edges"].push_back(
            {{"from", s}, {"to", g.target(e)}, {"condition", condition(e)}, {"fired", fired}});
      }
    j["anomalies"] = nlohmann::json::array();
    for (const auto& a : g.anomalies()) {
      nlohmann::json cycle = nlohmann::json::array();
      for (const auto& c : a.cycle) cycle.push_back(ts->describe(c));
      j["anomalies"].push_back({{"message", a.message},
                                {"inputs", engine::simplify(a.condition, inputs).to_string(inputs)},
                                {"cycle", cycle}});
    }
    std::cout << j.dump(2) << "\n";
  } else if (!dot_to_stdout || o.list) {
    std::cout << "semantics: " << sem
              << (sem == "grafcet"
                      ? (single ? " (IEC 60848, single input change)"
                                : " (IEC 60848, multiple input changes)")
                      : " (IEC 61131-3 scan cycle)")
              << "\n";
    std::cout << (sem == "grafcet" ? "situations: " : "states: ") << g.num_states();
    if (sem == "grafcet") std::cout << " (distinct step situations: " << situations.size() << ")";
    std::cout << "\nevolutions: " << g.num_edges();
    if (sem == "grafcet")
      std::cout << " (between distinct step situations: " << moves.size() << ")";
    std::cout << "\ninitial: " << g.initial_states().size() << "\n";
    std::cout << "build time: " << std::fixed << std::setprecision(3) << g.build_seconds()
              << " s\n";
    std::cout.unsetf(std::ios::fixed);
    if (o.list) {
      std::vector<bool> initial(g.num_states(), false);
      for (auto s : g.initial_states()) initial[s] = true;
      for (std::uint32_t s = 0; s < g.num_states(); ++s) {
        const auto [sit, out] = split_description(ts->describe(state(s)));
        std::cout << "s" << s << (initial[s] ? " (initial)" : "") << ": " << sit;
        if (!out.empty()) std::cout << " / " << out;
        const auto in = inputs_of(*ts, state(s));
        if (!in.empty()) std::cout << "   [inputs: " << in << "]";
        std::cout << "\n";
      }
      for (std::uint32_t s = 0; s < g.num_states(); ++s)
        for (auto e = g.edges_begin(s); g.expanded(s) && e < g.edges_end(s); ++e) {
          const auto t = g.target(e);
          const auto [from, out0] = split_description(ts->describe(state(s)));
          const auto [to, out] = split_description(ts->describe(state(t)));
          (void)out0;
          std::cout << "s" << s << " " << from << " --[" << condition(e) << "]--> s" << t << " "
                    << to;
          if (!out.empty()) std::cout << " / " << out;
          if (single) std::cout << "   (" << event_of(*ts, state(s), state(t)) << ")";
          std::cout << "\n";
        }
    }
  }

  auto write = [](const std::string& path, const std::string& text) {
    if (path == "-") {
      std::cout << text;
      return;
    }
    std::ofstream f(path);
    if (!f) throw InputError("cannot write " + path);
    f << text;
  };
  if (!o.dot.empty()) {
    report::SituationGraphOptions so;
    so.max_nodes = o.max_nodes;
    const auto grouped = report::situation_graph_dot(g, so);
    write(o.dot, grouped.dot);
    if (!grouped.truncation_note.empty()) std::cerr << "sfcv rsg --dot: " << grouped.truncation_note << "\n";
  }
  if (!o.dot_states.empty()) {
    std::ostringstream d;
    d << "digraph rsg {\n  rankdir=LR;\n  node [shape=box, fontname=\"monospace\"];\n";
    for (auto s : g.initial_states()) d << "  init" << s << " [shape=point];\n  init" << s << " -> s" << s << ";\n";
    for (std::uint32_t s = 0; s < g.num_states(); ++s)
      d << "  s" << s << " [label=\"" << dot_escape(ts->describe(state(s))) << "\"];\n";
    for (std::uint32_t s = 0; s < g.num_states(); ++s)
      for (auto e = g.edges_begin(s); g.expanded(s) && e < g.edges_end(s); ++e)
        d << "  s" << s << " -> s" << g.target(e) << " [label=\"" << dot_escape(condition(e))
          << "\"];\n";
    d << "}\n";
    write(o.dot_states, d.str());
  }

  // One line per distinct anomaly (the same cycle is met from many nodes).
  std::set<std::string> printed;
  for (const auto& a : g.anomalies()) {
    std::string line = o.model + ": error: " + a.message + "; inputs: " +
                       engine::simplify(a.condition, inputs).to_string(inputs);
    if (!a.cycle.empty()) {
      line += "; cycle:";
      for (const auto& c : a.cycle) line += " " + split_description(ts->describe(c)).first + " ->";
      line += " " + split_description(ts->describe(a.cycle.front())).first;
    }
    if (printed.insert(line).second) std::cerr << line << "\n";
  }
  if (!g.complete()) {
    (dot_to_stdout ? std::cerr : std::cout) << "unknown: the " << g.limit_reached() << " limit was reached after "
              << g.num_states() << " states; the graph is incomplete\n";
    return kUnknown;
  }
  return g.anomalies().empty() ? kHolds : kViolated;
}

}  // namespace

void add_rsg_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<RsgOptions>();
  auto* sub = app.add_subcommand(
      "rsg", "Build the reachable situations graph (Grafcet) or the cycle state graph (IEC)");
  sub->add_option("model", opts->model, "Chart file (PLCopen XML, IEC text, .g7, AGRAFE .grafcet)")
      ->required();
  sub->add_option("--format", opts->format, "Input format: auto, xml, iec, g7, agrafe");
  add_system_options(*sub, opts->system);
  sub->add_flag("--list", opts->list, "List every situation and evolution");
  sub->add_option("--dot", opts->dot,
                  "Write the graph grouped by step situation as Graphviz to FILE (- for stdout)");
  sub->add_option("--max-nodes", opts->max_nodes,
                  "Step situations drawn by --dot, breadth-first (0: all; default 60)");
  sub->add_option("--dot-states", opts->dot_states,
                  "Write every stable situation and its input conditions as Graphviz (- for stdout)");
  sub->add_flag("--json", opts->json, "Print the graph as JSON instead of the summary");
  add_limit_options(*sub, opts->limits, "verdict unknown", MemoryLimit::NotOffered);
  sub->callback([opts, &selected] {
    selected = [opts] { return run_rsg(*opts); };
  });
}

}  // namespace sfcv::cli
