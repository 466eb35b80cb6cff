#include "model/source_location.hpp"

#include "model/diagnostic.hpp"

namespace sfcv::model {

std::string SourceLocation::str() const {
  std::string s = file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (column > 0) s += ":" + std::to_string(column);
  }
  if (!element_path.empty()) s += (s.empty() ? "" : " ") + std::string("(") + element_path + ")";
  return s.empty() ? "<unknown>" : s;
}

std::string Diagnostic::str() const {
  const char* kind = severity == Severity::Error     ? "error"
                     : severity == Severity::Warning ? "warning"
                                                     : "note";
  return where.str() + ": " + kind + ": " + message;
}

bool has_errors(const Diagnostics& diagnostics) {
  for (const auto& d : diagnostics)
    if (d.severity == Severity::Error) return true;
  return false;
}

}  // namespace sfcv::model
