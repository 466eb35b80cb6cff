// sfcv patterns: the catalogue of requirement patterns that check --pattern takes, and the
// shipped library of examples (share/sfcv/patterns.spec).

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/shipped_files.hpp"
#include "logic/pattern.hpp"
#include "model/errors.hpp"
#include "report/pattern_list.hpp"

namespace sfcv::cli {

void add_patterns_command(CLI::App& app, CommandRunner& selected) {
  auto* sub = app.add_subcommand(
      "patterns", "List the requirement patterns of check --pattern, their English and their CTL");
  auto library = std::make_shared<bool>(false);
  sub->add_flag("--library", *library,
                "Print the path of the shipped library of examples (share/sfcv/patterns.spec, a "
                "spec file for check --spec)");
  auto as_json = std::make_shared<bool>(false);
  sub->add_flag("--json", *as_json,
                "The catalogue as JSON (names, parameters, English, CTL, the PLCverif ids and "
                "ESBMC-PLC kinds of --requirements), for tools that write requirements");
  sub->footer("Examples on the chemical plant: docs/properties.md and share/sfcv/patterns.spec.");
  sub->callback([&selected, library, as_json] {
    selected = [library, as_json] {
      if (*as_json) {
        std::cout << report::pattern_list_json(logic::pattern_catalogue());
        return 0;
      }
      if (*library) {
        const auto path = shipped_file("patterns.spec");
        if (path.empty())
          throw InputError("sfcv patterns: the shipped share/sfcv/patterns.spec was not found");
        std::cout << path << "\n";
        return 0;
      }
      std::cout << report::pattern_list_text(logic::pattern_catalogue());
      return 0;
    };
  });
}

}  // namespace sfcv::cli
