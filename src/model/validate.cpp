#include "model/validate.hpp"

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

#include "model/names.hpp"
#include "model/nesting.hpp"
#include "model/networks.hpp"

namespace sfcv::model {

namespace {

// ------------------------------------------------------------------------------- value types

/// What an expression evaluates to. `Unknown` follows an error already reported (or an
/// unresolvable part): it is compatible with everything so that one defect gives one diagnostic.
/// `Bit` is the literal 0 or 1, which IEC 61131-3 also accepts as a BOOL literal.
enum class Ty { Bool, Int, Time, Bit, Unknown };

std::string ty_name(Ty t) {
  switch (t) {
    case Ty::Bool: return "BOOL";
    case Ty::Int:
    case Ty::Bit: return "integer";
    case Ty::Time: return "TIME";
    case Ty::Unknown: break;
  }
  return "unknown";
}

std::optional<Ty> value_type(const Type& t) {
  switch (t.kind) {
    case TypeKind::Bool: return Ty::Bool;
    case TypeKind::Int: return Ty::Int;
    case TypeKind::Time: return Ty::Time;
    case TypeKind::FunctionBlock: break;
  }
  return std::nullopt;  // a function block instance is not a value
}

bool clash(Ty a, Ty b) {
  if (a == Ty::Unknown || b == Ty::Unknown || a == b) return false;
  if (a == Ty::Bit) return b == Ty::Time;
  if (b == Ty::Bit) return a == Ty::Time;
  return true;
}

/// `Bit` read as a number.
Ty numeric(Ty t) { return t == Ty::Bit ? Ty::Int : t; }

/// The members of the standard function blocks (IEC 61131-3 table 2.5.2.3).
struct FbMember {
  Ty type;
  bool input;
};

std::optional<FbMember> fb_member(StandardFb fb, std::string_view member) {
  struct Row {
    StandardFb fb;
    std::string_view name;
    Ty type;
    bool input;
  };
  static constexpr std::array<Row, 30> rows{{
      {StandardFb::TON, "IN", Ty::Bool, true},   {StandardFb::TON, "PT", Ty::Time, true},
      {StandardFb::TON, "Q", Ty::Bool, false},   {StandardFb::TON, "ET", Ty::Time, false},
      {StandardFb::TOF, "IN", Ty::Bool, true},   {StandardFb::TOF, "PT", Ty::Time, true},
      {StandardFb::TOF, "Q", Ty::Bool, false},   {StandardFb::TOF, "ET", Ty::Time, false},
      {StandardFb::TP, "IN", Ty::Bool, true},    {StandardFb::TP, "PT", Ty::Time, true},
      {StandardFb::TP, "Q", Ty::Bool, false},    {StandardFb::TP, "ET", Ty::Time, false},
      {StandardFb::R_TRIG, "CLK", Ty::Bool, true}, {StandardFb::R_TRIG, "Q", Ty::Bool, false},
      {StandardFb::F_TRIG, "CLK", Ty::Bool, true}, {StandardFb::F_TRIG, "Q", Ty::Bool, false},
      {StandardFb::SR, "S1", Ty::Bool, true},    {StandardFb::SR, "R", Ty::Bool, true},
      {StandardFb::SR, "Q1", Ty::Bool, false},   {StandardFb::RS, "S", Ty::Bool, true},
      {StandardFb::RS, "R1", Ty::Bool, true},    {StandardFb::RS, "Q1", Ty::Bool, false},
      {StandardFb::CTU, "CU", Ty::Bool, true},   {StandardFb::CTU, "R", Ty::Bool, true},
      {StandardFb::CTU, "PV", Ty::Int, true},    {StandardFb::CTU, "Q", Ty::Bool, false},
      {StandardFb::CTD, "CD", Ty::Bool, true},   {StandardFb::CTD, "LD", Ty::Bool, true},
      {StandardFb::CTD, "PV", Ty::Int, true},    {StandardFb::CTD, "Q", Ty::Bool, false},
  }};
  // CV is common to both counters; kept out of the table to keep it one row per member.
  if ((fb == StandardFb::CTU || fb == StandardFb::CTD) && iequals(member, "CV"))
    return FbMember{Ty::Int, false};
  // CODESYS and TwinCAT name the counters' reset and load inputs RESET and LOAD.
  if (fb == StandardFb::CTU && iequals(member, "RESET")) return FbMember{Ty::Bool, true};
  if (fb == StandardFb::CTD && iequals(member, "LOAD")) return FbMember{Ty::Bool, true};
  for (const auto& r : rows)
    if (r.fb == fb && iequals(r.name, member)) return FbMember{r.type, r.input};
  return std::nullopt;
}

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
}

const SourceLocation& at(const SourceLocation& own, const SourceLocation& fallback) {
  return own.known() ? own : fallback;
}

/// `loc` for a message about an element at `here`: "12:5" in the same file, else the full form.
std::string place(const SourceLocation& loc, const SourceLocation& here) {
  if (loc.line > 0 && loc.file == here.file)
    return "line " + std::to_string(loc.line) +
           (loc.column > 0 ? ":" + std::to_string(loc.column) : std::string());
  return loc.str();
}

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

// ---------------------------------------------------------------------------------- validator

class Validator {
 public:
  explicit Validator(const Project& project) : project_(project) {}

