#pragma once
// Identifiers for outside languages (NuSMV, Promela): chart names like "MAIN.S1" or "T#2s" are
// mapped to legal, unique identifiers, and the mapping is kept for comments and trace read-back.

#include <string>
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

}  // namespace sfcv::engine
