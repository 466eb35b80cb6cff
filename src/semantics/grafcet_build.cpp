// GrafcetSystem::build: a model::Project into the Grafcet system's tables, one function per
// group of IEC 60848 rules (charts and steps, enclosing and macro-steps, the variables that
// continuous and stored actions write, transitions, stored and continuous actions, forcing
// orders, inputs and delays, observables, the initial situation). The expression compiler and
// the evolution rules are in grafcet_system.cpp.

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

#include "model/errors.hpp"
#include "model/names.hpp"
#include "semantics/detail/grafcet_system_impl.hpp"

namespace sfcv::semantics::grafcet {

void GrafcetSystem::build(const model::Project& project) {
  build_charts(project);
  build_enclosures_and_expansions(project);
  if (!ok_) return;
  build_expansion_entries_and_exits();
  if (!ok_) return;
  build_step_fields();
  build_macro_step_activity();
  build_variables(project);
  if (!ok_) return;
  build_variable_fields();
  std::size_t cid = 0;
  for (const auto& pou : project.pous) {
    for (const auto& chart : pou.charts) build_transitions(pou, chart, static_cast<int>(cid++));
    build_stored_actions(pou);
    build_continuous_actions(pou);
    build_forcing_orders(pou);
  }
  if (!options_.assumptions.empty())
    error({}, "assumptions are not supported by the Grafcet semantics yet");
  if (!ok_) return;
  build_inputs_and_delays();
  build_observables(project);
  build_initial_situation(project);
}

void GrafcetSystem::poll_build_deadline() {
  if ((++build_polls_ & 1023U) != 0 || !options_.deadline) return;
  if (std::chrono::steady_clock::now() > *options_.deadline)
    throw LimitReached(Limit::Time, "time limit reached while building the system");
}

// Charts and steps.
void GrafcetSystem::build_charts(const model::Project& project) {
  for (const auto& pou : project.pous) {
    for (const auto& chart : pou.charts) {
      GChart gc;
      gc.name = chart.name;
      gc.pou = pou.name;
      gc.macro_entry = chart.macro_entry;
      gc.macro_exit = chart.macro_exit;
      const int cid = static_cast<int>(charts_.size());
      for (const auto& st : chart.steps) {
        poll_build_deadline();
        GStep gs;
        gs.name = st.name;
        gs.chart = cid;
        gs.kind = st.kind;
        gs.initial = st.initial;
        gs.linked = st.activation_link;
        gc.has_initial = gc.has_initial || st.initial;
        gc.has_linked = gc.has_linked || st.activation_link;
        auto& entry = step_index_[model::to_upper(pou.name) + "." + model::to_upper(st.name)];
        entry.step = static_cast<int>(steps_.size());
        ++entry.count;
        ++step_name_count_[model::to_upper(st.name)];
        gc.steps.push_back(static_cast<int>(steps_.size()));
        steps_.push_back(std::move(gs));
      }
      chart_index_.emplace(model::to_upper(gc.pou) + "." + model::to_upper(gc.name),
                           static_cast<int>(charts_.size()));
      charts_.push_back(std::move(gc));
    }
  }
}

// Macro-step expansions and enclosures.
void GrafcetSystem::build_enclosures_and_expansions(const model::Project& project) {
  std::size_t sid = 0;
  for (const auto& pou : project.pous)
    for (const auto& chart : pou.charts)
      for (const auto& st : chart.steps) {
        GStep& gs = steps_[sid++];
        if (st.kind == model::StepKind::MacroStep) {
          gs.expansion = find_chart(pou.name, st.expansion);
          if (gs.expansion < 0) {
            error(st.where, "macro-step " + st.name + ": unknown expansion '" + st.expansion + "'");
            continue;
          }
          charts_[gs.expansion].top_level = false;
        } else if (st.kind == model::StepKind::Enclosing) {
          for (const auto& name : st.enclosed) {
            const int c = find_chart(pou.name, name);
            if (c < 0) {
              error(st.where,
                    "enclosing step " + st.name + ": unknown partial grafcet '" + name + "'");
              continue;
            }
            gs.enclosed.push_back(c);
            charts_[c].top_level = false;
          }
          enclosing_.push_back(static_cast<int>(sid - 1));
        }
      }
}

// Entry and exit steps of expansions: the steps the file marks (`entry`/`exit`, AGRAFE's), else
// "E<macro>"/"S<macro>" by name (IEC 60848's naming), else the initial-marked step / the first
// and last steps.
void GrafcetSystem::build_expansion_entries_and_exits() {
  for (auto& gs : steps_) {
    if (gs.kind != model::StepKind::MacroStep) continue;
    const auto& ex = charts_[gs.expansion];
    // Macro-step M2 (or 2) has entry step E2 and exit step S2.
    const std::string number = gs.name.size() > 1 && (gs.name[0] == 'M' || gs.name[0] == 'm')
                                   ? gs.name.substr(1)
                                   : gs.name;
    for (int s : ex.steps) {
      if (model::iequals(steps_[s].name, "E" + number) ||
          model::iequals(steps_[s].name, "E" + gs.name))
        gs.entry = s;
      if (model::iequals(steps_[s].name, "S" + number) ||
          model::iequals(steps_[s].name, "S" + gs.name))
        gs.exit = s;
    }
    for (int s : ex.steps) {
      if (!ex.macro_entry.empty() && steps_[s].name == ex.macro_entry) gs.entry = s;
      if (!ex.macro_exit.empty() && steps_[s].name == ex.macro_exit) gs.exit = s;
    }
    if (gs.entry < 0)
      for (int s : ex.steps)
        if (steps_[s].initial) gs.entry = s;
    if (gs.entry < 0 && !ex.steps.empty()) gs.entry = ex.steps.front();
    if (gs.exit < 0 && !ex.steps.empty()) gs.exit = ex.steps.back();
    if (gs.entry < 0) {
      error({}, "macro-step " + gs.name + ": empty expansion " + ex.name);
      return;
    }
    if (steps_[gs.entry].kind == model::StepKind::MacroStep ||
        steps_[gs.exit].kind == model::StepKind::MacroStep) {
      error({}, "macro-step " + gs.name +
                    ": an entry or exit step that is itself a macro-step is "
                    "not supported");
      return;
    }
  }
}

// Step fields (a macro-step has none: its activity is derived).
void GrafcetSystem::build_step_fields() {
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    auto& gs = steps_[i];
    if (gs.kind == model::StepKind::MacroStep) continue;
    gs.field = static_cast<int>(
        layout_.add_field(charts_[gs.chart].name + "." + gs.name, FieldKind::StepActive));
    const auto bit = layout_.fields()[static_cast<std::size_t>(gs.field)].offset;
    if (step_mask_.size() <= bit / 64) step_mask_.resize(bit / 64 + 1, 0);
    step_mask_[bit / 64] |= StateWord{1} << (bit % 64);
    if (step_field_at_bit_.size() <= bit) step_field_at_bit_.resize(bit + 1, 0);
    step_field_at_bit_[bit] = static_cast<std::uint32_t>(gs.field);
  }
}

