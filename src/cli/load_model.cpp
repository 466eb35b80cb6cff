#include "cli/load_model.hpp"

#include <iostream>

#include "cli/commands.hpp"
#include "cli/diagnostic_lines.hpp"
#include "cli/exit_code.hpp"
#include "cli/file_kind.hpp"
#include "model/validate.hpp"

namespace sfcv::cli {

CheckedModel load_and_validate(const std::string& path, io::Format format,
                               const model::Budget* budget) {
  refuse_foreign_file(path);  // a report or a trace is no model: say so, not 50 lexer errors
  auto loaded = io::load_file(path, format, budget);
  CheckedModel result{std::move(loaded.project), std::move(loaded.diagnostics)};
  // Validating a half-built model would only repeat the importer's errors in other words.
  if (result.project && !model::has_errors(result.diagnostics)) {
    auto more = model::validate(*result.project, budget);
    result.diagnostics.insert(result.diagnostics.end(), std::make_move_iterator(more.begin()),
                              std::make_move_iterator(more.end()));
  }
  return result;
}

model::Project load_model_or_throw(const std::string& path, io::Format format, bool quiet,
                                   const model::Budget* budget) {
  auto result = load_and_validate(path, format, budget);
  std::size_t errors = 0;
  for (const auto& d : result.diagnostics) errors += d.severity == model::Severity::Error;
  print_diagnostic_lines(result.diagnostics, quiet || global_options().quiet, std::cerr);
  if (!result.project)
    throw InputError(path + ": " + std::to_string(errors ? errors : 1) +
                     (errors > 1 ? " errors" : " error") + ", no model loaded");
  if (errors)
    throw InputError(path + ": " + std::to_string(errors) + (errors == 1 ? " error" : " errors") +
                     " in the model (see 'sfcv lint')");
  return std::move(*result.project);
}

io::Format parse_format(const std::string& name) {
  if (name == "auto") return io::Format::Auto;
  if (name == "xml" || name == "plcopen") return io::Format::PlcopenXml;
  if (name == "iec" || name == "st" || name == "sfc") return io::Format::IecText;
  if (name == "g7") return io::Format::G7;
  if (name == "agrafe" || name == "grafcet") return io::Format::AgrafeXmi;
  if (name == "twincat") return io::Format::TwinCat;
  if (name == "l5x" || name == "rockwell") return io::Format::L5x;
  if (name == "codesys") return io::Format::CodesysExport;
  if (name == "simatic" || name == "siemens") return io::Format::SimaticGraph;
  throw InputError("unknown format '" + name +
                   "' (expected auto, xml, iec, g7, agrafe, twincat, l5x, codesys or simatic)");
}

}  // namespace sfcv::cli
