#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// The SFC object model CODESYS archives (SFCImplementationObject -> Root SFCSegment ->
// ElementList of SFCStep, SFCTransition, SFCJump and SFCBranch in document order; a branch holds
// legs, each an SFCSegment), shared by the TwinCAT 3 reader (`<XmlArchive>` in a `.TcPOU`) and
// the CODESYS native export reader (`.export`). The two files serialise the same objects in two
// XML spellings (Encoding). Element attributes are records keyed by GUIDs that the archive
// describes in its own table (GUID -> Identifier): they are read through it, never hard-coded.

#include <functional>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "io/plcopen_pou.hpp"
#include "model/chart.hpp"

namespace sfcv::io::sfc_archive {

/// A GUID as a lookup key: lower case, without braces or spaces (archives write both forms).
std::string guid_key(std::string_view s);

/// How an archive writes its objects.
enum class Encoding {
  /// TwinCAT `<XmlArchive>`: `<o n="member" t="Type">`, `<v n="member">"text"</v>`,
  /// `<l2 n="list" cet="ElementType">`, `<d2 n="dictionary">` of alternating key/value.
  Compact,
  /// CODESYS `.export`: `<Single Name="member" Type="{class GUID}">` (objects and values),
  /// `<List2 Name="list">`, `<Dictionary2 Name="dictionary">` of `<Entry><Key/><Value/>`;
  /// `<Null Name="member"/>` for an absent object. Types are class GUIDs only.
  Verbose,
};

/// Reading one archive's objects in either encoding.
class Format {
 public:
  explicit Format(Encoding e) : encoding_(e) {}
  Encoding encoding() const { return encoding_; }

  /// The member object `<o n=name>` / `<Single Name=name>` (absent when null).
  pugi::xml_node object(pugi::xml_node obj, std::string_view name) const;
  /// The member value's node and text (compact strings are written quoted: unquoted here).
  pugi::xml_node value_node(pugi::xml_node obj, std::string_view name) const;
  std::string value(pugi::xml_node obj, std::string_view name) const;
  std::string text(pugi::xml_node value) const;
  pugi::xml_node list(pugi::xml_node obj, std::string_view name) const;
  pugi::xml_node dictionary(pugi::xml_node obj, std::string_view name) const;
  /// Entries of a dictionary as (key node, value object) pairs.
  std::vector<std::pair<pugi::xml_node, pugi::xml_node>> entries(pugi::xml_node dict) const;
  /// `ElementList/InnerList`: the elements of a segment, branch or step, in order.
  std::vector<pugi::xml_node> inner_list(pugi::xml_node obj) const;
  /// The object's type name (SFCStep, ...): compact files name it; a verbose one gives the
  /// class GUID, named here for the SFC classes (the same GUIDs a TwinCAT `<TypeList>` names),
  /// else "{guid}".
  std::string type(pugi::xml_node obj) const;
  /// The archive object id (`Id` member).
  std::string id(pugi::xml_node obj) const;

 private:
  pugi::xml_node member(pugi::xml_node obj, std::string_view compact_tag,
                        std::string_view name) const;
  Encoding encoding_;
};

/// What differs between the readers sharing the walk.
struct Options {
  /// The condition of a transition object of the POU named `name` (TwinCAT `<Transition>`,
  /// CODESYS transition child objects): nullopt when the POU has none of that name; a null
  /// expression when it has one that could not be read (the reader reported why).
  std::function<std::optional<model::ExprPtr>(const std::string& name)> named_condition;
  /// Read IEC action associations written inside a step's own element list (CODESYS); when
  /// false they are refused (TwinCAT).
  bool step_associations = false;
};

/// The condition of a transition object whose ST body is `body`: `expr`, `NAME := expr;` or
/// `:= expr;`. Errors (an empty condition at `where`, parse errors) go to `ctx`; null then.
model::ExprPtr transition_body_condition(plcopen::BodyText body, const std::string& name,
                                         plcopen::XmlContext& ctx, pugi::xml_node where);

/// Reads the SFC implementation object `impl` into `chart` (steps, transitions) and `pc.pou`'s
/// associations; errors go to `pc.ctx` with the element path and archive object id.
void read_chart(plcopen::PouContext& pc, const Format& format, pugi::xml_node impl,
                const Options& options, model::Chart& chart);

}  // namespace sfcv::io::sfc_archive
