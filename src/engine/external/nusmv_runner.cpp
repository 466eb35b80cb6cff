#include "engine/external/nusmv_runner.hpp"

#include <chrono>
#include <fstream>
#include <sstream>

#include "engine/external/export_model.hpp"
#include "engine/external/external_tool.hpp"
#include "logic/formula.hpp"
#include "semantics/simulate.hpp"

namespace sfcv::engine {

const char* const kNusmvCommands =
    "unset use_coi_size_sorting\ngo\ncheck_ctlspec\ncheck_invar\nquit\n";

std::optional<std::string> find_nusmv() {
  return find_on_path({"NuSMV"});
}

NusmvVerdicts parse_nusmv_output(const std::string& text) {
  NusmvVerdicts v;
  std::istringstream in(text);
  std::string line;
  NusmvTrace* trace = nullptr;  // the trace being read, after a "false" verdict
  bool in_inputs = false;
  bool loop_next = false;
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    const auto first = line.find_first_not_of(' ');
    const std::string body = first == std::string::npos ? "" : line.substr(first);
    const bool spec = line.rfind("-- specification ", 0) == 0;
    const bool invar = line.rfind("-- invariant ", 0) == 0;
    if (spec || invar) {
      bool value;
      if (line.size() >= 8 && line.compare(line.size() - 8, 8, " is true") == 0)
        value = true;
      else if (line.size() >= 9 && line.compare(line.size() - 9, 9, " is false") == 0)
        value = false;
      else
        continue;
      (spec ? v.ctl : v.invariants).push_back(value);
      auto& traces = spec ? v.ctl_traces : v.invariant_traces;
      traces.emplace_back();
      trace = nullptr;
      if (!value) {
        traces.back().emplace();
        trace = &*traces.back();
      }
      in_inputs = loop_next = false;
      continue;
    }
    if (!trace) {  // (inside a trace, a variable's name may contain "error")
      if (body.rfind("file ", 0) == 0 || body.rfind("ERROR", 0) == 0 ||
          body.find("error") != std::string::npos)
        v.errors.push_back(body);
      continue;
    }
    if (body == "-- Loop starts here") {
      loop_next = true;
    } else if (body.rfind("-> State:", 0) == 0) {
      if (loop_next) trace->loop_start = trace->states;
      loop_next = false;
      ++trace->states;
      in_inputs = false;
    } else if (body.rfind("-> Input:", 0) == 0) {
      trace->inputs.push_back(trace->inputs.empty() ? std::map<std::string, bool>{}
                                                    : trace->inputs.back());
      in_inputs = true;
    } else if (in_inputs) {
      const auto eq = body.find(" = ");
      if (eq != std::string::npos)
        trace->inputs.back()[body.substr(0, eq)] = body.substr(eq + 3) == "TRUE";
    }
  }
  return v;
}

