#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// Helpers shared by the PLCopen TC6 XML importer: namespace-blind element access, element paths
// for diagnostics, text of ST elements, and IEC literals in attributes (durations, initial
// values). Internal to src/io.

#include <cstdint>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "model/budget.hpp"
#include "model/chart.hpp"
#include "model/diagnostic.hpp"
#include "model/literal.hpp"
#include "model/source_location.hpp"

namespace sfcv::io::plcopen {

/// CODESYS keeps a step's main (active), entry and exit actions in addData attributes with
/// these GUIDs (read by plcopen_sfc_graph.cpp, written by plcopen_writer.cpp).
inline constexpr const char* kCodesysActiveGuid = "700a583f-b4d4-43e4-8c14-629c7cd3bec8";
inline constexpr const char* kCodesysEntryGuid = "a6b08bd8-b696-47e3-9cbf-7408b61c9ff8";
inline constexpr const char* kCodesysExitGuid = "a2621e18-7de3-4ea6-ae6d-89e9e0b7befd";
/// sfcv's project-level addData naming the vendor whose dialect an exported model is in.
inline constexpr const char* kDialectData = "urn:sfcv:dialect";

/// The element's name without its namespace prefix ("xhtml:p" -> "p").
std::string_view local_name(pugi::xml_node node);

/// The first child element with local name `name` (any prefix), or an empty node.
pugi::xml_node child(pugi::xml_node node, std::string_view name);

/// All child elements with local name `name`, in document order.
std::vector<pugi::xml_node> children(pugi::xml_node node, std::string_view name);

/// All child elements, in document order.
std::vector<pugi::xml_node> element_children(pugi::xml_node node);

/// Where diagnostics go, and how XML nodes map to file:line:col.
class XmlContext {
 public:
  XmlContext(std::string file, std::string_view text, model::Diagnostics& diagnostics,
             const model::Budget* budget = nullptr);

  const std::string& file() const { return file_; }
  model::SourceLocation where(pugi::xml_node node) const;
  model::SourceLocation where_offset(std::ptrdiff_t offset) const;
  /// "/project/types/pous/pou[@name='P']/body/SFC/step[@localId='3']".
  std::string element_path(pugi::xml_node node) const;

  void error(pugi::xml_node node, std::string message);
  void warning(pugi::xml_node node, std::string message);
  void note(pugi::xml_node node, std::string message);
  void add(model::Diagnostic d) { diagnostics_.push_back(std::move(d)); }
  model::Diagnostics& diagnostics() { return diagnostics_; }
  /// Called once per element read: past the run's deadline, throws LimitReached(Time).
  void poll() const { poll_.tick_or_throw("reading the model"); }

  /// Upper-case names of the project's FUNCTION POUs: a block of such a type in an FBD/LD
  /// network is a call of that function.
  std::set<std::string> user_functions;
  /// Upper-case names of the project's FUNCTION_BLOCK POUs: a block of such a type with an
  /// instance name is a call of that instance.
  std::set<std::string> user_function_blocks;
  /// Upper-case names of the user FUNCTIONs and FUNCTION_BLOCKs whose POU element names ENO
  /// anywhere (declaration or body): only those may clear their ENO; for the others ENO is EN.
  std::set<std::string> pous_naming_eno;
  /// Variables dropped for a type sfcv does not model (REAL, LREAL...): upper-case POU name ->
  /// upper-case variable name -> the type as written. A write nothing modelled reads is left
  /// out (leave_out_unmodelled_writes); any other use stays an error, which names the type.
  std::map<std::string, std::map<std::string, std::string>> unmodelled_variables;
  /// Upper-case names of the user FUNCTIONs whose body only computes their result (pure_functions):
  /// a call of one may be left out with the write it feeds.
  std::set<std::string> pure_functions;
  /// The file's global variable lists (read before the POUs, each a POU of VAR_GLOBALs): a POU
  /// body is validated with them, since vendor bodies (AGRAFE's generated ST) assign them.
  std::vector<model::Pou> global_lists;

 private:
  std::string file_;
  std::vector<std::size_t> line_starts_;
  model::Diagnostics& diagnostics_;
  mutable model::BudgetPoll poll_;  ///< reading the clock does not change what was read

  /// The children of one element: each one's position among its same-named siblings, how many
  /// share its name, and how many share its name and localId (keyed "name\nlocalId").
  struct SiblingPositions {
    std::unordered_map<const void*, int> index;
    std::unordered_map<std::string, int> count, same_id;
  };
  const SiblingPositions& sibling_positions(pugi::xml_node parent) const;
  /// Filled as paths are asked for: a path per element of an SFC body with thousands of
  /// siblings would otherwise count them again each time.
  mutable std::unordered_map<const void*, SiblingPositions> siblings_;
};

/// Parses `text` into `doc`; a broken document is an error located at its offset (false).
bool load_document(pugi::xml_document& doc, std::string_view text, XmlContext& ctx);

/// Text of a textual body element (`ST`, `IL`, `inline/ST`): raw text, CDATA, `xhtml:p` or an
/// `xhtml` element; `start` is set to where the text begins.
struct BodyText {
  std::string text;
  model::SourceLocation start;
};
BodyText body_text(pugi::xml_node language_element, const XmlContext& ctx);
/// The text of `lines` (vendor files write one element per line of ST: L5X `<Line>`, CODESYS
/// `TextLines`), each ending a line, placed at their line and column in the file so that the
/// parser's diagnostics point into it; `start` is where the text begins.
BodyText lines_text(pugi::xml_node start, const std::vector<pugi::xml_node>& lines,
                    const XmlContext& ctx);

/// IEC literals, as written in attributes: `T#2s`, `TIME#1h2m`, `t#500ms`; `TRUE`, `FALSE`;
/// `42`, `-3`, `16#FF`, `INT#5`, `1_000`, through the one checked conversion (model/literal.hpp):
/// no value and the reason past the type's range. A text without a TIME prefix gives no value
/// and no reason (it may be a variable's name).
model::Converted<std::int64_t> parse_time_literal(std::string_view text);
model::Converted<std::int64_t> parse_int_literal(std::string_view text);
std::optional<bool> parse_bool_literal(std::string_view text);

std::string trim(std::string_view s);
bool attribute_true(pugi::xml_node node, const char* name);

}  // namespace sfcv::io::plcopen
