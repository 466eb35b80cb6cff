#include "engine/sat/sat_model_checker.hpp"

#include <chrono>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "engine/sat/bmc.hpp"
#include "engine/sat/certificate.hpp"
#include "engine/sat/grafcet_machine.hpp"
#include "engine/sat/houdini.hpp"
#include "engine/sat/ic3.hpp"
#include "engine/sat/k_induction.hpp"
#include "engine/sat/loop_pumping.hpp"
#include "engine/sat/observers.hpp"
#include "engine/sat/range_check.hpp"
#include "engine/sat/unrolling.hpp"
#include "logic/circuit_atom.hpp"
#include "logic/formula.hpp"
#include "logic/standard_checks.hpp"
#include "logic/trace_replay.hpp"
#include "model/names.hpp"
#include "semantics/grafcet_circuit.hpp"
#include "semantics/iec61131_circuit.hpp"

namespace sfcv::engine {

using logic::PropertyResult;
using logic::StandardCheck;
using logic::Verdict;
using sat::ReachResult;
using semantics::Aig;
using semantics::AigLit;

namespace {

using Clock = std::chrono::steady_clock;

/// --engine ic3 with several targets: the depth of the BMC pass that comes first (solve()).
constexpr std::uint32_t kBmcFirstDepth = 32;
/// The longest IC3 may try to prove that no range error can occur before the other targets
/// (Run::without_range_check); less when an eighth of the time left is less.
constexpr double kRangeProbeSeconds = 5.0;
/// The first try of that proof, before the first IC3 pass (Run::solve).
constexpr double kQuickRangeProbeSeconds = 0.25;
/// The first, short IC3 pass of `--engine ic3` on IEC charts (Run::solve).
constexpr double kFirstIc3Seconds = 1.0;
/// The time of each IC3 run in the first round of a pass over many targets, doubled each round
/// (Run::solve): the first pass's, and the last pass's.
constexpr double kFirstIc3Slice = 0.1;
constexpr double kIc3Slice = 0.5;
/// Houdini's share of the steps' mutual exclusions (Run::solve): at most this many pairs, for
/// at most this long (an eighth of the time left when less).
constexpr std::size_t kMaxStepPairs = 200000;
constexpr double kHoudiniSeconds = 5.0;
/// The AG EF checks' search for a situation that never reaches the goal (Run::find_stuck): how
/// many situations, how deep BMC looks from each before IC3, how long IC3 tries each goal.
constexpr std::size_t kMaxStuckSituations = 12;
constexpr std::uint32_t kStuckBmcDepth = 8;
constexpr double kStuckSlice = 0.5;
/// The AND nodes global-deadlock's "some input fires a transition" may add to the circuit.
constexpr std::size_t kMaxQuantifiedAnds = 1000000;
/// How many cycles ahead global-deadlock's invariant looks for a transition that can fire.
constexpr std::uint32_t kFireCycles = 4;

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string_view algorithm_name(SatAlgorithm a) {
  switch (a) {
    case SatAlgorithm::Bmc:
      return "bmc";
    case SatAlgorithm::KInduction:
      return "kind";
    case SatAlgorithm::Ic3:
      return "ic3";
  }
  return "sat";
}

/// A finding of the stored-actions and output-conflicts checks: always (a fact of the chart
/// text), or when its target is reached, described from the run that reaches it.
struct Finding {
  std::optional<std::size_t> target;  ///< index into the query's targets; none: always
  std::string text;                   ///< the finding when `target` is none
  std::function<std::string(const ReachResult&, const logic::Trace&)> describe;
};

/// How a property or check reads the answers for its targets.
struct Question {
  enum class Shape {
    Invariant,
    Reach,
    Check,
    Findings,
    Stuck,
    Unsupported
  } shape = Shape::Unsupported;
  std::vector<std::size_t> targets;  ///< indices into the query's targets
  std::vector<std::string> labels;   ///< Check: per target, the finding when it is unreachable
  // Findings (the explicit engine's messages, engine/standard_check_runner.hpp):
  std::vector<Finding> findings;
  std::vector<std::string> not_checked;  ///< parts of the check the system cannot express
  std::string holds_message, trace_note;
  bool stored_actions = false;  ///< its not-checked wording (else output-conflicts')
  std::string refusal;          ///< Unsupported: the message, when not the generic one
  /// Grafcet checks: the target "a stable situation" (none reachable: nothing to judge).
  std::optional<std::size_t> some_stable;
  /// Stuck (IEC, IC3): AG EF goal for each goal, violated by a situation from which IC3 proves
  /// the goal unreachable (Run::find_stuck); "holds" is not decided this way.
  struct Goal {
    AigLit lit;                               ///< over the circuit's latches and inputs
    std::string finding;                      ///< the finding, after "from situation ... "
    std::string note;                         ///< the trace's note
    std::optional<std::uint32_t> observable;  ///< marked in the trace
  };
  std::vector<Goal> goals;
  std::string formula;  ///< shown with the verdict ("AG EF init")
  std::string trivial;  ///< Stuck without goals: why it holds (no step on a loop)
  /// Grafcet initial-return: the goal is built after the solve, from the initial situations'
  /// step activities (Run::grafcet_initial_goal).
  bool initial_activities = false;
  struct Stuck {
    std::size_t goal = 0;
    ReachResult run;            ///< to the situation
    bool no_successor = false;  ///< no allowed cycle from it at all
  };
  std::optional<Stuck> stuck;
  std::string stuck_certificate;  ///< the proof, over the circuit started in the situation
  std::string stuck_why;          ///< no violation found: how far the search went
};

/// A deadline for one scope: the previous one is put back when it ends (a limit that throws
/// included).
class ScopedDeadline {
 public:
  ScopedDeadline(sat::Deadline& slot, sat::Deadline scoped) : slot_(slot), saved_(slot) {
    slot_ = scoped;
  }
  ~ScopedDeadline() { slot_ = saved_; }
  ScopedDeadline(const ScopedDeadline&) = delete;
  ScopedDeadline& operator=(const ScopedDeadline&) = delete;

 private:
  sat::Deadline& slot_;
  sat::Deadline saved_;
};

class Run {
 public:
  Run(const logic::CheckTask& task, const SatEngineOptions& options)
      : task_(task), options_(options), ts_(*task.system) {
    if (ts_.kind() == semantics::SemanticsKind::Grafcet) {
      grafcet_.emplace(semantics::build_grafcet_circuit(ts_, task.limits.deadline,
                                                        task.limits.max_memory_bytes));
      machine_.emplace(*grafcet_);
      step_ok_ = machine_->step_ok();
      steps_ = logic::step_refs(ts_, task_.project);
    } else {
      iec_.emplace(semantics::build_iec61131_circuit(ts_, task.limits.deadline,
                                                     task.limits.max_memory_bytes));
      step_ok_ = iec_->step_ok();
      steps_ = logic::step_refs(ts_, task_.project);
    }
  }

  logic::CheckReport check() {
    const auto start = Clock::now();
    logic::CheckReport report;
    report.engine = std::string(algorithm_name(options_.algorithm));
    report.states_known = false;
    report.edges_known = false;
    deadline_ =
        sat::Deadline{task_.limits.deadline, task_.limits.cancel.get()};  // the run's one deadline

    std::vector<Question> questions;
    for (const auto& p : task_.properties) questions.push_back(property_question(p));
    for (auto c : task_.checks) questions.push_back(check_question(c));
    for (const auto& q : questions) {
      // Targets of one kind: a Stuck question's two (global-deadlock's invariant and the range
      // check) are better proved apart, and its first has a large cone.
      if (q.shape != Question::Shape::Check && q.shape != Question::Shape::Findings) continue;
      std::vector<std::size_t> group = q.targets;
      for (const auto& f : q.findings)
        if (f.target) group.push_back(*f.target);
      if (group.size() > 1) groups_.push_back(std::move(group));
    }
    const auto searched = [](const Question& q) {
      return q.shape == Question::Shape::Stuck && (!q.goals.empty() || q.initial_activities);
    };
    // The AG EF checks start from the stable situations of the runs found: on a Grafcet, runs
    // to each step make sure there are some when reachable is not asked.
    if (machine_ && std::any_of(questions.begin(), questions.end(), searched))
      for (const auto& x : steps_) {
        const AigLit seen = grafcet_step_seen(x);
        if (std::find(targets_.begin(), targets_.end(), seen) == targets_.end())
          add_machine_target(seen);
      }
    std::optional<std::size_t> loop_limit;
    if (iec_ && iec_->loop_limit != Aig::kFalse && !targets_.empty())
      loop_limit = add_target(iec_->loop_limit);
    const bool any_stuck = std::any_of(questions.begin(), questions.end(), searched);
    {
      // The AG EF checks search after the others, in the third of the time they leave.
      auto first = deadline_;
      if (any_stuck && first.at) first.at = part_of_time_left_at(2, 3);
      const ScopedDeadline scope(deadline_, first);
      answers_ = solve();
    }
    if (loop_limit) distrust_cut_cycles(*loop_limit);
    if (any_stuck) {
      const bool cut_cycle_possible =
          loop_limit && answers_[*loop_limit].kind != ReachResult::Kind::Unreachable;
      std::size_t left = 0;
      for (const auto& question : questions) left += searched(question) ? 1 : 0;
      for (auto& question : questions) {
        if (!searched(question)) continue;
        if (question.initial_activities)
          grafcet_initial_goal(question, part_of_time_left(static_cast<int>(left)));
        if (!question.goals.empty()) {  // else no goal could be built: stuck_why says why
          if (cut_cycle_possible)
            question.stuck_why = iec_->loop_limit_message();
          else if (!holds_at_once(question))
            find_stuck(question, part_of_time_left(static_cast<int>(left)));
        }
        --left;
      }
    }

    std::size_t q = 0;
    for (const auto& p : task_.properties) {
      auto r = property_result(p, questions[q++]);
      r.where = p.where;
      report.results.push_back(std::move(r));
    }
    for (auto c : task_.checks) report.results.push_back(check_result(c, questions[q++]));
    for (const auto& a : answers_) {
      report.depth = std::max(report.depth, a.depth);
      if (a.kind == ReachResult::Kind::Unknown && a.why.find("time") != std::string::npos) {
        report.complete = false;
        report.limit = "time";
      }
    }
    report.seconds = since(start);
    for (auto& r : report.results) r.seconds = report.seconds;
    return report;
  }

 private:
  /// A cycle that meets the ST loop bound has no successor in the circuit, though the loop may
  /// still end (docs/semantics.md 1.9.1). Unless such a cycle is proved unreachable, nothing
  /// is known past it: every "unreachable" answer becomes unknown. A run that reaches a target
  /// takes no cut cycle (step_ok excludes them): it stays.
  void distrust_cut_cycles(std::size_t loop_limit) {
    if (answers_[loop_limit].kind == ReachResult::Kind::Unreachable) return;
    const std::string why = iec_->loop_limit_message();
    const bool reached = answers_[loop_limit].kind == ReachResult::Kind::Reached;
    for (auto& a : answers_)
      if (a.kind == ReachResult::Kind::Unreachable ||
          (reached && a.kind == ReachResult::Kind::Unknown)) {  // the bound is why
        a = ReachResult{};
        a.why = why;
      }
  }

  /// The circuit observables and properties are read on.
  semantics::TransitionCircuit& circuit() {
    return grafcet_ ? static_cast<semantics::TransitionCircuit&>(*grafcet_) : *iec_;
  }
  const semantics::TransitionCircuit& circuit() const {
    return grafcet_ ? static_cast<const semantics::TransitionCircuit&>(*grafcet_) : *iec_;
  }
  /// The circuit the engines unroll: the IEC scan cycle, or the Grafcet machine whose steps
  /// are micro-steps of the stable-situation relation.
  const Aig& engine_aig() const { return machine_ ? machine_->aig() : iec_->aig; }
  /// The same, to add gates over its latches and inputs (a disjunction of targets).
  Aig& mutable_engine_aig() { return machine_ ? machine_->mutable_aig() : iec_->aig; }