namespace {

// A propositional formula in one state.
bool holds_in(const semantics::TransitionSystem& ts, const logic::Formula& f,
              semantics::StateView s) {
  using logic::Op;
  auto arg = [&](std::size_t k) { return holds_in(ts, *f.args[k], s); };
  switch (f.op) {
    case Op::True:
      return true;
    case Op::Atom:
      return ts.observe(s, static_cast<std::uint32_t>(f.observable)) != 0;
    case Op::Compare:
      return logic::compare(f.cmp, ts.observe(s, static_cast<std::uint32_t>(f.observable)),
                            f.value);
    case Op::Relation:
      return logic::relation_holds(f, [&](std::uint32_t o) { return ts.observe(s, o); });
    case Op::Not:
      return !arg(0);
    case Op::And:
      return arg(0) && arg(1);
    case Op::Or:
      return arg(0) || arg(1);
    case Op::Implies:
      return !arg(0) || arg(1);
    case Op::Iff:
      return arg(0) == arg(1);
    case Op::Xor:
      return arg(0) != arg(1);
    default:
      return false;
  }
}

// The circuit inputs of each step of NuSMV's trace.
std::vector<std::vector<bool>> nusmv_frames(const ExportedModel& exported, const NusmvTrace& t) {
  const auto ids = nusmv_input_identifiers(exported.model);
  std::vector<std::vector<bool>> frames;
  for (const auto& values : t.inputs) {
    std::vector<bool> frame(ids.size(), false);
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (const auto it = values.find(ids[i]); it != values.end()) frame[i] = it->second;
    frames.push_back(std::move(frame));
  }
  return frames;
}

// NuSMV's trace replayed through the chart, or nullopt with `why` when it does not replay (or,
// for an invariant AG p, does not end in a state violating p).
std::optional<logic::Trace> to_sfcv_trace(const semantics::TransitionSystem& ts,
                                          const ExportedModel& exported, const NusmvTrace& t,
                                          const logic::Formula& property, std::string& why) {
  const auto frames = nusmv_frames(exported, t);
  if (t.states == 0 || frames.size() + 1 != t.states) {
    why = "NuSMV's trace has " + std::to_string(t.states) + " states and " +
          std::to_string(frames.size()) + " input steps";
    return std::nullopt;
  }
  const auto inputs = frames_to_inputs(ts, exported.circuit, frames);
  const auto sim = semantics::simulate(ts, semantics::first_initial_state(ts), inputs);
  if (!sim.ok) {
    why = "NuSMV's trace does not replay in sfcv at cycle " + std::to_string(sim.failed_cycle) +
          ": " + sim.error;
    return std::nullopt;
  }
  logic::Trace trace;
  trace.kind = logic::TraceKind::Counterexample;
  trace.loop_start = t.loop_start;
  for (std::size_t k = 0; k < sim.states.size(); ++k) {
    logic::TraceStep step;
    step.state = sim.states[k];
    if (k == 0) {
      step.inputs = logic::pick_inputs(semantics::InputCondition::always(), ts.inputs(), {});
    } else {
      step.inputs = inputs[k - 1];
      step.fired = sim.fired[k - 1];
    }
    trace.steps.push_back(std::move(step));
  }
  if (trace.loop_start && (*trace.loop_start >= trace.steps.size() ||
                           trace.steps[*trace.loop_start].state != trace.steps.back().state)) {
    why = "NuSMV's loop does not close in sfcv's replay";
    return std::nullopt;
  }
  if (is_invariant(property) && holds_in(ts, *property.args[0], trace.steps.back().state)) {
    why = "NuSMV's trace replays in sfcv to a state that satisfies the invariant";
    return std::nullopt;
  }
  trace.note = "NuSMV's counterexample, replayed through the chart";
  return trace;
}

// NuSMV's error lines, or the last line it printed.
std::string nusmv_failure(const ToolRun& run, const NusmvVerdicts& verdicts) {
  std::string why;
  for (std::size_t i = 0; i < verdicts.errors.size() && i < 3; ++i)
    why += (i ? "; " : "") + verdicts.errors[i];
  if (why.empty()) {
    std::istringstream in(run.output);
    for (std::string line; std::getline(in, line);)
      if (line.find_first_not_of(" \t\r") != std::string::npos) why = line;
  }
  if (why.empty()) why = "no output";
  return "NuSMV gave no verdict for every property (exit code " + std::to_string(run.exit_code) +
         "): " + why;
}

class NusmvModelChecker final : public ModelChecker {
 public:
  explicit NusmvModelChecker(std::string nusmv) : nusmv_(std::move(nusmv)) {}

  std::string_view name() const override { return "nusmv"; }

  bool can_handle(const logic::CheckTask& task, std::string* why) const override {
    auto no = [why](std::string w) {
      if (why) *why = std::move(w);
      return false;
    };
    if (const auto* ltl = logic::first_ltl_property(task)) {
      if (why) *why = logic::ltl_refusal("nusmv", *ltl);
      return false;
    }
    if (!task.system || task.system->kind() != semantics::SemanticsKind::Iec61131)
      return no("--engine nusmv: exports are not supported for Grafcet yet");
    if (!task.fairness.empty()) return no("--engine nusmv does not take fairness constraints yet");
    if (!task.checks.empty())
      return no("--engine nusmv checks properties only (use --checks none)");
    if (task.properties.empty()) return no("--engine nusmv needs at least one property");
    try {  // what the circuit cannot express is bad input, before NuSMV runs
      ExportRequest request;
      request.properties = task.properties;
      build_export(*task.system, request);
    } catch (const ExportError& e) {
      return no(std::string("--engine nusmv: ") + e.what());
    }
    return true;
  }

