#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "cli/load_model.hpp"
#include "cli/not_built.hpp"

namespace sfcv::cli {

namespace {
struct LintOptions {
  std::string model;
  std::string format = "auto";
};
}  // namespace

void add_lint_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<LintOptions>();
  auto* sub = app.add_subcommand("lint", "Validate a chart's structure, names and types");
  sub->add_option("model", opts->model, "Chart file (PLCopen XML, IEC text, .g7, AGRAFE .grafcet)")
      ->required();
  sub->add_option("--format", opts->format, "Input format: auto, xml, iec, g7, agrafe");
  sub->callback([opts, &selected] {
    selected = [opts] {
      load_model_or_throw(opts->model, parse_format(opts->format));
      return not_built_yet("'sfcv lint'");
    };
  });
}

}  // namespace sfcv::cli
