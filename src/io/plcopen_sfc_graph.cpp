// The SFC body of PLCopen TC6 XML is a graph: every element names its predecessors through
// connectionPointIn/connection@refLocalId. A transition's source steps are found by walking
// back through selection divergences and simultaneous convergences; its target steps by
// walking forward through selection convergences, simultaneous divergences and jumps.

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "io/il_reader.hpp"
#include "io/plcopen_network.hpp"
#include "io/plcopen_pou.hpp"
#include "io/plcopen_st.hpp"
#include "model/names.hpp"

namespace sfcv::io::plcopen {

namespace {

bool is_step(std::string_view k) {
  return k == "step" || k == "macroStep";
}

bool is_structural(std::string_view k) {
  return is_step(k) || k == "transition" || k == "selectionDivergence" ||
         k == "selectionConvergence" || k == "simultaneousDivergence" ||
         k == "simultaneousConvergence" || k == "jumpStep";
}

std::string describe(pugi::xml_node n) {
  std::string s(local_name(n));
  if (const auto name = n.attribute("name"); *name.value())
    s += " '" + std::string(name.value()) + "'";
  s += " (localId " + std::string(n.attribute("localId").value()) + ")";
  return s;
}

bool is_identifier(std::string_view s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s.front()))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
  });
}

void add_unique(std::vector<std::string>& v, const std::string& s) {
  for (const auto& x : v)
    if (model::iequals(x, s)) return;
  v.push_back(s);
}

class ChartBuilder {
 public:
  ChartBuilder(PouContext& pc, pugi::xml_node sfc, model::Chart& chart)
      : pc_(pc),
        ctx_(pc.ctx),
        sfc_(sfc),
        chart_(chart),
        net_(sfc, pc.ctx, pc.ctx.diagnostics(), chart.name) {}

  void build() {
    index();
    read_steps();
    read_transitions();
    read_action_blocks();
    read_codesys_step_actions();
    for (auto& c : net_.take_calls()) pc_.condition_calls.push_back(std::move(c));
    for (auto& v : net_.take_edge_instances()) pc_.pou.variables.push_back(std::move(v));
  }

 private:
  void index() {
    for (auto n : element_children(sfc_)) {
      ctx_.poll();
      const auto id = n.attribute("localId");
      if (!id) continue;
      if (!by_id_.emplace(id.value(), n).second) {
        ctx_.error(n, "duplicate localId '" + std::string(id.value()) + "' in the SFC body");
        continue;
      }
    }
    for (auto n : element_children(sfc_)) {
      ctx_.poll();
      if (!is_structural(local_name(n))) continue;
      for (auto cpi : children(n, "connectionPointIn"))
        for (auto c : children(cpi, "connection")) {
          const std::string ref = c.attribute("refLocalId").value();
          if (!by_id_.count(ref)) {
            ctx_.error(c, describe(n) + " is connected to unknown localId '" + ref + "'");
            continue;
          }
          successors_[ref].push_back(n);
        }
    }
  }

  void read_steps() {
    for (auto n : element_children(sfc_)) {
      ctx_.poll();
      const auto kind = local_name(n);
      if (!is_step(kind)) continue;
      model::Step s;
      s.name = trim(n.attribute("name").value());
      s.initial = attribute_true(n, "initialStep");
      s.where = ctx_.where(n);
      if (s.name.empty()) {
        ctx_.error(n, "step without a name");
        continue;
      }
      if (kind == "macroStep") {
        const auto body_sfc = child(child(n, "body"), "SFC");
        if (!body_sfc) {
          ctx_.error(n, "unsupported: macroStep '" + s.name + "' has no SFC body");
          continue;
        }
        s.kind = model::StepKind::MacroStep;
        s.expansion = s.name;
        macro_bodies_.emplace_back(s.name, body_sfc);
      }
      chart_.steps.push_back(std::move(s));
    }
  }

  // The alternative source-step sets of a transition whose input is `n`'s input. A selection
  // divergence passes its one input on; a simultaneous convergence joins its inputs (every
  // combination of their alternatives); a selection convergence, which TwinCAT puts between
  // the last steps of alternative branches and the transition they share, offers each input's
  // alternatives separately, so that the transition becomes one transition per source set. A
  // jump step ends its branch at its target: when TwinCAT wires it into a convergence, that
  // branch offers no source here.
  using SourceSets = std::vector<std::vector<std::string>>;

