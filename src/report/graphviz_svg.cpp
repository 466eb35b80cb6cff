#include "report/graphviz_svg.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/external/external_tool.hpp"
#include "report/text_encoding.hpp"

namespace sfcv::report {

SvgResult dot_to_svg(const std::string& dot, double timeout_seconds) {
  SvgResult r;
  const auto tool = engine::find_on_path({"dot"});
  if (!tool) {
    r.error = "graphviz's 'dot' is not installed (apt-get install graphviz): no chart picture";
    return r;
  }
  engine::TempDir dir;
  const auto in = std::filesystem::path(dir.path()) / "chart.dot";
  const auto out = std::filesystem::path(dir.path()) / "chart.svg";
  std::ofstream(in) << valid_utf8(dot);  // graphviz reads UTF-8; names are bytes
  const auto run = engine::run_tool({*tool, "-Tsvg", "-o", out.string(), in.string()}, dir.path(),
                                    timeout_seconds);
  if (run.timed_out) {
    r.error = "graphviz 'dot' did not lay the chart out within " +
              std::to_string(static_cast<int>(timeout_seconds)) + " s";
    return r;
  }
  std::ifstream f(out);
  std::stringstream ss;
  ss << f.rdbuf();
  const auto text = ss.str();
  const auto start = text.find("<svg");
  if (run.exit_code != 0 || start == std::string::npos) {
    r.error = "graphviz 'dot' failed: " + run.output.substr(0, 500);
    return r;
  }
  r.svg = text.substr(start);
  return r;
}

}  // namespace sfcv::report
