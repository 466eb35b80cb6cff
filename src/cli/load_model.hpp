#pragma once
// Loading the model a subcommand works on: diagnostics go to standard error; errors end the run
// with exit code 2.

#include <string>

#include "io/load.hpp"
#include "model/chart.hpp"

namespace sfcv::cli {

/// Loads `path`; prints warnings to stderr; throws InputError when the file has errors.
model::Project load_model_or_throw(const std::string& path, io::Format format = io::Format::Auto);

/// Parses a --format value ("auto", "xml", "iec", "g7", "agrafe").
io::Format parse_format(const std::string& name);

}  // namespace sfcv::cli
