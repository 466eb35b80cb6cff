#include "cli/system_options.hpp"

#include <iostream>

#include "cli/action_order.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_lines.hpp"
#include "cli/exit_code.hpp"
#include "cli/iec_options.hpp"
#include "semantics/grafcet_system.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::cli {

void add_system_options(CLI::App& sub, SystemOptions& o, SemanticsChoice choice) {
  if (choice == SemanticsChoice::Both) {
    sub.add_option("--semantics", o.semantics, "grafcet or iec61131 (default: from the model)");
    sub.add_flag("--multi-input-change", o.multi_input_change,
                 "Grafcet: several inputs may change at once (default: one per event)");
  }
  sub.add_option(
      "--pou", o.pous,
      "IEC: POU(s) run in one cycle, in this order (default: every PROGRAM, else the SFC POU)");
  sub.add_option("--priority", o.priority, "IEC conflicts: standard (default) or none");
  sub.add_option("--time", o.time, "IEC timers: abstract (default) or discrete");
  sub.add_option("--cycle", o.cycle, "IEC cycle time for --time discrete (default 10ms)");
  sub.add_option("--unwritten", o.unwritten,
                 "IEC variables that the run reads and no POU of it writes: free (default: "
                 "inputs, any value each cycle) or keep (their initial values)");
  sub.add_option("--action-order", o.action_order,
                 "IEC actions within a cycle: declaration (default), alphabetical, unordered "
                 "(actions writing a common variable in any order) or FILE of pairs 'A < B' "
                 "(default under --dialect codesys or twincat: the vendor's order)");
  sub.add_option("--dialect", o.dialect,
                 "IEC: whose reading of the final call of IEC actions and of the action order: "
                 "iec, codesys, twincat, siemens or rockwell (default: the vendor that wrote "
                 "the file)");
}

std::optional<semantics::VendorDialect> given_dialect(const std::string& text) {
  if (text.empty() || text == "auto") return std::nullopt;
  if (const auto d = semantics::parse_vendor_dialect(text)) return *d;
  throw UsageError("bad --dialect '" + text +
                   "' (expected iec, codesys, twincat, siemens or rockwell)");
}

semantics::VendorDialect chosen_dialect(const model::Project& project, const SystemOptions& o) {
  return given_dialect(o.dialect).value_or(semantics::file_dialect(project));
}

semantics::Iec61131Options default_iec_options(const model::Project& project) {
  semantics::Iec61131Options options;
  semantics::set_dialect(options, semantics::file_dialect(project));
  return options;
}

std::string chosen_semantics(const model::Project& project, const SystemOptions& o) {
  if (o.semantics.empty() || o.semantics == "auto")
    return project.dialect == model::Dialect::Grafcet ? "grafcet" : "iec61131";
  if (o.semantics == "grafcet") return "grafcet";
  if (o.semantics == "iec61131" || o.semantics == "iec") return "iec61131";
  throw InputError("bad --semantics '" + o.semantics + "' (expected grafcet or iec61131)");
}

BuiltSystem build_system(const model::Project& project, const SystemOptions& o,
                         const std::vector<model::ExprPtr>& assumptions, const std::string& command,
                         semantics::ActionOrder action_order, const model::Budget* budget) {
  BuiltSystem built;
  built.semantics = chosen_semantics(project, o);
  model::Diagnostics diags;
  if (built.semantics == "grafcet") {
    // An IEC option on a Grafcet would be silently ignored: say so instead.
    if (!o.pous.empty() || o.priority != "standard" || o.time != "abstract" || o.cycle != "10ms" ||
        o.unwritten != "free" || (!o.action_order.empty() && o.action_order != "declaration") ||
        !o.dialect.empty())
      throw InputError(command +
                       ": --pou, --priority, --time, --cycle, --unwritten, --action-order and "
                       "--dialect apply to the IEC 61131-3 semantics only");
    semantics::GrafcetOptions g;
    g.single_input_change = !o.multi_input_change;
    g.assumptions = assumptions;
    if (budget) g.deadline = budget->deadline;
    built.system = semantics::make_grafcet_system(project, g, diags);
  } else {
    if (o.multi_input_change)
      throw InputError(command + ": --multi-input-change applies to the Grafcet semantics only");
    semantics::Iec61131Options i;
    i.priority = parse_priority(o.priority);
    i.time = parse_time_mode(o.time);
    i.cycle_ms = parse_cycle_ms(o.cycle);
    i.unwritten = parse_unwritten(o.unwritten);
    i.pous = o.pous;
    i.action_order = action_order;
    semantics::set_dialect(i, chosen_dialect(project, o));
    if (!o.action_order.empty()) parse_action_order(o.action_order, i);
    i.assumptions = assumptions;
    if (budget) i.deadline = budget->deadline;
    built.system = semantics::make_iec61131_system(project, i, diags);
  }
  bool errors = false;
  bool bad_pou = false;
  print_diagnostic_lines(diags, global_options().quiet, std::cerr);
  for (const auto& d : diags) {
    const bool error = d.severity == model::Severity::Error;
    errors = errors || error;
    bad_pou = bad_pou || (error && d.message.rfind("no POU named", 0) == 0);
  }
  // A misspelled --pou is a usage error, not a chart the semantics cannot model.
  if (bad_pou) throw UsageError(command + ": bad --pou (the error above names the POUs)");
  if (errors || !built.system)
    throw InputError(command + ": the " + built.semantics + " semantics cannot model this chart");
  return built;
}

}  // namespace sfcv::cli