  logic::CheckReport check(const logic::CheckTask& task) const override {
    const auto start = std::chrono::steady_clock::now();
    ExportRequest request;
    request.target = ExportTarget::Smv;
    request.properties = task.properties;
    const auto exported = build_export(*task.system, request);
    TempDir dir;
    {
      std::ofstream f(dir.path() + "/model.smv");
      write_nusmv(f, exported.model);
    }
    {
      // NuSMV 2.6 checks (and prints) the properties of one kind ordered by the size of their
      // cone of influence, not in file order, and its verdict lines carry no property name:
      // read in file order, the verdicts of two properties could swap (a false "holds").
      std::ofstream f(dir.path() + "/sfcv.cmd");
      f << kNusmvCommands;
    }
    // Under the run's deadline, and killed with its process group when the run is cancelled
    // (the memory watchdog, a signal).
    const auto run = run_tool({nusmv_, "-source", "sfcv.cmd", "model.smv"}, dir.path(),
                              task.limits.seconds_left(), task.limits.cancel.get());
    const auto verdicts = parse_nusmv_output(run.output);

    logic::CheckReport report;
    report.engine = "nusmv";
    std::vector<logic::PropertyResult> results(task.properties.size());
    for (std::size_t p = 0; p < task.properties.size(); ++p) {
      results[p].name = task.properties[p].name;
      results[p].formula = logic::to_string(task.properties[p].formula);
      results[p].where = task.properties[p].where;
      results[p].verdict = logic::Verdict::Unknown;
      results[p].message =
          run.timed_out ? "NuSMV reached the time limit" : "no verdict in NuSMV's output";
    }
    // A cycle may meet the ST loop bound (sfcv_loop_limit, export_model.hpp): every property
    // fails where the flag is set, so such a false verdict is unknown.
    const bool flag_reached = exported.loop_limit_bad &&
                              verdicts.invariants.size() > *exported.loop_limit_bad &&
                              !verdicts.invariants[*exported.loop_limit_bad];
    auto set = [&](std::int32_t p, bool holds, const std::optional<NusmvTrace>& trace,
                   bool invariant) {
      if (p < 0) return;
      const auto& prop = task.properties[static_cast<std::size_t>(p)];
      auto& r = results[static_cast<std::size_t>(p)];
      const bool unknown =
          !holds && flag_reached &&
          (!invariant || !trace || ends_in_loop_limit(exported, nusmv_frames(exported, *trace)));
      if (unknown) {
        r.verdict = logic::Verdict::Unknown;
        r.message = "NuSMV: false where " + exported.circuit.loop_limit_message();
        return;
      }
      r.verdict = holds ? logic::Verdict::Holds : logic::Verdict::Violated;
      r.message = holds ? "NuSMV: true" : "NuSMV: false";
      if (holds) return;
      std::string why = "NuSMV printed no trace";
      if (trace) r.trace = to_sfcv_trace(*task.system, exported, *trace, *prop.formula, why);
      if (r.trace)
        r.trace->marked = logic::atom_observables(*prop.formula);
      else
        r.message += " (" + why + ")";
    };
    const bool complete = verdicts.ctl.size() == exported.ctl_property.size() &&
                          verdicts.invariants.size() == exported.bad_property.size();
    if (complete && !run.timed_out) {
      for (std::size_t i = 0; i < verdicts.ctl.size(); ++i)
        set(exported.ctl_property[i], verdicts.ctl[i], verdicts.ctl_traces[i], false);
      for (std::size_t i = 0; i < verdicts.invariants.size(); ++i)
        set(exported.bad_property[i], verdicts.invariants[i], verdicts.invariant_traces[i], true);
    } else {
      report.complete = false;
      report.limit = run.timed_out ? "time" : "";
      if (!run.timed_out)
        for (auto& r : results) r.message = nusmv_failure(run, verdicts);
    }
    report.results = std::move(results);
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
  }

 private:
  std::string nusmv_;
};

}  // namespace

ModelCheckerPtr make_nusmv_model_checker(std::string nusmv) {
  return std::make_unique<NusmvModelChecker>(std::move(nusmv));
}

}  // namespace sfcv::engine
