#include "cli/json_input.hpp"

#include "model/errors.hpp"
#include "model/input_file.hpp"

namespace sfcv::cli {

nlohmann::json read_json_file(const std::string& path, const std::string& what,
                              const std::string& not_json) {
  const std::string text = model::read_input_file(path, what);
  const auto bounded = [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    if (static_cast<std::size_t>(depth) > kMaxJsonDepth)
      throw InputError("nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
    return true;
  };
  try {
    return nlohmann::json::parse(text, bounded);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": " + not_json + ": " + e.what());
  } catch (const InputError& e) {
    throw InputError(path + ": " + not_json + ": " + e.what());
  }
}

}  // namespace sfcv::cli
