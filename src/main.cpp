// sfcv: one top-level catch that turns error kinds (model/errors.hpp) into exit codes, the only
// place that does (like storm-cli.cpp).

#include <exception>
#include <iostream>
#include <new>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "model/errors.hpp"

namespace {

int internal_error(const char* what) {
  std::cerr << "sfcv: internal error: " << what
            << "\nThis is a bug in sfcv: please report it with the command line and the input "
               "files.\n";
  return sfcv::cli::kInternalError;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return sfcv::cli::run(argc, argv);
  } catch (const sfcv::InputError& e) {  // and UnsupportedConstruct
    std::cerr << "sfcv: error: " << e.what() << "\n";
    return sfcv::cli::kBadInput;
  } catch (const sfcv::UsageError& e) {
    std::cerr << "sfcv: error: " << e.what() << "\n";
    return sfcv::cli::kBadInput;
  } catch (const sfcv::LimitReached& e) {
    std::cerr << "sfcv: " << e.what() << "; verdict unknown\n";
    return sfcv::cli::kUnknown;
  } catch (const std::bad_alloc&) {
    std::cerr << "sfcv: out of memory; verdict unknown\n";
    return sfcv::cli::kUnknown;
  } catch (const std::exception& e) {  // InternalError, std::logic_error, anything unexpected
    return internal_error(e.what());
  } catch (...) {
    return internal_error("an exception of unknown type");
  }
}