// Derived activity of macro-steps (expansions may hold macro-steps: close transitively).
void GrafcetSystem::build_macro_step_activity() {
  for (auto& gs : steps_) {
    if (gs.kind != model::StepKind::MacroStep) continue;
    std::vector<int> todo{gs.expansion};
    std::vector<bool> seen(charts_.size());
    while (!todo.empty()) {
      const int c = todo.back();
      todo.pop_back();
      if (seen[static_cast<std::size_t>(c)]) continue;
      seen[static_cast<std::size_t>(c)] = true;
      for (int s : charts_[c].steps) {
        if (steps_[s].field >= 0) gs.derived_from.push_back(steps_[s].field);
        if (steps_[s].expansion >= 0) todo.push_back(steps_[s].expansion);
        for (int e : steps_[s].enclosed) todo.push_back(e);
      }
    }
  }
}

// Writers: stored actions and continuous actions. A Boolean variable both kinds write is kept
// (IEC 60848 gives it one mode; output-conflicts reports where the two disagree, 2.7).
void GrafcetSystem::build_variables(const model::Project& project) {
  for (const auto& pou : project.pous) {
    auto var_of = [&](const std::string& name, bool continuous,
                      const model::SourceLocation& where) -> int {
      const std::string key = model::to_upper(pou.name) + "." + model::to_upper(name);
      if (auto it = var_index_.find(key); it != var_index_.end()) {
        auto& v = vars_[static_cast<std::size_t>(it->second)];
        if (continuous && v.type.kind != model::TypeKind::Bool) {
          error(where, "continuous action on non-Boolean variable '" + name + "'");
          return -1;
        }
        (continuous ? v.continuous : v.stored) = true;
        return it->second;
      }
      GVar v;
      const model::Variable* decl = pou.find_variable(name);
      v.name = decl ? decl->name : name;
      v.type = decl ? decl->type : model::Type::boolean();
      if (v.type.kind == model::TypeKind::FunctionBlock) {
        error(where, "'" + name + "' is a function block instance, not a Grafcet variable");
        return -1;
      }
      if (continuous && v.type.kind != model::TypeKind::Bool) {
        error(where, "continuous action on non-Boolean variable '" + name + "'");
        return -1;
      }
      (continuous ? v.continuous : v.stored) = true;
      vars_.push_back(v);
      var_index_[key] = static_cast<int>(vars_.size() - 1);
      return static_cast<int>(vars_.size() - 1);
    };
    for (const auto& sa : pou.stored_actions) var_of(sa.variable, false, sa.where);
    for (const auto& as : pou.associations) {
      if (as.qualifier != model::Qualifier::N) {
        error(as.where, "action qualifier " + std::string(model::to_string(as.qualifier)) +
                            " is not part of IEC 60848: use a stored action or a delay");
        continue;
      }
      std::string target = as.action;
      if (const auto* a = pou.find_action(as.action)) {
        if (a->kind == model::ActionBodyKind::Variable) {
          target = a->variable;
        } else {
          error(as.where,
                "action '" + as.action + "' has a body: Grafcet actions assign variables");
          continue;
        }
      }
      var_of(target, true, as.where);
    }
  }
}