  Diagnostics run() {
    // An empty file (or one of comments only) is no model: nothing could be checked in it.
    // A Grafcet needs a step; an IEC 61131-3 POU without steps is a program that runs its body
    // (possibly empty) every cycle.
    bool any_program = project_.dialect != Dialect::Grafcet && !project_.pous.empty();
    for (const auto& pou : project_.pous) any_program = any_program || pou.has_sfc();
    if (!any_program)
      error(project_.where, project_.dialect == Dialect::Grafcet
                                ? "the model has no chart (no step in any partial grafcet): nothing to check"
                                : "the model has no chart and no POU: nothing to check");
    check_duplicates(project_.pous, "POU", project_.where);
    for (const auto& pou : project_.pous) check_pou(pou);
    std::stable_sort(out_.begin(), out_.end(), [](const Diagnostic& a, const Diagnostic& b) {
      if (a.where.file != b.where.file) return a.where.file < b.where.file;
      if (a.where.line != b.where.line) return a.where.line < b.where.line;
      return a.where.column < b.where.column;
    });
    return std::move(out_);
  }

 private:
  const Project& project_;
  const Pou* pou_ = nullptr;
  /// The charts of pou_ by upper-cased name (the first of equal names, as Pou::chart_index):
  /// 10,000 nested macro-steps must not cost 10,000 linear searches.
  std::unordered_map<std::string, int> chart_by_name_;
  Diagnostics out_;
  std::set<std::string> outside_warned_;  ///< per POU: names already reported by outside_model

  /// Step indices by upper-case name (the first declaration), built once per chart: checks look
  /// steps up per transition and association, and a linear search each time is quadratic.
  mutable std::map<const Chart*, std::unordered_map<std::string, int>> step_indices_;

  bool grafcet() const { return project_.dialect == Dialect::Grafcet; }

  int step_index(const Chart& chart, std::string_view name) const {
    auto [it, fresh] = step_indices_.try_emplace(&chart);
    if (fresh)
      for (std::size_t i = 0; i < chart.steps.size(); ++i)
        it->second.try_emplace(to_upper(chart.steps[i].name), static_cast<int>(i));
    const auto found = it->second.find(to_upper(std::string(name)));
    return found == it->second.end() ? -1 : found->second;
  }
  bool has_step(const Chart& chart, std::string_view name) const { return step_index(chart, name) >= 0; }

  void error(const SourceLocation& where, std::string message) {
    out_.push_back({Severity::Error, where, std::move(message)});
  }
  void warning(const SourceLocation& where, std::string message) {
    out_.push_back({Severity::Warning, where, std::move(message)});
  }

  /// Elements with the same name (case-insensitive): one error at each repetition.
  template <typename T>
  void check_duplicates(const std::vector<T>& items, std::string_view what,
                        const SourceLocation& fallback) {
    std::map<std::string, const T*> first;
    for (const auto& item : items) {
      if (item.name.empty()) continue;
      auto [it, fresh] = first.emplace(to_upper(item.name), &item);
      if (fresh) continue;
      const auto& here = at(item.where, fallback);
      error(here, "duplicate " + std::string(what) + " " + quoted(item.name) +
                      (it->second->where.known()
                           ? " (first declared at " + place(it->second->where, here) + ")"
                           : std::string()));
    }
  }

  // ------------------------------------------------------------------------------- one POU

  void check_pou(const Pou& pou) {
    pou_ = &pou;
    chart_by_name_.clear();
    for (std::size_t i = 0; i < pou.charts.size(); ++i)
      chart_by_name_.emplace(to_upper(pou.charts[i].name), static_cast<int>(i));
    outside_warned_.clear();
    check_duplicates(pou.variables, "variable", pou.where);
    check_duplicates(pou.actions, "action", pou.where);
    const auto activated = charts_activated_by_grafcet_orders();
    for (std::size_t c = 0; c < pou.charts.size(); ++c)
      check_chart(pou.charts[c], activated.count(c) > 0);
    check_hierarchy();
    for (const auto& a : pou.actions) check_action(a);
    for (const auto& as : pou.associations) check_association(as);
    for (const auto& sa : pou.stored_actions) check_stored_action(sa);
    for (const auto& fo : pou.forcing_orders) check_forcing_order(fo);
    check_statements(pou.body, pou.where);
  }

  bool step_exists(std::string_view name) const {
    for (const auto& c : pou_->charts)
      if (has_step(c, name)) return true;
    return false;
  }

  /// The chart an association / stored action / forcing order names. An empty chart name is
  /// accepted when exactly one chart declares the step.
  const Chart* chart_of(const std::string& chart_name, const std::string& step,
                        const SourceLocation& where, std::string_view what) {
    if (const Chart* c = find_chart(chart_name)) {
      if (!has_step(*c, step))
        error(where, std::string(what) + " names undeclared step " + quoted(step) +
                         (chart_name.empty() ? std::string() : " of chart " + quoted(chart_name)));
      return c;
    }
    if (chart_name.empty()) {
      const Chart* found = nullptr;
      int count = 0;
      for (const auto& c : pou_->charts)
        if (has_step(c, step)) {
          found = &c;
          ++count;
        }
      if (count == 1) return found;
      error(where, std::string(what) + " names " +
                       (count == 0 ? "undeclared step " : "ambiguous step ") + quoted(step));
      return nullptr;
    }
    error(where, std::string(what) + " names undeclared chart " + quoted(chart_name));
    return nullptr;
  }

