// The IEC compiler's charts: steps, transitions and divergences, actions and their
// associations with qualifiers, action execution orders, step .T timers and step observables.

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::semantics::iec::detail {

void Compiler::structure() {
  // Steps and charts.
  for (auto& sc : scopes) {
    const auto& pou = *sc.pou;
    Pou cp;
    cp.name = sc.name;
    cp.type = sc.pou->name;
    cp.unit = sc.unit;
    cp.owner = sc.owner;
    cp.instance = sc.instance;
    for (std::size_t ci = 0; ci < pou.charts.size(); ++ci) {
      const auto& ch = pou.charts[ci];
      Chart c;
      c.pou = sc.index;
      const auto cid = static_cast<std::uint32_t>(p.charts.size());
      sc.chart_ids.push_back(cid);
      cp.charts.push_back(cid);
      bool has_initial = false;
      for (const auto& st : ch.steps) {
        poll_deadline();
        if (st.kind != model::StepKind::Normal)
          error(st.where,
                "step '" + st.name + "' is a Grafcet macro/enclosing step, not IEC 61131-3");
        Step s;
        s.short_name = st.name;
        s.name = sc.name + "." + (ch.parent_action.empty() ? "" : ch.parent_action + ".") + st.name;
        s.chart = cid;
        s.initial = st.initial;
        has_initial |= st.initial;
        s.ready = add_field(s.name, FieldKind::StepReady, 0, 1, 0, true);
        c.steps.push_back(static_cast<std::uint32_t>(p.steps.size()));
        p.steps.push_back(std::move(s));
      }
      if (!has_initial)
        error(ch.where, "chart '" + ch.name + "' of " + pou.name + " has no initial step");
      p.charts.push_back(std::move(c));
    }
    p.pous.push_back(std::move(cp));
  }
  // Actions.
  for (auto& sc : scopes) {
    const auto& pou = *sc.pou;
    for (const auto& a : pou.actions) add_action(sc, a.name, a.kind, a.where);
  }
  // Nested charts: their parent actions.
  for (auto& sc : scopes) {
    const auto& pou = *sc.pou;
    for (std::size_t ci = 0; ci < pou.charts.size(); ++ci) {
      const auto& ch = pou.charts[ci];
      if (ch.parent_action.empty()) continue;
      const auto* act = pou.find_action(ch.parent_action);
      auto it = sc.actions.find(model::to_upper(ch.parent_action));
      if (!act || it == sc.actions.end() || act->kind != model::ActionBodyKind::Chart) {
        error(ch.where, "chart '" + ch.name + "' is the body of '" + ch.parent_action +
                            "', which is not an SFC action of " + pou.name);
        continue;
      }
      p.charts[sc.chart_ids[ci]].parent_action = static_cast<std::int32_t>(it->second);
    }
  }
}

std::uint32_t Compiler::add_action(PouScope& sc, const std::string& name,
                                   model::ActionBodyKind kind, const model::SourceLocation& where) {
  const auto up = model::to_upper(name);
  if (auto it = sc.actions.find(up); it != sc.actions.end()) {
    error(where, "action '" + name + "' is declared twice in " + sc.pou->name);
    return it->second;
  }
  Action a;
  a.name = sc.name + "." + name;
  a.pou = sc.index;
  a.kind = kind;
  a.where = where;
  a.active = add_field(a.name, FieldKind::ActionActive, 0, 1, 0, true);
  p.actions.push_back(std::move(a));
  const auto id = static_cast<std::uint32_t>(p.actions.size() - 1);
  sc.actions[up] = id;
  Observable o;
  o.name = p.actions[id].name;
  o.aliases = {name, name + ".A"};
  o.kind = ObservableKind::Action;
  o.type = model::Type::boolean();
  p.observables.push_back(std::move(o));
  p.observable_refs.push_back(ObservableRef{ObservableKind::Action, id});
  return id;
}

void Compiler::actions_and_transitions() {
  for (auto& sc : scopes) {
    const auto& pou = *sc.pou;
    auto& cp = p.pous[sc.index];
    cp.body = block(sc, pou.body, sc.input_copies);
    // Action bodies.
    for (const auto& a : pou.actions) {
      auto& ca = p.actions[sc.actions[model::to_upper(a.name)]];
      if (a.kind == model::ActionBodyKind::Statements) {
        ca.body = block(sc, a.body);
      } else if (a.kind == model::ActionBodyKind::Variable) {
        auto it = sc.names.find(model::to_upper(a.variable));
        if (it == sc.names.end() || it->second.kind != Ref::Field || !it->second.is_bool)
          error(a.where, "action '" + a.name + "' names '" + a.variable +
                             "', which is not a Boolean variable sfcv can write");
        else
          ca.variable = static_cast<std::int32_t>(it->second.index);
      }
    }
    // Associations.
    for (const auto& as : pou.associations) {
      poll_deadline();
      std::optional<std::uint32_t> step;
      if (!as.chart.empty()) {
        const int ci = pou.chart_index(as.chart);
        if (ci < 0) {
          error(as.where, "unknown chart '" + as.chart + "'");
          continue;
        }
        const int si = pou.charts[static_cast<std::size_t>(ci)].step_index(as.step);
        if (si >= 0)
          step = p.charts[sc.chart_ids[static_cast<std::size_t>(ci)]]
                     .steps[static_cast<std::size_t>(si)];
      } else {
        step = find_step(sc, as.step, -1, as.where, true);
      }
      if (!step) {
        error(as.where, "action block of unknown step '" + as.step + "'");
        continue;
      }
      auto it = sc.actions.find(model::to_upper(as.action));
      if (it == sc.actions.end() && callable_association(sc, as.action)) {
        // `inst.ACT` or an SFC action run as a unit: an action whose body calls it, so that
        // the step runs it in every cycle where the association keeps the action active.
        const auto id = add_action(sc, as.action, model::ActionBodyKind::Statements, as.where);
        model::StmtList call;
        call.push_back(model::make_fb_call(as.action, {}, as.where));
        p.actions[id].body = block(sc, call);
        it = sc.actions.find(model::to_upper(as.action));
      }
      if (it == sc.actions.end()) {
        // An action block may name a Boolean variable directly.
        auto v = sc.names.find(model::to_upper(as.action));
        if (v == sc.names.end() || v->second.kind != Ref::Field || !v->second.is_bool) {
          error(as.where, "action block names '" + as.action +
                              "', which is neither an action nor a Boolean variable of " +
                              pou.name);
          continue;
        }
        const auto id = add_action(sc, as.action, model::ActionBodyKind::Variable, as.where);
        p.actions[id].variable = static_cast<std::int32_t>(v->second.index);
        it = sc.actions.find(model::to_upper(as.action));
      }
      if (const auto* ma = pou.find_action(as.action); ma && ma->body_unsupported) {
        error(as.where, "step '" + as.step + "' activates action '" + ma->name +
                            "', whose body sfcv does not model (" + ma->unsupported_reason + ")");
        continue;
      }
      Assoc ca;
      ca.step = *step;
      ca.action = it->second;
      ca.q = as.qualifier;
      ca.step_action = as.step_action;
      if (as.qualifier == Qualifier::DL) {
        error(as.where, "qualifier DL is not defined by IEC 61131-3 (use D, L, SD, DS or SL)");
        continue;
      }
      if (model::is_timed(as.qualifier)) {
        std::optional<std::int64_t> d = as.duration_ms;
        if (!d && !as.duration_variable.empty()) d = constant_variable(pou, as.duration_variable);
        if (!d) {
          error(as.where, "qualifier " + std::string(model::to_string(as.qualifier)) +
                              " needs a constant duration (a literal, or a VAR or VAR_OUTPUT "
                              "that nothing writes)");
          continue;
        }
        const std::string nm = p.steps[*step].name + "." + as.action + "." +
                               std::string(model::to_string(as.qualifier));
        ca.timer = make_timer(nm, *d, nm);
        if (as.qualifier == Qualifier::SD || as.qualifier == Qualifier::SL)
          ca.latch = static_cast<std::int32_t>(
              add_field(nm + ".set", FieldKind::ActionStored, 0, 1, 0, true));
      }
      auto& act = p.actions[ca.action];
      if ((as.qualifier == Qualifier::S || as.qualifier == Qualifier::DS) && act.stored == kNone)
        act.stored = static_cast<std::int32_t>(
            add_field(act.name + ".stored", FieldKind::ActionStored, 0, 1, 0, true));
      p.assocs.push_back(ca);
      act.assocs.push_back(static_cast<std::uint32_t>(p.assocs.size() - 1));
    }
    // Transitions.
    for (std::size_t ci = 0; ci < pou.charts.size(); ++ci) {
      const auto& ch = pou.charts[ci];
      const auto cid = sc.chart_ids[ci];
      // Indexed once per chart: Chart::step_index per transition is quadratic on long charts.
      std::unordered_map<std::string, int> step_of;
      for (std::size_t i = 0; i < ch.steps.size(); ++i)
        step_of.try_emplace(model::to_upper(ch.steps[i].name), static_cast<int>(i));
      for (const auto& t : ch.transitions) {
        poll_deadline();
        Transition ct;
        ct.chart = cid;
        bool good = true;
        auto resolve = [&](const std::vector<std::string>& names, std::vector<std::uint32_t>& out) {
          for (const auto& n : names) {
            const auto found = step_of.find(model::to_upper(n));
            const int si = found == step_of.end() ? -1 : found->second;
            if (si < 0) {
              error(t.where,
                    "transition refers to unknown step '" + n + "' of chart '" + ch.name + "'");
              good = false;
            } else {
              out.push_back(p.charts[cid].steps[static_cast<std::size_t>(si)]);
            }
          }
        };
        resolve(t.sources, ct.sources);
        resolve(t.targets, ct.targets);
        if (ct.sources.empty() || ct.targets.empty()) {
          if (good) error(t.where, "transition without source or target step");
          continue;
        }
        ct.guard = bool_expr(sc, t.guard, static_cast<int>(cid), t.where, "transition condition");
        ct.rank = (static_cast<std::int64_t>(t.priority.value_or(std::numeric_limits<int>::max()))
                   << 32) +
                  t.order;
        ct.index = static_cast<std::uint32_t>(p.transitions.size());
        TransitionInfo info;
        const std::string prefix =
            sc.name + (ch.parent_action.empty() ? "" : "." + ch.parent_action);
        if (!t.name.empty()) {
          info.name = prefix + "." + t.name;
        } else {
          std::string src, dst;
          for (auto s : t.sources) src += (src.empty() ? "" : ", ") + s;
          for (auto s : t.targets) dst += (dst.empty() ? "" : ", ") + s;
          info.name = prefix + ": " + src + " -> " + dst;
        }
        info.pou = sc.name;
        info.chart = ch.name;
        info.where = t.where;
        p.transition_infos.push_back(std::move(info));
        p.transitions.push_back(std::move(ct));
      }
    }
  }
  // Per chart: priority order, or the groups of alternatives for PriorityMode::None.
  for (std::uint32_t ti = 0; ti < p.transitions.size(); ++ti)
    p.charts[p.transitions[ti].chart].ordered.push_back(ti);
  for (auto& c : p.charts) {
    std::stable_sort(c.ordered.begin(), c.ordered.end(),
                     [&](auto a, auto b) { return p.transitions[a].rank < p.transitions[b].rank; });
    if (p.options.priority != PriorityMode::None) continue;
    std::vector<std::uint8_t> grouped(p.transitions.size());
    // Document order within the group.
    std::vector<std::uint32_t> doc = c.ordered;
    std::stable_sort(doc.begin(), doc.end(), [&](auto a, auto b) {
      return (p.transitions[a].rank & 0xffffffff) < (p.transitions[b].rank & 0xffffffff);
    });
    for (auto s : c.steps) {
      std::vector<std::uint32_t> out;
      for (auto ti : doc)
        if (std::find(p.transitions[ti].sources.begin(), p.transitions[ti].sources.end(), s) !=
            p.transitions[ti].sources.end())
          out.push_back(ti);
      if (out.size() < 2) continue;
      bool simple = true;
      for (auto ti : out)
        if (p.transitions[ti].sources.size() != 1) {
          error(p.transition_infos[ti].where,
                "with --priority none, transition '" + p.transition_infos[ti].name +
                    "' synchronises several steps and conflicts with another transition leaving '" +
                    p.steps[s].short_name + "'; sfcv cannot model this conflict faithfully");
          simple = false;
        }
      if (!simple) continue;
      AltGroup g;
      g.step = s;
      g.transitions = out;
      g.choice_input = add_input(
          "choice:" + p.steps[s].name,
          model::Type::integer("INT", 0, static_cast<std::int64_t>(out.size()) - 1), true);
      for (auto ti : out) grouped[ti] = 1;
      c.groups.push_back(std::move(g));
    }
    for (auto ti : doc)
      if (!grouped[ti]) c.singles.push_back(ti);
  }
}

// CODESYS SFC help, "Processing order in SFC" (Beckhoff's TwinCAT 3 help, "Processing order in
// SFC", the same): a cycle runs the exit actions of the steps, then their entry actions, then
// the step (main) actions, each "from top to bottom, left to right", and then the IEC actions
// "in alphabetical order". A step action's place is its first role's, by step.
void Compiler::vendor_order(std::vector<std::uint32_t>& order) const {
  auto key = [&](std::uint32_t a) {
    int role = 3;  // an IEC action (or none associated: never active)
    std::uint32_t step = 0;
    for (auto x : p.actions[a].assocs) {
      const auto& as = p.assocs[x];
      if (!as.step_action) continue;
      const int r = as.q == Qualifier::P0 ? 0 : as.q == Qualifier::P1 ? 1 : 2;
      if (role == 3 || std::pair(r, as.step) < std::pair(role, step)) role = r, step = as.step;
    }
    return std::tuple(role, step, role == 3 ? model::to_upper(p.actions[a].name) : std::string());
  };
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return key(a) < key(b); });
}