void GrafcetSystem::build_variable_fields() {
  for (auto& v : vars_) {
    const auto lo = v.type.kind == model::TypeKind::Bool ? 0 : v.type.lo;
    const auto hi = v.type.kind == model::TypeKind::Bool ? 1 : v.type.hi;
    v.field = static_cast<int>(layout_.add_field(v.name, FieldKind::Variable, lo, hi));
    if (v.mixed())
      v.memory_field = static_cast<int>(
          layout_.add_field(v.name + std::string(kStoredFieldSuffix), FieldKind::Variable, 0, 1));
  }
}

// Transitions: the steps they clear (need) and activate (act), and their receptivity.
void GrafcetSystem::build_transitions(const model::Pou& pou, const model::Chart& chart,
                                      int chart_id) {
  // Indexed once per chart (the first step of a name, as a linear search would find):
  // looking steps up per transition is quadratic on long charts.
  std::unordered_map<std::string, int> step_index;
  for (int s : charts_[chart_id].steps) step_index.try_emplace(model::to_upper(steps_[s].name), s);
  auto step_of = [&](const std::string& n) {
    const auto it = step_index.find(model::to_upper(n));
    return it == step_index.end() ? -1 : it->second;
  };
  for (const auto& t : chart.transitions) {
    poll_build_deadline();
    GTrans gt;
    gt.chart = chart_id;
    bool good = true;
    for (const auto& n : t.sources) {
      const int s = step_of(n);
      if (s < 0) {
        error(t.where, "unknown step '" + n + "'");
        good = false;
        continue;
      }
      const auto& gs = steps_[s];
      gt.need.push_back(gs.field >= 0 ? gs.field : steps_[gs.exit].field);
    }
    for (const auto& n : t.targets) {
      const int s = step_of(n);
      if (s < 0) {
        error(t.where, "unknown step '" + n + "'");
        good = false;
        continue;
      }
      const auto& gs = steps_[s];
      gt.act.push_back(gs.field >= 0 ? gs.field : steps_[gs.entry].field);
    }
    if (!good || !compile_top(pou, *t.guard, gt.guard)) continue;
    trans_.push_back(std::move(gt));
    TransitionInfo info;
    // As IEC 60848 writes it: "(5) X2 -> X4", "X1 -> X2,X3" when unnumbered; a step
    // name that several charts use keeps its chart ("G1.X2"), like the observables.
    auto step_text = [&](const std::string& n) {
      return steps_named(n) > 1 ? chart.name + ".X" + n : "X" + n;
    };
    std::string from, to;
    for (const auto& n : t.sources) from += (from.empty() ? "" : ",") + step_text(n);
    for (const auto& n : t.targets) to += (to.empty() ? "" : ",") + step_text(n);
    info.name = (t.name.empty() ? "" : "(" + t.name + ") ") + from + " -> " + to;
    info.pou = pou.name;
    info.chart = chart.name;
    info.where = t.where;
    trans_info_.push_back(std::move(info));
  }
}

