#pragma once
// Diagnostics returned (never printed) by importers and validators, like spot::parsed_formula.

#include <string>
#include <vector>

#include "model/source_location.hpp"

namespace sfcv::model {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLocation where;
  std::string message;

  /// "file:line:col: error: message"
  std::string str() const;
};

using Diagnostics = std::vector<Diagnostic>;

bool has_errors(const Diagnostics& diagnostics);

}  // namespace sfcv::model