  // `in_branch`: `n` lies in a branch of a simultaneous convergence being walked.
  bool walk_back(pugi::xml_node n, pugi::xml_node transition, bool join, SourceSets& out,
                 std::set<std::string>& seen, bool in_branch = false) {
    bool ok = true;
    SourceSets acc;
    bool first = true;
    for (auto cpi : children(n, "connectionPointIn"))
      for (auto c : children(cpi, "connection")) {
        const auto it = by_id_.find(c.attribute("refLocalId").value());
        if (it == by_id_.end()) {
          ok = false;  // reported by index()
          continue;
        }
        const auto src = it->second;
        const auto k = local_name(src);
        SourceSets here;
        if (is_step(k)) {
          here.push_back({trim(src.attribute("name").value())});
        } else if (k == "jumpStep" && (local_name(n) == "selectionConvergence" ||
                                       local_name(n) == "simultaneousConvergence")) {
          // This branch ends in its jump (TwinCAT and CODESYS still wire it into the
          // convergence): it adds no source, whether the branch is alternative or parallel.
          if (local_name(n) == "simultaneousConvergence" || in_branch)
            note_parallel_branch_jump(src, n);
          continue;
        } else if (k == "selectionDivergence" || k == "simultaneousConvergence" ||
                   k == "selectionConvergence") {
          if (!seen.insert(it->first).second) {
            ctx_.error(transition, "transition (localId " +
                                       std::string(transition.attribute("localId").value()) +
                                       ") is reached through a cycle of " + describe(src));
            ok = false;
            continue;
          }
          ok = walk_back(src, transition, k == "simultaneousConvergence", here, seen,
                         in_branch || (join && local_name(n) == "simultaneousConvergence")) &&
               ok;
          seen.erase(it->first);
          // Every branch of `src` ended in a jump: like a single jump, it adds no source.
          if (here.empty()) continue;
        } else if (k == "jumpStep") {
          ctx_.error(transition,
                     "transition (localId " + std::string(transition.attribute("localId").value()) +
                         ") directly follows the jump to '" +
                         trim(src.attribute("targetName").value()) + "' (localId " + it->first +
                         "): a jump ends its branch, so no step precedes the "
                         "transition");
          ok = false;
          continue;
        } else {
          ctx_.error(transition, "transition (localId " +
                                     std::string(transition.attribute("localId").value()) +
                                     ") follows " + describe(src) +
                                     ": expected a step, a selection divergence or convergence, "
                                     "or a simultaneous convergence before a transition");
          ok = false;
          continue;
        }
        if (!join) {
          for (auto& set : here) acc.push_back(std::move(set));
          continue;
        }
        if (first) {
          acc = std::move(here);
        } else {
          SourceSets product;
          for (const auto& a : acc)
            for (const auto& b : here) {
              auto joined = a;
              for (const auto& step : b) add_unique(joined, step);
              product.push_back(std::move(joined));
            }
          acc = std::move(product);
        }
        first = false;
      }
    for (auto& set : acc) out.push_back(std::move(set));
    return ok;
  }

  // CODESYS: "a parallel branch ends with a double line or with a jump". The convergence then
  // waits for the other branches only, and the jump's target becomes active even if it already
  // is (a step is a flag): said once per jump, and recorded so that validate() does not refuse
  // the resulting "unsafe" structure.
  void note_parallel_branch_jump(pugi::xml_node jump, pugi::xml_node convergence) {
    if (!warned_jumps_.insert(jump.attribute("localId").value()).second) return;
    if (!chart_.parallel_branch_jump.known()) chart_.parallel_branch_jump = ctx_.where(jump);
    ctx_.warning(jump, "a parallel branch ends in the jump to '" +
                           trim(jump.attribute("targetName").value()) +
                           "': " + describe(convergence) +
                           " waits for the other branches only, and the jump activates its "
                           "target even while it is active (CODESYS/TwinCAT step flags, "
                           "docs/semantics.md 1.2b)");
  }

