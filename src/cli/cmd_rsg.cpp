// sfcv rsg: builds the reachable situations graph (Grafcet) or the cycle-level state graph
// (IEC 61131-3) and prints its size, its listing, a Graphviz or a JSON rendering.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "cli/output_file.hpp"
#include "cli/progress_line.hpp"
#include "cli/run_guard.hpp"
#include "cli/system_options.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "report/situation_graph_dot.hpp"
#include "report/situation_graph_render.hpp"
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

int run_rsg(const RsgOptions& o, const RunGuard& guard) {
  const OutputPath dot{o.dot, "--dot"}, dot_states{o.dot_states, "--dot-states"};
  check_output_paths({dot, dot_states});
  const model::Budget& budget = guard.budget();  // one budget for every phase
  ProgressLine progress(!global_options().quiet);
  progress.phase("load");
  const model::Project project =
      load_model_or_throw(o.model, parse_format(o.format), false, &budget);
  budget.check_time("loading the model");
  progress.phase("build");
  const auto built =
      build_system(project, o.system, {}, "sfcv rsg", semantics::ActionOrder::Declaration, &budget);
  budget.check_time("building the system");
  const auto& ts = built.system;
  const std::string& sem = built.semantics;

  progress.phase("explore");
  engine::ExplorationOptions eo;
  eo.max_states = budget.max_states;
  eo.deadline = budget.deadline;
  eo.cancel = budget.cancel.get();  // the memory watchdog
  eo.max_memory_bytes = budget.max_memory_bytes;
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
  // The limit's name: a cancel is the memory watchdog's.
  const std::string limit = guard.watchdog().tripped() ? std::string("memory") : g.limit_reached();
  // Past the deadline or the memory, the listing, the JSON and the pictures (in states times
  // steps) are not rendered: the summary and the limit are what the run has.
  if (!g.complete() && budget.expired() &&
      (o.list || o.json || !o.dot.empty() || !o.dot_states.empty()))
    throw guard.reason(LimitReached(
        Limit::Time, "time limit reached while exploring: the graph is incomplete after " +
                         std::to_string(g.num_states()) + " states and is not written"));
  report::SituationGraphText shown;
  shown.semantics = sem;
  shown.single_input_change = sem == "grafcet" && !o.system.multi_input_change;
  shown.list = o.list;
  // A graph written to stdout is the whole output (dot reads it from a pipe).
  const bool dot_to_stdout = o.dot == "-" || o.dot_states == "-";
  if (o.json)
    std::cout << report::situation_graph_json(g, *ts, shown).dump(2) << "\n";
  else if (!dot_to_stdout || o.list)
    std::cout << report::situation_graph_text(g, *ts, shown);

  if (!o.dot.empty()) {
    report::SituationGraphOptions so;
    so.max_nodes = o.max_nodes;
    const auto grouped = report::situation_graph_dot(g, so);
    write_output(dot, grouped.dot);
    if (!grouped.truncation_note.empty())
      std::cerr << "sfcv rsg --dot: " << grouped.truncation_note << "\n";
  }
  if (!o.dot_states.empty()) write_output(dot_states, report::state_graph_dot(g, *ts));
  for (const auto& line : report::anomaly_lines(g, *ts, o.model)) std::cerr << line << "\n";
  if (!g.complete()) {
    // Under --json standard output holds the JSON document alone (its "complete" and "limit").
    (dot_to_stdout || o.json ? std::cerr : std::cout)
        << "unknown: the " << limit << " limit was reached after " << g.num_states()
        << " states; the graph is incomplete\n";
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
  sub->add_option("--format", opts->format, kFormatHelp);
  add_system_options(*sub, opts->system);
  sub->add_flag("--list", opts->list, "List every situation and evolution");
  sub->add_option("--dot", opts->dot,
                  "Write the graph grouped by step situation as Graphviz to FILE (- for stdout)");
  sub->add_option("--max-nodes", opts->max_nodes,
                  "Step situations drawn by --dot, breadth-first (0: all; default 60)");
  sub->add_option(
      "--dot-states", opts->dot_states,
      "Write every stable situation and its input conditions as Graphviz (- for stdout)");
  sub->add_flag("--json", opts->json, "Print the graph as JSON instead of the summary");
  add_limit_options(*sub, opts->limits, "verdict unknown");
  sub->callback([opts, &selected] {
    selected = [opts] {
      return run_limited(opts->limits, [&](const RunGuard& g) { return run_rsg(*opts, g); });
    };
  });
}

}  // namespace sfcv::cli
