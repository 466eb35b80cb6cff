// sfcv export: the chart for outside checkers (NuSMV, Cadence SMV, Promela, AIGER) or people
// (DOT, IEC text, .g7, PLCopen XML). The circuit exports mean what sfcv check means:
// engine/external/ export_model.hpp says how.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/iec_options.hpp"
#include "cli/load_model.hpp"
#include "cli/output_file.hpp"
#include "cli/run_guard.hpp"
#include "cli/system_options.hpp"
#include "engine/external/aiger_writer.hpp"
#include "engine/external/export_model.hpp"
#include "io/g7_writer.hpp"
#include "io/iec_text_writer.hpp"
#include "io/plcopen_writer.hpp"
#include "logic/check_inputs.hpp"
#include "logic/formula.hpp"
#include "model/input_file.hpp"
#include "model/names.hpp"
#include "report/chart_dot.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::cli {

namespace {
struct ExportOptions {
  std::string model;
  std::string format = "auto";
  std::string to;
  std::string output;
  std::vector<std::string> ctl;
  std::vector<std::string> ltl;
  std::string spec;
  std::vector<std::string> assume;
  std::string checks;  ///< empty: reachability when no property is given
  SystemOptions system;
  LimitOptions limits;
};

void print_or_throw(const model::Diagnostics& diags, const std::string& what) {
  bool errors = false;
  for (const auto& d : diags) {
    std::cerr << d.str() << "\n";
    errors = errors || d.severity == model::Severity::Error;
  }
  if (errors) throw InputError("sfcv export: " + what);
}

// The circuit exports: nusmv, casmv, promela, aiger, aag.
void export_circuit(const ExportOptions& o, const model::Project& project, std::ostream& out,
                    const RunGuard& guard) {
  logic::CheckInputs inputs{
      o.ctl,    o.spec.empty() ? "" : model::read_input_file(o.spec, "the spec file"),
      o.spec,   {},
      o.assume, {},
      {},       o.ltl};
  auto parsed = logic::parse_check_inputs(inputs);
  print_or_throw(parsed.diagnostics, "errors in the properties");
  if (!parsed.spec.fairness.empty())
    throw InputError("sfcv export: fairness constraints are not exported yet");
  if (project.dialect == model::Dialect::Grafcet)
    throw InputError("sfcv export --to " + o.to + ": not supported for Grafcet yet");

  const auto built =
      build_system(project, o.system, logic::assumption_exprs(parsed.spec), "sfcv export",
                   semantics::ActionOrder::Declaration, &guard.budget());
  // Inputs and previous values named by a property are kept in the state only then.
  model::Diagnostics history_diags;
  const auto history = logic::history_system_for(parsed.spec, *built.system, history_diags);
  print_or_throw(history_diags, "errors in the properties");
  const semantics::TransitionSystem* ts = history ? history.get() : built.system.get();

  logic::CheckTask task;
  task.system = ts;
  model::Diagnostics resolve_diags;
  logic::resolve_into(parsed.spec, *ts, task, resolve_diags);
  print_or_throw(resolve_diags, "errors in the properties");

  std::string why;
  const auto checks = logic::parse_check_selection(
      o.checks.empty() ? (task.properties.empty() ? "reachable" : "none") : o.checks, &why);
  if (!checks) throw InputError(why);
  engine::ExportRequest request;
  const bool smv = o.to == "nusmv" || o.to == "casmv";
  request.target = smv ? engine::ExportTarget::Smv : engine::ExportTarget::Circuit;
  request.properties = task.properties;
  for (auto c : *checks) {
    if (c == logic::StandardCheck::Reachable)
      request.reachability = true;
    else
      std::cerr << "sfcv export: the standard check '" << logic::to_string(c)
                << "' is not exported (only 'reachable' is)\n";
  }
  request.header = {"Exported by sfcv from " + o.model + " (IEC 61131-3 semantics, priority " +
                    o.system.priority + ", time " + o.system.time +
                    (o.system.time == "discrete" ? ", cycle " + o.system.cycle : "") + ")"};
  for (const auto& a : parsed.spec.assumptions)
    request.header.push_back("assumption: " + logic::to_string(a.formula));

  engine::ExportedModel exported;
  guard.check("building the system");
  try {
    exported = engine::build_export(*ts, request);
  } catch (const engine::ExportError& e) {
    throw InputError(std::string("sfcv export: ") + e.what());
  }
  if (exported.loop_limit_latch)
    std::cerr << "sfcv export: " << exported.circuit.loop_limit_message()
              << "; such a cycle sets the latch sfcv_loop_limit, where every exported property "
                 "fails (a counterexample ending there is unknown, docs/exports.md)\n";
  if (o.to != "promela" && !exported.model.ltl.empty())
    throw InputError("sfcv export --to " + o.to + ": LTL properties are exported to promela only");
  if (!smv && !exported.ctl_only.empty()) {
    std::string names;
    for (const auto& n : exported.ctl_only) names += (names.empty() ? "" : ", ") + n;
    throw InputError("sfcv export --to " + o.to +
                     ": only invariants (AG p, p without temporal operators) can be exported "
                     "there; not: " +
                     names + " (use --to nusmv or --to casmv)");
  }
  if (o.to == "nusmv") {
    engine::write_nusmv(out, exported.model);
  } else if (o.to == "casmv") {
    engine::write_casmv(out, exported.model);
  } else if (o.to == "promela") {
    engine::write_promela(out, exported.model);
  } else {
    std::string comment;
    for (const auto& h : exported.model.header) comment += h + "\n";
    const auto& m = exported.model;
    if (!m.aig.constraints().empty())
      comment +=
          "A latch sfcv_valid (initially 1) records that every cycle so far kept the\n"
          "constraint; each bad output is `sfcv_valid & bad`.\n";
    const auto circuit = engine::aiger_circuit(exported.model);
    const auto symbols = engine::aiger_symbols(circuit);  // as the symbol table names them
    for (std::size_t l = 0; l < m.latch_comments.size(); ++l)
      comment +=
          "l" + std::to_string(l) + " " + symbols.latches[l] + ": " + m.latch_comments[l] + "\n";
    for (std::size_t i = 0; i < m.input_comments.size(); ++i)
      comment +=
          "i" + std::to_string(i) + " " + symbols.inputs[i] + ": " + m.input_comments[i] + "\n";
    engine::write_aiger(out, circuit,
                        o.to == "aiger" ? engine::AigerMode::Binary : engine::AigerMode::Ascii,
                        comment);
  }
}

int run_export(const ExportOptions& o, const RunGuard& guard) {
  static const std::vector<std::string> kTargets = {"nusmv", "casmv", "promela", "aiger",  "aag",
                                                    "dot",   "iec",   "g7",      "plcopen"};
  if (std::find(kTargets.begin(), kTargets.end(), o.to) == kTargets.end())
    throw InputError("bad --to '" + o.to +
                     "' (expected nusmv, casmv, promela, aiger, aag, dot, iec, g7 or plcopen)");
  if (o.to == "aiger" && o.output.empty() && ::isatty(1))
    throw InputError(
        "sfcv export --to aiger writes binary AIGER: give -o FILE or redirect "
        "standard output (--to aag writes ASCII)");
  const OutputPath output{o.output, "-o"};
  check_output_paths({output});
  const auto project = load_model_or_throw(o.model, parse_format(o.format), false, &guard.budget());
  guard.check("loading the model");

  std::ostringstream text;
  try {
    if (o.to == "dot") {
      report::print_chart_dot(text, project);
    } else if (o.to == "iec") {
      text << io::write_iec_text(project);
    } else if (o.to == "g7") {
      text << io::write_g7(project);
    } else if (o.to == "plcopen") {
      text << io::write_plcopen_xml(project);
    } else {
      export_circuit(o, project, text, guard);
    }
  } catch (const UnsupportedConstruct& e) {  // the writers' (G7WriteError among them)
    throw UnsupportedConstruct("sfcv export --to " + o.to + ": " + e.what());
  }
  // A partial export would not mean the chart: past a limit, nothing is written.
  guard.check("writing the export");
  if (o.output.empty())
    std::cout << text.str();
  else
    write_output(output, text.str());
  return kHolds;
}
}  // namespace