  // Target steps reached from the element with localId `id`.
  bool walk_forward(const std::string& id, pugi::xml_node transition, std::vector<std::string>& out,
                    std::set<std::string>& seen) {
    bool ok = true;
    const auto it = successors_.find(id);
    if (it == successors_.end()) return true;
    for (auto succ : it->second) {
      const auto k = local_name(succ);
      if (is_step(k)) {
        add_unique(out, trim(succ.attribute("name").value()));
      } else if (k == "jumpStep") {
        const std::string target = trim(succ.attribute("targetName").value());
        const auto* step = chart_.find_step(target);
        if (!step) {
          ctx_.error(succ, "jump to unknown step '" + target + "'");
          ok = false;
          continue;
        }
        add_unique(out, step->name);
      } else if (k == "selectionConvergence" || k == "simultaneousDivergence") {
        const std::string sid = succ.attribute("localId").value();
        if (seen.insert(sid).second) ok = walk_forward(sid, transition, out, seen) && ok;
      } else {
        ctx_.error(transition, "transition (localId " +
                                   std::string(transition.attribute("localId").value()) +
                                   ") leads to " + describe(succ) +
                                   ": expected a step, a jump, a selection convergence or a "
                                   "simultaneous divergence after a transition");
        ok = false;
      }
    }
    return ok;
  }

  void read_transitions() {
    int order = 0;
    for (auto n : element_children(sfc_)) {
      ctx_.poll();
      if (local_name(n) != "transition") continue;
      model::Transition t;
      t.name = trim(n.attribute("name").value());
      // TC6 gives an SFC transition no name attribute; the name of its inline condition
      // (`<inline name="T1">`, empty in Beremiz exports) is where a named transition's name goes.
      if (t.name.empty())
        t.name = trim(child(child(n, "condition"), "inline").attribute("name").value());
      t.where = ctx_.where(n);
      const std::string id = n.attribute("localId").value();
      if (const std::string p = trim(n.attribute("priority").value()); !p.empty()) {
        // The range the IEC text reader allows: an int, and no wrap-around on the way.
        const auto v = parse_int_literal(p);
        if (!v)
          ctx_.error(n, "priority '" + p + "': " + v.error);
        else if (*v < 0 || *v > 1000000)
          ctx_.error(n, "priority " + p + " is outside 0..1000000");
        else
          t.priority = static_cast<int>(*v);
      }
      // Beremiz: a transition wired to nothing (no input, nothing reads its output) is left
      // over from editing; Beremiz's code generator ignores it, and so does sfcv.
      if (!child(child(n, "connectionPointIn"), "connection") && successors_[id].empty()) {
        ctx_.warning(n, "transition (localId " + id + ") is connected to nothing: ignored");
        continue;
      }
      std::set<std::string> seen_back, seen_fwd;
      SourceSets source_sets;
      bool ok = walk_back(n, n, true, source_sets, seen_back);
      ok = walk_forward(id, n, t.targets, seen_fwd) && ok;
      t.guard = condition(n);
      if (!t.guard) ok = false;
      if (ok && source_sets.empty()) {
        const auto in = by_id_.find(
            child(child(n, "connectionPointIn"), "connection").attribute("refLocalId").value());
        const bool converges =
            in != by_id_.end() && (local_name(in->second) == "selectionConvergence" ||
                                   local_name(in->second) == "simultaneousConvergence");
        ctx_.error(
            n, "transition (localId " + id + ") has no source step" +
                   (converges ? ": every branch into " + describe(in->second) + " ends in a jump"
                              : std::string()));
        ok = false;
      }
      if (ok && t.targets.empty()) {
        ctx_.error(n, "dangling transition (localId " + id + "): it leads to no step");
        ok = false;
      }
      if (!ok) continue;
      // One transition per source set (several only after a selection convergence); each keeps
      // the name, guard and priority, numbered apart when named so that names stay unique.
      for (std::size_t i = 0; i < source_sets.size(); ++i) {
        model::Transition copy = t;
        copy.sources = std::move(source_sets[i]);
        copy.order = order++;
        if (source_sets.size() > 1 && !t.name.empty())
          copy.name = t.name + "_" + std::to_string(i + 1);
        chart_.transitions.push_back(std::move(copy));
      }
    }
  }