void Compiler::final_calls() {
  const auto dialect = p.options.dialect;
  const bool vendor = dialect == VendorDialect::Codesys || dialect == VendorDialect::Twincat;
  const auto written_by = file_dialect(project);
  std::vector<std::string> without;     // --dialect iec: IEC actions whose final call is lost
  const auto count = p.actions.size();  // twins are appended
  for (std::size_t ai = 0; ai < count; ++ai) {
    bool iec = false, step = false;
    for (auto x : p.actions[ai].assocs) (p.assocs[x].step_action ? step : iec) = true;
    // A Boolean variable action has no body: its variable is FALSE again either way.
    if (!iec || p.actions[ai].kind == model::ActionBodyKind::Variable) continue;
    if (!vendor) {
      without.push_back(p.actions[ai].name);
      continue;
    }
    // Neither vendor's help says what the final call of an action whose body is a chart does
    // (its chart run once more? reset?): a verdict would rest on a guess, so it is refused by
    // name, and --dialect iec (no final calls, the chart suspended as in 1.3) reads it.
    if (p.actions[ai].kind == model::ActionBodyKind::Chart) {
      error(p.actions[ai].where,
            "action '" + p.actions[ai].name + "' has a chart as its body and is an IEC action: " +
                std::string(to_string(dialect)) +
                " runs it once more after it becomes inactive (its final call), and its help "
                "does not say what that call does to the chart, so sfcv does not read it under "
                "--dialect " +
                std::string(to_string(dialect)) +
                "; --dialect iec reads it without final calls (docs/semantics.md 1.4a)");
      continue;
    }
    if (step) step_action_twin(static_cast<std::uint32_t>(ai));
    auto& a = p.actions[ai];
    a.final_call = static_cast<std::int32_t>(
        add_field(a.name + ".final", FieldKind::ActionFinalCall, 0, 1, 0, true));
  }
  if (vendor || without.empty() ||
      (written_by != VendorDialect::Codesys && written_by != VendorDialect::Twincat))
    return;
  std::string list;
  for (std::size_t i = 0; i < without.size() && i < 3; ++i) list += (i ? ", " : "") + without[i];
  if (without.size() > 3) list += " and " + std::to_string(without.size() - 3) + " more";
  warning(project.where, std::string(to_string(written_by)) +
                             " runs each IEC action once more in the cycle after it becomes "
                             "inactive (its final call); --dialect " +
                             std::string(to_string(dialect)) +
                             " does not (docs/semantics.md 1.4a), so the verdicts do not cover "
                             "what the final calls of " +
                             list + " do");
}

