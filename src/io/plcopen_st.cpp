#include "io/plcopen_st.hpp"

#include <cctype>
#include <map>
#include <utility>

#include "io/st_names.hpp"
#include "io/st_parser.hpp"

namespace sfcv::io::plcopen {

namespace {

// CODESYS/TwinCAT conditions read members of members of FB instances
// (`Table.AtStack.DI_SwitchTrue`), which the ST grammar of the model does not have. Each such
// chain is replaced by a placeholder name before parsing and comes back as the member
// `DI_SwitchTrue` of `Table.AtStack`: the chart still loads, and the semantics, which cannot
// resolve `Table.AtStack`, refuses it by name instead of the loader refusing the whole file.
std::string hide_nested_members(
    std::string_view text, std::map<std::string, std::pair<std::string, std::string>>& chains) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    // Skip comments and literals with '#' (T#1.5s), whose parts are not identifiers.
    if (c == '(' && i + 1 < text.size() && text[i + 1] == '*') {
      const auto end = text.find("*)", i + 2);
      const auto stop = end == std::string_view::npos ? text.size() : end + 2;
      out.append(text.substr(i, stop - i));
      i = stop;
      continue;
    }
    if (!is_st_identifier_start(c) ||
        (i > 0 && (is_st_identifier_char(text[i - 1]) || text[i - 1] == '#'))) {
      out += c;
      ++i;
      continue;
    }
    std::vector<std::string> parts;
    std::size_t j = i;
    while (true) {
      std::size_t k = j;
      while (k < text.size() && is_st_identifier_char(text[k])) ++k;
      parts.emplace_back(text.substr(j, k - j));
      if (k < text.size() && text[k] == '#') {  // a typed literal: leave it alone
        parts.clear();
        j = k;
        break;
      }
      if (k + 1 < text.size() && text[k] == '.' && is_st_identifier_start(text[k + 1])) {
        j = k + 1;
        continue;
      }
      j = k;
      break;
    }
    if (parts.size() >= 3) {
      std::string prefix = parts[0];
      for (std::size_t p = 1; p + 1 < parts.size(); ++p) prefix += "." + parts[p];
      const std::string placeholder = "sfcv_nested_member_" + std::to_string(chains.size());
      chains[placeholder] = {prefix, parts.back()};
      out += placeholder;
    } else {
      out.append(text.substr(i, j - i));
    }
    i = j;
  }
  return out;
}

model::ExprPtr restore(const model::ExprPtr& e,
                       const std::map<std::string, std::pair<std::string, std::string>>& chains) {
  if (!e) return e;
  if (e->kind == model::ExprKind::Name) {
    const auto it = chains.find(e->name);
    if (it == chains.end()) return e;
    return model::make_member(it->second.first, it->second.second, e->where);
  }
  bool changed = false;
  std::vector<model::ExprPtr> args;
  for (const auto& a : e->args) {
    args.push_back(restore(a, chains));
    changed = changed || args.back() != a;
  }
  if (!changed) return e;
  auto copy = std::make_shared<model::Expr>(*e);
  copy->args = std::move(args);
  return copy;
}

}  // namespace

model::ExprPtr parse_expression_text(const BodyText& text, model::Diagnostics& problems) {
  std::map<std::string, std::pair<std::string, std::string>> chains;
  const std::string hidden = hide_nested_members(text.text, chains);
  if (chains.empty()) return parse_st_expression(text.text, text.start, problems);
  auto e = parse_st_expression(hidden, text.start, problems);
  return restore(e, chains);
}

std::optional<model::StmtList> parse_statements_text(const BodyText& text,
                                                     model::Diagnostics& problems) {
  model::Diagnostics local;
  auto body = parse_st_statements(text.text, text.start, local);
  const bool failed = model::has_errors(local);
  for (auto& d : local) problems.push_back(std::move(d));
  if (failed) return std::nullopt;
  return body;
}

}  // namespace sfcv::io::plcopen