  model::ExprPtr condition(pugi::xml_node transition) {
    const auto cond = child(transition, "condition");
    if (!cond) {
      ctx_.error(transition, "transition without a condition");
      return nullptr;
    }
    model::ExprPtr guard;
    if (const auto inl = child(cond, "inline")) {
      const auto lang = body_language(inl);
      if (!lang || local_name(lang) != "ST") {
        ctx_.error(inl, "unsupported: inline condition in " +
                            (lang ? std::string(local_name(lang)) : std::string("no language")) +
                            " (ST, a reference or a connection are modelled)");
        return nullptr;
      }
      guard = st_condition(body_text(lang, ctx_), inl);
    } else if (const auto ref = child(cond, "reference")) {
      guard = named_transition(trim(ref.attribute("name").value()), ref);
    } else if (const auto cpi = child(cond, "connectionPointIn")) {
      guard = net_.condition(cpi);
    } else if (child(cond, "connection")) {
      // TC6 v1.0 (Beremiz 2008): the condition holds its connections itself, without a
      // connectionPointIn around them.
      guard = net_.condition(cond);
    } else {
      ctx_.error(cond, "condition has neither inline text, a reference nor a connection");
      return nullptr;
    }
    if (guard && attribute_true(cond, "negated"))
      guard = model::make_unary(model::ExprKind::Not, guard, ctx_.where(cond));
    return guard;
  }

  model::ExprPtr st_condition(const BodyText& text, pugi::xml_node where) {
    if (trim(text.text).empty()) {
      ctx_.error(where, "empty condition");
      return nullptr;
    }
    return parse_expression_text(text, ctx_.diagnostics());
  }

  // A transition declared in pou/transitions (ST: `expr`, `NAME := expr;` or `:= expr;`;
  // FBD/LD: the output named after the transition).
  model::ExprPtr named_transition(const std::string& name, pugi::xml_node ref) {
    const std::string key = model::to_upper(name);
    if (const auto it = pc_.transition_guards.find(key); it != pc_.transition_guards.end())
      return it->second;
    const auto it = pc_.named_transitions.find(key);
    if (it == pc_.named_transitions.end()) {
      ctx_.error(ref, "condition refers to transition '" + name +
                          "', which pou/transitions does not declare");
      return nullptr;
    }
    const auto decl = it->second;
    const auto lang = body_language(child(decl, "body"));
    model::ExprPtr guard;
    const auto k = lang ? local_name(lang) : std::string_view{};
    if (k == "ST") {
      auto text = body_text(lang, ctx_);
      std::string s = trim(text.text);
      if (s.rfind(":=", 0) == 0) {
        s = s.substr(2);
      } else if (const auto pos = s.find(":=");
                 pos != std::string::npos && model::iequals(trim(s.substr(0, pos)), name)) {
        s = s.substr(pos + 2);
      }
      s = trim(s);
      while (!s.empty() && (s.back() == ';' || s.back() == ' ' || s.back() == '\n')) s.pop_back();
      text.text = s;
      guard = st_condition(text, decl);
    } else if (k == "FBD" || k == "LD") {
      Network net(lang, ctx_, ctx_.diagnostics(), "T_" + name);
      bool found = false;
      guard = net.output_named(name, found);
      if (!found)
        ctx_.error(decl, "transition '" + name + "' in " + std::string(k) +
                             ": no output variable or coil named '" + name + "'");
      for (auto& c : net.take_calls()) pc_.condition_calls.push_back(std::move(c));
      for (auto& v : net.take_edge_instances()) pc_.pou.variables.push_back(std::move(v));
    } else {
      ctx_.error(decl, "unsupported: transition '" + name + "' written in " +
                           (lang ? std::string(k) : std::string("no language")) +
                           " (ST, FBD and LD are modelled)");
    }
    pc_.transition_guards[key] = guard;
    return guard;
  }

  std::string unique_action_name(const std::string& base) {
    std::string name = base;
    for (int i = 2; pc_.pou.find_action(name) || pc_.pou.find_variable(name); ++i)
      name = base + "_" + std::to_string(i);
    return name;
  }

