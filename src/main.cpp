// sfcv: the command line, with error kinds (model/errors.hpp) turned into exit codes in one
// place (cli/exit_code.hpp), like storm-cli.cpp.

#include <iostream>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"

int main(int argc, char** argv) {
  return sfcv::cli::run_with_exit_codes([&] { return sfcv::cli::run(argc, argv); }, std::cerr);
}
