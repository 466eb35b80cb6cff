#pragma once
// The one naming policy of the exported models (NuSMV, Cadence SMV, Promela, AIGER): chart
// names like "MAIN.S1" or "T#2s" are mapped to legal, unique identifiers (a sanitised stem of
// letters, digits and '_' after a prefix of its kind, a _2, _3 suffix when stems meet, never a
// reserved word of the target), and the original name only ever appears in a comment or a
// symbol-table line, as comment_text() makes it: one line that cannot close its comment.
// docs/exports.md, "Names in exported models".

#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

namespace sfcv::engine {

class IdentifierTable {
 public:
  /// `reserved` words of the target language may never be produced.
  explicit IdentifierTable(std::unordered_set<std::string> reserved = {});

  /// A legal identifier for `name` with `prefix` (e.g. "in_"), unique in this table; asking
  /// twice for the same (prefix, name) gives the same identifier.
  const std::string& get(const std::string& prefix, const std::string& name);
  /// A new identifier for `name` every time (property names that must not clash).
  std::string fresh(const std::string& prefix, const std::string& name);

 private:
  std::unordered_set<std::string> reserved_;
  std::unordered_set<std::string> used_;
  std::string make_unique(const std::string& prefix, const std::string& name);

  std::unordered_map<std::string, std::string> map_;
};

/// How a comment of the target ends: at the end of the line (`--` of SMV, AIGER symbol and
/// comment lines) or at a closer (`/* */` of Promela, which also goes through the C
/// preprocessor).
enum class CommentKind { Line, Block };

/// `text` made safe inside a comment: one line (a backslash doubled; newline, carriage return,
/// tab and every other control byte as \n, \r, \t, \xNN) and, for block comments, no "*/"
/// (written "*\/"). The escaping is reversible, so distinct names stay distinct; valid UTF-8
/// is kept as it is.
std::string comment_text(std::string_view text, CommentKind kind = CommentKind::Line);

}  // namespace sfcv::engine