void add_export_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<ExportOptions>();
  auto* sub = app.add_subcommand(
      "export",
      "Export a chart to NuSMV, Cadence SMV, Promela, AIGER, DOT, IEC text, .g7 or PLCopen XML");
  sub->add_option("model", opts->model, "Chart file (PLCopen XML, IEC text, .g7, AGRAFE .grafcet)")
      ->required();
  sub->add_option("--to", opts->to,
                  "nusmv, casmv, promela, aiger (binary), aag, dot, iec, g7, plcopen")
      ->required();
  sub->add_option("-o,--output", opts->output, "Output file (default: standard output)");
  sub->add_option("--format", opts->format, kFormatHelp);
  sub->add_option("--ctl", opts->ctl,
                  "A CTL property (repeatable); promela/aiger: invariants AG p");
  sub->add_option("--ltl", opts->ltl, "An LTL property (repeatable); promela only: an ltl claim");
  sub->add_option("--spec", opts->spec, "A file of 'property name: formula;', 'assume e;'");
  sub->add_option("--assume", opts->assume, "Assumption on inputs and state (repeatable)");
  sub->add_option("--checks", opts->checks,
                  "reachable (default without properties) or none: EF X per step (SMV), "
                  "invariant AG !X per step (promela/aiger)");
  add_system_options(*sub, opts->system, SemanticsChoice::IecOnly);
  add_limit_options(*sub, opts->limits, "nothing is written (exit 3)");
  sub->callback([opts, &selected] {
    selected = [opts] {
      return run_limited(opts->limits, [&](const RunGuard& g) { return run_export(*opts, g); });
    };
  });
}

}  // namespace sfcv::cli
