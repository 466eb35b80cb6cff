#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// Loading the model a subcommand works on: the importer's diagnostics and those of
// model::validate go to standard error; errors end the run with exit code 2.

#include <optional>
#include <string>

#include "io/load.hpp"
#include "model/chart.hpp"
#include "model/diagnostic.hpp"

namespace sfcv::cli {

/// A loaded and validated model; prints nothing.
struct CheckedModel {
  std::optional<model::Project> project;  ///< empty when the importer could not build one
  model::Diagnostics diagnostics;         ///< the importer's, then validate's
};

/// Loads `path` and, when the importer built a model without errors, validates it; past
/// `budget`'s deadline (when given) throws LimitReached.
CheckedModel load_and_validate(const std::string& path, io::Format format = io::Format::Auto,
                               const model::Budget* budget = nullptr);

/// Loads and validates `path`; prints errors to stderr, and warnings unless `quiet`; throws
/// InputError when the file or the model has errors, LimitReached past `budget`'s deadline.
model::Project load_model_or_throw(const std::string& path, io::Format format = io::Format::Auto,
                                   bool quiet = false, const model::Budget* budget = nullptr);

/// The --format values parse_format() takes, for every subcommand's help.
inline constexpr const char* kFormatHelp =
    "Input format: auto, xml, iec, g7, agrafe, twincat, l5x, codesys, simatic";

/// Parses a --format value (kFormatHelp).
io::Format parse_format(const std::string& name);

}  // namespace sfcv::cli
