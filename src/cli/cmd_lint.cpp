#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "cli/run_guard.hpp"
#include "cli/system_options.hpp"
#include "report/project_summary.hpp"
#include "report/text_encoding.hpp"
#include "semantics/grafcet_system.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::cli {

namespace {
struct LintOptions {
  std::string model;
  std::string format = "auto";
  bool json = false;
  LimitOptions limits;
};

/// What the semantics refuses (a POU body or an action it does not model, an unknown name):
/// lint's exit 0 must mean that `check` can model the file, so the system is built exactly as
/// `check` without `--pou` builds it (its default choice of programs).
model::Diagnostics semantic_diagnostics(const model::Project& project,
                                        const model::Budget& budget) {
  model::Diagnostics out;
  semantics::GrafcetOptions grafcet;
  auto iec = default_iec_options(project);
  grafcet.deadline = iec.deadline = budget.deadline;
  if (project.dialect == model::Dialect::Grafcet)
    semantics::make_grafcet_system(project, grafcet, out);
  else if (const auto system = semantics::make_iec61131_system(project, iec, out))
    // One warning per variable that the run reads and nothing writes, at its declaration
    // (docs/semantics.md 1.8): perhaps a sensor whose I/O mapping is not in the file, perhaps
    // a constant not declared CONSTANT, perhaps a forgotten assignment.
    for (const auto& u : semantics::unwritten_variables(*system))
      out.push_back({model::Severity::Warning, u.declared,
                     "variable '" + u.name + "' is read (in " + u.read_in +
                         (u.read_at.line > 0 ? ", line " + std::to_string(u.read_at.line) : "") +
                         ") but no POU of the run writes it: it is an input, free each cycle "
                         "(declare it CONSTANT if it is one; --unwritten keep holds it at its "
                         "initial value)"});
  std::erase_if(out,
                [](const model::Diagnostic& d) { return d.severity == model::Severity::Note; });
  return out;
}

int lint(const LintOptions& opts, const RunGuard& guard) {
  auto checked = load_and_validate(opts.model, parse_format(opts.format), &guard.budget());
  // A limit in the semantic checks: the diagnostics found so far are printed, then the limit.
  std::optional<LimitReached> stopped;
  try {
    if (checked.project && !model::has_errors(checked.diagnostics))
      for (auto& d : semantic_diagnostics(*checked.project, guard.budget()))
        checked.diagnostics.push_back(std::move(d));
    guard.check("checking the semantics");
  } catch (const LimitReached& e) {
    stopped = guard.reason(e);
  }
  std::size_t errors = 0, warnings = 0;
  for (const auto& d : checked.diagnostics) {
    if (d.severity == model::Severity::Error) ++errors;
    if (d.severity == model::Severity::Warning) ++warnings;
  }
  // An importer that fails without saying why still fails.
  if (!checked.project && errors == 0) ++errors;
  if (opts.json) {
    auto doc = report::diagnostics_json(checked.diagnostics, errors, warnings);
    report::make_valid_utf8(doc);  // names are bytes; the JSON is UTF-8
    std::cout << doc.dump(2) << "\n";
  } else {
    report::print_diagnostics(checked.diagnostics, errors, warnings, std::cout);
  }
  if (errors) return kBadInput;  // errors found are errors, whatever was left unchecked
  if (stopped) return report_limit(*stopped);
  return kHolds;
}
}  // namespace

void add_lint_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<LintOptions>();
  auto* sub = app.add_subcommand(
      "lint", "Validate a chart's structure, names and types (exit 2 on errors, 0 otherwise)");
  sub->add_option("model", opts->model, "Chart file (PLCopen XML, IEC text, .g7, AGRAFE .grafcet)")
      ->required();
  sub->add_option("--format", opts->format, kFormatHelp);
  sub->add_flag("--json", opts->json,
                "Print the diagnostics as JSON: {schema_version, diagnostics: [{file, line, "
                "column, element_path, severity, message}], errors, warnings}");
  add_limit_options(*sub, opts->limits, "what is not checked is unknown");
  sub->callback([opts, &selected] {
    selected = [opts] {
      return run_limited(opts->limits, [&](const RunGuard& g) { return lint(*opts, g); });
    };
  });
}

}  // namespace sfcv::cli