  /// A target read in the situations the property judges: every IEC cycle, Grafcet's stable
  /// situations only (grafcet_machine.hpp).
  std::size_t add_target(AigLit circuit_lit) {
    targets_.push_back(machine_ ? machine_->in_stable_situation(circuit_lit) : circuit_lit);
    return targets_.size() - 1;
  }

  Question property_question(const logic::Property& p) {
    Question q;
    const auto& f = *p.formula;
    if (!task_.fairness.empty()) return q;
    if ((f.op == logic::Op::AG || f.op == logic::Op::EF) && logic::is_propositional(*f.args[0])) {
      const AigLit inner = logic::circuit_literal(circuit(), *f.args[0]);
      q.shape = f.op == logic::Op::AG ? Question::Shape::Invariant : Question::Shape::Reach;
      q.targets.push_back(add_target(f.op == logic::Op::AG ? Aig::make_not(inner) : inner));
    } else if (const auto step = next_cycle_parts(f); step && iec_) {
      // AG (p -> AX q), the next-cycle patterns: an observer latch holds p of the cycle before
      // (FALSE in an initial state, where no cycle has run yet), and the question is the
      // invariant "never the latch and not q" (docs/engines.md). Grafcet is left out: its
      // machine's steps are micro-steps, not the edges AX reads.
      auto& aig = iec_->aig;
      const AigLit p_lit = logic::circuit_literal(*iec_, *step->first);
      const AigLit q_lit = logic::circuit_literal(*iec_, *step->second);
      const AigLit was_p = aig.add_latch("prev(" + logic::to_string(step->first) + ")", false);
      aig.set_next(static_cast<std::uint32_t>(aig.latches().size() - 1), p_lit);
      q.shape = Question::Shape::Invariant;
      q.targets.push_back(add_target(aig.make_and(was_p, Aig::make_not(q_lit))));
    } else if (const auto bound = bounded_response_parts(f); bound && iec_) {
      // AG (p -> W_n(s)), response(P, S, within N cycles): an observer counts the cycles since
      // the oldest p still waiting for s; its target is the invariant's violation
      // (observers.hpp, docs/engines.md).
      auto& aig = iec_->aig;
      if (iec_->loop_limit != Aig::kFalse) {  // a cut cycle would look like a deadlock
        q.refusal = "not checked by the " + std::string(algorithm_name(options_.algorithm)) +
                    " engine: " + iec_->loop_limit_message();
        return q;
      }
      if (!dead_) dead_ = sat::no_successor(aig, step_ok_);
      if (!*dead_) {
        q.refusal = "not checked by the " + std::string(algorithm_name(options_.algorithm)) +
                    " engine: whether a state has a successor depends on too many inputs for "
                    "the bounded response's deadlock condition; use --engine explicit or bdd";
        return q;
      }
      const AigLit p_lit = logic::circuit_literal(*iec_, *bound->p);
      const AigLit s_lit = logic::circuit_literal(*iec_, *bound->s);
      q.shape = Question::Shape::Invariant;
      q.targets.push_back(add_target(sat::bounded_response_target(
          aig, p_lit, s_lit, bound->n, **dead_, "response(" + logic::to_string(bound->p) + ")")));
    }
    return q;
  }

  struct BoundedResponse {
    logic::FormulaPtr p, s;
    std::uint32_t n = 0;
  };
  /// (p, s, n) when `f` is AG (p -> W_n) with W_0 = s, W_k = s | (EX TRUE & AX W_{k-1}), n >= 1
  /// and p, s propositional: the formula of response(P, S, within N cycles) (logic/pattern.cpp).
  static std::optional<BoundedResponse> bounded_response_parts(const logic::Formula& f) {
    if (f.op != logic::Op::AG) return std::nullopt;
    const auto& body = *f.args[0];
    if (body.op != logic::Op::Implies || !logic::is_propositional(*body.args[0]))
      return std::nullopt;
    const auto& w = body.args[1];
    if (w->op != logic::Op::Or || w->args.size() != 2) return std::nullopt;
    BoundedResponse out{body.args[0], w->args[0], 0};
    if (!logic::is_propositional(*out.s)) return std::nullopt;
    const auto s_text = logic::to_string(out.s);
    const logic::Formula* at = w.get();
    while (logic::to_string(*at) != s_text) {
      if (at->op != logic::Op::Or || at->args.size() != 2 ||
          logic::to_string(at->args[0]) != s_text)
        return std::nullopt;
      const auto& next = *at->args[1];
      if (next.op != logic::Op::And || next.args.size() != 2 || next.args[0]->op != logic::Op::EX ||
          next.args[0]->args[0]->op != logic::Op::True || next.args[1]->op != logic::Op::AX)
        return std::nullopt;
      at = next.args[1]->args[0].get();
      ++out.n;
    }
    if (out.n == 0) return std::nullopt;
    return out;
  }

  /// (p, q) when `f` is AG (p -> AX q) with p and q propositional.
  static std::optional<std::pair<logic::FormulaPtr, logic::FormulaPtr>> next_cycle_parts(
      const logic::Formula& f) {
    if (f.op != logic::Op::AG) return std::nullopt;
    const auto& body = *f.args[0];
    if (body.op != logic::Op::Implies || body.args[1]->op != logic::Op::AX) return std::nullopt;
    const auto& p = body.args[0];
    const auto& q = body.args[1]->args[0];
    if (!logic::is_propositional(*p) || !logic::is_propositional(*q)) return std::nullopt;
    return std::make_pair(p, q);
  }

  Question check_question(StandardCheck c) {
    Question q;
    if (grafcet_) return grafcet_check_question(c);
    auto& iec = *iec_;
    switch (c) {
      case StandardCheck::Reachable:
        for (const auto& s : logic::step_refs(ts_, task_.project)) {
          q.targets.push_back(
              add_target(logic::circuit_literal(iec, *logic::observable_atom(ts_, s.observable))));
          q.labels.push_back("step " + logic::describe_step(s) + " is never active");
        }
        q.shape = q.targets.empty() ? Question::Shape::Unsupported : Question::Shape::Check;
        break;
      case StandardCheck::DeadTransitions: {
        const auto& trs = ts_.transitions();
        for (std::uint32_t t = 0; t < trs.size(); ++t) {
          q.targets.push_back(add_target(iec.aig.make_and(iec.fired[t], step_ok_)));
          q.labels.push_back("transition " + trs[t].name +
                             (trs[t].where.known() ? " (" + trs[t].where.str() + ")" : "") +
                             " never fires");
        }
        q.shape = q.targets.empty() ? Question::Shape::Unsupported : Question::Shape::Check;
        break;
      }
      case StandardCheck::Instability:
        // IEC 61131-3 has no transient evolutions; range errors are its anomalies.
        q.shape = Question::Shape::Invariant;
        q.targets.push_back(add_target(iec.anomaly_step()));
        break;
      case StandardCheck::StoredActions:
        stored_actions_question(q);
        break;
      case StandardCheck::OutputConflicts:
        output_conflicts_question(q);
        break;
      case StandardCheck::Reentry:
      case StandardCheck::LocalDeadlock:
      case StandardCheck::InitialReturn:
      case StandardCheck::GlobalDeadlock:
        stuck_question(c, q);
        break;
      default:
        break;
    }
    return q;
  }

  /// The AG EF checks as goals (the explicit engine's findings, standard_check_runner.hpp): a
  /// step on a loop that becomes active again (reentry), a step left and re-entered (local
  /// deadlock), the initial step activity (initial return), a transition that fires (global
  /// deadlock). IC3 only, without fairness (reentry would read AG AF).
  /// Grafcet: goals at the machine's stable situations, each at least what the explicit
  /// engine reads, so a situation from which no run meets it fails there too: a step active
  /// in a stable situation or crossed by an event that stabilises (the explicit engine reads
  /// a transient step's crossing), a stable situation without the step, an event that clears
  /// a transition and stabilises, a stable situation with the steps of some initial situation
  /// (they may differ; grafcet_initial_goal lists them after the solve).
  void stuck_question(StandardCheck c, Question& q) {
    if (options_.algorithm != SatAlgorithm::Ic3 || !task_.fairness.empty()) return;
    const auto step_lit = [&](const logic::StepRef& x) {
      return logic::circuit_literal(circuit(), *logic::observable_atom(ts_, x.observable));
    };
    const auto active = [&](const logic::StepRef& x) {
      return machine_ ? grafcet_step_seen(x) : step_lit(x);
    };
    const auto inactive = [&](const logic::StepRef& x) {
      return machine_ ? machine_->in_stable_situation(Aig::make_not(step_lit(x)))
                      : Aig::make_not(step_lit(x));
    };
    q.shape = Question::Shape::Stuck;
    switch (c) {
      case StandardCheck::Reentry:
        q.formula = "AG EF X";
        for (const auto& x : steps_)
          if (x.on_loop || !task_.project)
            q.goals.push_back({active(x),
                               "step " + logic::describe_step(x) +
                                   ": a reachable situation exists from which it can never "
                                   "become active again (AG EF " +
                                   ts_.observables()[x.observable].name + " is violated)",
                               "after the last situation, " + logic::describe_step(x) +
                                   " can never become active again",
                               x.observable});
        if (q.goals.empty()) q.trivial = "no step lies on a loop";
        break;
      case StandardCheck::LocalDeadlock:
        q.formula = "AG (X -> EF !X) & AG (!X -> EF X)";
        for (const auto& x : steps_)
          for (const bool leave : {true, false}) {
            const char* what =
                leave ? "once active, is never left" : "once inactive, never becomes active again";
            q.goals.push_back(
                {leave ? inactive(x) : active(x), "step " + logic::describe_step(x) + ", " + what,
                 "from the last situation on, " + logic::describe_step(x) + " " + what,
                 x.observable});
          }
        break;
      case StandardCheck::InitialReturn: {
        q.formula = "AG EF init";
        if (steps_.empty()) {  // whole states: the explicit and bdd engines
          q.shape = Question::Shape::Unsupported;
          return;
        }
        if (machine_) {
          q.initial_activities = true;
          break;
        }
        auto& iec = *iec_;
        // The step activity of the initial state (the IEC circuit has one).
        std::vector<bool> inputs(iec.aig.inputs().size(), false), latches;
        for (const auto& l : iec.aig.latches()) latches.push_back(l.initial);
        const auto nodes = iec.aig.evaluate(inputs, latches);
        std::vector<AigLit> same;
        for (const auto& x : steps_) {
          const AigLit lit = step_lit(x);
          same.push_back(Aig::value_of(nodes, lit) ? lit : Aig::make_not(lit));
        }
        q.goals.push_back({iec.aig.make_and(same), "",
                           "from the last situation the initial "
                           "situation is unreachable",
                           std::nullopt});
        break;
      }
      case StandardCheck::GlobalDeadlock: {
        if (machine_) {
          const AigLit clears = machine_->mutable_aig().make_or(machine_->fired());
          q.goals.push_back({machine_->seen_during_event(clears, "a transition cleared", false),
                             "no transition can ever fire again, whatever the inputs",
                             "the last situation is a global deadlock", std::nullopt});
          break;
        }
        auto& iec = *iec_;
        std::vector<AigLit> fires;
        for (const auto f : iec.fired) fires.push_back(iec.aig.make_and(f, step_ok_));
        if (fires.empty()) {
          q.shape = Question::Shape::Unsupported;
          return;
        }
        q.goals.push_back({iec.aig.make_or(fires),
                           "no transition can ever fire again, whatever "
                           "the inputs",
                           "the last situation is a global deadlock", std::nullopt});
        // Holds when from every reachable situation some inputs fire a transition within a
        // few cycles (AG EF fires follows): the invariant "can fire soon", the inputs
        // quantified out (can_fire_soon); left to the search for a violation when the
        // expansion is too large. It reads allowed cycles, not step_ok: the range check reads
        // most inputs, and quantifying them all is what is too large. So the invariant proves
        // the check only with the proof that no allowed cycle raises a range error (then every
        // allowed cycle of a reachable state has its successor), a second target.
        std::vector<AigLit> allowed_fires;
        for (const auto f : iec.fired) allowed_fires.push_back(iec.aig.make_and(f, iec.allowed));
        if (const auto can_fire = can_fire_soon(allowed_fires)) {
          q.targets.push_back(add_target(Aig::make_not(*can_fire)));
          if (iec.range_error != Aig::kFalse)
            q.targets.push_back(add_target(iec.range_error_step()));
        }
        break;
      }
      default:
        q.shape = Question::Shape::Unsupported;
    }
  }