void Compiler::step_action_twin(std::uint32_t ai) {
  // CODESYS calls a step action in the step phase and an IEC action in the IEC phase, apart: an
  // action in both roles is two actions of one body, the twin holding the step associations
  // (no final call, the step actions' place in the order). It has no observable of its own.
  Action twin;
  twin.name = p.actions[ai].name + " (step action)";
  twin.pou = p.actions[ai].pou;
  twin.kind = p.actions[ai].kind;
  twin.body = p.actions[ai].body;
  twin.active = add_field(twin.name, FieldKind::ActionActive, 0, 1, 0, true);
  const auto id = static_cast<std::uint32_t>(p.actions.size());
  auto& a = p.actions[ai];
  std::erase_if(a.assocs, [&](std::uint32_t x) {
    if (!p.assocs[x].step_action) return false;
    p.assocs[x].action = id;
    twin.assocs.push_back(x);
    return true;
  });
  scopes[twin.pou].actions[model::to_upper(twin.name)] = id;
  p.actions.push_back(std::move(twin));
}

void Compiler::orders() {
  const auto& pairs = p.options.action_pairs;
  std::vector<std::uint32_t> pair_used(pairs.size(), 0);
  for (auto& sc : scopes) {
    auto& cp = p.pous[sc.index];
    std::vector<std::uint32_t> acts;
    for (const auto& [up, id] : sc.actions) acts.push_back(id);
    std::sort(acts.begin(), acts.end());  // creation order = declaration order
    cp.exec_order = acts;
    if (p.options.action_order == ActionOrder::Alphabetical)
      std::stable_sort(cp.exec_order.begin(), cp.exec_order.end(), [&](auto a, auto b) {
        return model::to_upper(p.actions[a].name) < model::to_upper(p.actions[b].name);
      });
    if (p.options.action_order == ActionOrder::Vendor) vendor_order(cp.exec_order);
    if (p.options.action_order == ActionOrder::Partial ||
        p.options.action_order == ActionOrder::Unordered)
      action_order(sc, pair_used);
    // Topological order: an action after the actions holding the charts of its steps.
    std::vector<int> mark(p.actions.size(), 0);
    std::function<void(std::uint32_t)> visit = [&](std::uint32_t a) {
      if (mark[a] == 2) return;
      if (mark[a] == 1) {
        error(sc.pou->where, "action '" + p.actions[a].name +
                                 "' is associated with a step of a chart it (indirectly) holds");
        return;
      }
      mark[a] = 1;
      for (auto x : p.actions[a].assocs) {
        const auto pa = p.charts[p.steps[p.assocs[x].step].chart].parent_action;
        if (pa != kNone) visit(static_cast<std::uint32_t>(pa));
      }
      mark[a] = 2;
      cp.topo_order.push_back(a);
    };
    for (auto a : acts) visit(a);
  }
  // Every pair names two actions of one POU (of some instance, for a function block's).
  auto known = [&](const std::string& name) {
    const auto up = model::to_upper(name);
    for (const auto& a : p.actions) {
      const auto full = model::to_upper(a.name);
      if (full == up || full.ends_with("." + up)) return true;
    }
    return false;
  };
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (p.options.action_order != ActionOrder::Partial || (pair_used[k] & 1)) continue;
    const auto& pr = pairs[k];
    if (!known(pr.before) || !known(pr.after))
      error(pr.where, "the action order names an unknown action '" +
                          (known(pr.before) ? pr.after : pr.before) + "'");
    else
      error(pr.where, "'" + pr.before + "' and '" + pr.after + "' are not actions of one POU");
  }
}

