#include "cli/exit_footers.hpp"

#include <CLI/CLI.hpp>
#include <map>
#include <string>

namespace sfcv::cli {

namespace {

const std::map<std::string, std::string>& footers() {
  static const std::map<std::string, std::string> texts = {
      {"info",
       "Exit codes: 0 the model was read and described, 2 bad usage or input (the message "
       "names file, line and column), 3 a limit was reached while loading, 4 internal error."},
      {"lint",
       "Exit codes: 0 no error (warnings and notes allowed: 'sfcv check' can model the file), "
       "2 some error in the model or bad usage, 4 internal error."},
      {"export",
       "Exit codes: 0 the model was written, 2 bad usage or input (also: the target format "
       "cannot express the model; the message names the construct), 3 a limit was reached, 4 "
       "internal error."},
      {"report",
       "Exit codes: 0 the report was written, 2 bad usage, or a result file that is no 'sfcv "
       "check --json' output, 4 internal error."},
      {"rsg",
       "Exit codes: 0 the situation graph is complete and has no anomaly, 1 it has an anomaly "
       "(a deadlock, an instability: listed on standard error), 2 bad usage or input, 3 a limit "
       "was reached (the graph is incomplete), 4 internal error."},
      {"query",
       "Exit codes: 0 every query was answered (with --assert: every asserted set is empty), 1 "
       "with --assert: some set is not empty, 2 bad usage or input (also: a query that does not "
       "compile), 3 a limit was reached before an answer was certain, 4 internal error."},
      {"patterns", "Exit codes: 0 the list was printed, 4 internal error."},
  };
  return texts;
}

}  // namespace

const char* top_level_exit_codes() {
  return "Exit codes (each subcommand's --help says what they mean for it): 0 success (check: "
         "every property holds), 1 a violation was found, 2 bad usage or input, 3 unknown (a "
         "resource limit was reached), 4 internal error (a bug: please report it).";
}

void set_exit_code_footers(CLI::App& app) {
  const std::string inherited = app.get_footer();
  for (auto* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    const auto it = footers().find(sub->get_name());
    if (it == footers().end()) continue;
    const std::string own = sub->get_footer();
    if (own.empty() || own == inherited)
      sub->footer(it->second);
    else if (own.find("Exit codes") == std::string::npos)
      sub->footer(own + "\n" + it->second);
  }
}

}  // namespace sfcv::cli
