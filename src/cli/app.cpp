#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/build_info.hpp"
#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/exit_footers.hpp"
#include "cli/interrupt.hpp"
#include "cli/output_file.hpp"
#include "cli/usage_hint.hpp"

namespace sfcv::cli {

namespace {
GlobalOptions g_options;
}  // namespace

const GlobalOptions& global_options() {
  return g_options;
}

int run(int argc, char** argv) {
  CLI::App app{
      "sfcv: a verifier for Sequential Function Charts (IEC 61131-3) and Grafcet "
      "(IEC 60848)",
      "sfcv"};
  g_options.argv.assign(argv, argv + argc);
  // The first line stays "sfcv VERSION"; then the commit and the BuDDy and CaDiCaL versions.
  auto version = version_text();
  version.pop_back();  // CLI11 adds the line break
  app.set_version_flag("--version", version);
  app.require_subcommand(1);
  app.add_flag("-q,--quiet", g_options.quiet,
               "No progress, notes or warnings on standard error (errors still)");
  app.add_flag("-v,--verbose", g_options.verbose,
               "Findings and diagnostics in full: absolute paths, XML element paths, every note");
  app.fallthrough();  // `sfcv check m.g7 --quiet` as well as `sfcv --quiet check m.g7`
  app.footer(top_level_exit_codes());

  CommandRunner selected;
  add_check_command(app, selected);
  add_info_command(app, selected);
  add_lint_command(app, selected);
  add_simulate_command(app, selected);
  add_rsg_command(app, selected);
  add_query_command(app, selected);
  add_export_command(app, selected);
  add_report_command(app, selected);
  add_patterns_command(app, selected);
  add_equiv_command(app, selected);
  add_plan_command(app, selected);
  add_merge_command(app, selected);
  set_exit_code_footers(app);  // each subcommand's exit codes in its own words

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // An unknown word: name it and the closest known one, instead of CLI11's generic message.
    if (const auto hint = usage_hint(app, std::vector<std::string>(argv + 1, argv + argc))) {
      std::cerr << "sfcv: error: " << *hint << "\n";
      if (wants_json(argc, argv)) write_json_error(std::cout, "usage", *hint, kBadInput);
      return kBadInput;
    }
    app.exit(e);
    if (wants_json(argc, argv)) write_json_error(std::cout, "usage", e.what(), kBadInput);
    return kBadInput;  // CLI11 uses its own codes; ours are a contract
  }
  if (!selected) return kBadInput;
  install_interrupt_handlers();
  const int code = selected();
  flush_standard_output();  // `> /dev/full`: an error, not a silent loss (exit 2)
  return code;
}

}  // namespace sfcv::cli