void Compiler::step_timers() {
  const auto cycle = std::max<std::int64_t>(p.options.cycle_ms, 1);
  for (auto& [step, keys] : t_keys) {
    auto& s = p.steps[step];
    if (p.options.time == TimeMode::Discrete) {
      const auto mx = std::max<std::int64_t>(*keys.rbegin(), 0);
      s.t_max = mx / cycle + 1;
      s.t_field = static_cast<std::int32_t>(
          add_field(s.name + ".T", FieldKind::Timer, 0, s.t_max, 0, false));
    } else {
      s.thresholds.assign(keys.begin(), keys.end());
      const auto top = static_cast<std::int64_t>(s.thresholds.size());
      s.t_field =
          static_cast<std::int32_t>(add_field(s.name + ".T", FieldKind::Timer, 0, top, 0, false));
      s.elapse_input = static_cast<std::int32_t>(
          add_input("elapse:" + s.name, model::Type::integer("INT", 0, top), true));
    }
  }
  // A user FB instance's chart runs at its calls, which need not be one per cycle: its step
  // times and qualifier timers read the cycle clock instead (docs/semantics.md §1.6).
  for (auto& s : p.steps) s.clocked = p.pous[p.charts[s.chart].pou].instance;
  for (const auto& as : p.assocs)
    if (as.timer != kNone && p.steps[as.step].clocked)
      p.timers[static_cast<std::size_t>(as.timer)].clocked = true;
  for (auto n : t_nodes) {
    auto& node = p.nodes[n];
    const auto& th = p.steps[node.a].thresholds;
    node.k = (std::lower_bound(th.begin(), th.end(), node.k) - th.begin()) + 1;
  }
}

void Compiler::step_observables() {
  for (std::uint32_t i = 0; i < p.steps.size(); ++i) {
    const auto& s = p.steps[i];
    Observable o;
    o.name = s.name;
    o.aliases = {s.short_name, s.short_name + ".X", s.name + ".X"};
    // A step of an instance is also named from its program: Crane.Init for Main.Crane.Init.
    if (const auto& pou = p.pous[p.charts[s.chart].pou]; pou.instance) {
      const auto below = s.name.substr(s.name.find('.') + 1);
      o.aliases.push_back(below);
      o.aliases.push_back(below + ".X");
    }
    o.kind = ObservableKind::Step;
    o.type = model::Type::boolean();
    p.observables.push_back(std::move(o));
    p.observable_refs.push_back(ObservableRef{ObservableKind::Step, i});
  }
}

}  // namespace sfcv::semantics::iec::detail
