// Validation of one chart's structure: step kinds, initial steps, reachability along the
// transitions, and the IEC 61131-3 parallel structure (unsafe and unreachable SFCs).

#include <algorithm>
#include <array>
#include <cctype>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "model/detail/validator.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"
#include "model/networks.hpp"

namespace sfcv::model::detail {

std::string Validator::chart_label(const Chart& chart) const {
  if (!chart.parent_action.empty()) return "the chart of action " + quoted(chart.parent_action);
  return "chart " + quoted(chart.name.empty() ? pou_->name : chart.name);
}

void Validator::check_chart(const Chart& chart, bool activated_otherwise) {
  const auto& where = at(chart.where, pou_->where);
  check_duplicates(chart.steps, "step", where);
  check_duplicates(chart.transitions, "transition", where);

  if (!chart.parent_action.empty() && !pou_->find_action(chart.parent_action))
    error(where, chart_label(chart) + " belongs to an undeclared action");

  for (const auto& s : chart.steps) {
    poll_.tick_or_throw("validating the model");
    check_step_kind(s, where);
  }

  // An undeclared step is one defect however many transitions name it: one error, at the
  // first transition that names it, listing the others.
  struct Undeclared {
    std::string name;
    const SourceLocation* first;
    bool as_source;
    std::vector<const SourceLocation*> others;
  };
  std::vector<Undeclared> undeclared;
  auto note_undeclared = [&](const std::string& name, const SourceLocation& here, bool source) {
    for (auto& u : undeclared)
      if (iequals(u.name, name)) {
        if (u.first != &here &&
            std::find(u.others.begin(), u.others.end(), &here) == u.others.end())
          u.others.push_back(&here);
        return;
      }
    undeclared.push_back({name, &here, source, {}});
  };
  for (const auto& t : chart.transitions) {
    poll_.tick_or_throw("validating the model");
    const auto& here = at(t.where, where);
    // IEC 60848 has source transitions (no upstream step) and sink transitions (no
    // downstream step); IEC 61131-3 has neither.
    if (!grafcet() && t.sources.empty()) error(here, "transition has no source step");
    if (!grafcet() && t.targets.empty()) error(here, "transition has no target step");
    for (const auto& s : t.sources)
      if (!has_step(chart, s)) note_undeclared(s, here, true);
    for (const auto& s : t.targets)
      if (!has_step(chart, s)) note_undeclared(s, here, false);
    expect_bool(t.guard, here, "the guard");
  }
  for (const auto& u : undeclared) {
    std::string also;
    for (const auto* o : u.others) also += (also.empty() ? "" : ", ") + place(*o, *u.first);
    error(*u.first, std::string("transition ") + (u.as_source ? "from" : "to") +
                        " undeclared step " + quoted(u.name) +
                        (also.empty() ? std::string()
                                      : " (also named by the transition" +
                                            std::string(u.others.size() > 1 ? "s" : "") + " at " +
                                            also + ")"));
  }

  check_initial_steps(chart, activated_otherwise);
  check_reachability(chart);
  // A parallel branch ending in a jump is the CODESYS/TwinCAT idiom the reader warned about
  // (docs/semantics.md 1.2b): "unsafe" by design there, and run with step flags.
  if (!grafcet() && !chart.parallel_branch_jump.known()) check_parallel_structure(chart);
}

void Validator::check_step_kind(const Step& s, const SourceLocation& fallback) {
  const auto& here = at(s.where, fallback);
  if (s.kind == StepKind::MacroStep) {
    if (s.expansion.empty())
      error(here, "macro-step " + quoted(s.name) + " has no expansion");
    else if (!find_chart(s.expansion))
      error(here, "macro-step " + quoted(s.name) + " expands into undeclared chart " +
                      quoted(s.expansion));
  }
  if (s.kind == StepKind::Enclosing) {
    for (const auto& e : s.enclosed)
      if (!find_chart(e))
        error(here, "enclosing step " + quoted(s.name) + " encloses undeclared chart " + quoted(e));
  }
}

void Validator::check_initial_steps(const Chart& chart, bool activated_otherwise) {
  const auto& where = at(chart.where, pou_->where);
  const bool any =
      std::any_of(chart.steps.begin(), chart.steps.end(), [](const Step& s) { return s.initial; });
  if (!any) {
    // A Grafcet partial grafcet may start empty when an enclosing step, a macro-step or a
    // forcing order activates it; an IEC 61131-3 SFC always needs an initial step.
    if (!(grafcet() && activated_otherwise))
      error(where, chart_label(chart) + " has no initial step");
    return;
  }
  if (grafcet()) return;  // IEC 60848: any set of steps may be initial
  // IEC 61131-3: one initial step per network; several networks are several sequences.
  const auto network = step_networks(chart);
  std::map<int, const Step*> initial_of;
  for (std::size_t i = 0; i < chart.steps.size(); ++i) {
    const Step& s = chart.steps[i];
    if (!s.initial) continue;
    auto [it, fresh] = initial_of.emplace(network[i], &s);
    if (!fresh) {
      const auto& here = at(s.where, where);
      error(here, "second initial step " + quoted(s.name) + " in the network of initial step " +
                      quoted(it->second->name) +
                      " (IEC 61131-3 allows one initial step per network)");
    }
  }
}

void Validator::check_reachability(const Chart& chart) {
  std::vector<char> reached(chart.steps.size(), 0);
  bool seeded = false;
  for (std::size_t i = 0; i < chart.steps.size(); ++i)
    if (chart.steps[i].initial) reached[i] = seeded = true;
  for (const auto& fo : pou_->forcing_orders)
    if (iequals(fo.target, chart.name))
      for (const auto& s : fo.situation)
        if (const int i = step_index(chart, s); i >= 0)
          reached[static_cast<std::size_t>(i)] = seeded = true;
  for (const auto& t : chart.transitions)
    if (t.sources.empty()) seeded = true;  // a Grafcet source transition
  // Entry steps of enclosed charts and macro-step expansions are not marked in the IR, and
  // "no initial step" is already an error otherwise.
  if (!seeded) return;

  // A worklist (linear in the chart): a transition fires once its last source is reached.
  const std::size_t n_trans = chart.transitions.size();
  std::vector<std::vector<std::size_t>> leaving(chart.steps.size());
  std::vector<std::size_t> missing(n_trans, 0);  // source steps not reached yet
  std::vector<std::size_t> work;
  auto reach = [&](int i) {
    if (i < 0 || reached[static_cast<std::size_t>(i)]) return;
    reached[static_cast<std::size_t>(i)] = 1;
    work.push_back(static_cast<std::size_t>(i));
  };
  std::vector<std::size_t> ready;
  for (std::size_t t = 0; t < n_trans; ++t) {
    bool undeclared = false;
    for (const int i : declared_steps(chart, chart.transitions[t].sources)) {
      leaving[static_cast<std::size_t>(i)].push_back(t);
      ++missing[t];
    }
    for (const auto& s : chart.transitions[t].sources)
      undeclared = undeclared || !has_step(chart, s);
    if (undeclared) missing[t] = std::numeric_limits<std::size_t>::max();  // can never fire
    // A Grafcet source transition (no source step) can always fire.
    else if (missing[t] == 0)
      ready.push_back(t);
  }
  for (std::size_t i = 0; i < chart.steps.size(); ++i)
    if (reached[i]) work.push_back(i);
  auto fire = [&](std::size_t t) {
    for (const auto& s : chart.transitions[t].targets) reach(step_index(chart, s));
  };
  for (const auto t : ready) fire(t);
  while (!work.empty()) {
    const auto s = work.back();
    work.pop_back();
    for (const auto t : leaving[s])
      if (missing[t] != std::numeric_limits<std::size_t>::max() && --missing[t] == 0) fire(t);
  }
  const auto& where = at(chart.where, pou_->where);
  for (std::size_t i = 0; i < chart.steps.size(); ++i) {
    const Step& s = chart.steps[i];
    if (reached[i] || step_index(chart, s.name) != static_cast<int>(i)) continue;  // dup
    warning(at(s.where, where), "step " + quoted(s.name) +
                                    " is unreachable: no sequence of transitions leads to it "
                                    "from an initial step");
  }
}

std::string Validator::describe(const Context& ctx, const Chart& chart,
                                const SourceLocation& here) const {
  if (ctx.empty()) return "outside any parallel branch";
  const auto& b = ctx.back();
  const auto& d = chart.transitions[static_cast<std::size_t>(b.divergence)];
  return "in branch " + std::to_string(b.index + 1) + " of the simultaneous divergence" +
         (d.name.empty() ? std::string() : " " + quoted(d.name)) +
         (d.where.known() ? " at " + place(d.where, here) : std::string());
}

std::vector<int> Validator::declared_steps(const Chart& chart,
                                           const std::vector<std::string>& names) {
  std::vector<int> result;
  for (const auto& n : names) {
    const int i = step_index(chart, n);
    if (i >= 0 && std::find(result.begin(), result.end(), i) == result.end()) result.push_back(i);
  }
  return result;
}

void Validator::check_parallel_structure(const Chart& chart) {
  const std::size_t n_steps = chart.steps.size(), n_trans = chart.transitions.size();
  const auto& chart_where = at(chart.where, pou_->where);
  std::vector<std::vector<int>> sources(n_trans), targets(n_trans);
  std::vector<std::vector<int>> leaving(n_steps);
  for (std::size_t t = 0; t < n_trans; ++t) {
    sources[t] = declared_steps(chart, chart.transitions[t].sources);
    targets[t] = declared_steps(chart, chart.transitions[t].targets);
    for (int s : sources[t]) leaving[static_cast<std::size_t>(s)].push_back(static_cast<int>(t));
  }

  std::vector<std::optional<Context>> ctx(n_steps);
  std::vector<char> done(n_trans, 0);
  std::deque<int> queue;
  for (std::size_t i = 0; i < n_steps; ++i)
    if (chart.steps[i].initial && step_index(chart, chart.steps[i].name) == static_cast<int>(i)) {
      ctx[i] = Context{};
      queue.push_back(static_cast<int>(i));
    }

  while (!queue.empty()) {
    const auto s = static_cast<std::size_t>(queue.front());
    queue.pop_front();
    for (int ti : leaving[s]) {
      const auto t = static_cast<std::size_t>(ti);
      if (done[t]) continue;
      const bool ready = std::all_of(sources[t].begin(), sources[t].end(), [&](int src) {
        return ctx[static_cast<std::size_t>(src)].has_value();
      });
      if (!ready) continue;
      done[t] = 1;
      const auto& tr = chart.transitions[t];
      const auto& here = at(tr.where, chart_where);
      const Context in = input_context(chart, sources[t], targets, ctx, here);
      for (std::size_t k = 0; k < targets[t].size(); ++k) {
        Context out = in;
        if (targets[t].size() > 1) out.push_back({ti, static_cast<int>(k)});
        const auto g = static_cast<std::size_t>(targets[t][k]);
        if (!ctx[g]) {
          ctx[g] = std::move(out);
          queue.push_back(static_cast<int>(g));
          continue;
        }
        if (*ctx[g] == out) continue;
        report_context_clash(chart, ti, chart.steps[g], *ctx[g], out, here);
      }
    }
  }
}

Validator::Context Validator::input_context(const Chart& chart, const std::vector<int>& srcs,
                                            const std::vector<std::vector<int>>& targets,
                                            const std::vector<std::optional<Context>>& ctx,
                                            const SourceLocation& here) {
  if (srcs.empty()) return {};
  const Context& first = *ctx[static_cast<std::size_t>(srcs[0])];
  if (srcs.size() == 1) return first;

  // A simultaneous convergence: all sources one level inside the same divergence.
  auto common_prefix = [&] {
    Context p = first;
    for (int s : srcs) {
      const Context& c = *ctx[static_cast<std::size_t>(s)];
      std::size_t k = 0;
      while (k < p.size() && k < c.size() && p[k] == c[k]) ++k;
      p.resize(k);
    }
    return p;
  };
  for (int s : srcs) {
    const Context& c = *ctx[static_cast<std::size_t>(s)];
    const bool same_level = !c.empty() && !first.empty() && c.size() == first.size() &&
                            std::equal(c.begin(), c.end() - 1, first.begin()) &&
                            c.back().divergence == first.back().divergence;
    if (!same_level) {
      const auto& a = chart.steps[static_cast<std::size_t>(srcs[0])];
      const auto& b = chart.steps[static_cast<std::size_t>(s == srcs[0] ? srcs[1] : s)];
      const Context& cb = *ctx[static_cast<std::size_t>(s == srcs[0] ? srcs[1] : s)];
      if (cb == first)
        error(here, "simultaneous convergence joins steps " + quoted(a.name) + " and " +
                        quoted(b.name) + ", which are not parallel branches: both are " +
                        describe(first, chart, here));
      else
        error(here,
              "simultaneous convergence joins steps that are not branches of one "
              "simultaneous divergence: step " +
                  quoted(a.name) + " is " + describe(first, chart, here) + ", step " +
                  quoted(b.name) + " is " + describe(cb, chart, here));
      return common_prefix();
    }
  }
  const auto d = static_cast<std::size_t>(first.back().divergence);
  const std::size_t width = targets[d].size();
  std::set<int> covered;
  bool repeated = false;
  for (int s : srcs)
    repeated |= !covered.insert(ctx[static_cast<std::size_t>(s)]->back().index).second;
  if (repeated || covered.size() != width) {
    const auto& div = chart.transitions[d];
    error(here, "simultaneous convergence joins " +
                    (repeated ? std::string("several steps of one branch")
                              : std::to_string(covered.size()) + " of the " +
                                    std::to_string(width) + " branches") +
                    " of the simultaneous divergence" +
                    (div.name.empty() ? std::string() : " " + quoted(div.name)) +
                    (div.where.known() ? " at " + place(div.where, here) : std::string()));
  }
  return Context(first.begin(), first.end() - 1);
}

void Validator::report_context_clash(const Chart& chart, int ti, const Step& target,
                                     const Context& known, const Context& out,
                                     const SourceLocation& here) {
  const Transition& tr = chart.transitions[static_cast<std::size_t>(ti)];
  const bool known_is_prefix =
      known.size() < out.size() && std::equal(known.begin(), known.end(), out.begin());
  const bool out_is_prefix =
      out.size() < known.size() && std::equal(out.begin(), out.end(), known.begin());
  const std::string src = tr.sources.empty() ? std::string("?") : tr.sources.front();
  if (known_is_prefix && out.size() == known.size() + 1 && out.back().divergence == ti) {
    // This transition is the divergence: its branch starts at a step already in use.
    error(here, "simultaneous divergence into step " + quoted(target.name) + ", which is " +
                    describe(known, chart, here) +
                    " on another path: a parallel branch must start a sequence of its own");
  } else if (known_is_prefix) {
    const Context exited(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(known.size()) + 1);
    error(here, "jump out of a parallel branch: this transition leaves step " + quoted(src) + ", " +
                    describe(exited, chart, here) + ", for step " + quoted(target.name) + ", " +
                    describe(known, chart, here));
  } else if (out_is_prefix) {
    error(here, "jump into a parallel branch: step " + quoted(target.name) + " is " +
                    describe(known, chart, here) + ", but this transition reaches it from " +
                    "step " + quoted(src) + ", " + describe(out, chart, here));
  } else {
    error(here, "transition connects different parallel branches: step " + quoted(target.name) +
                    " is " + describe(known, chart, here) + ", but this transition reaches it " +
                    describe(out, chart, here));
  }
}

}  // namespace sfcv::model::detail