  /// Grafcet (docs/engines.md): the checks that read the explicit graph's edges, whose events
  /// end in a stable situation, as targets at the machine's stable situations with an
  /// observer of the event (GrafcetMachine::seen_during_event): a step active in a stable
  /// situation or crossed by an event, a transition cleared by one (the start's
  /// stabilisation included, as fires_initially). The others stay not checked.
  Question grafcet_check_question(StandardCheck c) {
    Question q;
    auto& m = *machine_;
    switch (c) {
      case StandardCheck::Reachable:
        for (const auto& s : logic::step_refs(ts_, task_.project)) {
          q.targets.push_back(add_machine_target(grafcet_step_seen(s)));
          q.labels.push_back("step " + logic::describe_step(s) + " is never active");
        }
        break;
      case StandardCheck::DeadTransitions: {
        const auto& trs = ts_.transitions();
        for (std::uint32_t t = 0; t < trs.size(); ++t) {
          q.targets.push_back(
              add_machine_target(m.seen_during_event(m.fired()[t], "fired " + trs[t].name, false)));
          q.labels.push_back("transition " + trs[t].name +
                             (trs[t].where.known() ? " (" + trs[t].where.str() + ")" : "") +
                             " never fires");
        }
        break;
      }
      case StandardCheck::OutputConflicts:
        output_conflicts_question(q);
        q.some_stable = add_machine_target(m.at_stable());
        return q;
      case StandardCheck::Instability:
        // An event whose evolutions come back to a configuration (they never stabilise), or
        // raise a range error or a forcing conflict (grafcet_instability_result).
        q.shape = Question::Shape::Invariant;
        q.targets.push_back(add_machine_target(m.at_repeated_transient()));
        q.targets.push_back(add_machine_target(m.at_anomaly()));
        return q;
      case StandardCheck::Reentry:
      case StandardCheck::LocalDeadlock:
      case StandardCheck::GlobalDeadlock:
      case StandardCheck::InitialReturn:
        stuck_question(c, q);
        return q;
      case StandardCheck::Conflicts:
      case StandardCheck::StoredActions:
        if (!task_.project) {
          q.refusal = "not checked: needs the chart (no project given)";
          return q;
        }
        if (c == StandardCheck::Conflicts)
          grafcet_conflicts(q);
        else
          grafcet_stored_actions(q);
        q.some_stable = add_machine_target(m.at_stable());
        return q;
      default:
        return q;
    }
    if (q.targets.empty()) return q;
    // A finding needs a stable situation to judge (seed 90 of SatEngineAgreement.RandomGrafcets:
    // every initial valuation's evolutions loop forever, and "never active" was proved of every
    // step): without one the answer is unknown, as on the explicit engine.
    q.some_stable = add_machine_target(m.at_stable());
    q.shape = Question::Shape::Check;
    return q;
  }
  /// "A stable situation where step `x` is active, or that ends an event which crossed it"
  /// (docs/semantics.md 2.5): one observer per step, shared by the checks that read it.
  AigLit grafcet_step_seen(const logic::StepRef& x) {
    auto [it, fresh] = step_seen_.try_emplace(x.observable, Aig::kFalse);
    if (fresh)
      it->second = machine_->seen_during_event(
          machine_->in_situation(grafcet_observable_lit(x.observable)), "seen " + x.step, true);
    return it->second;
  }

  /// Grafcet initial-return: the step activities of the initial situations, one by one (a
  /// stable situation not yet left whose steps are none of those found, until the engine
  /// proves there is none; at most kMaxInitialSituations), then the goal "a stable situation
  /// with one of them", exactly the explicit engine's. Sets q.goals, or q.stuck_why.
  void grafcet_initial_goal(Question& q, sat::Deadline deadline) {
    auto& m = *machine_;
    Aig& aig = m.mutable_aig();
    std::vector<AigLit> steps;
    for (const auto& x : steps_)
      steps.push_back(m.in_situation(grafcet_observable_lit(x.observable)));
    const AigLit first = m.at_initial_stable();
    const ScopedDeadline scope(deadline_, deadline);  // reach_one's
    std::vector<AigLit> activities;
    for (;;) {
      const auto a = reach_one(aig, aig.make_and(first, Aig::make_not(aig.make_or(activities))));
      if (a.kind == ReachResult::Kind::Unreachable) break;
      if (a.kind == ReachResult::Kind::Unknown || activities.size() == kMaxInitialSituations) {
        q.stuck_why = "the steps of the initial situations are not known (" +
                      std::to_string(activities.size()) + " found; " +
                      (a.kind == ReachResult::Kind::Unknown
                           ? a.why
                           : "more remain past the bound kMaxInitialSituations") +
                      "); whether the initial situation can be reached again needs the "
                      "explicit or bdd engine";
        return;
      }
      const auto nodes =
          aig.evaluate(std::vector<bool>(aig.inputs().size(), false), last_latches(aig, a));
      std::vector<AigLit> same;
      for (const auto lit : steps)
        same.push_back(Aig::value_of(nodes, lit) ? lit : Aig::make_not(lit));
      activities.push_back(aig.make_and(same));
    }
    q.goals.push_back({aig.make_and(m.at_stable(), aig.make_or(activities)), "",
                       "from the last situation the initial situation is unreachable",
                       std::nullopt});
  }

  /// A target already over the machine's latches (Grafcet).
  std::size_t add_machine_target(AigLit machine_lit) {
    targets_.push_back(machine_lit);
    return targets_.size() - 1;
  }

  AigLit grafcet_observable_lit(std::uint32_t o) {
    return logic::circuit_literal(*grafcet_, *logic::observable_atom(ts_, o));
  }

  /// Grafcet conflicts, the explicit engine's findings (standard_check_runner.hpp): two
  /// transitions with a common upstream step both cleared during one event from a stable
  /// situation (the start's stabilisation is not an event of the graph), each seen by an
  /// observer of the event, at the stable situation it ends in.
  void grafcet_conflicts(Question& q) {
    auto& m = *machine_;
    auto& aig = m.mutable_aig();
    q.shape = Question::Shape::Findings;
    q.trace_note = "in the last situation conflicting transitions are enabled together";
    q.holds_message = "no two alternative transitions are enabled together";
    const auto upstream = logic::grafcet_upstream_steps(ts_, *task_.project);
    const auto& trs = ts_.transitions();
    if (upstream.size() != trs.size()) {
      q.refusal =
          "not checked: the transitions of the system could not be matched with the chart's "
          "transitions";
      q.shape = Question::Shape::Unsupported;
      return;
    }
    std::map<std::uint32_t, AigLit> cleared;  // per transition in some pair: its observer
    auto cleared_in_event = [&](std::uint32_t t) {
      auto it = cleared.find(t);
      if (it == cleared.end())
        it = cleared.emplace(t, m.seen_during_event(m.fired()[t], "cleared " + trs[t].name, false))
                 .first;
      return it->second;
    };
    const AigLit after_an_event = Aig::make_not(m.at_initial_stable());
    // The pairs with a common upstream step, through the transitions of each step (a chart of
    // thousands of transitions has few such pairs).
    std::map<std::string, std::vector<std::uint32_t>> downstream;
    for (std::uint32_t t = 0; t < trs.size(); ++t)
      for (const auto& step : upstream[t]) downstream[step].push_back(t);
    std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (const auto& [step, list] : downstream)
      for (std::size_t a = 0; a < list.size(); ++a)
        for (std::size_t b = a + 1; b < list.size(); ++b)
          pairs.emplace(std::min(list[a], list[b]), std::max(list[a], list[b]));
    for (const auto& [i, j] : pairs) {
      const auto common = logic::common_steps(upstream[i], upstream[j]);
      const AigLit both =
          aig.make_and(aig.make_and(cleared_in_event(i), cleared_in_event(j)), after_an_event);
      q.findings.push_back(
          {add_machine_target(both),
           {},
           [this, text = "transitions " + trs[i].name + " and " + trs[j].name +
                         " share the upstream step " + common.front() +
                         " and are cleared together from situation "](
               const ReachResult&, const logic::Trace& t) { return text + describe_at(t, 1); }});
    }
  }

  /// Grafcet stored actions (docs/semantics.md 2.7), the explicit engine's findings: an output
  /// stored to 1 and never to 0 (a fact of the chart), and two stored actions on activation
  /// writing different values whose steps are both activated by one event: both active in the
  /// stable situation it ends in, neither in the one it started from.
  void grafcet_stored_actions(Question& q) {
    auto& m = *machine_;
    auto& aig = m.mutable_aig();
    q.shape = Question::Shape::Findings;
    q.stored_actions = true;
    q.trace_note = "the last situation shows the stored-action defect";
    std::size_t stored = 0;
    const AigLit after_an_event = Aig::make_not(m.at_initial_stable());
    for (const auto& pou : task_.project->pous)
      for (const auto& instance : logic::instances_of(ts_, pou)) {
        for (const auto& v : logic::grafcet_stored_variables(pou)) {
          ++stored;
          if (v.never_reset)
            q.findings.push_back({std::nullopt,
                                  "output " + v.variable + " is set to 1 by stored actions (" +
                                      v.first->where.str() + ") and never reset to 0",
                                  {}});
          for (const auto& [a, b] : v.different) {
            const auto* sa = logic::find_step(steps_, instance.path, a->chart, a->step);
            const auto* sb = logic::find_step(steps_, instance.path, b->chart, b->step);
            if (!sa || !sb) {
              q.not_checked.push_back("stored actions on " + a->variable +
                                      " at steps without an observable");
              continue;
            }
            const AigLit xa = m.in_situation(grafcet_observable_lit(sa->observable));
            const AigLit xb = m.in_situation(grafcet_observable_lit(sb->observable));
            const AigLit neither_before =
                m.held_at_event_source(aig.make_and(Aig::make_not(xa), Aig::make_not(xb)),
                                       "neither " + sa->step + " nor " + sb->step);
            const AigLit both_now =
                aig.make_and(aig.make_and(m.at_stable(), aig.make_and(xa, xb)), neither_before);
            q.findings.push_back(
                {add_machine_target(aig.make_and(both_now, after_an_event)),
                 {},
                 [this, text = "output " + a->variable +
                               " is set to different values at once by the activation of " +
                               sa->step + " and " + sb->step +
                               ", from situation "](const ReachResult&, const logic::Trace& t) {
                   return text + describe_at(t, 1);
                 }});
          }
        }
      }
    q.holds_message =
        stored == 0 ? "the chart has no stored action" : "stored actions are used correctly";
    if (stored == 0) q.not_checked.clear();
  }

  // ------------------------------------------- stored-actions and output-conflicts (IEC)
  // The explicit engine's findings (engine/standard_check_runner.hpp), each one a target of
  // the circuit: a set of situations becomes a state predicate, "from s a successor in x"
  // an observer latch holding the predicate of the cycle before (FALSE initially).

