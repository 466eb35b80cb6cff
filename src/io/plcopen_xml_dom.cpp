#include "io/plcopen_xml_dom.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>

#include "model/names.hpp"

namespace sfcv::io::plcopen {

std::string_view local_name(pugi::xml_node node) {
  std::string_view n = node.name();
  const auto colon = n.find(':');
  return colon == std::string_view::npos ? n : n.substr(colon + 1);
}

pugi::xml_node child(pugi::xml_node node, std::string_view name) {
  for (auto c = node.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element && local_name(c) == name) return c;
  return {};
}

std::vector<pugi::xml_node> children(pugi::xml_node node, std::string_view name) {
  std::vector<pugi::xml_node> r;
  for (auto c = node.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element && local_name(c) == name) r.push_back(c);
  return r;
}

std::vector<pugi::xml_node> element_children(pugi::xml_node node) {
  std::vector<pugi::xml_node> r;
  for (auto c = node.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element) r.push_back(c);
  return r;
}

const XmlContext::SiblingPositions& XmlContext::sibling_positions(pugi::xml_node parent) const {
  auto [it, fresh] = siblings_.try_emplace(parent.internal_object());
  if (fresh) {
    auto& pos = it->second;
    std::unordered_map<std::string_view, int> seen;
    for (auto s = parent.first_child(); s; s = s.next_sibling()) {
      if (s.type() != pugi::node_element) continue;
      const auto name = local_name(s);
      pos.index[s.internal_object()] = ++seen[name];
      ++pos.same_id[std::string(name) + '\n' + s.attribute("localId").value()];
    }
    for (const auto& [name, count] : seen) pos.count[std::string(name)] = count;
  }
  return it->second;
}

std::string XmlContext::element_path(pugi::xml_node node) const {
  std::vector<std::string> parts;
  for (auto n = node; n && n.type() == pugi::node_element; n = n.parent()) {
    std::string part(local_name(n));
    // TwinCAT object files spell it `Name`.
    const auto name = n.attribute("name") ? n.attribute("name") : n.attribute("Name");
    const auto id = n.attribute("localId");
    const auto formal = n.attribute("formalParameter");
    if (name && *name.value()) {
      part += "[@name='" + std::string(name.value()) + "']";
    } else if (id) {
      part += "[@localId='" + std::string(id.value()) + "']";
    } else if (formal && *formal.value()) {
      part += "[@formalParameter='" + std::string(formal.value()) + "']";
    }
    // Elements without a distinguishing attribute (or with a repeated localId such as the
    // localId="0" Beremiz gives every action of a block) get their position among same-named
    // siblings, counted once per parent (an SFC body has thousands of siblings).
    if (!(name && *name.value()) && n.parent()) {
      const auto& pos = sibling_positions(n.parent());
      const std::string local(local_name(n));
      const int count = pos.count.at(local);
      const int same_id = id ? pos.same_id.at(local + '\n' + id.value()) : 0;
      if (count > 1 && (!id || same_id > 1))
        part += "[" + std::to_string(pos.index.at(n.internal_object())) + "]";
    }
    parts.push_back(std::move(part));
  }
  std::string path;
  for (auto it = parts.rbegin(); it != parts.rend(); ++it) path += "/" + *it;
  return path;
}

// ---------------------------------------------------------------------------------- XmlContext

XmlContext::XmlContext(std::string file, std::string_view text, model::Diagnostics& diagnostics,
                       const model::Budget* budget)
    : file_(std::move(file)), diagnostics_(diagnostics), poll_(budget, 1024) {
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') line_starts_.push_back(i + 1);
}

model::SourceLocation XmlContext::where_offset(std::ptrdiff_t offset) const {
  model::SourceLocation w;
  w.file = file_;
  if (offset >= 0) {
    const auto off = static_cast<std::size_t>(offset);
    const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), off);
    const auto line = static_cast<std::size_t>(it - line_starts_.begin());  // 1-based
    w.line = static_cast<int>(line);
    w.column = static_cast<int>(off - line_starts_[line - 1]) + 1;
  }
  return w;
}