// The step an action or forcing order names: in `chart` when given, else the POU's step of that
// name.
int GrafcetSystem::step_in(const model::Pou& pou, const std::string& chart, const std::string& step,
                           const model::SourceLocation& where) {
  const int c = chart.empty() ? -1 : find_chart(pou.name, chart);
  int s = -1;
  if (c >= 0) {
    for (int x : charts_[c].steps)
      if (model::iequals(steps_[x].name, step)) s = x;
  } else {
    s = find_step(pou.name, step);
  }
  if (s < 0) error(where, "unknown step '" + (chart.empty() ? "" : chart + ".") + step + "'");
  return s;
}

// Stored actions: on activation, on deactivation, on event.
void GrafcetSystem::build_stored_actions(const model::Pou& pou) {
  for (const auto& sa : pou.stored_actions) {
    GStored g;
    g.step = step_in(pou, sa.chart, sa.step, sa.where);
    g.when = sa.when;
    g.var = var_index_.at(model::to_upper(pou.name) + "." + model::to_upper(sa.variable));
    if (g.step < 0) continue;
    if (sa.when == model::StoredWhen::Event) {
      if (!sa.event) {
        error(sa.where, "stored action on event without an event");
        continue;
      }
      if (!compile_top(pou, *sa.event, g.event)) continue;
    }
    if (!sa.value || !compile_top(pou, *sa.value, g.value)) {
      if (!sa.value) error(sa.where, "stored action without a value");
      continue;
    }
    stored_.push_back(std::move(g));
  }
}

// Continuous actions, possibly with an assignment condition.
void GrafcetSystem::build_continuous_actions(const model::Pou& pou) {
  for (const auto& as : pou.associations) {
    GContinuous g;
    g.step = step_in(pou, as.chart, as.step, as.where);
    g.var =
        var_index_.at(model::to_upper(pou.name) + "." + model::to_upper(pou.assigned_variable(as)));
    if (g.step < 0) continue;
    if (as.condition) {
      g.has_condition = true;
      if (!compile_top(pou, *as.condition, g.condition)) continue;
    }
    continuous_.push_back(std::move(g));
  }
}

// Forcing orders on partial grafcets.
void GrafcetSystem::build_forcing_orders(const model::Pou& pou) {
  for (const auto& fo : pou.forcing_orders) {
    GForce g;
    g.step = step_in(pou, fo.chart, fo.step, fo.where);
    g.chart = find_chart(pou.name, fo.target);
    g.kind = fo.kind;
    if (g.chart < 0) {
      error(fo.where, "forcing order on unknown partial grafcet '" + fo.target + "'");
      continue;
    }
    for (const auto& n : fo.situation) {
      int s = -1;
      for (int x : charts_[g.chart].steps)
        if (model::iequals(steps_[x].name, n)) s = x;
      if (s < 0) {
        error(fo.where, "forced step '" + n + "' is not in partial grafcet " + fo.target);
      } else if (steps_[s].field < 0) {
        g.situation.push_back(steps_[s].entry);
      } else {
        g.situation.push_back(s);
      }
    }
    if (g.step >= 0) forces_.push_back(std::move(g));
  }
}

