// Writes of values sfcv does not model. A vendor project computes REAL values for its HMI
// (`AVCnt := AverageVal(Cnt1, ...)`) that no control decision reads: such a variable is
// dropped when its declaration is read, and an assignment to it is left out of the body when
// its right side has no effect besides its value (standard functions and pure user functions).
// Nothing else is lost: a read of the variable anywhere stays an error, so the POU is refused
// as before, and a property cannot name it (docs/semantics.md 1.7b).

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/plcopen_pou.hpp"
#include "io/plcopen_st.hpp"
#include "model/names.hpp"

namespace sfcv::io::plcopen {

namespace {

/// Adds to `user` the user functions `e` calls (upper case).
void calls_in(const model::Expr& e, const XmlContext& ctx, std::set<std::string>& user) {
  if (e.kind == model::ExprKind::Call && ctx.user_functions.count(model::to_upper(e.name)))
    user.insert(model::to_upper(e.name));
  for (const auto& a : e.args)
    if (a) calls_in(*a, ctx, user);
}

/// True when `body` only assigns names in `own` (the function's result and its own variables)
/// and calls no instance; the user functions its expressions call go to `user`.
bool computes_only_own(const model::StmtList& body, const std::set<std::string>& own,
                       const XmlContext& ctx, std::set<std::string>& user) {
  for (const auto& s : body) {
    switch (s->kind) {
      case model::StmtKind::Assign:
      case model::StmtKind::For:
        if (!own.count(model::to_upper(s->target)) || !s->target_indices.empty() ||
            !s->outputs.empty())
          return false;
        break;
      case model::StmtKind::FbCall:
        return false;
      default:
        break;
    }
    for (const auto* e : {&s->value, &s->limit, &s->step})
      if (*e) calls_in(**e, ctx, user);
    for (const auto& c : s->conditions)
      if (c) calls_in(*c, ctx, user);
    for (const auto& b : s->bodies)
      if (!computes_only_own(b, own, ctx, user)) return false;
    if (!computes_only_own(s->else_body, own, ctx, user)) return false;
  }
  return true;
}

/// True when evaluating `e` has no effect besides its value: it calls standard functions and
/// pure user functions only.
bool only_computes(const model::Expr& e, const XmlContext& ctx) {
  std::set<std::string> user;
  calls_in(e, ctx, user);
  return std::all_of(user.begin(), user.end(),
                     [&](const std::string& f) { return ctx.pure_functions.count(f) > 0; });
}

/// Leaves out the assignments to a variable of `dropped` whose right side only computes.
void leave_out(const XmlContext& ctx, const std::map<std::string, std::string>& dropped,
               model::StmtList& body, model::Diagnostics& problems) {
  model::StmtList kept;
  for (const auto& s : body) {
    if (s->kind == model::StmtKind::Assign && s->target_indices.empty() && s->outputs.empty() &&
        s->value && dropped.count(model::to_upper(s->target)) && only_computes(*s->value, ctx)) {
      problems.push_back({model::Severity::Note, s->where,
                          "assignment to '" + s->target + "' (" +
                              dropped.at(model::to_upper(s->target)) +
                              ", a type sfcv does not model) left out: its right side only "
                              "computes the value, which nothing modelled reads"});
      continue;
    }
    if (s->bodies.empty() && s->else_body.empty()) {
      kept.push_back(s);
      continue;
    }
    auto copy = std::make_shared<model::Stmt>(*s);
    for (auto& b : copy->bodies) leave_out(ctx, dropped, b, problems);
    leave_out(ctx, dropped, copy->else_body, problems);
    kept.push_back(std::move(copy));
  }
  body = std::move(kept);
}

}  // namespace

std::set<std::string> pure_functions(XmlContext& ctx, const std::vector<pugi::xml_node>& pous) {
  // Candidates: an ST body assigning only the function's own variables, without VAR_IN_OUT,
  // VAR_OUTPUT or VAR_EXTERNAL; pure once every user function it calls is (least fixpoint, so
  // recursion is not pure).
  std::map<std::string, std::set<std::string>> calls;
  for (auto p : pous) {
    if (std::string_view(p.attribute("pouType").value()) != "function") continue;
    const std::string name = model::to_upper(trim(p.attribute("name").value()));
    std::set<std::string> own{name};
    bool ok = true;
    for (auto section : element_children(child(p, "interface"))) {
      const auto k = local_name(section);
      if (k == "returnType" || k == "documentation" || k == "addData") continue;
      if (k != "inputVars" && k != "localVars" && k != "tempVars") {
        ok = ok && children(section, "variable").empty();
        continue;
      }
      for (auto v : children(section, "variable"))
        own.insert(model::to_upper(trim(v.attribute("name").value())));
    }
    const auto lang = body_language(child(p, "body"));
    if (!ok || !lang || local_name(lang) != "ST") continue;
    model::Diagnostics ignored;
    const auto body = parse_statements_text(body_text(lang, ctx), ignored);
    std::set<std::string> user;
    if (body && computes_only_own(*body, own, ctx, user)) calls[name] = std::move(user);
  }
  std::set<std::string> pure;
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& [f, called] : calls)
      if (!pure.count(f) && std::all_of(called.begin(), called.end(),
                                        [&](const auto& g) { return pure.count(g) > 0; })) {
        pure.insert(f);
        grew = true;
      }
  }
  return pure;
}

void leave_out_unmodelled_writes(PouContext& pc, model::StmtList& body,
                                 model::Diagnostics& problems) {
  const auto it = pc.ctx.unmodelled_variables.find(model::to_upper(pc.pou.name));
  if (it == pc.ctx.unmodelled_variables.end()) return;
  // A variable this body also reads keeps its writes: the read is refused, and so is the POU.
  std::map<std::string, std::string> dropped;
  for (const auto& [name, type] : it->second)
    if (!model::reads(body, name)) dropped.emplace(name, type);
  if (!dropped.empty()) leave_out(pc.ctx, dropped, body, problems);
}

void name_unmodelled_types(const PouContext& pc, model::Diagnostics& problems) {
  const auto it = pc.ctx.unmodelled_variables.find(model::to_upper(pc.pou.name));
  if (it == pc.ctx.unmodelled_variables.end()) return;
  for (auto& d : problems) {
    // The name the error is about: the first one it quotes ("... undeclared variable 'AVCnt'").
    const auto open = d.message.find('\'');
    const auto close = open == std::string::npos ? open : d.message.find('\'', open + 1);
    if (d.severity != model::Severity::Error || close == std::string::npos) continue;
    const auto type =
        it->second.find(model::to_upper(d.message.substr(open + 1, close - open - 1)));
    if (type == it->second.end()) continue;
    d.message += " (declared as " + type->second +
                 ", a type sfcv does not model: only a write that nothing modelled reads is left "
                 "out)";
  }
}

}  // namespace sfcv::io::plcopen