  static std::string qualify(const std::string& pou, const std::string& name) {
    return pou.empty() ? name : pou + "." + name;
  }
  AigLit observable_lit(std::uint32_t o) {
    return logic::circuit_literal(*iec_, *logic::observable_atom(ts_, o));
  }
  /// The circuit's node values in frame `j` of run `r`.
  std::vector<bool> frame_values(const ReachResult& r, std::uint32_t j) const {
    const Aig& aig = engine_aig();
    std::vector<bool> latches;
    for (const auto& l : aig.latches()) latches.push_back(l.initial);
    for (std::uint32_t k = 0; k < j; ++k) {
      const auto nodes = aig.evaluate(r.inputs[k], latches);
      for (std::size_t l = 0; l < latches.size(); ++l)
        latches[l] = Aig::value_of(nodes, aig.latches()[l].next);
    }
    return aig.evaluate(r.inputs[j], latches);
  }
  /// The first of `lits` true in the last frame of `r`.
  std::size_t first_true(const ReachResult& r, const std::vector<AigLit>& lits) const {
    const auto nodes = frame_values(r, r.depth);
    for (std::size_t i = 0; i < lits.size(); ++i)
      if (Aig::value_of(nodes, lits[i])) return i;
    throw std::logic_error("sat engine: a finding's run does not show it");
  }
  /// The situation `back` steps before the trace's last. A Grafcet event that returns to its
  /// own situation adds no step to the trace: it starts from the last one then.
  std::string describe_at(const logic::Trace& t, std::size_t back) const {
    const auto n = t.steps.size();
    return ts_.describe(t.steps[n > back ? n - 1 - back : 0].state);
  }
  /// A finding when `target` is reached (none when it is FALSE by construction).
  void finding_if(Question& q, AigLit target,
                  std::function<std::string(const ReachResult&, const logic::Trace&)> text) {
    if (target == Aig::kFalse) return;
    q.findings.push_back({add_target(target), {}, std::move(text)});
  }

  void stored_actions_question(Question& q) {
    if (!task_.project) {
      q.refusal = "not checked: needs the chart (no project given)";
      return;
    }
    auto& aig = iec_->aig;
    q.shape = Question::Shape::Findings;
    q.stored_actions = true;
    q.trace_note = "the last situation shows the stored-action defect";
    std::size_t stored = 0;
    for (const auto& pou : task_.project->pous) {
      if (!pou.stored_actions.empty()) {  // IEC 60848 stored actions: not on an IEC system
        q.shape = Question::Shape::Unsupported;
        return;
      }
    }
    for (const auto& pou : task_.project->pous)
      for (const auto& instance : logic::instances_of(ts_, pou)) {
        // IEC 61131-3: S (and SD, DS, SL) sets an action's stored flag, R resets it. Each
        // instance of the POU has its own steps and stored flags.
        for (const auto& entry : logic::stored_action_steps(pou, instance, steps_, q.not_checked)) {
          const auto& sets = entry.sets;
          const auto& resets = entry.resets;
          ++stored;
          const std::string name = qualify(entry.scope, entry.action);
          if (!entry.reset_anywhere)
            q.findings.push_back({std::nullopt,
                                  "action " + name + " is stored at step " + entry.first_set +
                                      " and never reset (no R qualifier anywhere)",
                                  {}});
          std::vector<AigLit> set_at, reset_at;
          for (const auto* x : sets) set_at.push_back(observable_lit(x->observable));
          for (const auto* y : resets) reset_at.push_back(observable_lit(y->observable));
          // Set and reset in one situation.
          finding_if(q, aig.make_and(aig.make_or(set_at), aig.make_or(reset_at)),
                     [=, this](const ReachResult& r, const logic::Trace& t) {
                       return "action " + name + " is set (S at " +
                              sets[first_true(r, set_at)]->step + ") and reset (R at " +
                              resets[first_true(r, reset_at)]->step + ") in the same situation " +
                              describe_at(t, 0);
                     });
          // Set again while stored: from a situation where the stored flag is set and a set step
          // is not active, into one where it is (observer latch per set step).
          const auto field = logic::stored_flag_field(ts_, entry.scope, entry.action);
          if (!field) {
            q.not_checked.push_back("set again while stored (" + name +
                                    "): the system exposes no stored flag for it");
            continue;
          }
          const AigLit flagged = field_nonzero(*field);
          std::vector<AigLit> again;
          for (std::size_t i = 0; i < set_at.size(); ++i) {
            const AigLit before =
                aig.add_latch("stored-again(" + name + ", " + sets[i]->step + ")", false);
            aig.set_next(static_cast<std::uint32_t>(aig.latches().size() - 1),
                         aig.make_and(flagged, Aig::make_not(set_at[i])));
            again.push_back(aig.make_and(before, set_at[i]));
          }
          finding_if(q, aig.make_or(again), [=, this](const ReachResult& r, const logic::Trace& t) {
            return "action " + name + " is set again (S at " + sets[first_true(r, again)]->step +
                   ") while already stored, from situation " + describe_at(t, 1);
          });
        }
      }
    q.holds_message =
        stored == 0 ? "the chart has no stored action" : "stored actions are used correctly";
    if (stored == 0) q.not_checked.clear();  // as the explicit engine: nothing stored to check
  }

  /// Layout field `f` is non-zero (its latches encode value - lo).
  AigLit field_nonzero(std::uint32_t f) {
    auto& aig = circuit().aig;
    const auto& bits = circuit().field_latches[f];
    const auto lo = ts_.layout().fields()[f].lo;
    semantics::BitVector value;
    for (const auto l : bits) value.push_back(aig.latches()[l].current);
    const auto width = static_cast<std::uint32_t>(bits.size());
    if (lo > 0 || (width < 63 && -lo >= (std::int64_t{1} << width))) return Aig::kTrue;
    return Aig::make_not(semantics::bv_equal(aig, value, semantics::bv_constant(-lo, width)));
  }

  void output_conflicts_question(Question& q) {
    if (!task_.project) {
      q.refusal = "not checked: needs the chart (no project given)";
      return;
    }
    q.shape = Question::Shape::Findings;
    if (grafcet_) {
      grafcet_output_conflicts(q);
      return;
    }
    auto& aig = iec_->aig;
    q.trace_note = "in the last cycle both actions are active";
    const auto conflicts = logic::instance_write_conflicts(ts_, *task_.project);
    for (const auto& c : conflicts) {
      if (!c.not_checked.empty()) {
        q.not_checked.push_back(c.not_checked);
        continue;
      }
      std::vector<AigLit> both;
      for (const auto& [a, b] : c.together)
        both.push_back(aig.make_and(observable_lit(a), observable_lit(b)));
      finding_if(q, aig.make_or(both),
                 [=, this, what = c.what](const ReachResult&, const logic::Trace& t) {
                   return what + " in the same cycle, in situation " + describe_at(t, 0);
                 });
    }
    q.holds_message = conflicts.empty()
                          ? "no variable is written by two actions with different values"
                          : "actions writing the same variable are never active together";
  }

  /// Grafcet: a variable written by both continuous and stored actions, in a stable situation
  /// where its continuous assignation and its stored value disagree (the explicit engine's
  /// findings, standard_check_runner.hpp; docs/semantics.md 2.7).
  void grafcet_output_conflicts(Question& q) {
    auto& aig = grafcet_->aig;
    q.trace_note = "in the last situation the continuous assignation and the stored value disagree";
    const auto mixed = logic::grafcet_mixed_writers(ts_, *task_.project);
    for (const auto& m : mixed) {
      const AigLit assigned = field_nonzero(m.assigned), stored = field_nonzero(m.stored);
      const std::pair<AigLit, const char*> disagreements[] = {
          {aig.make_and(assigned, Aig::make_not(stored)),
           "a continuous action assigns it 1 while its stored value is 0"},
          {aig.make_and(stored, Aig::make_not(assigned)),
           "its stored value is 1 while no continuous action assigns it (the assignation rule "
           "gives 0)"}};
      for (const auto& [lit, what] : disagreements)
        finding_if(q, lit,
                   [this, head = m.what + ": " + what](const ReachResult&, const logic::Trace& t) {
                     return head + ", in situation " + describe_at(t, 0);
                   });
    }
    q.holds_message = mixed.empty()
                          ? "no variable is written by both continuous and stored actions"
                          : "the continuous assignation and the stored value of every variable "
                            "written both ways always agree";
  }

