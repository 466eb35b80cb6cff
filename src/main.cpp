// sfcv: the command line, with error kinds (model/errors.hpp) turned into exit codes in one
// place (cli/exit_code.hpp), like storm-cli.cpp.

#include <iostream>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"

int main(int argc, char** argv) {
  // Under --json an error is also a JSON object on standard output.
  std::ostream* json_errors = sfcv::cli::wants_json(argc, argv) ? &std::cout : nullptr;
  return sfcv::cli::run_with_exit_codes([&] { return sfcv::cli::run(argc, argv); }, std::cerr,
                                        json_errors);
}
