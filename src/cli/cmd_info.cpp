#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "cli/run_guard.hpp"
#include "cli/system_options.hpp"
#include "report/project_summary.hpp"
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

/// The variables that the run (default options: every PROGRAM) reads and no POU of it writes,
/// read as inputs (docs/semantics.md 1.8); nullopt when the semantics cannot model the project.
std::optional<std::vector<semantics::UnwrittenVariable>> unwritten(const model::Project& p,
                                                                   const model::Budget& budget) {
  if (p.dialect == model::Dialect::Grafcet) return std::vector<semantics::UnwrittenVariable>{};
  model::Diagnostics ignored;  // `sfcv lint` reports them
  auto options = default_iec_options(p);
  options.deadline = budget.deadline;
  const auto system = semantics::make_iec61131_system(p, options, ignored);
  if (!system) return std::nullopt;
  return semantics::unwritten_variables(*system);
}
}  // namespace

void add_info_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<InfoOptions>();
  auto* sub =
      app.add_subcommand("info", "Summarise a chart: POUs, steps, transitions, actions, variables");
  sub->add_option("model", opts->model, "Chart file (PLCopen XML, IEC text, .g7, AGRAFE .grafcet)")
      ->required();
  sub->add_option("--format", opts->format, kFormatHelp);
  sub->add_flag("--json", opts->json, "Print the summary as JSON (schema: docs/formats.md)");
  add_limit_options(*sub, opts->limits, "what is not counted is left out (exit 3)");
  sub->callback([opts, &selected] {
    selected = [opts] {
      return run_limited(opts->limits, [&](const RunGuard& guard) {
        const auto project =
            load_model_or_throw(opts->model, parse_format(opts->format), false, &guard.budget());
        std::optional<LimitReached> stopped;
        std::optional<std::vector<semantics::UnwrittenVariable>> unwritten_list;
        try {
          unwritten_list = unwritten(project, guard.budget());
          guard.check("finding the unwritten variables");
        } catch (const LimitReached& e) {
          unwritten_list.reset();
          stopped = guard.reason(e);
        }
        auto info = report::project_summary_json(opts->model, project, unwritten_list);
        report::make_valid_utf8(info);  // names are bytes; the JSON is UTF-8
        if (opts->json)
          std::cout << info.dump(2) << "\n";
        else
          report::print_project_summary(info, std::cout, stopped.has_value());
        return stopped ? report_limit(*stopped) : kHolds;
      });
    };
  });
}

}  // namespace sfcv::cli
