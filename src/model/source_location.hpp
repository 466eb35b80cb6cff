#pragma once
// Where a model element came from: file:line:col for text formats, an element path for XML.

#include <string>

namespace sfcv::model {

struct SourceLocation {
  std::string file;
  int line = 0;    ///< 1-based; 0 when unknown (XML elements use element_path instead)
  int column = 0;  ///< 1-based; 0 when unknown
  std::string
      element_path;  ///< e.g. "/project/types/pous/pou[@name='P']/body/SFC/step[@localId='3']"

  bool known() const { return !file.empty() || !element_path.empty(); }
  /// "file:line:col", "file:line", "file (element path)" or "<unknown>".
  std::string str() const;
};

}  // namespace sfcv::model
