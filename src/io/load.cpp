#include "io/load.hpp"

#include <cctype>
#include <filesystem>

#include "model/input_file.hpp"

namespace sfcv::io {

namespace {
bool ends_with(const std::string& s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    const char a = static_cast<char>(
        std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])));
    if (a != suffix[i]) return false;
  }
  return true;
}
}  // namespace

Format detect_format(const std::string& path, std::string_view text) {
  if (ends_with(path, ".tcpou") || ends_with(path, ".tcgvl") || ends_with(path, ".tcdut"))
    return Format::TwinCat;
  if (ends_with(path, ".plcproj")) return Format::TwinCatProject;
  // A bare <SFCContent> is one Studio 5000 SFC routine's content: the L5X reader says what it
  // lacks rather than the PLCopen reader calling it a PLCopen file with a wrong root.
  if (ends_with(path, ".l5x") ||
      text.substr(0, 4096).find("<RSLogix5000Content") != std::string_view::npos ||
      text.substr(0, 512).find("<SFCContent") != std::string_view::npos)
    return Format::L5x;
  if (text.find("<TcPlcObject") != std::string_view::npos) return Format::TwinCat;
  if (ends_with(path, ".export") ||
      text.substr(0, 4096).find("<ExportFile") != std::string_view::npos)
    return Format::CodesysExport;
  if (const auto head = text.substr(0, 4096); head.find("<SW.Blocks.") != std::string_view::npos ||
                                              (head.find("<Document") != std::string_view::npos &&
                                               head.find("<Engineering") != std::string_view::npos))
    return Format::SimaticGraph;
  if (ends_with(path, ".g7")) return Format::G7;
  if (ends_with(path, ".grafcet")) return Format::AgrafeXmi;
  if (ends_with(path, ".st") || ends_with(path, ".sfc") || ends_with(path, ".txt") ||
      ends_with(path, ".st.tmpl"))
    return Format::IecText;
  if (ends_with(path, ".xml")) {
    if (text.find("grafcet:Grafcet") != std::string_view::npos) return Format::AgrafeXmi;
    return Format::PlcopenXml;
  }
  // Sniff the content.
  const auto first = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  if (first != std::string_view::npos && text[first] == '<')
    return text.find("grafcet:Grafcet") != std::string_view::npos ? Format::AgrafeXmi
                                                                  : Format::PlcopenXml;
  return Format::IecText;
}

LoadResult load_file(const std::string& path, Format format, const model::Budget* budget) {
  std::error_code ec;
  // A folder is a TwinCAT project only when asked (--format twincat): a folder given by
  // mistake stays an error rather than a scan of everything under it.
  if (format == Format::TwinCatProject || (format == Format::Auto && ends_with(path, ".plcproj")) ||
      (format == Format::TwinCat && std::filesystem::is_directory(path, ec)))
    return load_twincat_project(path, budget);
  std::string text;
  if (auto reason = model::try_read_input_file(path, "the model", text)) {
    LoadResult r;
    model::SourceLocation where;
    where.file = path;
    r.diagnostics.push_back({model::Severity::Error, where, *reason});
    return r;
  }
  if (format == Format::Auto) format = detect_format(path, text);
  switch (format) {
    case Format::PlcopenXml:
      return load_plcopen_xml(text, path, budget);
    case Format::IecText:
      return load_iec_text(text, path, budget);
    case Format::G7:
      return load_g7(text, path, budget);
    case Format::AgrafeXmi:
      return load_agrafe_xmi(text, path, budget);
    case Format::TwinCat:
      return load_twincat(text, path, budget);
    case Format::TwinCatProject:
      return load_twincat_project(path, budget);
    case Format::L5x:
      return load_l5x(text, path, budget);
    case Format::CodesysExport:
      return load_codesys_export(text, path, budget);
    case Format::SimaticGraph:
      return load_simatic_graph(text, path, budget);
    case Format::Auto:
      break;
  }
  return {};
}

}  // namespace sfcv::io