  void read_action_blocks() {
    for (auto ab : element_children(sfc_)) {
      ctx_.poll();
      if (local_name(ab) != "actionBlock") continue;
      const auto conn = child(child(ab, "connectionPointIn"), "connection");
      const auto it = by_id_.find(conn.attribute("refLocalId").value());
      if (!conn || it == by_id_.end() || !is_step(local_name(it->second))) {
        ctx_.error(ab, std::string("actionBlock is not connected to a step") +
                           (conn ? " (refLocalId '" +
                                       std::string(conn.attribute("refLocalId").value()) + "')"
                                 : ""));
        continue;
      }
      const std::string step = trim(it->second.attribute("name").value());
      for (auto a : children(ab, "action")) read_action(a, step);
    }
  }

  void read_action(pugi::xml_node a, const std::string& step) {
    model::ActionAssociation as;
    as.chart = chart_.name;
    as.step = step;
    as.where = ctx_.where(a);
    const std::string q = trim(a.attribute("qualifier").value());
    if (!q.empty()) {
      const auto parsed = model::parse_qualifier(q);
      if (!parsed) {
        ctx_.error(a, "unknown action qualifier '" + q + "'");
        return;
      }
      as.qualifier = *parsed;
    }
    if (const std::string d = trim(a.attribute("duration").value()); !d.empty()) {
      const auto ms = parse_time_literal(d);
      if (ms && *ms < 0) {
        ctx_.error(a, "negative duration '" + d + "'");
        return;
      } else if (ms) {
        as.duration_ms = *ms;
      } else if (!ms.error.empty()) {
        ctx_.error(a, "cannot read the duration '" + d + "': " + ms.error);
        return;
      } else if (is_identifier(d)) {
        as.duration_variable = d;
      } else {
        ctx_.error(a, "cannot read the duration '" + d + "' (a TIME literal or variable)");
        return;
      }
      if (!model::is_timed(as.qualifier))
        ctx_.warning(a, "duration '" + d + "' ignored: qualifier " +
                            std::string(model::to_string(as.qualifier)) + " is not timed");
    } else if (model::is_timed(as.qualifier)) {
      ctx_.error(a,
                 "qualifier " + std::string(model::to_string(as.qualifier)) + " needs a duration");
      return;
    }
    as.indicator = trim(a.attribute("indicator").value());
    if (const auto ref = child(a, "reference")) {
      as.action = trim(ref.attribute("name").value());
      if (as.action.empty()) {
        ctx_.error(ref, "action reference without a name");
        return;
      }
    } else if (const auto inl = child(a, "inline")) {
      // Numbered per POU in document order, as matiec's textual twin of a Beremiz chart names
      // them (corpus 03/04): INLINE1, INLINE2, ...
      model::Action act;
      act.name = unique_action_name("INLINE" + std::to_string(++pc_.inline_actions));
      act.kind = model::ActionBodyKind::Statements;
      act.where = ctx_.where(inl);
      const auto lang = body_language(inl);
      if (!lang) {
        ctx_.error(inl, "inline action without a body");
        return;
      }
      read_action_body(pc_, act, lang);
      as.action = act.name;
      pc_.pou.actions.push_back(std::move(act));
    } else {
      ctx_.error(a, "action without a reference or an inline body");
      return;
    }
    pc_.pou.associations.push_back(std::move(as));
  }

  void read_codesys_step_actions() {
    for (auto n : element_children(sfc_)) {
      ctx_.poll();
      if (!is_step(local_name(n))) continue;
      for (auto data : children(child(n, "addData"), "data")) {
        const std::string_view dname = data.attribute("name").value();
        if (dname.size() < 12 || dname.substr(dname.size() - 12) != "/sfc/element") continue;
        for (auto attr : children(child(data, "attributes"), "attribute")) {
          const std::string_view guid = attr.attribute("guid").value();
          model::Qualifier q;
          if (guid == kCodesysActiveGuid)
            q = model::Qualifier::N;
          else if (guid == kCodesysEntryGuid)
            q = model::Qualifier::P1;
          else if (guid == kCodesysExitGuid)
            q = model::Qualifier::P0;
          else
            continue;
          const std::string action = trim(attr.text().get());
          if (action.empty()) continue;
          model::ActionAssociation as;
          as.chart = chart_.name;
          as.step = trim(n.attribute("name").value());
          as.action = action;
          as.qualifier = q;
          as.step_action = true;
          as.where = ctx_.where(attr);
          pc_.pou.associations.push_back(std::move(as));
        }
      }
    }
  }

