#include "io/load.hpp"

namespace sfcv::io {

// Placeholder until the importer lands: an honest error, never a wrong model.
LoadResult load_plcopen_xml(std::string_view, const std::string& file) {
  LoadResult r;
  model::SourceLocation where;
  where.file = file;
  r.diagnostics.push_back({model::Severity::Error, where, "the PLCopen XML importer is not built yet"});
  return r;
}

}  // namespace sfcv::io