model::SourceLocation XmlContext::where(pugi::xml_node node) const {
  auto w = where_offset(node ? node.offset_debug() : -1);
  if (node) w.element_path = element_path(node);
  return w;
}

void XmlContext::error(pugi::xml_node node, std::string message) {
  diagnostics_.push_back({model::Severity::Error, where(node), std::move(message)});
}
void XmlContext::warning(pugi::xml_node node, std::string message) {
  diagnostics_.push_back({model::Severity::Warning, where(node), std::move(message)});
}
void XmlContext::note(pugi::xml_node node, std::string message) {
  diagnostics_.push_back({model::Severity::Note, where(node), std::move(message)});
}

// ------------------------------------------------------------------------------------ body text

namespace {
void collect_text(pugi::xml_node node, std::string& out, std::ptrdiff_t& first_offset,
                  bool& first) {
  for (auto c = node.first_child(); c; c = c.next_sibling()) {
    if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
      if (first) {
        first = false;
        // pugixml's offset of a CDATA node is already that of its text, past "<![CDATA[".
        first_offset = c.offset_debug();
      }
      out += c.value();
    } else if (c.type() == pugi::node_element) {
      const auto n = local_name(c);
      if (n == "br") {
        out += "\n";
        continue;
      }
      collect_text(c, out, first_offset, first);
      // Paragraphs are lines.
      if (n == "p" || n == "div") out += "\n";
    }
  }
}
}  // namespace

BodyText body_text(pugi::xml_node language_element, const XmlContext& ctx) {
  BodyText r;
  std::ptrdiff_t offset = -1;
  bool first = true;
  collect_text(language_element, r.text, offset, first);
  r.start = ctx.where_offset(offset >= 0 ? offset : language_element.offset_debug());
  r.start.element_path = ctx.element_path(language_element);
  return r;
}

bool load_document(pugi::xml_document& doc, std::string_view text, XmlContext& ctx) {
  const auto parsed =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_auto);
  if (parsed) return true;
  ctx.add({model::Severity::Error, ctx.where_offset(parsed.offset),
           std::string("XML parse error: ") + parsed.description()});
  return false;
}

BodyText lines_text(pugi::xml_node start, const std::vector<pugi::xml_node>& lines,
                    const XmlContext& ctx) {
  BodyText r;
  r.start = ctx.where(start);
  int line = r.start.line, column = r.start.column;
  bool first = true;
  for (auto l : lines) {
    if (!first) {  // each Line ends a line of text, wherever the next one is
      r.text += '\n';
      ++line;
      column = 1;
    }
    first = false;
    for (auto c = l.first_child(); c; c = c.next_sibling()) {
      if (c.type() != pugi::node_cdata && c.type() != pugi::node_pcdata) continue;
      const auto at = ctx.where_offset(c.offset_debug());
      if (at.line > line || (at.line == line && at.column >= column)) {
        while (line < at.line) {
          r.text += '\n';
          ++line;
          column = 1;
        }
        while (column < at.column) {
          r.text += ' ';
          ++column;
        }
      }
      const std::string v = c.value();
      r.text += v;
      for (char ch : v) {
        if (ch == '\n') {
          ++line;
          column = 1;
        } else {
          ++column;
        }
      }
    }
  }
  return r;
}

// ------------------------------------------------------------------------------------- literals

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

bool attribute_true(pugi::xml_node node, const char* name) {
  const std::string v = model::to_upper(trim(node.attribute(name).value()));
  return v == "TRUE" || v == "1";
}

model::Converted<std::int64_t> parse_time_literal(std::string_view text) {
  return model::time_literal(trim(text));
}

model::Converted<std::int64_t> parse_int_literal(std::string_view text) {
  return model::integer_literal(trim(text));
}

std::optional<bool> parse_bool_literal(std::string_view text) {
  std::string s = model::to_upper(trim(text));
  if (s.rfind("BOOL#", 0) == 0) s = s.substr(5);
  if (s == "TRUE" || s == "1") return true;
  if (s == "FALSE" || s == "0") return false;
  return std::nullopt;
}

}  // namespace sfcv::io::plcopen
