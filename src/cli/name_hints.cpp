#include "cli/name_hints.hpp"

#include <string>

#include "model/names.hpp"

namespace sfcv::cli {

namespace {

/// "a step" or "a variable" of `pou` named `name`, or empty.
std::string what_in(const model::Pou& pou, const std::string& name) {
  for (const auto& c : pou.charts)
    for (const auto& s : c.steps)
      if (model::iequals(s.name, name)) return "a step";
  for (const auto& v : pou.variables)
    if (model::iequals(v.name, name)) return "a variable";
  return {};
}

}  // namespace

void explain_left_out_names(model::Diagnostics& diagnostics, const model::Project& project) {
  const std::string marker = "unknown name '";
  for (auto& d : diagnostics) {
    const auto at = d.message.find(marker);
    if (at == std::string::npos || d.message.find("did you mean") != std::string::npos) continue;
    const auto from = at + marker.size();
    const auto to = d.message.find('\'', from);
    if (to == std::string::npos) continue;
    const std::string name = d.message.substr(from, to - from);
    const auto parts = model::split_path(name);
    for (const auto& pou : project.pous) {
      const auto what = what_in(pou, parts.back());
      if (what.empty()) continue;
      d.message += ": '" + parts.back() + "' is " + what + " of POU '" + pou.name +
                   "', which this run leaves out (add it with --pou, e.g. --pou " + pou.name +
                   ", or call an instance of it)";
      break;
    }
  }
}

}  // namespace sfcv::cli
