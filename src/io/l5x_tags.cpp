#include "io/l5x_tags.hpp"

#include <algorithm>
#include <cctype>

#include "io/plcopen_xml_dom.hpp"
#include "model/names.hpp"
#include "model/types.hpp"

namespace sfcv::io::l5x {

namespace {

using plcopen::child;
using plcopen::children;
using plcopen::trim;

// One step of an operand below its tag: `.name`, `.2` (a bit) or `[i,j]`.
struct Segment {
  bool index = false;
  std::string name;
  std::vector<int> indices;
};

bool all_digits(const std::string& s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
}

std::optional<std::vector<Segment>> segments(const std::string& operand, std::size_t at,
                                             std::string& error) {
  std::vector<Segment> out;
  while (at < operand.size()) {
    Segment s;
    if (operand[at] == '.') {
      const auto start = ++at;
      while (at < operand.size() &&
             (std::isalnum(static_cast<unsigned char>(operand[at])) || operand[at] == '_'))
        ++at;
      s.name = operand.substr(start, at - start);
      if (s.name.empty()) break;
    } else if (operand[at] == '[') {
      const auto close = operand.find(']', at);
      if (close == std::string::npos) break;
      s.index = true;
      std::string list = operand.substr(at + 1, close - at - 1);
      for (std::size_t from = 0;;) {
        const auto comma = list.find(',', from);
        const std::string one = trim(list.substr(from, comma - from));
        if (!all_digits(one) || one.size() > 6) {
          error = "unsupported: operand '" + operand + "' (an element chosen by '" + one +
                  "' is read where it is a BOOL or an integer and the operand's only such index)";
          return std::nullopt;
        }
        s.indices.push_back(std::stoi(one));
        if (comma == std::string::npos) break;
        from = comma + 1;
      }
      at = close + 1;
    } else {
      break;
    }
    out.push_back(std::move(s));
  }
  if (at != operand.size()) {
    error = "operand '" + operand + "' not read at offset " + std::to_string(at);
    return std::nullopt;
  }
  return out;
}

// The decorated data's child of `structure` holding `member` (DataValueMember, StructureMember
// or ArrayMember).
pugi::xml_node member_value(pugi::xml_node structure, const std::string& member) {
  for (auto m : structure.children())
    if (model::iequals(trim(m.attribute("Name").value()), member)) return m;
  return {};
}

// The element of an Array/ArrayMember at `index` (`[2]`, `[1,0]`): its structure if it has one.
pugi::xml_node element_value(pugi::xml_node array, const std::string& index) {
  for (auto e : children(array, "Element")) {
    std::string written = e.attribute("Index").value();
    written.erase(
        std::remove_if(written.begin(), written.end(),
                       [](char c) { return std::isspace(static_cast<unsigned char>(c)); }),
        written.end());
    if (written != index) continue;
    if (auto s = child(e, "Structure")) return s;
    return e;
  }
  return {};
}

std::string variable_name(const std::string& path) {
  std::string out;
  for (char c : path) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    if (keep)
      out += c;
    else if (!out.empty() && out.back() != '_')
      out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

}  // namespace

TagTypes::TagTypes(pugi::xml_node data_types) {
  for (auto t : children(data_types, "DataType"))
    types_[model::to_upper(trim(t.attribute("Name").value()))] = t;
}

bool TagTypes::is_user_type(const std::string& name) const {
  return types_.count(model::to_upper(name)) > 0;
}

std::optional<std::vector<int>> tag_dimensions(const std::string& text) {
  std::vector<int> dims;
  std::string word;
  const std::string all = text + " ";
  for (char c : all) {
    if (!std::isspace(static_cast<unsigned char>(c)) && c != ',') {
      word += c;
      continue;
    }
    if (word.empty()) continue;
    if (!all_digits(word) || word.size() > 6) return std::nullopt;
    if (const int d = std::stoi(word); d > 0) dims.push_back(d);
    word.clear();
  }
  return dims;
}

std::optional<TagTypes::Indexed> TagTypes::indexed(const StructuredTag& tag,
                                                   const std::string& operand,
                                                   std::string& error) const {
  // The first index (at bracket depth 0) that is not a list of constants.
  std::size_t open = std::string::npos, close = std::string::npos;
  int depth = 0;
  for (std::size_t at = 0; at < operand.size(); ++at) {
    if (operand[at] == '[' && depth++ == 0) open = at;
    if (operand[at] == ']' && --depth == 0) {
      const auto inside = operand.substr(open + 1, at - open - 1);
      if (inside.find_first_not_of("0123456789, \t") != std::string::npos) {
        close = at;
        break;
      }
    }
  }
  if (close == std::string::npos) return std::nullopt;
  Indexed out;
  out.index = trim(operand.substr(open + 1, close - open - 1));
  if (out.index.find(',') != std::string::npos) {
    error = "unsupported: operand '" + operand + "' (an index list with a tag in it: '" +
            out.index + "')";
    return std::nullopt;
  }
  const auto prefix = operand.substr(0, open), suffix = operand.substr(close + 1);
  // One such index per operand: two would multiply the elements read.
  for (auto at = suffix.find('['); at != std::string::npos; at = suffix.find('[', at + 1)) {
    const auto end = suffix.find(']', at);
    if (end == std::string::npos ||
        suffix.substr(at + 1, end - at - 1).find_first_not_of("0123456789, \t") !=
            std::string::npos) {
      error = "unsupported: operand '" + operand + "' (an element chosen by '" + out.index +
              "' is read where it is a BOOL or an integer and the operand's only such index)";
      return std::nullopt;
    }
  }
  std::vector<int> dims;
  std::string whole_error;
  resolve(tag, prefix, whole_error, &dims);
  if (dims.size() != 1) {
    error = dims.empty()
                ? "operand '" + operand + "': '" + prefix + "' is not an array" +
                      (whole_error.empty() ? "" : " (" + whole_error + ")")
                : "unsupported: operand '" + operand + "' (a tag chooses an element of '" + prefix +
                      "', which has " + std::to_string(dims.size()) + " dimensions)";
    return std::nullopt;
  }
  if (dims[0] > kMaxIndexedElements) {
    error = "unsupported: operand '" + operand + "' (a tag chooses among the " +
            std::to_string(dims[0]) + " elements of '" + prefix + "'; at most " +
            std::to_string(kMaxIndexedElements) + " are read)";
    return std::nullopt;
  }
  for (int k = 0; k < dims[0]; ++k) {
    out.elements.push_back(prefix + "[" + std::to_string(k) + "]" + suffix);
    if (!resolve(tag, out.elements.back(), error)) return std::nullopt;
  }
  return out;
}

std::optional<TagLeaf> TagTypes::resolve(const StructuredTag& tag, const std::string& operand,
                                         std::string& error, std::vector<int>* whole_array) const {
  std::size_t head = 0;
  while (head < operand.size() && operand[head] != '.' && operand[head] != '[') ++head;
  const auto segs = segments(operand, head, error);
  if (!segs) return std::nullopt;
  TagLeaf leaf;
  leaf.tag = &tag;
  leaf.path = tag.name;
  std::string type = tag.data_type;
  std::vector<int> dims = tag.dimensions;
  for (auto d : children(tag.node, "Data"))
    if (std::string_view(d.attribute("Format").value()) == "Decorated")
      leaf.value = d.first_child();
  std::size_t i = 0;
  for (;;) {
    if (!dims.empty()) {
      if (i == segs->size() && whole_array) {
        *whole_array = dims;
        return std::nullopt;
      }
      if (i == segs->size() || !(*segs)[i].index) {
        error = "unsupported: operand '" + operand + "' (a whole array, '" + leaf.path +
                "', is not read: its elements are)";
        return std::nullopt;
      }
      const auto& idx = (*segs)[i].indices;
      if (idx.size() != dims.size()) {
        error = "operand '" + operand + "': '" + leaf.path + "' has " +
                std::to_string(dims.size()) + " dimension(s), not " + std::to_string(idx.size());
        return std::nullopt;
      }
      std::string written = "[";
      for (std::size_t k = 0; k < idx.size(); ++k) {
        if (idx[k] >= dims[k]) {
          error = "operand '" + operand + "': index " + std::to_string(idx[k]) +
                  " is out of the bounds of '" + leaf.path + "' (0.." +
                  std::to_string(dims[k] - 1) + ")";
          return std::nullopt;
        }
        written += (k ? "," : "") + std::to_string(idx[k]);
      }
      written += "]";
      leaf.path += written;
      leaf.value = element_value(leaf.value, written);
      dims.clear();
      ++i;
      continue;
    }
    const auto user = types_.find(model::to_upper(type));
    if (user == types_.end()) break;
    if (i == segs->size() || (*segs)[i].index || all_digits((*segs)[i].name)) {
      error = "unsupported: operand '" + operand + "' (a whole structure, '" + leaf.path +
              "' of type " + type + ", is not read: its members are)";
      return std::nullopt;
    }
    pugi::xml_node member;
    for (auto m : children(child(user->second, "Members"), "Member"))
      if (model::iequals(trim(m.attribute("Name").value()), (*segs)[i].name)) member = m;
    if (!member) {
      error = "operand '" + operand + "': '" + leaf.path + "' (of type " + type +
              ") has no member '" + (*segs)[i].name + "'";
      return std::nullopt;
    }
    const std::string name = trim(member.attribute("Name").value());
    leaf.path += "." + name;
    leaf.value = member_value(leaf.value, name);
    // A BOOL member is a BIT of a hidden SINT the type packs its BOOLs into.
    type = trim(member.attribute("DataType").value());
    if (model::iequals(type, "BIT")) type = "BOOL";
    const auto d = tag_dimensions(member.attribute("Dimension").value());
    if (!d) {
      error = "member '" + name + "' of type " + user->first + ": dimension not read";
      return std::nullopt;
    }
    dims = *d;
    ++i;
  }
  if (segs->size() > i + 1 || (i < segs->size() && (*segs)[i].index)) {
    error = "unsupported: operand '" + operand + "' (below '" + leaf.path + "' of type " + type +
            " only a bit or a TIMER or COUNTER member is read)";
    return std::nullopt;
  }
  if (i < segs->size()) leaf.rest = (*segs)[i].name;
  leaf.type_name = type;
  leaf.variable = variable_name(leaf.path);
  const auto et = model::elementary_type(type);
  if (model::iequals(type, "TIMER"))
    leaf.kind = LeafKind::Timer;
  else if (model::iequals(type, "COUNTER"))
    leaf.kind = LeafKind::Counter;
  else if (et && et->kind == model::TypeKind::Bool)
    leaf.kind = LeafKind::Bool;
  else if (et && et->kind == model::TypeKind::Int && et->enumerators.empty())
    leaf.kind = LeafKind::Int;
  return leaf;
}

std::optional<std::int64_t> leaf_initial(const TagLeaf& leaf) {
  if (!leaf.value || leaf.value.attribute("Value").empty()) return 0;
  return plcopen::parse_int_literal(trim(leaf.value.attribute("Value").value())).value;
}

std::int64_t leaf_member(const TagLeaf& leaf, const char* member) {
  const auto pre = member_value(leaf.value, member);
  if (!pre) return 0;
  const auto v = plcopen::parse_int_literal(trim(pre.attribute("Value").value()));
  return v.value ? *v.value : 0;
}

}  // namespace sfcv::io::l5x