  std::vector<ReachResult> solve() {
    sat::ReachQuery query;
    query.aig = &engine_aig();
    query.step_ok = step_ok_;
    query.targets = targets_;
    query.simplify = !machine_;
    if (query.simplify) query.cuts = std::make_shared<sat::CutMapping>(*query.aig);
    sat::BoundOptions bounds;
    bounds.max_depth = options_.max_depth;
    bounds.deadline = deadline_;
    bounds.on_depth =
        level_reporter(options_.algorithm == SatAlgorithm::KInduction ? "k-induction" : "bmc");
    // Every proof is re-checked by fresh solvers before it may read as "holds".
    auto recheck = [&](std::size_t t, ReachResult& r) {
      if (r.kind != ReachResult::Kind::Unreachable) return;
      const auto verdict = sat::recheck(query, t, r.certificate, deadline_);
      if (!verdict.ok) {
        r.kind = ReachResult::Kind::Unknown;
        r.why = verdict.failed == "time"
                    ? "the time limit passed while re-checking the certificate"
                    : "the certificate failed its re-check (" + verdict.failed +
                          "): an engine error, please report it";
      }
    };
    std::vector<ReachResult> out;
    switch (options_.algorithm) {
      case SatAlgorithm::Bmc:
        bounds.min_depth = options_.min_depth;
        return sat::bmc(query, bounds);
      case SatAlgorithm::KInduction:
        // Re-checked by k_induction as each proof is found (a re-check here, after the
        // deadline that ends the deepening, would fail for lack of time).
        return sat::k_induction(query, bounds);
      case SatAlgorithm::Ic3:
        break;
    }
    out.resize(targets_.size());
    std::vector<bool> decided(targets_.size(), false);
    if (targets_.size() > 1) {
      // Many targets (the standard checks: one per step, transition or finding): BMC first, to
      // a shallow depth and for a quarter of the time left, reaches the shallow ones with
      // shortest runs at once, and IC3 works on the rest only. IC3 alone, target by target,
      // left 71 of the 101 steps of corpus 09 undecided at --timeout 40.
      sat::BoundOptions shallow;
      shallow.max_depth = std::min<std::uint32_t>(options_.max_depth, kBmcFirstDepth);
      shallow.deadline = part_of_time_left(4);
      shallow.on_depth = level_reporter("bmc");
      auto first = sat::bmc(query, shallow);
      for (std::size_t t = 0; t < first.size(); ++t)
        if (first[t].kind == ReachResult::Kind::Reached) {
          out[t] = std::move(first[t]);
          decided[t] = true;
        }
    }
    // Every invariant proved so far (re-checked): the IC3 runs after it assume it. First the
    // steps' mutual exclusions that hold (Houdini, houdini.hpp).
    known_ = sat::houdini(query, sat::step_exclusion_candidates(step_latch_groups(), kMaxStepPairs),
                          share_of_time_left(kHoudiniSeconds));
    auto learn = [&](const sat::Certificate& c) {
      if (c.kind != sat::Certificate::Kind::Invariant) return;
      known_.insert(known_.end(), c.clauses.begin(), c.clauses.end());
      std::sort(known_.begin(), known_.end());
      known_.erase(std::unique(known_.begin(), known_.end()), known_.end());
    };
    // A run IC3 found to `target` (of the engine's circuit), with its inputs: IC3's own when
    // they replay, else a shortest one by BMC up to its depth (which double-checks IC3's claim).
    auto with_inputs = [&](ReachResult r, AigLit target) {
      if (r.kind != ReachResult::Kind::Reached || r.inputs.size() == r.depth + 1) return r;
      sat::ReachQuery one = query;
      one.targets = {target};
      sat::BoundOptions b;
      b.max_depth = r.depth;
      b.deadline = deadline_;
      auto run = sat::bmc(one, b).front();
      if (run.kind == ReachResult::Kind::Unknown && run.why.find("time") == std::string::npos)
        throw std::logic_error("ic3: a counterexample that BMC cannot rebuild");
      return run;
    };
    // IC3 on target `t` within `deadline`. An unknown stays undecided for a later try unless
    // `last`, or unless IC3 stopped for another reason than time.
    auto ic3_target = [&](const sat::ReachQuery& search, std::size_t t, sat::Deadline deadline,
                          bool last) {
      sat::Ic3Options io;
      io.deadline = deadline;
      io.on_frame = level_reporter("ic3");
      io.known_invariant = &known_;
      auto r = with_inputs(sat::ic3(search, t, io), targets_[t]);
      // At once: a later target that runs out of time must not cost this proof.
      recheck(t, r);
      if (!last && r.kind == ReachResult::Kind::Unknown && r.why.find("time") != std::string::npos)
        return;
      if (r.kind == ReachResult::Kind::Unreachable) learn(r.certificate);
      out[t] = std::move(r);
      decided[t] = true;
    };
    // IC3 on the disjunction of a question's undecided targets `members`: one proof for all of
    // them (513 output-conflict targets of PPU scenario 10 hold for the same few step
    // invariants), or a run that reaches some, which are then decided.
    auto ic3_group = [&](const sat::ReachQuery& search, const std::vector<std::size_t>& members,
                         sat::Deadline deadline) {
      std::vector<AigLit> lits;
      for (auto t : members) lits.push_back(targets_[t]);
      AigLit any = Aig::kFalse;
      try {  // one gate more in the engine's circuit, read by this search only
        any = mutable_engine_aig().make_or(lits);
      } catch (const LimitReached&) {
        return;  // the circuit's deadline or memory: each target alone, as before
      }
      sat::ReachQuery group_search = search;
      group_search.targets = {any};
      sat::Ic3Options io;
      io.deadline = deadline;
      io.on_frame = level_reporter("ic3");
      io.known_invariant = &known_;
      auto r = with_inputs(sat::ic3(group_search, 0, io), any);
      if (r.kind == ReachResult::Kind::Unreachable) {
        sat::ReachQuery group_query = query;
        group_query.targets = {any};
        if (!sat::recheck(group_query, 0, r.certificate, deadline_).ok) return;  // each alone
        learn(r.certificate);
        for (auto t : members) {
          out[t] = r;
          decided[t] = true;
        }
      } else if (r.kind == ReachResult::Kind::Reached) {
        // The run's last frame meets at least one of them.
        const auto nodes = frame_values(r, r.depth);
        bool met = false;
        for (auto t : members)
          if (Aig::value_of(nodes, targets_[t])) {
            out[t] = r;
            decided[t] = true;
            met = true;
          }
        if (!met) throw std::logic_error("ic3: a run to a disjunction that meets no target");
      }
    };
    // Rounds over the undecided targets, each IC3 run within `slice` seconds, doubled each
    // round, and never past `deadline`: a target IC3 cannot decide no longer takes the time of
    // every target after it (the final pass of main c14329e ran the targets in turn, each to
    // the deadline: corpus PPU scenario 10 left its 513 output conflicts and its range check
    // unsearched). Each round first tries every question's undecided targets together.
    auto ic3_rounds = [&](const sat::ReachQuery& search, sat::Deadline deadline, double slice,
                          bool last) {
      const auto seconds = [](double x) {
        return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(x));
      };
      for (;;) {
        std::size_t left = 0;
        for (std::size_t t = 0; t < targets_.size(); ++t) left += decided[t] ? 0 : 1;
        if (left == 0 || deadline.passed()) return;
        // Without a deadline, one round with no slice: each run to its answer.
        const bool whole =
            !deadline.at || left == 1 || Clock::now() + seconds(slice) >= *deadline.at;
        const auto round_cut = [&] {
          sat::Deadline d = deadline;
          if (!whole) d.at = std::min(*deadline.at, Clock::now() + seconds(slice));
          return d;
        };
        for (const auto& group : groups_) {
          std::vector<std::size_t> members;
          for (auto t : group)
            if (!decided[t]) members.push_back(t);
          if (members.size() > 1) ic3_group(search, members, round_cut());
        }
        for (std::size_t t = 0; t < targets_.size() && !deadline.passed(); ++t)
          if (!decided[t]) ic3_target(search, t, round_cut(), last && whole);
        if (whole) return;
        slice *= 2;
      }
    };
    auto undecided = [&] {
      return std::find(decided.begin(), decided.end(), false) != decided.end();
    };
    bool range_error_reached = false;
    sat::ReachQuery search = query;
    bool relaxed = false;
    if (iec_ && undecided()) {
      // A quick proof that no range error can occur (levels 4: 0.05 s) lets the first IC3 pass
      // search without the range check already; a reachable range error costs only its budget.
      search = without_range_check(query, kQuickRangeProbeSeconds);
      relaxed = search.step_ok != query.step_ok;
      // A short IC3 pass first: what it proves at once (most bounds that hold) needs no
      // pumping, whose frame caps can cost seconds on a counter that never repeats.
      ic3_rounds(search, share_of_time_left(kFirstIc3Seconds), kFirstIc3Slice, false);
    }
    if (iec_ && undecided()) {
      // Deep runs that repeat a short loop (an INT counter counting while a step waits), for
      // the targets and for a range error (which then needs no proof that it cannot occur).
      sat::ReachQuery pumped_query = query;
      pumped_query.targets.push_back(iec_->range_error_step());
      std::vector<bool> wanted(decided.size());
      for (std::size_t t = 0; t < targets_.size(); ++t) wanted[t] = !decided[t];
      wanted.push_back(!relaxed && iec_->range_error != Aig::kFalse);  // else proved unreachable
      sat::PumpOptions pumping;
      pumping.deadline = eighth_of_time_left();  // and its frame caps
      auto pumped = sat::pump_loops(pumped_query, counter_latches(), wanted, pumping);
      range_error_reached = pumped.back().kind == ReachResult::Kind::Reached;
      for (std::size_t t = 0; t < targets_.size(); ++t)
        if (pumped[t].kind == ReachResult::Kind::Reached) {
          out[t] = std::move(pumped[t]);
          decided[t] = true;
        }
    }
    if (undecided()) {
      if (range_error_reached)
        search = query;
      else if (!relaxed)
        search = without_range_check(query, kRangeProbeSeconds);
      ic3_rounds(search, deadline_, kIc3Slice, true);
    }
    for (std::size_t t = 0; t < targets_.size(); ++t)
      if (!decided[t] && out[t].why.empty())
        out[t].why = "the time limit passed before IC3 decided it";
    return out;
  }

  /// The query IC3 searches: `query`, or, when IC3 proves
  /// within a short budget that no range error can occur, `query` without the range check
  /// (range_check.hpp: on `sfcv-gen levels 6` the cone of `lvl_0 <= 9` shrinks from six tanks
  /// to one). Proofs are still re-checked against `query`, and runs replay on it.
  sat::ReachQuery without_range_check(const sat::ReachQuery& query, double seconds) {
    if (!iec_ || targets_.empty()) return query;
    return sat::without_range_check(query, *iec_, share_of_time_left(seconds));
  }

  /// Reports each depth (BMC, k-induction) or frame (IC3) on the progress line, so that a long
  /// SAT search shows where it is; empty without a progress callback.
  std::function<void(std::uint32_t)> level_reporter(const char* phase) const {
    if (!task_.limits.progress) return {};
    return [this, phase](std::uint32_t level) {
      logic::Progress p;
      p.phase = phase;
      p.depth = level;
      task_.limits.report(p);
    };
  }

  /// The run's deadline cut to 1 / `parts` of the time left (none without a deadline): for a
  /// pass that may fail, so that failing costs little.
  sat::Deadline part_of_time_left(int parts) const {
    sat::Deadline d = deadline_;
    if (deadline_.at) {
      const auto now = Clock::now();
      d.at = now + (*deadline_.at - now) / parts;
    }
    return d;
  }
  sat::Deadline eighth_of_time_left() const { return part_of_time_left(8); }
  /// The point `num` / `den` of the time left from now (the run's deadline must be set).
  Clock::time_point part_of_time_left_at(int num, int den) const {
    const auto now = Clock::now();
    return now + (*deadline_.at - now) * num / den;
  }
  /// The same, and at most `seconds` from now.
  sat::Deadline share_of_time_left(double seconds) const {
    sat::Deadline d = eighth_of_time_left();
    const auto cap = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>(seconds));
    d.at = d.at ? std::min(*d.at, cap) : cap;
    return d;
  }

  /// "Some inputs make one of `fires` true within kFireCycles cycles", over latches: F_1 =
  /// some input valuation fires one now, F_(k+1) = F_k or some allowed cycle (range errors
  /// aside: the caller proves there are none) leads to a state in F_k (the inputs quantified
  /// out, observers.hpp); the deepest level built within kMaxQuantifiedAnds new AND nodes and
  /// an eighth of the time left. A step whose action must run a cycle before its transition
  /// can fire needs F_2 (PPU scenario 0: F_1, 136 000 new AND nodes, fails at depth 5; F_2,
  /// 640 000, is proved in 2.3 s). nullopt when not even F_1 can be built.
  std::optional<AigLit> can_fire_soon(const std::vector<AigLit>& fires) {
    auto& aig = iec_->aig;
    const std::size_t start = aig.num_ands();
    std::optional<AigLit> level;
    // Within an eighth of the time left: past it the levels built so far stand.
    aig.set_deadline(eighth_of_time_left().at);
    struct Clear {
      Aig& aig;
      ~Clear() { aig.set_deadline(std::nullopt); }
    } clear{aig};
    try {
      level = sat::some_input_satisfies(aig, fires, kMaxQuantifiedAnds);
      for (std::uint32_t k = 1; level && k < kFireCycles; ++k) {
        const std::size_t used = aig.num_ands() - start;
        if (used >= kMaxQuantifiedAnds) break;
        const auto later = sat::at_next_cycle(aig, *level, kMaxQuantifiedAnds - used);
        if (!later) break;
        const auto via = sat::some_input_satisfies(aig, {aig.make_and(iec_->allowed, *later)},
                                                   kMaxQuantifiedAnds - (aig.num_ands() - start));
        if (!via) break;
        level = aig.make_or(*level, *via);
      }
    } catch (const LimitReached&) {
      // Time or the circuit's memory limit: the levels built so far stand (none: no target).
    }
    return level;
  }

  /// A Stuck question whose sufficient invariant (global-deadlock: a transition can fire
  /// soon, and no range error) IC3 proved.
  bool holds_at_once(const Question& q) const {
    return !q.targets.empty() &&
           std::all_of(q.targets.begin(), q.targets.end(), [&](std::size_t t) {
             return answers_[t].kind == ReachResult::Kind::Unreachable;
           });
  }

  /// The situations find_stuck tries, each with the run that reaches it: the initial one,
  /// then those of the runs found (answers_), depth by depth, distinct, at most
  /// kMaxStuckSituations. Each run is simulated once, one cycle per depth (replaying every
  /// prefix from the start cost seconds on corpus 11's 200 runs), and the list is built once
  /// for all the AG EF checks.
  const std::vector<std::pair<ReachResult, std::vector<bool>>>& stuck_situations(
      const sat::Deadline& deadline) {
    if (situations_) return *situations_;
    auto& out = situations_.emplace();
    const Aig& aig = engine_aig();
    std::vector<bool> initial;
    for (const auto& l : aig.latches()) initial.push_back(l.initial);
    ReachResult start;  // the initial state, a run of no cycle
    start.kind = ReachResult::Kind::Reached;
    start.inputs.assign(1, std::vector<bool>(aig.inputs().size(), false));
    // A Grafcet machine starts in Boot and its micro-steps cross transient situations: only
    // the stable situations on the runs are situations of the explicit graph.
    if (!machine_) out.emplace_back(start, initial);
    std::set<std::vector<bool>> seen{initial};
    std::vector<std::size_t> runs;
    for (std::size_t a = 0; a < answers_.size(); ++a)
      if (answers_[a].kind == ReachResult::Kind::Reached &&
          answers_[a].inputs.size() == answers_[a].depth + 1 && answers_[a].depth > 0)
        runs.push_back(a);
    std::vector<std::vector<bool>> at(runs.size(), initial);  // each run's state at depth j
    for (std::uint32_t j = 1; out.size() < kMaxStuckSituations && !deadline.passed(); ++j) {
      bool any = false;
      for (std::size_t k = 0; k < runs.size() && out.size() < kMaxStuckSituations; ++k) {
        const auto& r = answers_[runs[k]];
        if (r.depth < j) continue;
        any = true;
        const auto nodes = aig.evaluate(r.inputs[j - 1], at[k]);
        for (std::size_t l = 0; l < at[k].size(); ++l)
          at[k][l] = Aig::value_of(nodes, aig.latches()[l].next);
        if ((machine_ && !machine_->is_stable(at[k])) || !seen.insert(at[k]).second) continue;
        ReachResult run = r;
        run.depth = j;
        run.inputs.resize(j + 1);
        out.emplace_back(std::move(run), at[k]);
      }
      if (!any) break;
    }
    return out;
  }

