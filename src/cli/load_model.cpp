#include "cli/load_model.hpp"

#include <iostream>

#include "cli/exit_code.hpp"

namespace sfcv::cli {

model::Project load_model_or_throw(const std::string& path, io::Format format) {
  auto result = io::load_file(path, format);
  std::size_t errors = 0;
  for (const auto& d : result.diagnostics) {
    std::cerr << d.str() << "\n";
    if (d.severity == model::Severity::Error) ++errors;
  }
  if (errors || !result.project)
    throw InputError(path + ": " + std::to_string(errors ? errors : 1) +
                     (errors == 1 ? " error" : " errors") + ", no model loaded");
  return std::move(*result.project);
}

io::Format parse_format(const std::string& name) {
  if (name == "auto") return io::Format::Auto;
  if (name == "xml" || name == "plcopen") return io::Format::PlcopenXml;
  if (name == "iec" || name == "st" || name == "sfc") return io::Format::IecText;
  if (name == "g7") return io::Format::G7;
  if (name == "agrafe" || name == "grafcet") return io::Format::AgrafeXmi;
  throw InputError("unknown format '" + name + "' (expected auto, xml, iec, g7 or agrafe)");
}

}  // namespace sfcv::cli
