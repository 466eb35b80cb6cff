#include "engine/external/identifiers.hpp"

#include <cctype>
#include <cstdio>

namespace sfcv::engine {

IdentifierTable::IdentifierTable(std::unordered_set<std::string> reserved)
    : reserved_(std::move(reserved)) {}

const std::string& IdentifierTable::get(const std::string& prefix, const std::string& name) {
  const std::string key = prefix + '\0' + name;
  if (auto it = map_.find(key); it != map_.end()) return it->second;
  return map_.emplace(key, make_unique(prefix, name)).first->second;
}

std::string IdentifierTable::fresh(const std::string& prefix, const std::string& name) {
  return make_unique(prefix, name);
}

std::string IdentifierTable::make_unique(const std::string& prefix, const std::string& name) {
  // ASCII only: std::isalnum of the C locale, and bytes of UTF-8 sequences (>= 0x80) become '_'.
  // A long name keeps its first kMaxStem characters (the suffix keeps it unique): the name is
  // in the comment, and outside tools have buffers (Spin's lexer).
  constexpr std::size_t kMaxStem = 48;
  std::string id = prefix;
  for (char c : name.substr(0, kMaxStem)) {
    const auto u = static_cast<unsigned char>(c);
    id += u < 0x80 && (std::isalnum(u) || c == '_') ? c : '_';
  }
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0]))) id = "v_" + id;
  std::string unique = id;
  for (int k = 2; used_.count(unique) || reserved_.count(unique); ++k)
    unique = id + "_" + std::to_string(k);
  used_.insert(unique);
  return unique;
}

std::string comment_text(std::string_view text, CommentKind kind) {
  std::string r;
  r.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const auto u = static_cast<unsigned char>(c);
    if (c == '\\') {
      r += "\\\\";
    } else if (c == '\n') {
      r += "\\n";
    } else if (c == '\r') {
      r += "\\r";
    } else if (c == '\t') {
      r += "\\t";
    } else if (u < 0x20 || u == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      r += hex;
    } else if (kind == CommentKind::Block && c == '*' && i + 1 < text.size() &&
               text[i + 1] == '/') {
      r += "*\\/";
      ++i;
    } else {
      r += c;
    }
  }
  return r;
}

}  // namespace sfcv::engine
