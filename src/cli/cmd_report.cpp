// sfcv report: renders a saved `sfcv check --json` result. The chart comes from the model the
// result names (or --model), built with the same system options as the check.

#include <CLI/CLI.hpp>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/json_input.hpp"
#include "cli/load_model.hpp"
#include "cli/output_file.hpp"
#include "cli/run_guard.hpp"
#include "cli/system_options.hpp"
#include "report/check_html.hpp"

namespace sfcv::cli {

namespace {

struct ReportOptions {
  std::string result;
  std::string html;
  std::string model;  ///< empty: the result's "model"
  std::string format = "auto";
  SystemOptions system;
  LimitOptions limits;
};

int run_report(const ReportOptions& o, const RunGuard& guard) {
  nlohmann::json result =
      read_json_file(o.result, "the result", "not a JSON result of 'sfcv check --json'");
  if (!result.contains("properties") || !result["properties"].is_array())
    throw InputError(o.result + ": not a JSON result of 'sfcv check --json' (no \"properties\")");
  // A result of a later, incompatible JSON version (share/sfcv/check-result.schema.json) is
  // refused rather than half read; one without schema_version predates it.
  if (const auto v = result.find("schema_version");
      v != result.end() && (!v->is_string() || !v->get<std::string>().starts_with("1.")))
    throw InputError(o.result + ": schema_version " + v->dump() +
                     " is not one this sfcv reads (1.x)");
  const std::string model = !o.model.empty() ? o.model : result.value("model", std::string());
  if (model.empty()) throw InputError(o.result + ": names no model: give --model");
  // Before the model is loaded and built (the long part).
  const OutputPath html{o.html, "--html"};
  check_output_paths({html});
  const auto& budget = guard.budget();
  const auto project = load_model_or_throw(model, parse_format(o.format), true, &budget);
  SystemOptions system = o.system;
  if (system.semantics.empty()) system.semantics = result.value("semantics", std::string());
  const auto built = build_system(project, system, {}, "sfcv report",
                                  semantics::ActionOrder::Declaration, &budget);
  guard.check("building the system");
  auto page = report::check_html(
      report::html_report(std::move(result), project, *built.system, picture_limits(budget)));
  // The pictures took what was left of the time (a note replaces a layout cut short).
  write_output(html, page);
  return kHolds;
}

}  // namespace

void add_report_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<ReportOptions>();
  auto* sub =
      app.add_subcommand("report", "Render a saved 'sfcv check --json' result as an HTML report");
  sub->add_option("result", opts->result, "The JSON result of 'sfcv check --json'")->required();
  sub->add_option("--html", opts->html, "The HTML file to write")->required();
  sub->add_option("--model", opts->model, "The chart file (default: the one the result names)");
  sub->add_option("--format", opts->format, kFormatHelp);
  add_system_options(*sub, opts->system);
  add_limit_options(*sub, opts->limits, "the report is not written (exit 3)");
  sub->callback([opts, &selected] {
    selected = [opts] {
      return run_limited(opts->limits, [&](const RunGuard& g) { return run_report(*opts, g); });
    };
  });
}

}  // namespace sfcv::cli