 public:
  std::vector<std::pair<std::string, pugi::xml_node>> macro_bodies_;

 private:
  PouContext& pc_;
  XmlContext& ctx_;
  pugi::xml_node sfc_;
  model::Chart& chart_;
  Network net_;
  std::map<std::string, pugi::xml_node> by_id_;
  std::map<std::string, std::vector<pugi::xml_node>> successors_;
  std::set<std::string> warned_jumps_;
};

}  // namespace

pugi::xml_node body_language(pugi::xml_node body) {
  for (auto c : element_children(body)) {
    const auto k = local_name(c);
    if (k == "documentation" || k == "addData") continue;
    return c;
  }
  return {};
}

int build_sfc_chart(PouContext& pc, pugi::xml_node sfc, const std::string& chart_name,
                    const std::string& parent_action) {
  // Reserve the slot first: macro-step bodies read below append their own charts after it.
  const int index = static_cast<int>(pc.pou.charts.size());
  pc.pou.charts.emplace_back();
  model::Chart chart;
  chart.name = chart_name;
  chart.parent_action = parent_action;
  chart.where = pc.ctx.where(sfc);
  std::vector<std::pair<std::string, pugi::xml_node>> macros;
  {
    ChartBuilder b(pc, sfc, chart);
    b.build();
    macros = std::move(b.macro_bodies_);
  }
  pc.pou.charts[static_cast<std::size_t>(index)] = std::move(chart);
  for (const auto& [name, body] : macros) {
    if (pc.pou.find_chart(name)) {
      pc.ctx.error(body, "macroStep '" + name + "': a chart of that name already exists");
      continue;
    }
    build_sfc_chart(pc, body, name, "");
  }
  return index;
}

std::optional<model::StmtList> read_statement_body(PouContext& pc, pugi::xml_node language,
                                                   const std::string& edge_prefix,
                                                   model::Diagnostics& problems) {
  const auto k = local_name(language);
  std::optional<model::StmtList> body;
  std::vector<model::Variable> edges;
  if (k == "ST") {
    body = parse_statements_text(body_text(language, pc.ctx), problems);
  } else if (k == "IL") {
    body = read_il_statements(body_text(language, pc.ctx), problems);
  } else if (k == "FBD" || k == "LD") {
    Network net(language, pc.ctx, problems, edge_prefix, &pc.pou.variables);
    body = net.statements();
    edges = net.take_edge_instances();
  } else {
    problems.push_back({model::Severity::Error, pc.ctx.where(language),
                        "bodies in " + std::string(k) + " are not modelled"});
  }
  if (!body || model::has_errors(problems)) return std::nullopt;
  for (auto& v : edges) pc.pou.variables.push_back(std::move(v));
  leave_out_unmodelled_writes(pc, *body, problems);
  return body;
}

void read_action_body(PouContext& pc, model::Action& action, pugi::xml_node language) {
  const auto k = local_name(language);
  model::Diagnostics problems;
  auto body = read_statement_body(pc, language, action.name, problems);
  if (body) {
    action.kind = model::ActionBodyKind::Statements;
    action.body = std::move(*body);
    for (auto& p : problems) pc.ctx.add(std::move(p));
    return;
  }
  // Real exports hold code the model does not cover; the chart must still load, and the
  // semantics refuses the action (body_unsupported) instead of running it as a no-op.
  action.kind = model::ActionBodyKind::Statements;
  action.body.clear();
  action.body_unsupported = true;
  if (k == "ST" || k == "IL") {
    action.unsupported_language = std::string(k);
    action.unsupported_text = body_text(language, pc.ctx).text;
  }
  std::string reason;
  for (const auto& p : problems)
    if (p.severity == model::Severity::Error) {
      reason = p.message;
      break;
    }
  action.unsupported_reason = reason;
  pc.ctx.warning(language, "action '" + action.name + "': body not modelled (" + reason +
                               "); checks that need this action will be refused");
  for (auto& p : problems) {
    p.severity = model::Severity::Note;
    pc.ctx.add(std::move(p));
  }
}

}  // namespace sfcv::io::plcopen
