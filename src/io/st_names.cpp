#include "io/st_names.hpp"

#include <cctype>

#include "io/st_parser.hpp"

namespace sfcv::io {

bool is_st_identifier_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}

bool is_st_identifier_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

bool is_st_identifier(std::string_view s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80 || !(std::isalnum(u) || c == '_')) return false;
  }
  return !st::is_reserved(s);
}

bool is_st_dotted_name(std::string_view s) {
  for (std::size_t from = 0;;) {
    const auto dot = s.find('.', from);
    if (!is_st_identifier(s.substr(from, dot == std::string_view::npos ? dot : dot - from)))
      return false;
    if (dot == std::string_view::npos) return true;
    from = dot + 1;
  }
}

std::string first_non_st_name(const model::ExprPtr& e) {
  if (!e) return {};
  using model::ExprKind;
  if (e->kind == ExprKind::Name || e->kind == ExprKind::Member || e->kind == ExprKind::Call) {
    if (!is_st_dotted_name(e->name)) return e->name;
    if (e->kind == ExprKind::Member && !is_st_identifier(e->member)) return e->member;
    for (const auto& n : e->arg_names)
      if (!n.empty() && !is_st_identifier(n)) return n;
  }
  for (const auto& a : e->args)
    if (auto bad = first_non_st_name(a); !bad.empty()) return bad;
  return {};
}

std::string first_non_st_name(const model::StmtList& body) {
  for (const auto& s : body) {
    // An array element's target holds "[*]" where its indices go (target_indices).
    std::string target = s->target;
    for (auto at = target.find("[*]"); at != std::string::npos; at = target.find("[*]"))
      target.erase(at, 3);
    if (!target.empty() && !is_st_dotted_name(target)) return s->target;
    for (const auto& i : s->target_indices)
      if (auto bad = first_non_st_name(i); !bad.empty()) return bad;
    for (const auto& labels : s->labels)
      for (const auto& l : labels)
        for (const auto* n : {&l.lo_name, &l.hi_name})
          if (!n->empty() && !is_st_dotted_name(*n)) return *n;
    for (const auto& [param, value] : s->arguments) {
      if (!is_st_identifier(param)) return param;
      if (auto bad = first_non_st_name(value); !bad.empty()) return bad;
    }
    for (const auto& [out, var] : s->outputs) {
      if (!is_st_identifier(out)) return out;
      if (!is_st_dotted_name(var)) return var;
    }
    for (const auto* e : {&s->value, &s->limit, &s->step})
      if (auto bad = first_non_st_name(*e); !bad.empty()) return bad;
    for (const auto& c : s->conditions)
      if (auto bad = first_non_st_name(c); !bad.empty()) return bad;
    for (const auto& b : s->bodies)
      if (auto bad = first_non_st_name(b); !bad.empty()) return bad;
    if (auto bad = first_non_st_name(s->else_body); !bad.empty()) return bad;
  }
  return {};
}

namespace {

// The first Grafcet-only operator in `e`: it has no ST form.
std::string first_operator_without_st(const model::ExprPtr& e, std::string_view where) {
  if (!e) return {};
  switch (e->kind) {
    case model::ExprKind::Rising:
      return "rising edge in " + std::string(where);
    case model::ExprKind::Falling:
      return "falling edge in " + std::string(where);
    case model::ExprKind::Delay:
      return "Grafcet delay in " + std::string(where);
    default:
      break;
  }
  for (const auto& a : e->args)
    if (auto why = first_operator_without_st(a, where); !why.empty()) return why;
  return {};
}

std::string first_operator_without_st(const model::StmtList& body, std::string_view where) {
  for (const auto& s : body) {
    for (const auto* e : {&s->value, &s->limit, &s->step})
      if (auto why = first_operator_without_st(*e, where); !why.empty()) return why;
    for (const auto& i : s->target_indices)
      if (auto why = first_operator_without_st(i, where); !why.empty()) return why;
    for (const auto& c : s->conditions)
      if (auto why = first_operator_without_st(c, where); !why.empty()) return why;
    for (const auto& b : s->bodies)
      if (auto why = first_operator_without_st(b, where); !why.empty()) return why;
    if (auto why = first_operator_without_st(s->else_body, where); !why.empty()) return why;
    for (const auto& a : s->arguments)
      if (auto why = first_operator_without_st(a.second, where); !why.empty()) return why;
  }
  return {};
}

std::string not_an_identifier(const std::string& name, std::string_view where) {
  if (name.empty()) return {};
  return "name '" + name + "' in " + std::string(where) + " is not an IEC identifier";
}

}  // namespace

std::string st_text_obstacle(const model::ExprPtr& e, std::string_view where) {
  if (auto why = first_operator_without_st(e, where); !why.empty()) return why;
  return not_an_identifier(first_non_st_name(e), where);
}

std::string st_text_obstacle(const model::StmtList& body, std::string_view where) {
  if (auto why = not_an_identifier(first_non_st_name(body), where); !why.empty()) return why;
  return first_operator_without_st(body, where);
}

}  // namespace sfcv::io
