#include "engine/external/identifiers.hpp"

#include <cctype>

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
  std::string id = prefix;
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    id += std::isalnum(u) || c == '_' ? c : '_';
  }
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0]))) id = "v_" + id;
  std::string unique = id;
  for (int k = 2; used_.count(unique) || reserved_.count(unique); ++k)
    unique = id + "_" + std::to_string(k);
  used_.insert(unique);
  return unique;
}

}  // namespace sfcv::engine