  /// A violation of AG EF goal for some goal of `q`: a situation on a run the engine found
  /// (the initial one, then the situations of the runs to steps and transitions, shallowest
  /// first, at most kMaxStuckSituations) from which no goal-reaching run exists: BMC from the
  /// situation drops the goals it reaches within kStuckBmcDepth cycles, IC3 then tries each
  /// goal left within kStuckSlice seconds, assuming the invariants proved so far (a reachable
  /// situation satisfies them, and so does every situation after it), and a fresh solver
  /// re-checks its proof over the circuit started in the situation. Sets q.stuck, or
  /// q.stuck_why when none was found: whether the check holds is not decided this way.
  void find_stuck(Question& q, sat::Deadline deadline) {
    const auto& situations = stuck_situations(deadline);
    // The circuit itself, started in the situation under test, and its initial state put
    // back after (a copy of a large circuit costs its size once more).
    Aig& from = mutable_engine_aig();
    std::vector<bool> initial;
    for (const auto& l : from.latches()) initial.push_back(l.initial);
    struct Restore {
      Aig& aig;
      const std::vector<bool>& values;
      ~Restore() {
        for (std::uint32_t l = 0; l < values.size(); ++l) aig.set_initial(l, values[l]);
      }
    } restore{from, initial};
    std::size_t tried = 0;
    for (const auto& [run, latches] : situations) {
      if (deadline.passed()) break;
      ++tried;
      for (std::uint32_t l = 0; l < latches.size(); ++l) from.set_initial(l, latches[l]);
      // A stable situation's event observers describe the event that ended there, not a run
      // from it. Cleared, the start may be a state no run reaches (the observers read nothing
      // else), so the invariants proved for the machine are not assumed.
      if (machine_)
        for (const auto l : machine_->event_observer_latches()) from.set_initial(l, false);
      sat::ReachQuery query{&from, step_ok_, {}, true, nullptr};
      for (const auto& g : q.goals) query.targets.push_back(g.lit);
      sat::BoundOptions bounds;
      bounds.max_depth = kStuckBmcDepth;
      bounds.deadline = deadline;
      const auto near = sat::bmc(query, bounds);
      for (std::size_t k = 0; k < q.goals.size() && !deadline.passed(); ++k) {
        if (near[k].kind == ReachResult::Kind::Reached) continue;
        sat::Ic3Options io;
        io.deadline = deadline;
        const auto slice = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                              std::chrono::duration<double>(kStuckSlice));
        io.deadline.at = io.deadline.at ? std::min(*io.deadline.at, slice) : slice;
        io.known_invariant = machine_ ? nullptr : &known_;
        const auto r = sat::ic3(query, k, io);
        if (r.kind != ReachResult::Kind::Unreachable ||
            !sat::recheck(query, k, r.certificate, deadline).ok)
          continue;
        q.stuck = Question::Stuck{k, run, false};
        q.stuck_certificate = sat::certificate_text(from, r.certificate);
        if (machine_) return;  // "no successor" is an edge question of the explicit graph
        // No successor at all, or successors that fire nothing (global-deadlock's wording).
        sat::ReachQuery any_step{&from, step_ok_, {step_ok_}, true, nullptr};
        sat::BoundOptions now;
        now.max_depth = 0;
        now.deadline = deadline;
        const auto step = sat::bmc(any_step, now).front();
        q.stuck->no_successor =
            step.kind != ReachResult::Kind::Reached && step.why.find("time") == std::string::npos;
        return;
      }
    }
    q.stuck_why = "no situation found from which the property fails (" + std::to_string(tried) +
                  " of the situations on the runs found tried" +
                  (deadline.passed() ? ", then the time limit passed" : "") +
                  "); whether it holds needs the explicit or bdd engine";
  }

  /// The latches of the steps' activity, one group per chart instance (the fields named
  /// "INSTANCE.STEP" with one prefix).
  std::vector<std::vector<std::uint32_t>> step_latch_groups() const {
    const auto& latches_of = circuit().field_latches;
    std::map<std::string, std::vector<std::uint32_t>> by_prefix;
    const auto& fields = ts_.layout().fields();
    for (std::size_t f = 0; f < fields.size(); ++f) {
      const auto kind = fields[f].kind;
      if ((kind != semantics::FieldKind::StepReady && kind != semantics::FieldKind::StepActive) ||
          latches_of[f].size() != 1)
        continue;
      const auto& name = fields[f].name;
      const auto dot = name.rfind('.');
      by_prefix[dot == std::string::npos ? std::string() : name.substr(0, dot)].push_back(
          latches_of[f][0]);
    }
    std::vector<std::vector<std::uint32_t>> out;
    for (auto& [prefix, latches] : by_prefix)
      if (latches.size() > 1) out.push_back(std::move(latches));
    return out;
  }

  /// The latches of fields of two bits or more (integer variables, timers, counters of
  /// standard FBs): what a pumped loop may change (loop_pumping.hpp).
  std::vector<std::uint32_t> counter_latches() const {
    std::vector<std::uint32_t> out;
    const auto& fields = ts_.layout().fields();
    for (std::size_t f = 0; f < fields.size(); ++f) {
      const auto kind = fields[f].kind;
      if (kind != semantics::FieldKind::Variable && kind != semantics::FieldKind::Timer &&
          kind != semantics::FieldKind::FbState)
        continue;
      if (fields[f].width < 2) continue;
      for (auto l : iec_->field_latches[f]) out.push_back(l);
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  /// `r` cut at the first frame where `target` holds (IC3's run may pass one before its end):
  /// the trace ends where the property first fails. Grafcet runs are kept as they are.
  ReachResult first_hit(const ReachResult& r, AigLit target) const {
    if (machine_) return r;
    const Aig& aig = iec_->aig;
    std::vector<bool> latches;
    for (const auto& l : aig.latches()) latches.push_back(l.initial);
    for (std::uint32_t j = 0; j < r.depth; ++j) {
      const auto nodes = aig.evaluate(r.inputs[j], latches);
      if (Aig::value_of(nodes, target)) {
        ReachResult cut = r;
        cut.depth = j;
        cut.inputs.resize(j + 1);
        return cut;
      }
      for (std::size_t l = 0; l < latches.size(); ++l)
        latches[l] = Aig::value_of(nodes, aig.latches()[l].next);
    }
    return r;
  }

  /// Puts back each bit of `row` that differs from `before` where the step from `latches` then
  /// still happens, fires the same transitions and reaches the same latches (`nodes`: the
  /// circuit's values under `row`, updated).
  void keep_unneeded_input_bits(const std::vector<bool>& before, std::vector<bool>& row,
                                const std::vector<bool>& latches, std::vector<bool>& nodes) const {
    const auto& iec = *iec_;
    const Aig& aig = iec.aig;
    const auto same_step = [&](const std::vector<bool>& a, const std::vector<bool>& b) {
      if (!Aig::value_of(b, step_ok_)) return false;
      for (const auto f : iec.fired)
        if (Aig::value_of(a, f) != Aig::value_of(b, f)) return false;
      for (const auto& l : aig.latches())
        if (Aig::value_of(a, l.next) != Aig::value_of(b, l.next)) return false;
      return true;
    };
    for (std::size_t b = 0; b < row.size() && b < before.size(); ++b) {
      if (row[b] == before[b]) continue;
      auto kept = row;
      kept[b] = before[b];
      auto kept_nodes = aig.evaluate(kept, latches);
      if (!same_step(nodes, kept_nodes)) continue;
      row = std::move(kept);
      nodes = std::move(kept_nodes);
    }
  }

  /// The run as a trace. `tidy_inputs` false skips keeping the input bits a step does not need
  /// (the states are the same either way): for a finding's words, which read states only.
  logic::Trace trace_of(const ReachResult& r, logic::TraceKind kind,
                        bool tidy_inputs = true) const {
    if (machine_) return grafcet_trace_of(r, kind);
    const auto& iec = *iec_;
    const Aig& aig = iec.aig;
    std::vector<bool> latches;
    for (const auto& l : aig.latches()) latches.push_back(l.initial);
    logic::Trace t;
    t.kind = kind;
    t.steps.push_back({logic::pick_inputs(semantics::InputCondition::always(), ts_.inputs(), {}),
                       semantics::state_from_latches(ts_, iec, latches),
                       {}});
    // The run is replayed on the circuit itself: a model that is not a run is an engine bug.
    // An input bit the step does not need to change keeps the step before's value: the
    // solver's model leaves the bits it does not read free (the simplified unrolling reads
    // fewer), and a row that toggles them says an input changed for nothing (and a program and
    // its IL twin gave different traces of one run).
    auto inputs = r.inputs;
    for (std::uint32_t j = 0; j < r.depth; ++j) {
      auto nodes = aig.evaluate(inputs[j], latches);
      if (!Aig::value_of(nodes, step_ok_))
        throw std::logic_error("sat engine: a run without a step");
      if (j > 0 && tidy_inputs) keep_unneeded_input_bits(inputs[j - 1], inputs[j], latches, nodes);
      logic::TraceStep step;
      step.inputs = semantics::inputs_from_bits(ts_, iec, inputs[j]);
      for (std::uint32_t tr = 0; tr < iec.fired.size(); ++tr)
        if (Aig::value_of(nodes, iec.fired[tr])) step.fired.push_back(tr);
      for (std::size_t l = 0; l < latches.size(); ++l)
        latches[l] = Aig::value_of(nodes, aig.latches()[l].next);
      step.state = semantics::state_from_latches(ts_, iec, latches);
      t.steps.push_back(std::move(step));
    }
    return t;
  }

  /// The machine's run as a run of stable situations: each Stable frame is a row, with the
  /// inputs of the event that left the previous one and every transition cleared on the way;
  /// an event back to the same situation (a stutter, no edge of the explicit graph) is dropped.
  /// With `before_any_situation`, a run that ends before its first stable situation (an
  /// instability of the start) gives a trace without rows instead of an error.
  logic::Trace grafcet_trace_of(const ReachResult& r, logic::TraceKind kind,
                                bool before_any_situation = false) const {
    const Aig& aig = machine_->aig();
    std::vector<bool> latches;
    for (const auto& l : aig.latches()) latches.push_back(l.initial);
    logic::Trace t;
    t.kind = kind;
    std::vector<bool> event, fired(machine_->fired().size(), false);
    for (std::uint32_t j = 0; j <= r.depth; ++j) {
      const auto nodes = aig.evaluate(r.inputs[j], latches);
      if (Aig::value_of(nodes, machine_->at_stable()) ||
          Aig::value_of(nodes, machine_->at_boot())) {
        if (Aig::value_of(nodes, machine_->at_stable())) {
          std::vector<bool> state_latches(
              latches.begin(),
              latches.begin() + static_cast<std::ptrdiff_t>(machine_->num_state_latches()));
          logic::TraceStep step;
          step.inputs = semantics::inputs_from_bits(ts_, *grafcet_, event);
          step.state = semantics::state_from_latches(ts_, *grafcet_, state_latches);
          for (std::uint32_t tr = 0; tr < fired.size(); ++tr)
            if (fired[tr]) step.fired.push_back(tr);
          if (t.steps.empty() || step.state != t.steps.back().state)
            t.steps.push_back(std::move(step));
        }
        event = r.inputs[j];
        fired.assign(fired.size(), false);
      } else {
        for (std::size_t tr = 0; tr < fired.size(); ++tr)
          if (Aig::value_of(nodes, machine_->fired()[tr])) fired[tr] = true;
      }
      if (j == r.depth) break;
      if (!Aig::value_of(nodes, step_ok_))
        throw std::logic_error("sat engine: a run without a step");
      for (std::size_t l = 0; l < latches.size(); ++l)
        latches[l] = Aig::value_of(nodes, aig.latches()[l].next);
    }
    if (t.steps.empty()) {
      if (before_any_situation) return t;
      throw std::logic_error("sat engine: a Grafcet run without a stable situation");
    }
    // The model's values of an integer input may move inside its region while another input
    // changes: one event per row, as `sfcv simulate` reads it (docs/semantics.md 2.15). The
    // replay runs the system, which stops at the deadline: a run found by then is still a run
    // (a verdict it proves is kept), its rows as the model gave them.
    try {
      logic::minimise_input_changes(ts_, t);
    } catch (const LimitReached&) {
    }
    return t;
  }

  std::string certificates(const Question& q) const {
    // Targets proved together share one certificate: each is printed once.
    std::string out;
    std::set<std::string> printed;
    for (auto t : q.targets)
      if (answers_[t].kind == ReachResult::Kind::Unreachable) {
        auto text = sat::certificate_text(engine_aig(), answers_[t].certificate);
        if (printed.insert(text).second) out += text;
      }
    return out;
  }

  std::string not_checked() const {
    return "not checked by the " + std::string(algorithm_name(options_.algorithm)) +
           " engine (it decides AG p, EF p, AG (p -> AX q) and the bounded response AG (p -> s | "
           "EX TRUE & AX (...)) for propositional p, q and s, without fairness); use "
           "--engine explicit or bdd";
  }

  PropertyResult property_result(const logic::Property& p, const Question& q) {
    PropertyResult r;
    r.name = p.name;
    r.formula = logic::to_string(p.formula);
    if (q.shape == Question::Shape::Unsupported) {
      r.verdict = Verdict::NotChecked;  // counts as unknown (exit 3), says why
      r.message = q.refusal.empty() ? not_checked() : q.refusal;
      return r;
    }
    const auto initial = initial_situations();
    if (initial == 0u) {  // as the explicit engine: no state to judge
      r.verdict = Verdict::Unknown;
      r.message = "no initial state: every initial valuation's evolutions end in an anomaly";
      return r;
    }
    const auto& a = answers_[q.targets.front()];
    const bool invariant = q.shape == Question::Shape::Invariant;
    if (!invariant && a.kind == ReachResult::Kind::Reached && initial != 1u)
      // EF p must hold in EVERY initial state; a run from one of a Grafcet's several initial
      // situations (one per initial valuation) does not show it for the others.
      return grafcet_ef(std::move(r), *p.formula->args[0], targets_[q.targets.front()]);
    switch (a.kind) {
      case ReachResult::Kind::Reached:
        r.verdict = invariant ? Verdict::Violated : Verdict::Holds;
        r.trace =
            trace_of(first_hit(a, targets_[q.targets.front()]),
                     invariant ? logic::TraceKind::Counterexample : logic::TraceKind::Witness);
        r.trace->marked = logic::atom_observables(*p.formula);
        break;
      case ReachResult::Kind::Unreachable:
        r.verdict = invariant ? Verdict::Holds : Verdict::Violated;
        r.certificate = certificates(q);
        break;
      case ReachResult::Kind::Unknown:
        r.verdict = Verdict::Unknown;
        r.message = a.why;
        break;
    }
    return r;
  }

  /// One target of `aig` (step_ok: the machine's) by the run's algorithm, its proof re-checked.
  ReachResult reach_one(const Aig& aig, AigLit target) {
    sat::ReachQuery query{
        &aig, machine_->step_ok(), {target}, false, nullptr};  // a Grafcet machine
    sat::BoundOptions bounds;
    bounds.max_depth = options_.max_depth;
    bounds.deadline = deadline_;
    ReachResult r;
    switch (options_.algorithm) {
      case SatAlgorithm::Bmc:
        bounds.min_depth = options_.min_depth;
        return sat::bmc(query, bounds).front();
      case SatAlgorithm::KInduction:
        r = sat::k_induction(query, bounds).front();
        break;
      case SatAlgorithm::Ic3: {
        sat::Ic3Options io;
        io.deadline = deadline_;
        r = sat::ic3(query, 0, io);
        if (r.kind == ReachResult::Kind::Reached && r.inputs.size() != r.depth + 1) {
          bounds.max_depth = r.depth;  // rebuild the run with its inputs (as solve())
          r = sat::bmc(query, bounds).front();
        }
        break;
      }
    }
    if (r.kind == ReachResult::Kind::Unreachable) {
      const auto verdict = sat::recheck(query, 0, r.certificate, deadline_);
      if (!verdict.ok) {
        r = ReachResult{};
        r.why = "the certificate of EF failed its re-check (" + verdict.failed + ")";
      }
    }
    return r;
  }

  /// The machine's latch values in the last frame of run `r`.
  static std::vector<bool> last_latches(const Aig& aig, const ReachResult& r) {
    std::vector<bool> latches;
    for (const auto& l : aig.latches()) latches.push_back(l.initial);
    for (std::uint32_t j = 0; j < r.depth; ++j) {
      const auto nodes = aig.evaluate(r.inputs[j], latches);
      for (std::size_t l = 0; l < latches.size(); ++l)
        latches[l] = Aig::value_of(nodes, aig.latches()[l].next);
    }
    return latches;
  }

  /// The most initial situations EF p on a Grafcet examines one by one (grafcet_ef).
  static constexpr std::size_t kMaxInitialSituations = 256;

  /// EF p on a Grafcet whose initial situations are many (docs/engines.md, "EF on Grafcet"):
  /// the initial situations stay a predicate of the machine (at_initial_stable: the stable
  /// situation its Boot step reaches under any initial valuation), and the engine asks, by
  /// its own algorithm, "an initial situation where p is false and not yet covered": none,
  /// EF p holds (p holds there, or a run to p was found from each covered one); one, s0: a
  /// copy of the machine started in s0 asks whether p is reachable from s0: not, EF p is
  /// violated (the run to s0 is the counterexample); yes, s0 is covered, and again. Past
  /// kMaxInitialSituations covered situations the answer is unknown.
  PropertyResult grafcet_ef(PropertyResult r, const logic::Formula& body, AigLit target) {
    auto& m = *machine_;
    Aig& aig = m.mutable_aig();
    const AigLit p = m.in_situation(logic::circuit_literal(*grafcet_, body));
    const AigLit first = m.at_initial_stable();
    const auto n = static_cast<std::uint32_t>(m.num_state_latches());
    AigLit uncovered = Aig::kTrue;
    for (std::size_t covered = 0;; ++covered) {
      const AigLit probe = aig.make_and(first, aig.make_and(Aig::make_not(p), uncovered));
      const auto a = reach_one(aig, probe);
      if (a.kind == ReachResult::Kind::Unknown) {
        r.verdict = Verdict::Unknown;
        r.message = "EF p: a run to p from " + std::to_string(covered) +
                    " initial situations without p; the others: " + a.why;
        return r;
      }
      if (a.kind == ReachResult::Kind::Unreachable) {
        r.verdict = Verdict::Holds;
        r.message = covered == 0 ? "p holds in every initial situation"
                                 : "p holds in every initial situation or a run reaches it (" +
                                       std::to_string(covered) +
                                       " initial situations without p, a run from each)";
        r.certificate = sat::certificate_text(aig, a.certificate);
        return r;
      }
      if (covered == kMaxInitialSituations) {
        r.verdict = Verdict::Unknown;
        r.message = "EF shown from " + std::to_string(covered) +
                    " initial situations without p, and more remain (the bound "
                    "kMaxInitialSituations of the SAT engines); use --engine bdd";
        return r;
      }
      const auto s0 = last_latches(aig, a);
      Aig from_s0 = aig;
      for (std::uint32_t l = 0; l < s0.size(); ++l) from_s0.set_initial(l, s0[l]);
      const auto b = reach_one(from_s0, target);
      if (b.kind == ReachResult::Kind::Unknown) {
        r.verdict = Verdict::Unknown;
        r.message = "whether an initial situation reaches p: " + b.why;
        return r;
      }
      if (b.kind == ReachResult::Kind::Unreachable) {
        r.verdict = Verdict::Violated;
        r.trace = trace_of(a, logic::TraceKind::Counterexample);
        r.trace->note = "no run from this initial situation reaches p";
        r.trace->marked = logic::atom_observables(body);
        r.certificate = sat::certificate_text(from_s0, b.certificate);
        return r;
      }
      AigLit cube = Aig::kTrue;
      for (std::uint32_t l = 0; l < n; ++l)
        cube = aig.make_and(
            cube, s0[l] ? aig.latches()[l].current : Aig::make_not(aig.latches()[l].current));
      uncovered = aig.make_and(uncovered, Aig::make_not(cube));
    }
  }

  /// The number of distinct initial states (IEC: one; Grafcet: one per stable situation some
  /// initial valuation leads to), counted explicitly on charts of at most kCountedInputs
  /// inputs (the enumeration is exponential in them); nullopt when not counted.
  static constexpr std::size_t kCountedInputs = 10;
  std::optional<std::size_t> initial_situations() {
    if (!grafcet_) return 1;
    if (ts_.inputs().size() > kCountedInputs) return std::nullopt;
    if (!initial_count_) {
      struct Collect final : semantics::SuccessorSink {
        std::set<std::vector<semantics::StateWord>> states;
        void successor(const semantics::Successor& s) override {
          states.emplace(s.target.begin(), s.target.end());
        }
      } init;
      ts_.initial_states(init);
      initial_count_ = init.states.size();
    }
    return initial_count_;
  }

  /// Stored-actions and output-conflicts: the explicit engine's findings, verdicts and
  /// messages; the trace is the shallowest run to a finding (the first of equal depth).
  PropertyResult findings_result(PropertyResult r, const Question& q) {
    auto add = [&](std::string finding) {
      ++r.findings_total;
      if (task_.max_findings == 0 || r.findings.size() < task_.max_findings)
        r.findings.push_back(std::move(finding));
    };
    std::size_t unknown = 0;
    std::string why;
    const ReachResult* shallowest = nullptr;
    std::map<std::vector<std::vector<bool>>, logic::Trace> traces;  // by the run's inputs
    for (const auto& f : q.findings) {
      if (!f.target) {
        add(f.text);
        continue;
      }
      const auto& a = answers_[*f.target];
      if (a.kind == ReachResult::Kind::Unknown) {
        ++unknown;
        why = a.why;
      }
      if (a.kind != ReachResult::Kind::Reached) continue;
      // Findings reached by one run (a disjunction of targets, Run::solve) share its states,
      // which is all their words read: built once per run, without tidying its inputs bit by
      // bit (hundreds of findings took 2.7 s past --timeout 20 on xPPU 1).
      auto it = traces.find(a.inputs);
      if (it == traces.end())
        it = traces.emplace(a.inputs, trace_of(a, logic::TraceKind::Counterexample, false)).first;
      add(f.describe(a, it->second));
      if (!shallowest || a.depth < shallowest->depth) shallowest = &a;
    }
    if (shallowest) {
      r.trace = trace_of(*shallowest, logic::TraceKind::Counterexample);
      r.trace->note = q.trace_note;
    }
    const bool judged =
        !q.some_stable || shallowest || answers_[*q.some_stable].kind == ReachResult::Kind::Reached;
    if (!r.findings.empty() && judged) {
      r.verdict = Verdict::Violated;
      if (unknown > 0) r.message = std::to_string(unknown) + " more undecided: " + why;
      if (q.stored_actions && !q.not_checked.empty())
        r.message = "not checked: " + q.not_checked.front();
      return r;
    }
    if (unknown > 0) {
      r.verdict = Verdict::Unknown;
      r.message = std::to_string(unknown) + " of " + std::to_string(q.findings.size()) +
                  " undecided: " + why;
      return r;
    }
    if (!judged) {
      // Grafcet: no stable situation reached, nothing judged (as grafcet_check_question); a
      // finding of the chart itself (an output only ever stored to 1) waits for one too.
      r.findings.clear();
      r.findings_total = 0;
      const auto& a = answers_[*q.some_stable];
      r.verdict = Verdict::Unknown;
      r.message = a.kind == ReachResult::Kind::Unreachable
                      ? "no initial state (the instability check says why): nothing to check"
                      : "no stable situation reached yet: " + a.why;
      return r;
    }
    r.verdict = Verdict::Holds;
    r.message = q.holds_message;
    if (!q.not_checked.empty()) {
      r.verdict = Verdict::NotChecked;
      r.message =
          q.stored_actions
              ? "no defect found in the parts checked; not checked: " + q.not_checked.front() +
                    (q.not_checked.size() > 1
                         ? " (and " + std::to_string(q.not_checked.size() - 1) + " more)"
                         : "")
              : "not checked: " + q.not_checked.front();
    }
    return r;
  }

  PropertyResult stuck_result(StandardCheck c, PropertyResult r, const Question& q) {
    r.formula = q.formula;
    if (q.goals.empty() && q.initial_activities) {
      r.verdict = Verdict::Unknown;
      r.message = q.stuck_why;
      return r;
    }
    if (q.goals.empty()) {
      r.verdict = Verdict::Holds;
      r.message = q.trivial;
      return r;
    }
    if (holds_at_once(q)) {
      r.verdict = Verdict::Holds;
      r.message = "from every reachable situation some transition can still fire";
      r.certificate = certificates(q);
      return r;
    }
    if (!q.stuck) {
      r.verdict = Verdict::Unknown;
      r.message = q.stuck_why;
      return r;
    }
    const auto& found = *q.stuck;
    const auto& goal = q.goals[found.goal];
    r.verdict = Verdict::Violated;
    r.trace = trace_of(found.run, logic::TraceKind::Counterexample);
    r.trace->note = goal.note;
    if (goal.observable) r.trace->marked = {*goal.observable};
    const auto situation = ts_.describe(r.trace->steps.back().state);
    switch (c) {
      case StandardCheck::InitialReturn:
        r.findings.push_back("from situation " + situation + " the initial situation " +
                             ts_.describe(r.trace->steps.front().state) +
                             " can never be reached again");
        break;
      case StandardCheck::GlobalDeadlock: {
        // A Grafcet run counts micro-steps; its trace counts the stable situations.
        const std::size_t depth = machine_ ? r.trace->steps.size() - 1 : found.run.depth;
        r.findings.push_back("situation " + situation + " (after " + std::to_string(depth) +
                             (depth == 1 ? " evolution): " : " evolutions): ") +
                             (found.no_successor
                                  ? "no successor at all (the assumptions exclude every input)"
                                  : goal.finding));
        break;
      }
      default:
        r.findings.push_back(goal.finding);
        r.message = "the ic3 engine reports the first violation it proves";
        break;
    }
    r.certificate = q.stuck_certificate;
    return r;
  }

  /// The inputs of a Grafcet run's Boot step in words (a Boolean by name or `!`name, a number
  /// as name=value): what the first row of an `sfcv simulate --inputs` CSV would hold.
  std::string initial_valuation_text(const std::vector<bool>& bits) const {
    const auto values = semantics::inputs_from_bits(ts_, *grafcet_, bits);
    std::string out;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const auto& in = ts_.inputs()[i];
      out += out.empty() ? "" : " ";
      out += in.type.kind == model::TypeKind::Bool ? (values[i] ? "" : "!") + in.name
                                                   : in.name + "=" + std::to_string(values[i]);
    }
    return "initial inputs " + out;
  }

  /// Grafcet instability (docs/semantics.md 2.11), in the BDD engine's words: an event whose
  /// evolutions repeat a configuration, or raise a range error or a forcing conflict, from a
  /// stable situation or during the start. Holds when both are proved unreachable.
  PropertyResult grafcet_instability_result(PropertyResult r, const Question& q) {
    const std::string what[2] = {"starts transient evolutions that never reach a stable situation",
                                 "raises a range error or a forcing conflict"};
    const std::string at_start[2] = {
        "instability: under some initial input valuation the transient evolutions never reach "
        "a stable situation",
        "range error: under some initial input valuation an evolution raises a range error or "
        "a forcing conflict"};
    std::string why;
    bool proved = true;
    for (std::size_t k = 0; k < 2; ++k) {
      const auto& a = answers_[q.targets[k]];
      proved = proved && a.kind == ReachResult::Kind::Unreachable;
      if (a.kind == ReachResult::Kind::Unknown && why.empty()) why = a.why;
      if (a.kind != ReachResult::Kind::Reached) continue;
      r.verdict = Verdict::Violated;
      auto trace = grafcet_trace_of(a, logic::TraceKind::Counterexample, true);
      if (trace.steps.empty()) {  // no row to show: the valuation is in the words
        r.findings.push_back(at_start[k] + " (" + initial_valuation_text(a.inputs.front()) + ")");
        continue;
      }
      r.findings.push_back(std::string(k == 0 ? "instability" : "range error") + ": from " +
                           ts_.describe(trace.steps.back().state) + " an input event " + what[k]);
      if (!r.trace) {
        trace.note = "an input event from the last situation " + what[k];
        r.trace = std::move(trace);
      }
    }
    if (r.verdict == Verdict::Violated) return r;
    if (proved) {
      r.verdict = Verdict::Holds;
      r.message = "every evolution reaches a stable situation";
      r.certificate = certificates(q);
    } else {
      r.verdict = Verdict::Unknown;
      r.message = why;
    }
    return r;
  }

  PropertyResult check_result(StandardCheck c, const Question& q) {
    PropertyResult r;
    r.name = std::string(logic::to_string(c));
    r.check = r.name;
    // As every engine (standard_check_runner.hpp): a question without meaning on the system.
    if (const auto why = logic::not_applicable(c, ts_, task_.priority_resolves_conflicts)) {
      r.verdict = Verdict::NotApplicable;
      r.message = *why;
      return r;
    }
    if (q.shape == Question::Shape::Unsupported) {
      r.verdict = Verdict::NotChecked;
      const std::string engine(algorithm_name(options_.algorithm));
      r.message =
          !q.refusal.empty() ? q.refusal
          : grafcet_
              ? "not checked by the " + engine +
                    " engine on an IEC 60848 grafcet; use --engine explicit, bdd or auto"
              : "not checked by the " + engine + " engine; use --engine explicit, bdd or auto";
      return r;
    }
    if (q.shape == Question::Shape::Findings) return findings_result(std::move(r), q);
    if (q.shape == Question::Shape::Stuck) return stuck_result(c, std::move(r), q);
    if (q.shape == Question::Shape::Invariant && grafcet_)
      return grafcet_instability_result(std::move(r), q);
    if (q.shape == Question::Shape::Invariant) {  // Instability: a reachable range error
      const auto& a = answers_[q.targets.front()];
      if (a.kind == ReachResult::Kind::Reached) {
        r.verdict = Verdict::Violated;
        r.trace = trace_of(a, logic::TraceKind::Counterexample);
        r.findings.push_back(
            "a range error (integer overflow, division by zero or a value out "
            "of its type) can occur in " +
            ts_.describe(r.trace->steps.back().state));
      } else if (a.kind == ReachResult::Kind::Unreachable) {
        r.verdict = Verdict::Holds;
        r.message = "no range error can occur";
        r.certificate = certificates(q);
      } else {
        r.verdict = Verdict::Unknown;
        r.message = a.why;
      }
      return r;
    }
    // A step or transition reached shows a stable situation too (its target is one).
    const auto reached = [&](std::size_t t) {
      return answers_[t].kind == ReachResult::Kind::Reached;
    };
    if (q.some_stable && !reached(*q.some_stable) &&
        std::none_of(q.targets.begin(), q.targets.end(), reached)) {
      const auto& a = answers_[*q.some_stable];
      r.verdict = Verdict::Unknown;
      r.message = a.kind == ReachResult::Kind::Unreachable
                      ? "no initial state (the instability check says why): nothing to check"
                      : "no stable situation reached yet: " + a.why;
      return r;
    }
    std::size_t unknown = 0;
    std::string why;
    r.target_answers.assign(q.targets.size(), logic::TargetAnswer::Clear);
    for (std::size_t k = 0; k < q.targets.size(); ++k) {
      const auto& a = answers_[q.targets[k]];
      if (a.kind == ReachResult::Kind::Unreachable) {
        r.findings.push_back(q.labels[k]);
        r.target_answers[k] = logic::TargetAnswer::Defect;
      }
      if (a.kind == ReachResult::Kind::Unknown) {
        ++unknown;
        why = a.why;
        r.target_answers[k] = logic::TargetAnswer::Undecided;
      }
    }
    if (!r.findings.empty()) {
      r.verdict = Verdict::Violated;
      r.certificate = certificates(q);
    } else if (unknown > 0) {
      r.verdict = Verdict::Unknown;
      r.message = std::to_string(unknown) + " of " + std::to_string(q.targets.size()) +
                  " undecided: " + why;
    } else {
      r.verdict = Verdict::Holds;
      r.message = c == StandardCheck::Reachable
                      ? "all " + std::to_string(q.targets.size()) + " steps are reachable"
                      : "all " + std::to_string(q.targets.size()) + " transitions can fire";
    }
    if (r.verdict == Verdict::Violated && unknown > 0)
      r.message = std::to_string(unknown) + " more undecided: " + why;
    return r;
  }

  const logic::CheckTask& task_;
  SatEngineOptions options_;
  const semantics::TransitionSystem& ts_;
  std::optional<semantics::TransitionCircuit> iec_;
  std::optional<semantics::GrafcetCircuit> grafcet_;
  std::optional<sat::GrafcetMachine> machine_;  ///< over *grafcet_
  std::map<std::uint32_t, AigLit> step_seen_;   ///< grafcet_step_seen, per observable
  AigLit step_ok_ = Aig::kTrue;
  std::vector<AigLit> targets_;
  /// Per question of two targets or more, its targets (steps, transitions, findings): IC3 tries
  /// the undecided ones of each together first (Run::solve).
  std::vector<std::vector<std::size_t>> groups_;
  std::vector<logic::StepRef> steps_;  ///< the chart's steps (stored-actions)
  /// The states without a successor (observers.hpp), built once when a property needs it;
  /// nullopt inside when too many inputs decide it.
  std::optional<std::optional<AigLit>> dead_;
  std::optional<std::size_t> initial_count_;
  std::vector<ReachResult> answers_;
  sat::Deadline deadline_;
  /// Re-checked invariants of the circuit (Houdini's, then each IC3 proof's): every later IC3
  /// run assumes them, from the initial state or from a reachable situation.
  std::vector<sat::LatchClause> known_;
  std::optional<std::vector<std::pair<ReachResult, std::vector<bool>>>> situations_;
};

