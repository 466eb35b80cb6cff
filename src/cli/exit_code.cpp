#include "cli/exit_code.hpp"

#include <exception>
#include <new>

namespace sfcv::cli {

namespace {

int internal_error(std::ostream& err, const char* what) {
  err << "sfcv: internal error: " << what
      << "\nThis is a bug in sfcv: please report it with the command line and the input "
         "files.\n";
  return kInternalError;
}

}  // namespace

int run_with_exit_codes(const std::function<int()>& command, std::ostream& err) {
  try {
    return command();
  } catch (const InputError& e) {  // and UnsupportedConstruct
    err << "sfcv: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const UsageError& e) {
    err << "sfcv: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const LimitReached& e) {
    err << "sfcv: " << e.what() << "; verdict unknown\n";
    return kUnknown;
  } catch (const std::bad_alloc&) {
    err << "sfcv: out of memory; verdict unknown\n";
    return kUnknown;
  } catch (const std::exception& e) {  // InternalError, std::logic_error, anything unexpected
    return internal_error(err, e.what());
  } catch (...) {
    return internal_error(err, "an exception of unknown type");
  }
}

}  // namespace sfcv::cli
