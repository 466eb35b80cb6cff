#include "model/statement.hpp"

#include <algorithm>

#include "model/names.hpp"

namespace sfcv::model {

StmtPtr make_assign(std::string target, ExprPtr value, SourceLocation where) {
  auto s = std::make_shared<Stmt>();
  s->kind = StmtKind::Assign;
  s->target = std::move(target);
  s->value = std::move(value);
  s->where = std::move(where);
  return s;
}

StmtPtr make_fb_call(std::string instance, std::vector<std::pair<std::string, ExprPtr>> arguments,
                     SourceLocation where) {
  auto s = std::make_shared<Stmt>();
  s->kind = StmtKind::FbCall;
  s->target = std::move(instance);
  s->arguments = std::move(arguments);
  s->where = std::move(where);
  return s;
}

bool is_loop(StmtKind k) {
  return k == StmtKind::For || k == StmtKind::While || k == StmtKind::Repeat;
}

bool reads(const StmtList& body, std::string_view variable) {
  auto read = [&](const ExprPtr& e) { return e && reads(*e, variable); };
  for (const auto& s : body) {
    if (read(s->value) || read(s->limit) || read(s->step)) return true;
    if (std::any_of(s->conditions.begin(), s->conditions.end(), read) ||
        std::any_of(s->target_indices.begin(), s->target_indices.end(), read))
      return true;
    for (const auto& [name, argument] : s->arguments)
      if (read(argument)) return true;
    for (const auto& b : s->bodies)
      if (reads(b, variable)) return true;
    if (reads(s->else_body, variable)) return true;
  }
  return false;
}

bool equal(const Stmt& a, const Stmt& b) {
  if (a.kind != b.kind || !equal(a.limit, b.limit) || !equal(a.step, b.step) ||
      to_upper(a.target) != to_upper(b.target) || !equal(a.value, b.value) ||
      a.conditions.size() != b.conditions.size() || a.labels != b.labels ||
      a.bodies.size() != b.bodies.size() || !equal(a.else_body, b.else_body) ||
      a.arguments.size() != b.arguments.size() || a.outputs.size() != b.outputs.size() ||
      a.target_indices.size() != b.target_indices.size())
    return false;
  for (std::size_t i = 0; i < a.target_indices.size(); ++i)
    if (!equal(a.target_indices[i], b.target_indices[i])) return false;
  for (std::size_t i = 0; i < a.outputs.size(); ++i)
    if (to_upper(a.outputs[i].first) != to_upper(b.outputs[i].first) ||
        to_upper(a.outputs[i].second) != to_upper(b.outputs[i].second))
      return false;
  for (std::size_t i = 0; i < a.conditions.size(); ++i)
    if (!equal(a.conditions[i], b.conditions[i])) return false;
  for (std::size_t i = 0; i < a.bodies.size(); ++i)
    if (!equal(a.bodies[i], b.bodies[i])) return false;
  for (std::size_t i = 0; i < a.arguments.size(); ++i)
    if (to_upper(a.arguments[i].first) != to_upper(b.arguments[i].first) ||
        !equal(a.arguments[i].second, b.arguments[i].second))
      return false;
  return true;
}

bool equal(const StmtList& a, const StmtList& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!equal(*a[i], *b[i])) return false;
  return true;
}

namespace {
void print(const StmtList& body, int indent, std::string& out) {
  const std::string pad(static_cast<std::size_t>(indent), ' ');
  for (const auto& s : body) {
    switch (s->kind) {
      case StmtKind::Assign: {
        std::string value = to_st(s->value);
        if (!s->outputs.empty()) {  // `y := F(x := 1, q => z)`: the call gets its outputs back
          value.pop_back();
          for (std::size_t i = 0; i < s->outputs.size(); ++i)
            value += (i == 0 && value.back() == '(' ? "" : ", ") + s->outputs[i].first + " => " +
                     s->outputs[i].second;
          value += ")";
        }
        out += pad +
               (s->target_indices.empty() ? s->target
                                          : to_st(make_index(s->target, s->target_indices))) +
               " := " + value + ";\n";
        break;
      }
      case StmtKind::FbCall: {
        out += pad + s->target + "(";
        for (std::size_t i = 0; i < s->arguments.size(); ++i) {
          if (i) out += ", ";
          out += s->arguments[i].first + " := " + to_st(s->arguments[i].second);
        }
        for (std::size_t i = 0; i < s->outputs.size(); ++i) {
          if (i || !s->arguments.empty()) out += ", ";
          out += s->outputs[i].first + " => " + s->outputs[i].second;
        }
        out += ");\n";
        break;
      }
      case StmtKind::If:
        for (std::size_t i = 0; i < s->conditions.size(); ++i) {
          out += pad + (i ? "ELSIF " : "IF ") + to_st(s->conditions[i]) + " THEN\n";
          print(s->bodies[i], indent + 2, out);
        }
        if (!s->else_body.empty()) {
          out += pad + "ELSE\n";
          print(s->else_body, indent + 2, out);
        }
        out += pad + "END_IF;\n";
        break;
      case StmtKind::Case:
        out += pad + "CASE " + to_st(s->value) + " OF\n";
        for (std::size_t i = 0; i < s->labels.size(); ++i) {
          out += pad + "  ";
          for (std::size_t j = 0; j < s->labels[i].size(); ++j) {
            if (j) out += ", ";
            const auto& l = s->labels[i][j];
            out += l.lo_name.empty() ? std::to_string(l.lo) : l.lo_name;
            if (l.hi != l.lo || l.hi_name != l.lo_name)
              out += ".." + (l.hi_name.empty() ? std::to_string(l.hi) : l.hi_name);
          }
          out += ":\n";
          print(s->bodies[i], indent + 4, out);
        }
        if (!s->else_body.empty()) {
          out += pad + "ELSE\n";
          print(s->else_body, indent + 4, out);
        }
        out += pad + "END_CASE;\n";
        break;
      case StmtKind::For:
        out += pad + "FOR " + s->target + " := " + to_st(s->value) + " TO " + to_st(s->limit);
        if (s->step) out += " BY " + to_st(s->step);
        out += " DO\n";
        print(s->bodies.empty() ? StmtList{} : s->bodies[0], indent + 2, out);
        out += pad + "END_FOR;\n";
        break;
      case StmtKind::While:
        out += pad + "WHILE " + to_st(s->conditions[0]) + " DO\n";
        print(s->bodies[0], indent + 2, out);
        out += pad + "END_WHILE;\n";
        break;
      case StmtKind::Repeat:
        out += pad + "REPEAT\n";
        print(s->bodies[0], indent + 2, out);
        out += pad + "UNTIL " + to_st(s->conditions[0]) + "\n" + pad + "END_REPEAT;\n";
        break;
      case StmtKind::Exit:
        out += pad + "EXIT;\n";
        break;
      case StmtKind::Continue:
        out += pad + "CONTINUE;\n";
        break;
      case StmtKind::Return:
        out += pad + "RETURN;\n";
        break;
    }
  }
}
}  // namespace

std::string to_st(const StmtList& body, int indent) {
  std::string out;
  print(body, indent, out);
  return out;
}

}  // namespace sfcv::model