class SatModelChecker final : public ModelChecker {
 public:
  explicit SatModelChecker(SatEngineOptions options) : options_(options) {}
  std::string_view name() const override { return algorithm_name(options_.algorithm); }

  bool can_handle(const logic::CheckTask& task, std::string* why) const override {
    if (!task.system) {
      if (why) *why = "no system to check";
      return false;
    }
    if (const auto* ltl = logic::first_ltl_property(task)) {
      if (why) *why = logic::ltl_refusal(name(), *ltl);
      return false;
    }
    try {
      if (task.system->kind() == semantics::SemanticsKind::Grafcet)
        semantics::build_grafcet_circuit(*task.system, task.limits.deadline,
                                         task.limits.max_memory_bytes);
      else
        semantics::build_iec61131_circuit(*task.system, task.limits.deadline,
                                          task.limits.max_memory_bytes);
    } catch (const semantics::CircuitUnsupported& e) {
      if (why) *why = "the " + std::string(name()) + " engine cannot encode " + e.what();
      return false;
    } catch (const LimitReached&) {
      return true;  // check() meets the limit again and answers unknown
    }
    return true;
  }

  logic::CheckReport check(const logic::CheckTask& task) const override {
    Run run(task, options_);
    return run.check();
  }

 private:
  SatEngineOptions options_;
};

}  // namespace

ModelCheckerPtr make_sat_model_checker(const SatEngineOptions& options) {
  return std::make_unique<SatModelChecker>(options);
}

}  // namespace sfcv::engine
