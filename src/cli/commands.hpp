#pragma once
// Each subcommand registers itself on the CLI11 app and, when selected, stores the function that
// runs it. One file per subcommand: cmd_<name>.cpp.

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace sfcv::cli {

using CommandRunner = std::function<int()>;

/// Options of every subcommand alike, given before or after the subcommand's name.
struct GlobalOptions {
  bool quiet = false;  ///< --quiet: no progress, notes or warnings on standard error
  /// --verbose: findings and diagnostics with absolute paths and XML element paths, every note
  /// in full (else relative paths, line:col, notes in short).
  bool verbose = false;
  std::vector<std::string> argv;  ///< the command line as given, for the reports' provenance
};
/// The options of this run (set while parsing argv).
const GlobalOptions& global_options();

void add_check_command(CLI::App& app, CommandRunner& selected);
void add_info_command(CLI::App& app, CommandRunner& selected);
void add_lint_command(CLI::App& app, CommandRunner& selected);
void add_simulate_command(CLI::App& app, CommandRunner& selected);
void add_rsg_command(CLI::App& app, CommandRunner& selected);
void add_query_command(CLI::App& app, CommandRunner& selected);
void add_export_command(CLI::App& app, CommandRunner& selected);
void add_report_command(CLI::App& app, CommandRunner& selected);
void add_patterns_command(CLI::App& app, CommandRunner& selected);
void add_equiv_command(CLI::App& app, CommandRunner& selected);
void add_plan_command(CLI::App& app, CommandRunner& selected);
void add_merge_command(CLI::App& app, CommandRunner& selected);

/// Builds the app, parses argv, runs the selected subcommand; returns the exit code.
int run(int argc, char** argv);

}  // namespace sfcv::cli
