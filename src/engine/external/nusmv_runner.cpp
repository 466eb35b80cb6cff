#include "engine/external/nusmv_runner.hpp"

#include <chrono>
#include <fstream>
#include <sstream>

#include "engine/external/export_model.hpp"
#include "engine/external/external_tool.hpp"
#include "logic/formula.hpp"

namespace sfcv::engine {

std::optional<std::string> find_nusmv() { return find_on_path({"NuSMV"}); }

NusmvVerdicts parse_nusmv_output(const std::string& text) {
  NusmvVerdicts v;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    const bool spec = line.rfind("-- specification ", 0) == 0;
    const bool invar = line.rfind("-- invariant ", 0) == 0;
    if (!spec && !invar) continue;
    bool value;
    if (line.size() >= 8 && line.compare(line.size() - 8, 8, " is true") == 0) value = true;
    else if (line.size() >= 9 && line.compare(line.size() - 9, 9, " is false") == 0) value = false;
    else continue;
    (spec ? v.ctl : v.invariants).push_back(value);
  }
  return v;
}

namespace {

class NusmvModelChecker final : public ModelChecker {
 public:
  explicit NusmvModelChecker(std::string nusmv) : nusmv_(std::move(nusmv)) {}

  std::string_view name() const override { return "nusmv"; }

  bool can_handle(const logic::CheckTask& task, std::string* why) const override {
    auto no = [why](std::string w) {
      if (why) *why = std::move(w);
      return false;
    };
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
    const auto run = run_tool({nusmv_, "model.smv"}, dir.path(), task.limits.seconds_left());
    const auto verdicts = parse_nusmv_output(run.output);

    logic::CheckReport report;
    report.engine = "nusmv";
    std::vector<logic::PropertyResult> results(task.properties.size());
    for (std::size_t p = 0; p < task.properties.size(); ++p) {
      results[p].name = task.properties[p].name;
      results[p].formula = logic::to_string(task.properties[p].formula);
      results[p].where = task.properties[p].where;
      results[p].verdict = logic::Verdict::Unknown;
      results[p].message = run.timed_out ? "NuSMV reached the time limit"
                                         : "no verdict in NuSMV's output";
    }
    auto set = [&](std::int32_t p, bool holds) {
      if (p < 0) return;
      auto& r = results[static_cast<std::size_t>(p)];
      r.verdict = holds ? logic::Verdict::Holds : logic::Verdict::Violated;
      r.message = holds ? "NuSMV: true" : "NuSMV: false (its trace is not mapped back; run "
                                          "sfcv check for one)";
    };
    const bool complete = verdicts.ctl.size() == exported.ctl_property.size() &&
                          verdicts.invariants.size() == exported.bad_property.size();
    if (complete && !run.timed_out) {
      for (std::size_t i = 0; i < verdicts.ctl.size(); ++i)
        set(exported.ctl_property[i], verdicts.ctl[i]);
      for (std::size_t i = 0; i < verdicts.invariants.size(); ++i)
        set(exported.bad_property[i], verdicts.invariants[i]);
    } else {
      report.complete = false;
      report.limit = run.timed_out ? "time" : "";
      if (!run.timed_out) {
        auto tail = run.output.substr(run.output.size() > 400 ? run.output.size() - 400 : 0);
        for (auto& r : results) r.message = "NuSMV gave no verdict for every property: " + tail;
      }
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
