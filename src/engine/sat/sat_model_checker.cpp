#include "engine/sat/sat_model_checker.hpp"

#include <chrono>
#include <optional>
#include <set>
#include <stdexcept>

#include "engine/sat/bmc.hpp"
#include "engine/sat/certificate.hpp"
#include "engine/sat/grafcet_machine.hpp"
#include "engine/sat/ic3.hpp"
#include "engine/sat/k_induction.hpp"
#include "logic/circuit_atom.hpp"
#include "logic/formula.hpp"
#include "logic/standard_checks.hpp"
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

/// How a property or check reads the answers for its targets.
struct Question {
  enum class Shape { Invariant, Reach, Check, Unsupported } shape = Shape::Unsupported;
  std::vector<std::size_t> targets;  ///< indices into the query's targets
  std::vector<std::string> labels;   ///< Check: per target, the finding when it is unreachable
};

class Run {
 public:
  Run(const logic::CheckTask& task, const SatEngineOptions& options)
      : task_(task), options_(options), ts_(*task.system) {
    if (ts_.kind() == semantics::SemanticsKind::Grafcet) {
      grafcet_.emplace(semantics::build_grafcet_circuit(ts_));
      machine_.emplace(*grafcet_);
      step_ok_ = machine_->step_ok();
    } else {
      iec_.emplace(semantics::build_iec61131_circuit(ts_));
      step_ok_ = iec_->aig.make_and(iec_->allowed, Aig::make_not(iec_->range_error));
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
    answers_ = solve();

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
  /// The circuit observables and properties are read on.
  semantics::TransitionCircuit& circuit() {
    return grafcet_ ? static_cast<semantics::TransitionCircuit&>(*grafcet_) : *iec_;
  }
  /// The circuit the engines unroll: the IEC scan cycle, or the Grafcet machine whose steps
  /// are micro-steps of the stable-situation relation.
  const Aig& engine_aig() const { return machine_ ? machine_->aig() : iec_->aig; }

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
    }
    return q;
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
    // Grafcet's standard checks judge transient evolutions too (steps crossed only during
    // them, events that never stabilise): not invariants of the stable situations.
    if (grafcet_) return q;
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
        q.targets.push_back(add_target(iec.aig.make_and(iec.allowed, iec.range_error)));
        break;
      default:
        break;
    }
    return q;
  }

  std::vector<ReachResult> solve() {
    sat::ReachQuery query;
    query.aig = &engine_aig();
    query.step_ok = step_ok_;
    query.targets = targets_;
    sat::BoundOptions bounds;
    bounds.max_depth = options_.max_depth;
    bounds.deadline = deadline_;
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
        return sat::bmc(query, bounds);
      case SatAlgorithm::KInduction:
        out = sat::k_induction(query, bounds);
        for (std::size_t t = 0; t < out.size(); ++t) recheck(t, out[t]);
        return out;
      case SatAlgorithm::Ic3:
        break;
    }
    sat::Ic3Options io;
    io.deadline = deadline_;
    for (std::size_t t = 0; t < targets_.size(); ++t) {
      auto r = sat::ic3(query, t, io);
      if (r.kind == ReachResult::Kind::Reached && r.inputs.size() != r.depth + 1) {
        // IC3 returns its run's inputs once they replay on the circuit (ic3.hpp); else it
        // knows only that a run of r.depth cycles exists, and BMC up to that depth rebuilds a
        // shortest one with its inputs (and double-checks IC3's claim).
        sat::ReachQuery one = query;
        one.targets = {targets_[t]};
        sat::BoundOptions b;
        b.max_depth = r.depth;
        b.deadline = deadline_;
        auto run = sat::bmc(one, b).front();
        if (run.kind == ReachResult::Kind::Unknown && run.why.find("time") == std::string::npos)
          throw std::logic_error("ic3: a counterexample that BMC cannot rebuild");
        r = std::move(run);
      }
      // At once: a later target that runs out of time must not cost this proof.
      recheck(t, r);
      out.push_back(std::move(r));
    }
    return out;
  }

  logic::Trace trace_of(const ReachResult& r, logic::TraceKind kind) const {
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
    for (std::uint32_t j = 0; j < r.depth; ++j) {
      const auto nodes = aig.evaluate(r.inputs[j], latches);
      if (!Aig::value_of(nodes, step_ok_))
        throw std::logic_error("sat engine: a run without a step");
      logic::TraceStep step;
      step.inputs = semantics::inputs_from_bits(ts_, iec, r.inputs[j]);
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
  logic::Trace grafcet_trace_of(const ReachResult& r, logic::TraceKind kind) const {
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
    if (t.steps.empty())
      throw std::logic_error("sat engine: a Grafcet run without a stable situation");
    return t;
  }

  std::string certificates(const Question& q) const {
    std::string out;
    for (auto t : q.targets)
      if (answers_[t].kind == ReachResult::Kind::Unreachable)
        out += sat::certificate_text(engine_aig(), answers_[t].certificate);
    return out;
  }

  std::string not_checked() const {
    return "not checked by the " + std::string(algorithm_name(options_.algorithm)) +
           " engine (it decides AG p, EF p and AG (p -> AX q) for propositional p and q, without "
           "fairness); use "
           "--engine explicit or bdd";
  }

  PropertyResult property_result(const logic::Property& p, const Question& q) {
    PropertyResult r;
    r.name = p.name;
    r.formula = logic::to_string(p.formula);
    if (q.shape == Question::Shape::Unsupported) {
      r.verdict = Verdict::Unknown;
      r.message = not_checked();
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
    if (!invariant && a.kind == ReachResult::Kind::Reached && initial != 1u) {
      // EF p must hold in EVERY initial state; a run from one of a Grafcet's several initial
      // situations (one per initial valuation) does not show it for the others.
      r.verdict = Verdict::Unknown;
      r.message =
          "not checked by the " + std::string(algorithm_name(options_.algorithm)) +
          " engine: this Grafcet has " +
          (initial ? std::to_string(*initial) : std::string("maybe several")) +
          " initial situations and EF p needs a run from each; use --engine explicit or bdd";
      return r;
    }
    switch (a.kind) {
      case ReachResult::Kind::Reached:
        r.verdict = invariant ? Verdict::Violated : Verdict::Holds;
        r.trace =
            trace_of(a, invariant ? logic::TraceKind::Counterexample : logic::TraceKind::Witness);
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

  PropertyResult check_result(StandardCheck c, const Question& q) {
    PropertyResult r;
    r.name = std::string(logic::to_string(c));
    r.check = r.name;
    if (q.shape == Question::Shape::Unsupported) {
      r.verdict = Verdict::NotChecked;
      r.message = "not checked by the " + std::string(algorithm_name(options_.algorithm)) +
                  " engine" + (grafcet_ ? " on a Grafcet chart" : "") +
                  "; use --engine explicit or bdd";
      return r;
    }
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
    std::size_t unknown = 0;
    std::string why;
    for (std::size_t k = 0; k < q.targets.size(); ++k) {
      const auto& a = answers_[q.targets[k]];
      if (a.kind == ReachResult::Kind::Unreachable) r.findings.push_back(q.labels[k]);
      if (a.kind == ReachResult::Kind::Unknown) {
        ++unknown;
        why = a.why;
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
  AigLit step_ok_ = Aig::kTrue;
  std::vector<AigLit> targets_;
  std::optional<std::size_t> initial_count_;
  std::vector<ReachResult> answers_;
  sat::Deadline deadline_;
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
        semantics::build_grafcet_circuit(*task.system);
      else
        semantics::build_iec61131_circuit(*task.system);
    } catch (const semantics::CircuitUnsupported& e) {
      if (why) *why = "the " + std::string(name()) + " engine cannot encode " + e.what();
      return false;
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
