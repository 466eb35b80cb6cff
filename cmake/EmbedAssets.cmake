# cmake -DOUT=<file.cpp> -DJS=<report.js> -DCSS=<report.css> -P EmbedAssets.cmake
# Writes the HTML report's script and style sheet into a C++ source as raw string literals, so
# that `sfcv check --html` writes a self-contained page without reading files at run time.
file(READ "${JS}" js)
file(READ "${CSS}" css)
file(WRITE "${OUT}.tmp"
  "// Generated from share/sfcv/report.js and report.css by cmake/EmbedAssets.cmake: do not edit.\n"
  "#include \"report/report_assets.hpp\"\n\n"
  "namespace sfcv::report {\n\n"
  "std::string_view report_script() {\n  return R\"sfcv_asset(${js})sfcv_asset\";\n}\n\n"
  "std::string_view report_style() {\n  return R\"sfcv_asset(${css})sfcv_asset\";\n}\n\n"
  "}  // namespace sfcv::report\n")
file(COPY_FILE "${OUT}.tmp" "${OUT}" ONLY_IF_DIFFERENT)
