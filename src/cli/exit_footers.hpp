#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// What the exit codes mean, said in each subcommand's --help in its own words: info, lint,
// export, report, rsg and query once inherited the footer about properties.

namespace CLI {
class App;
}

namespace sfcv::cli {

/// The exit-code footer of the top-level help.
const char* top_level_exit_codes();

/// Gives each subcommand of `app` that kept the inherited footer the footer of its own exit
/// codes. Call after every subcommand is added.
void set_exit_code_footers(CLI::App& app);

}  // namespace sfcv::cli
