#pragma once
// DOT to SVG through graphviz's `dot` program, run once as a child process (with a time limit,
// since layout can take long on large graphs).

#include <string>

namespace sfcv::report {

struct SvgResult {
  std::string svg;    ///< the <svg> element (XML prolog and DOCTYPE removed); empty on failure
  std::string error;  ///< why there is no picture ("graphviz 'dot' is not installed", ...)
};

SvgResult dot_to_svg(const std::string& dot, double timeout_seconds = 60);

}  // namespace sfcv::report
