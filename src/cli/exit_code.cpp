#include "cli/exit_code.hpp"

#include <cstring>
#include <exception>
#include <new>
#include <nlohmann/json.hpp>

#include "report/check_render.hpp"
#include "report/text_encoding.hpp"

namespace sfcv::cli {

namespace {

int internal_error(std::ostream& err, const char* what) {
  err << "sfcv: internal error: " << what
      << "\nThis is a bug in sfcv: please report it with the command line and the input "
         "files.\n";
  return kInternalError;
}

}  // namespace

void write_json_error(std::ostream& out, const char* kind, const std::string& message,
                      int exit_code) {
  nlohmann::json j;
  j["schema_version"] = report::kCheckJsonSchemaVersion;
  j["error"] = {{"kind", kind}, {"message", message}};
  j["exit_code"] = exit_code;
  report::make_valid_utf8(j);
  out << j.dump(2) << "\n";
}

bool wants_json(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--json") == 0) return true;
  return false;
}

int run_with_exit_codes(const std::function<int()>& command, std::ostream& err,
                        std::ostream* json_out) {
  auto json = [json_out](const char* kind, const std::string& message, int code) {
    if (json_out) write_json_error(*json_out, kind, message, code);
    return code;
  };
  try {
    return command();
  } catch (const UnsupportedConstruct& e) {
    err << "sfcv: error: " << e.what() << "\n";
    return json("unsupported", e.what(), kBadInput);
  } catch (const InputError& e) {
    err << "sfcv: error: " << e.what() << "\n";
    return json("input", e.what(), kBadInput);
  } catch (const UsageError& e) {
    err << "sfcv: error: " << e.what() << "\n";
    return json("usage", e.what(), kBadInput);
  } catch (const LimitReached& e) {
    err << "sfcv: " << e.what() << "; verdict unknown\n";
    return json("limit", std::string(e.what()) + "; verdict unknown", kUnknown);
  } catch (const std::bad_alloc&) {
    err << "sfcv: out of memory; verdict unknown\n";
    return json("out-of-memory", "out of memory; verdict unknown", kUnknown);
  } catch (const std::exception& e) {  // InternalError, std::logic_error, anything unexpected
    json("internal", e.what(), kInternalError);
    return internal_error(err, e.what());
  } catch (...) {
    json("internal", "an exception of unknown type", kInternalError);
    return internal_error(err, "an exception of unknown type");
  }
}

}  // namespace sfcv::cli