// Inputs: stored ones get a memory field; each running delay gets a pseudo-input.
void GrafcetSystem::build_inputs_and_delays() {
  finish_inputs();
  for (auto& in : gin_) {
    if (!options_.single_input_change && !in.edge) continue;
    in.field =
        static_cast<int>(layout_.add_field(in.name, FieldKind::InputMemory, 0, in.regions() - 1));
  }
  for (std::size_t d = 0; d < delays_.size(); ++d) {
    auto& dl = delays_[d];
    dl.field =
        static_cast<int>(layout_.add_field(std::to_string(dl.t1) + "ms/" + model::to_st(dl.source) +
                                               "/" + std::to_string(dl.t2) + "ms",
                                           FieldKind::Timer, 0, 3));
    if (dl.t1 > 0 || dl.t2 > 0) {
      GInput p;
      p.name = "elapse(" + std::to_string(dl.t1) + "ms/" + model::to_st(dl.source) + "/" +
               std::to_string(dl.t2) + "ms)";
      p.pseudo = true;
      p.delay = static_cast<int>(d);
      gin_.push_back(p);
      dl.pseudo = static_cast<int>(gin_.size() - 1);
    }
  }
  if (layout_.bits() == 0) layout_.add_field("(empty)", FieldKind::Variable, 0, 0);
  for (const auto& in : gin_) {
    InputVariable iv;
    iv.name = in.name;
    iv.type = in.pseudo ? model::Type::boolean() : in.type;
    iv.pseudo = in.pseudo;
    input_vars_.push_back(iv);
  }
}

// Observables: steps, variables, stored inputs.
void GrafcetSystem::build_observables(const model::Project& project) {
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    const auto& gs = steps_[i];
    const auto& chart = charts_[gs.chart].name;
    const int same = steps_named(gs.name);
    Observable o;
    o.kind = ObservableKind::Step;
    o.type = model::Type::boolean();
    o.name = same > 1 ? chart + ".X" + gs.name : "X" + gs.name;
    o.aliases = {gs.name, chart + "." + gs.name, chart + ".X" + gs.name, "X" + gs.name};
    observables_.push_back(o);
    obs_info_.push_back({ObsRef::Step, static_cast<int>(i)});
  }
  for (std::size_t i = 0; i < vars_.size(); ++i) {
    const auto& v = vars_[i];
    Observable o;
    o.name = v.name;
    o.type = v.type;
    // Declared internal variables (counters, flags) are observable but not outputs.
    o.is_output = true;
    for (const auto& pou : project.pous)
      if (const auto* decl = pou.find_variable(v.name))
        o.is_output = decl->direction == model::VarDirection::Output ||
                      decl->direction == model::VarDirection::InOut;
    observables_.push_back(o);
    obs_info_.push_back({ObsRef::Variable, static_cast<int>(i)});
  }
  for (std::size_t i = 0; i < gin_.size(); ++i) {
    if (gin_[i].field < 0) continue;
    Observable o;
    o.name = gin_[i].name;
    o.type = gin_[i].type;
    observables_.push_back(o);
    obs_info_.push_back({ObsRef::Input, static_cast<int>(i)});
  }
}

// The initial situation before stabilisation: initial steps of the top-level partial
// grafcets, closed under enclosure (initial steps, else linked ones, 2.2) and macro-step entry.
void GrafcetSystem::build_initial_situation(const model::Project& project) {
  initial_template_.assign(layout_.words(), 0);
  for (std::size_t c = 0; c < charts_.size(); ++c)
    if (charts_[c].top_level) init_chart(initial_template_, static_cast<int>(c));
  for (const auto& v : vars_) {
    std::int64_t init =
        v.type.kind == model::TypeKind::Bool ? 0 : std::max<std::int64_t>(v.type.lo, 0);
    for (const auto& pou : project.pous)
      if (const auto* decl = pou.find_variable(v.name); decl && decl->initial)
        init = *decl->initial;
    layout_.set(initial_template_, static_cast<std::uint32_t>(v.stored_field()), init);
  }
}

}  // namespace sfcv::semantics::grafcet
