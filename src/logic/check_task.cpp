#include "logic/check_task.hpp"

namespace sfcv::logic {

CheckReport unknown_report(const CheckTask& task, const std::string& engine,
                           const LimitReached& why) {
  CheckReport report;
  report.engine = engine;
  report.states_known = false;
  report.edges_known = false;
  report.complete = false;
  report.limit = to_string(why.which());
  for (const auto& p : task.properties) {
    PropertyResult r;
    r.name = p.name;
    r.formula = to_string(p.formula);
    r.where = p.where;
    r.verdict = Verdict::Unknown;
    r.message = why.what();
    report.results.push_back(std::move(r));
  }
  for (auto c : task.checks) {
    PropertyResult r;
    r.name = std::string(to_string(c));
    r.check = r.name;
    const auto meaningless = task.system
                                 ? not_applicable(c, *task.system, task.priority_resolves_conflicts)
                                 : std::nullopt;
    r.verdict = meaningless ? Verdict::NotApplicable : Verdict::Unknown;
    r.message = meaningless ? *meaningless : why.what();
    report.results.push_back(std::move(r));
  }
  return report;
}

}  // namespace sfcv::logic