  /// Grafcet charts whose steps can be activated by something else than their initial steps:
  /// enclosed partial grafcets, macro-step expansions and targets of forcing orders.
  std::set<std::size_t> charts_activated_by_grafcet_orders() const {
    std::set<std::size_t> result;
    auto add = [&](const std::string& name) {
      const int i = chart_index(name);
      if (i >= 0) result.insert(static_cast<std::size_t>(i));
    };
    for (const auto& c : pou_->charts)
      for (const auto& s : c.steps) {
        if (s.kind == StepKind::MacroStep) add(s.expansion);
        if (s.kind == StepKind::Enclosing)
          for (const auto& e : s.enclosed) add(e);
      }
    for (const auto& fo : pou_->forcing_orders) add(fo.target);
    return result;
  }

  // ------------------------------------------------------------------------------ one chart

  std::string chart_label(const Chart& chart) const {
    if (!chart.parent_action.empty())
      return "the chart of action " + quoted(chart.parent_action);
    return "chart " + quoted(chart.name.empty() ? pou_->name : chart.name);
  }

  void check_chart(const Chart& chart, bool activated_otherwise) {
    const auto& where = at(chart.where, pou_->where);
    check_duplicates(chart.steps, "step", where);
    check_duplicates(chart.transitions, "transition", where);

    if (!chart.parent_action.empty() && !pou_->find_action(chart.parent_action))
      error(where, chart_label(chart) + " belongs to an undeclared action");

    for (const auto& s : chart.steps) check_step_kind(s, where);

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
                                              std::string(u.others.size() > 1 ? "s" : "") +
                                              " at " + also + ")"));
    }

    check_initial_steps(chart, activated_otherwise);
    check_reachability(chart);
    if (!grafcet()) check_parallel_structure(chart);
  }

  void check_step_kind(const Step& s, const SourceLocation& fallback) {
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
          error(here, "enclosing step " + quoted(s.name) + " encloses undeclared chart " +
                          quoted(e));
    }
  }

  void check_initial_steps(const Chart& chart, bool activated_otherwise) {
    const auto& where = at(chart.where, pou_->where);
    const bool any = std::any_of(chart.steps.begin(), chart.steps.end(),
                                 [](const Step& s) { return s.initial; });
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

  /// Steps that no sequence of transitions reaches from the initial steps, reading the chart
  /// as a Petri net without guards: a transition can fire once all its source steps can be
  /// active, whatever the guards say.
  void check_reachability(const Chart& chart) {
    std::vector<char> reached(chart.steps.size(), 0);
    bool seeded = false;
    for (std::size_t i = 0; i < chart.steps.size(); ++i)
      if (chart.steps[i].initial) reached[i] = seeded = true;
    for (const auto& fo : pou_->forcing_orders)
      if (iequals(fo.target, chart.name))
        for (const auto& s : fo.situation)
          if (const int i = step_index(chart, s); i >= 0) reached[static_cast<std::size_t>(i)] = seeded = true;
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
      for (const auto& s : chart.transitions[t].sources) undeclared = undeclared || !has_step(chart, s);
      if (undeclared) missing[t] = std::numeric_limits<std::size_t>::max();  // can never fire
      // A Grafcet source transition (no source step) can always fire.
      else if (missing[t] == 0) ready.push_back(t);
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

  // ---------------------------------------------------------------- parallel structure (IEC)
  //
  // The rule. Give every step a *token context*: the path of parallel branches it lies in,
  // from the outermost to the innermost, each branch being (simultaneous divergence, index of
  // the branch). Initial steps lie in no branch: context []. A transition carries its input
  // context to its targets:
  //   - one source step: the input context is that step's context;
  //   - several source steps (a simultaneous convergence): their contexts must be P+[(d,i)] for
  //     one prefix P and one divergence d, with the indices i covering each branch of d exactly
  //     once; the input context is then P. Otherwise the convergence joins branches of
  //     different divergences, or only some branches: an error ("unreachable" SFC: it waits for
  //     a token that never comes, or leaves tokens behind);
  //   - one target step gets the input context; with several targets (a simultaneous
  //     divergence d), target i gets input+[(d,i)].
  // Contexts are assigned breadth-first from the initial steps; each step must receive the
  // same context along every transition that reaches it. A transition that gives a step a
  // shorter context jumps out of a parallel branch ("unsafe" SFC: the branch's token escapes
  // and the convergence never completes, or a second token enters a sequence); a longer one
  // jumps into a branch from outside; any other difference connects two different branches.
  // A chart that passes keeps exactly one token per active sequence: every evolution moves a
  // token within its context, splits it into all branches, or joins all of them.
  // Applied to IEC 61131-3 only: IEC 60848 defines what activating an active step means.

  struct Branch {
    int divergence;  ///< transition index
    int index;       ///< branch number, in target order
    bool operator==(const Branch&) const = default;
  };
  using Context = std::vector<Branch>;

  std::string describe(const Context& ctx, const Chart& chart, const SourceLocation& here) const {
    if (ctx.empty()) return "outside any parallel branch";
    const auto& b = ctx.back();
    const auto& d = chart.transitions[static_cast<std::size_t>(b.divergence)];
    return "in branch " + std::to_string(b.index + 1) + " of the simultaneous divergence" +
           (d.name.empty() ? std::string() : " " + quoted(d.name)) +
           (d.where.known() ? " at " + place(d.where, here) : std::string());
  }

  std::vector<int> declared_steps(const Chart& chart, const std::vector<std::string>& names) {
    std::vector<int> result;
    for (const auto& n : names) {
      const int i = step_index(chart, n);
      if (i >= 0 && std::find(result.begin(), result.end(), i) == result.end())
        result.push_back(i);
    }
    return result;
  }

  void check_parallel_structure(const Chart& chart) {
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

  Context input_context(const Chart& chart, const std::vector<int>& srcs,
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
          error(here, "simultaneous convergence joins steps that are not branches of one "
                      "simultaneous divergence: step " + quoted(a.name) + " is " +
                          describe(first, chart, here) + ", step " + quoted(b.name) + " is " +
                          describe(cb, chart, here));
        return common_prefix();
      }
    }
    const auto d = static_cast<std::size_t>(first.back().divergence);
    const std::size_t width = targets[d].size();
    std::set<int> covered;
    bool repeated = false;
    for (int s : srcs) repeated |= !covered.insert(ctx[static_cast<std::size_t>(s)]->back().index).second;
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

  void report_context_clash(const Chart& chart, int ti, const Step& target, const Context& known,
                            const Context& out, const SourceLocation& here) {
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
      error(here, "jump out of a parallel branch: this transition leaves step " + quoted(src) +
                      ", " + describe(exited, chart, here) + ", for step " + quoted(target.name) +
                      ", " + describe(known, chart, here));
    } else if (out_is_prefix) {
      error(here, "jump into a parallel branch: step " + quoted(target.name) + " is " +
                      describe(known, chart, here) + ", but this transition reaches it from " +
                      "step " + quoted(src) + ", " + describe(out, chart, here));
    } else {
      error(here, "transition connects different parallel branches: step " +
                      quoted(target.name) + " is " + describe(known, chart, here) +
                      ", but this transition reaches it " + describe(out, chart, here));
    }
  }

  // -------------------------------------------------------------------------------- hierarchy

  struct Edge {
    std::size_t to;
    const SourceLocation* where;
  };

  /// Hierarchy: a chart's step activates an action whose body is a chart, encloses a partial
  /// grafcet, or is a macro-step. A cycle would nest a chart in itself without end.
  void check_hierarchy() {
    const std::size_t n = pou_->charts.size();
    std::vector<std::vector<Edge>> edges(n);
    for (const auto& as : pou_->associations) {
      const int from = chart_index_of_step(as.chart, as.step);
      const Action* a = pou_->find_action(as.action);
      if (from < 0 || !a || a->kind != ActionBodyKind::Chart) continue;
      if (a->chart < 0 || static_cast<std::size_t>(a->chart) >= n) continue;
      edges[static_cast<std::size_t>(from)].push_back({static_cast<std::size_t>(a->chart), &as.where});
    }
    for (std::size_t c = 0; c < n; ++c)
      for (const auto& s : pou_->charts[c].steps) {
        std::vector<std::string> below;
        if (s.kind == StepKind::MacroStep) below.push_back(s.expansion);
        if (s.kind == StepKind::Enclosing) below = s.enclosed;
        for (const auto& name : below)
          if (const int i = chart_index(name); i >= 0)
            edges[c].push_back({static_cast<std::size_t>(i), &s.where});
      }

    std::vector<int> color(n, 0);  // 0 new, 1 on the DFS path, 2 done
    std::vector<std::size_t> path;
    auto name_of = [&](std::size_t c) {
      const Chart& ch = pou_->charts[c];
      return ch.parent_action.empty() ? quoted(ch.name.empty() ? pou_->name : ch.name)
                                      : quoted(ch.parent_action);
    };
    bool too_deep = false;
    auto dfs = [&](auto&& self, std::size_t c) -> void {
      color[c] = 1;
      path.push_back(c);
      for (const auto& e : edges[c]) {
        if (path.size() >= static_cast<std::size_t>(kMaxNesting) && color[e.to] != 2) {
          // Deeper than any real chart: refused, so that no pass over the hierarchy (this
          // search, the macro-steps' derived activity) recurses or grows with its square.
          if (!too_deep)
            error(at(*e.where, pou_->where),
                  "charts nested more than " + std::to_string(kMaxNesting) +
                      " levels deep (macro-steps, enclosing steps or SFC actions inside "
                      "each other, from " + name_of(path.front()) + ")");
          too_deep = true;
          continue;
        }
        if (color[e.to] == 1) {
          std::string cycle;
          auto it = std::find(path.begin(), path.end(), e.to);
          for (; it != path.end(); ++it) cycle += name_of(*it) + " -> ";
          cycle += name_of(e.to);
          error(at(*e.where, pou_->where), "hierarchy cycle: " + cycle +
                                               " (a chart would contain itself)");
        } else if (color[e.to] == 0) {
          self(self, e.to);
        }
      }
      path.pop_back();
      color[c] = 2;
    };
    for (std::size_t c = 0; c < n; ++c)
      if (color[c] == 0) dfs(dfs, c);
  }

  int chart_index(std::string_view name) const {
    const auto it = chart_by_name_.find(to_upper(name));
    return it == chart_by_name_.end() ? -1 : it->second;
  }
  const Chart* find_chart(std::string_view name) const {
    const int i = chart_index(name);
    return i < 0 ? nullptr : &pou_->charts[static_cast<std::size_t>(i)];
  }

  int chart_index_of_step(const std::string& chart_name, const std::string& step) const {
    if (const int i = chart_index(chart_name); i >= 0) return i;
    if (!chart_name.empty()) return -1;
    for (std::size_t c = 0; c < pou_->charts.size(); ++c)
      if (has_step(pou_->charts[c], step)) return static_cast<int>(c);
    return -1;
  }

  // ---------------------------------------------------------------------- actions, associations

  void check_action(const Action& a) {
    const auto& here = at(a.where, pou_->where);
    switch (a.kind) {
      case ActionBodyKind::Variable:
        check_driven_variable(a.variable, here, "action " + quoted(a.name));
        break;
      case ActionBodyKind::Statements: check_statements(a.body, here); break;
      case ActionBodyKind::Chart:
        if (a.chart < 0 || static_cast<std::size_t>(a.chart) >= pou_->charts.size())
          error(here, "action " + quoted(a.name) + " has no chart body");
        break;
    }
  }

  /// A Boolean variable that an action drives: declared, BOOL, not an input.
  void check_driven_variable(const std::string& name, const SourceLocation& here,
                             const std::string& who) {
    const Variable* v = pou_->find_variable(name);
    if (!v) {
      error(here, who + " drives undeclared variable " + quoted(name));
      return;
    }
    if (v->type.kind != TypeKind::Bool)
      error(here, who + " drives variable " + quoted(name) + " of type " + v->type.name +
                      ", not BOOL");
    else if (v->direction == VarDirection::Input)
      write_to_input(here, who + " drives input variable " + quoted(name));
  }

  /// IEC 61131-3 inputs are read-only, but CODESYS and TwinCAT let a POU write its own
  /// VAR_INPUTs (corpus 07, 09), so for IEC charts this is a warning. A Grafcet input comes from
  /// the plant: writing it is an error.
  void write_to_input(const SourceLocation& here, const std::string& what) {
    if (grafcet())
      error(here, what + " (inputs are read-only)");
    else
      warning(here, what + " (IEC 61131-3 inputs are read-only; CODESYS and TwinCAT accept it)");
  }

  /// A qualified name whose first part the model does not declare: a global variable list,
  /// an instance of a function block type sfcv does not model, ... Its value is unknown to sfcv:
  /// one warning per name and POU, not an error, so that such charts still load.
  void outside_model(const SourceLocation& here, const std::string& full, const std::string& base) {
    if (!outside_warned_.insert(to_upper(full)).second) return;
    warning(here, quoted(full) + " refers to " + quoted(base) +
                      ", which this model does not declare (a global variable list or an "
                      "instance of a type sfcv does not model?): its value is unknown to sfcv");
  }

  /// An association names an action nobody declares. `inst.ACT_x` (TwinCAT: an action of a
  /// function block instance) whose instance the model does not declare is outside the model.
  void undeclared_action(const std::string& action, const SourceLocation& here,
                         const std::string& who) {
    const auto dot = action.rfind('.');
    if (dot != std::string::npos) {
      const std::string owner = action.substr(0, dot);
      const std::string first = owner.substr(0, owner.find('.'));
      if (!pou_->find_variable(first)) {
        if (!outside_warned_.insert(to_upper(action)).second) return;
        warning(here, who + " activates action " + quoted(action) + " of " + quoted(owner) +
                          ", which this model does not declare (an instance of a type sfcv "
                          "does not model?): the action is not modelled");
        return;
      }
    }
    error(here, who + " names undeclared action " + quoted(action));
  }

  void check_association(const ActionAssociation& as) {
    const auto& here = at(as.where, pou_->where);
    chart_of(as.chart, as.step, here, "action association");
    const std::string who = "step " + quoted(as.step);
    if (!pou_->find_action(as.action)) {
      // An action may be a Boolean variable used directly.
      if (pou_->find_variable(as.action))
        check_driven_variable(as.action, here, who);
      else
        undeclared_action(as.action, here, who);
    }
    if (is_timed(as.qualifier)) {
      if (!as.duration_ms && as.duration_variable.empty())
        error(here, "qualifier " + std::string(to_string(as.qualifier)) + " of action " +
                        quoted(as.action) + " needs a duration");
    }
    if (!as.duration_variable.empty()) {
      const Variable* v = pou_->find_variable(as.duration_variable);
      if (!v)
        error(here, "undeclared duration variable " + quoted(as.duration_variable));
      else if (v->type.kind != TypeKind::Time)
        error(here, "duration variable " + quoted(as.duration_variable) + " has type " +
                        v->type.name + ", not TIME");
    }
    if (!as.indicator.empty() && !pou_->find_variable(as.indicator))
      error(here, "undeclared indicator variable " + quoted(as.indicator));
    if (as.condition) expect_bool(as.condition, here, "the assignment condition");
  }

  // ---------------------------------------------------------------------------- Grafcet extras

  void check_stored_action(const StoredAction& sa) {
    const auto& here = at(sa.where, pou_->where);
    chart_of(sa.chart, sa.step, here, "stored action");
    if (sa.when == StoredWhen::Event) {
      if (!sa.event)
        error(here, "stored action on event has no event");
      else
        expect_bool(sa.event, here, "the event");
    }
    const Variable* v = pou_->find_variable(sa.variable);
    if (!v) {
      error(here, "stored action on undeclared variable " + quoted(sa.variable));
      return;
    }
    if (v->direction == VarDirection::Input)
      write_to_input(here, "stored action assigns input variable " + quoted(sa.variable));
    const auto target = value_type(v->type);
    if (!target) {
      error(here, "stored action assigns function block instance " + quoted(sa.variable));
      return;
    }
    if (!sa.value) {
      error(here, "stored action on " + quoted(sa.variable) + " has no value");
      return;
    }
    // Grafcet writes x := 1 / x := 0 for Boolean outputs: Ty::Bit fits BOOL.
    const Ty value = type_of(*sa.value, here);
    if (clash(value, *target))
      error(at(sa.value->where, here), "stored action assigns a " + ty_name(value) +
                                           " value to " + ty_name(*target) + " variable " +
                                           quoted(sa.variable));
  }

  void check_forcing_order(const ForcingOrder& fo) {
    const auto& here = at(fo.where, pou_->where);
    chart_of(fo.chart, fo.step, here, "forcing order");
    const Chart* target = find_chart(fo.target);
    if (!target) {
      error(here, "forcing order names undeclared partial grafcet " + quoted(fo.target));
      return;
    }
    if (fo.kind != ForcingKind::Situation) return;
    for (const auto& s : fo.situation)
      if (!has_step(*target, s))
        error(here, "forcing order names step " + quoted(s) + ", which partial grafcet " +
                        quoted(fo.target) + " does not declare");
  }

  // ------------------------------------------------------------------------------------ types

  void expect_bool(const ExprPtr& e, const SourceLocation& fallback, std::string_view what) {
    if (!e) return;
    const Ty t = type_of(*e, fallback);
    if (clash(t, Ty::Bool))
      error(at(e->where, fallback), std::string(what) + " has type " + ty_name(t) +
                                        ", expected BOOL");
  }

  Ty type_of(const Expr& e, const SourceLocation& fallback) {
    const auto& here = at(e.where, fallback);
    auto arg = [&](std::size_t i) -> Ty {
      if (i >= e.args.size() || !e.args[i]) return Ty::Unknown;
      return type_of(*e.args[i], here);
    };
    auto op = [&] { return to_st(e); };
    switch (e.kind) {
      case ExprKind::BoolConst: return Ty::Bool;
      case ExprKind::IntConst: return e.value == 0 || e.value == 1 ? Ty::Bit : Ty::Int;
      case ExprKind::TimeConst: return Ty::Time;
      case ExprKind::Name: return resolve_name(e, here);
      case ExprKind::Member: return resolve_member(e, here);
      case ExprKind::Not: {
        const Ty a = arg(0);
        if (a == Ty::Time) {
          error(here, "NOT of a TIME value in " + op());
          return Ty::Unknown;
        }
        return a;
      }
      case ExprKind::Neg: {
        const Ty a = arg(0);
        if (a == Ty::Bool) {
          error(here, "arithmetic negation of a BOOL value in " + op());
          return Ty::Unknown;
        }
        return numeric(a);
      }
      case ExprKind::And:
      case ExprKind::Or:
      case ExprKind::Xor: {
        // Boolean, or bitwise on integers; never mixed.
        std::optional<Ty> kind;
        bool unknown = false;
        for (std::size_t i = 0; i < e.args.size(); ++i) {
          const Ty a = arg(i);
          if (a == Ty::Unknown) {
            unknown = true;
            continue;
          }
          if (a == Ty::Bit) continue;  // fits BOOL and integer operands alike
          if (a == Ty::Time) {
            error(here, "logical operation on a TIME value in " + op());
            return Ty::Unknown;
          }
          if (kind && *kind != a) {
            error(here, "logical operation mixes BOOL and integer operands in " + op());
            return Ty::Unknown;
          }
          kind = a;
        }
        if (unknown) return Ty::Unknown;
        return kind ? *kind : Ty::Bit;
      }
      case ExprKind::Add:
      case ExprKind::Sub:
      case ExprKind::Mul:
      case ExprKind::Div:
      case ExprKind::Mod: return arithmetic(e.kind, arg(0), arg(1), here, op());
      case ExprKind::Eq:
      case ExprKind::Ne:
      case ExprKind::Lt:
      case ExprKind::Le:
      case ExprKind::Gt:
      case ExprKind::Ge: {
        const Ty a = arg(0), b = arg(1);
        if (clash(a, b)) error(here, "comparison of " + ty_name(a) + " with " + ty_name(b) +
                                         " in " + op());
        return Ty::Bool;
      }
      case ExprKind::Rising:
      case ExprKind::Falling:
      case ExprKind::Delay: {
        const Ty a = arg(0);
        if (clash(a, Ty::Bool))
          error(here, std::string(e.kind == ExprKind::Delay ? "time delay" : "edge") +
                          " of a " + ty_name(a) + " value in " + op() + " (expected BOOL)");
        return Ty::Bool;
      }
    }
    return Ty::Unknown;
  }

  Ty arithmetic(ExprKind kind, Ty a, Ty b, const SourceLocation& here, const std::string& op) {
    if (a == Ty::Unknown || b == Ty::Unknown) return Ty::Unknown;
    a = numeric(a);
    b = numeric(b);
    if (a == Ty::Int && b == Ty::Int) return Ty::Int;
    if ((kind == ExprKind::Add || kind == ExprKind::Sub) && a == Ty::Time && b == Ty::Time)
      return Ty::Time;
    if (kind == ExprKind::Mul && ((a == Ty::Time && b == Ty::Int) || (a == Ty::Int && b == Ty::Time)))
      return Ty::Time;
    if (kind == ExprKind::Div && a == Ty::Time && b == Ty::Int) return Ty::Time;
    error(here, "arithmetic on " + ty_name(a) + " and " + ty_name(b) + " in " + op);
    return Ty::Unknown;
  }

  Ty resolve_name(const Expr& e, const SourceLocation& here) {
    if (const Variable* v = pou_->find_variable(e.name)) {
      if (auto t = value_type(v->type)) return *t;
      error(here, "function block instance " + quoted(e.name) +
                      " used as a value (name one of its outputs, e.g. " + e.name + ".Q)");
      return Ty::Unknown;
    }
    if (step_exists(e.name)) return Ty::Bool;  // a step used as a Boolean: its activity
    // IEC 60848 step variable: X12 is the activity of step 12.
    if (grafcet() && e.name.size() > 1 && (e.name[0] == 'X' || e.name[0] == 'x') &&
        step_exists(std::string_view(e.name).substr(1)))
      return Ty::Bool;
    error(here, "unknown name " + quoted(e.name) +
                    " (not a variable" + (grafcet() ? ", step or step variable Xi)" : " or step)"));
    return Ty::Unknown;
  }

  Ty resolve_member(const Expr& e, const SourceLocation& here) {
    // Importers may keep a chain a.b.c as name "a.b", member "c".
    const std::string full = e.name + "." + e.member;
    std::vector<std::string> parts;
    for (std::size_t from = 0;;) {
      const auto dot = full.find('.', from);
      parts.push_back(full.substr(from, dot == std::string::npos ? dot : dot - from));
      if (dot == std::string::npos) break;
      from = dot + 1;
    }
    return resolve_path(parts, *pou_, true, here, full);
  }

  /// `parts` (>= 2) looked up in `scope`; `top` when `scope` is the POU being validated (steps
  /// and actions are only visible there).
  Ty resolve_path(const std::vector<std::string>& parts, const Pou& scope, bool top,
                  const SourceLocation& here, const std::string& full) {
    const std::string& base = parts[0];
    const std::string& member = parts[1];
    const bool simple = parts.size() == 2;
    if (const Variable* v = scope.find_variable(base)) {
      if (v->type.kind == TypeKind::FunctionBlock) {
        if (auto m = fb_member(v->type.fb, member); m && simple) return m->type;
        error(here, "function block " + v->type.name + " has no member " + quoted(member) +
                        " (in " + full + ")");
        return Ty::Unknown;
      }
      if (v->type.kind == TypeKind::Int && simple && all_digits(member)) return Ty::Bool;  // bit
      error(here, "variable " + quoted(base) + " of type " + v->type.name + " has no member " +
                      quoted(member) + " (in " + full + ")");
      return Ty::Unknown;
    }
    if (top && simple && step_exists(base)) {
      if (iequals(member, "X")) return Ty::Bool;
      if (iequals(member, "T")) return Ty::Time;
      error(here, "step " + quoted(base) + " has no member " + quoted(member) +
                      " (a step has X and T)");
      return Ty::Unknown;
    }
    if (top && simple && pou_->find_action(base)) {
      // IEC 61131-3 ed. 3 action control: A.A (active) and A.Q.
      if (iequals(member, "A") || iequals(member, "Q") || iequals(member, "X")) return Ty::Bool;
      error(here, "action " + quoted(base) + " has no member " + quoted(member) +
                      " (an action has A and Q)");
      return Ty::Unknown;
    }
    if (top) {
      if (const Pou* other = project_.find_pou(base)) {
        // A program's variable read from elsewhere: Main.x.
        const std::vector<std::string> rest(parts.begin() + 1, parts.end());
        if (rest.size() >= 2) return resolve_path(rest, *other, false, here, full);
        const Variable* v = other->find_variable(member);
        if (!v) {
          error(here, "POU " + quoted(other->name) + " declares no variable " + quoted(member));
          return Ty::Unknown;
        }
        if (auto t = value_type(v->type)) return *t;
        error(here, "function block instance " + quoted(full) + " used as a value");
        return Ty::Unknown;
      }
      // S.X / S.T on an undeclared step is a typo, not an outside reference.
      if (simple && (iequals(member, "X") || iequals(member, "T"))) {
        error(here, "unknown step " + quoted(base) + " in " + full);
        return Ty::Unknown;
      }
    }
    outside_model(here, full, top ? base : full.substr(0, full.rfind('.')));
    return Ty::Unknown;
  }

  // ------------------------------------------------------------------------------- statements

  /// The type an assignment target accepts; nullopt when it cannot be assigned (reported).
  std::optional<Ty> assignable(const std::string& target, const SourceLocation& here) {
    const auto dot = target.find('.');
    const std::string name = target.substr(0, dot);
    const Variable* v = pou_->find_variable(name);
    if (dot == std::string::npos) {
      if (!v) {
        error(here, "assignment to undeclared variable " + quoted(target));
        return std::nullopt;
      }
      if (v->direction == VarDirection::Input)
        write_to_input(here, "assignment to input variable " + quoted(target));
      if (auto t = value_type(v->type)) return t;
      error(here, "assignment to function block instance " + quoted(target));
      return std::nullopt;
    }
    const std::string member = target.substr(dot + 1);
    if (v && v->type.kind == TypeKind::FunctionBlock) {
      const auto m = fb_member(v->type.fb, member);
      if (!m) {
        error(here, "function block " + v->type.name + " has no member " + quoted(member));
        return std::nullopt;
      }
      if (!m->input) {
        error(here, "assignment to output " + quoted(target) + " of a function block instance");
        return std::nullopt;
      }
      return m->type;
    }
    if (v && v->type.kind == TypeKind::Int && all_digits(member)) {
      if (v->direction == VarDirection::Input)
        write_to_input(here, "assignment to input variable " + quoted(name));
      return Ty::Bool;
    }
    if (!v && step_exists(name)) {
      error(here, "assignment to step flag " + quoted(target) + " (step flags are read-only)");
      return std::nullopt;
    }
    if (!v && !pou_->find_action(name) && !project_.find_pou(name)) {
      outside_model(here, target, name);
      return std::nullopt;
    }
    error(here, "assignment to unknown " + quoted(target));
    return std::nullopt;
  }

  void check_statements(const StmtList& body, const SourceLocation& fallback) {
    for (const auto& sp : body) {
      if (!sp) continue;
      const Stmt& s = *sp;
      const auto& here = at(s.where, fallback);
      switch (s.kind) {
        case StmtKind::Assign: {
          const auto target = assignable(s.target, here);
          const Ty value = s.value ? type_of(*s.value, here) : Ty::Unknown;
          if (target && clash(value, *target))
            error(here, "assignment of a " + ty_name(value) + " value to " + ty_name(*target) +
                            " " + quoted(s.target));
          break;
        }
        case StmtKind::If:
          for (const auto& c : s.conditions) expect_bool(c, here, "the IF condition");
          for (const auto& b : s.bodies) check_statements(b, here);
          check_statements(s.else_body, here);
          break;
        case StmtKind::Case: {
          const Ty sel = s.value ? type_of(*s.value, here) : Ty::Unknown;
          if (clash(sel, Ty::Int))
            error(here, "CASE selector has type " + ty_name(sel) + ", expected an integer");
          for (const auto& b : s.bodies) check_statements(b, here);
          check_statements(s.else_body, here);
          break;
        }
        case StmtKind::FbCall: check_fb_call(s, here); break;
      }
    }
  }

  void check_fb_call(const Stmt& s, const SourceLocation& here) {
    const Variable* v = pou_->find_variable(s.target);
    // `ACT();`: a call of an action of the POU (IEC 61131-3 lets a body call its actions).
    if (!v && s.arguments.empty() && pou_->find_action(s.target)) return;
    if (!v) {
      error(here, "call of undeclared function block instance " + quoted(s.target));
      return;
    }
    if (v->type.kind != TypeKind::FunctionBlock) {
      error(here, "call of " + quoted(s.target) + ", which is a " + v->type.name +
                      " variable, not a function block instance");
      return;
    }
    for (const auto& [param, value] : s.arguments) {
      const auto m = fb_member(v->type.fb, param);
      if (!m) {
        error(here, "function block " + v->type.name + " has no parameter " + quoted(param));
        continue;
      }
      if (!value) continue;
      const Ty t = type_of(*value, here);
      if (clash(t, m->type))
        error(at(value->where, here), "parameter " + param + " of " + v->type.name +
                                          " expects " + ty_name(m->type) + ", got " + ty_name(t));
    }
  }
};

}  // namespace

Diagnostics validate(const Project& project) { return Validator(project).run(); }

}  // namespace sfcv::model
