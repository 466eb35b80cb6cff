#pragma once
// Loading a chart from a file. Importers return the project plus located diagnostics and print
// nothing (like spot::parsed_formula).

#include <optional>
#include <string>
#include <string_view>

#include "model/budget.hpp"
#include "model/chart.hpp"
#include "model/diagnostic.hpp"

namespace sfcv::io {

enum class Format {
  Auto,
  PlcopenXml,
  IecText,
  G7,
  AgrafeXmi,
  TwinCat,
  TwinCatProject,
  L5x,
  CodesysExport,
  SimaticGraph,
};

struct LoadResult {
  std::optional<model::Project> project;  ///< empty when an error prevented building a model
  model::Diagnostics diagnostics;

  bool ok() const { return project.has_value() && !model::has_errors(diagnostics); }
};

/// The format a file is in, from its extension (.xml, .st/.sfc/.txt, .g7, .grafcet, .TcPOU/
/// .TcGVL/.TcDUT, .plcproj) and, for XML, its root element.
Format detect_format(const std::string& path, std::string_view text);

/// Reads and parses `path`. A missing or unreadable file is an error diagnostic, not an
/// exception. Past `budget`'s deadline (when given), every loader throws LimitReached(Time):
/// the run's --timeout holds while a huge file is read, too.
LoadResult load_file(const std::string& path, Format format = Format::Auto,
                     const model::Budget* budget = nullptr);

LoadResult load_plcopen_xml(std::string_view text, const std::string& file,
                            const model::Budget* budget = nullptr);
LoadResult load_iec_text(std::string_view text, const std::string& file,
                         const model::Budget* budget = nullptr);
LoadResult load_g7(std::string_view text, const std::string& file,
                   const model::Budget* budget = nullptr);
LoadResult load_agrafe_xmi(std::string_view text, const std::string& file,
                           const model::Budget* budget = nullptr);
/// One TwinCAT 3 object file (.TcPOU, .TcGVL, .TcDUT); docs/formats.md.
LoadResult load_twincat(std::string_view text, const std::string& file,
                        const model::Budget* budget = nullptr);
/// A TwinCAT 3 PLC project: a .plcproj (the object files it compiles) or a folder (every
/// .TcPOU/.TcGVL/.TcDUT under it), read into one project. load_file reads a folder so only
/// with Format::TwinCat.
LoadResult load_twincat_project(const std::string& path, const model::Budget* budget = nullptr);

/// A Rockwell Studio 5000 export (.L5X): its programs with an SFC main routine; docs/formats.md.
LoadResult load_l5x(std::string_view text, const std::string& file,
                    const model::Budget* budget = nullptr);

/// A CODESYS native export (.export, `<ExportFile>`): its POUs, actions, transitions, global
/// lists and data types; docs/formats.md.
LoadResult load_codesys_export(std::string_view text, const std::string& file,
                               const model::Budget* budget = nullptr);

/// A Siemens TIA Portal SimaticML export (<Document> with <SW.Blocks.FB>): its S7-GRAPH function
/// blocks; docs/formats.md.
LoadResult load_simatic_graph(std::string_view text, const std::string& file,
                              const model::Budget* budget = nullptr);

}  // namespace sfcv::io
