// sfcv: one top-level catch that turns error types into exit codes (like storm-cli.cpp).

#include <exception>
#include <iostream>
#include <new>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"

int main(int argc, char** argv) {
  try {
    return sfcv::cli::run(argc, argv);
  } catch (const sfcv::cli::InputError& e) {
    std::cerr << "sfcv: error: " << e.what() << "\n";
    return sfcv::cli::kBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "sfcv: out of memory; verdict unknown\n";
    return sfcv::cli::kUnknown;
  } catch (const std::exception& e) {
    std::cerr << "sfcv: internal error: " << e.what() << "\n";
    return sfcv::cli::kBadInput;
  }
}
