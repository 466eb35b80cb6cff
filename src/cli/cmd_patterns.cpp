// sfcv patterns: the catalogue of requirement patterns that check --pattern takes.

#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/commands.hpp"
#include "logic/pattern.hpp"
#include "report/pattern_list.hpp"

namespace sfcv::cli {

void add_patterns_command(CLI::App& app, CommandRunner& selected) {
  auto* sub = app.add_subcommand(
      "patterns", "List the requirement patterns of check --pattern, their English and their CTL");
  sub->footer("Examples on the chemical plant: docs/properties.md.");
  sub->callback([&selected] {
    selected = [] {
      std::cout << report::pattern_list_text(logic::pattern_catalogue());
      return 0;
    };
  });
}

}  // namespace sfcv::cli
