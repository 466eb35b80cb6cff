#include "logic/vacuity.hpp"

#include "logic/formula.hpp"

namespace sfcv::logic {

FormulaPtr vacuity_antecedent(const Formula& f) {
  if (f.op != Op::AG || f.args.size() != 1) return nullptr;
  const auto& body = *f.args[0];
  if (body.op != Op::Implies || !is_propositional(*body.args[0])) return nullptr;
  // AG (a -> b) with a constant antecedent is not a trigger.
  if (body.args[0]->op == Op::True || body.args[0]->op == Op::False) return nullptr;
  return body.args[0];
}

std::vector<VacuityQuestion> add_vacuity_questions(CheckTask& task) {
  std::vector<VacuityQuestion> out;
  const auto n = task.properties.size();
  for (std::size_t i = 0; i < n; ++i) {
    auto a = vacuity_antecedent(*task.properties[i].formula);
    if (!a) continue;
    out.push_back({i, a});
    auto question = make_op(Op::EF, {a}, a->line, a->column);
    task.properties.push_back(Property{"EF " + to_string(a), question, task.properties[i].where});
  }
  return out;
}

void answer_vacuity(CheckReport& report, const std::vector<VacuityQuestion>& questions,
                    std::size_t num_properties) {
  if (questions.empty() || report.results.size() < num_properties + questions.size()) return;
  for (std::size_t q = 0; q < questions.size(); ++q) {
    const auto& answer = report.results[num_properties + q];
    auto& r = report.results[questions[q].property];
    if (r.verdict != Verdict::Holds) continue;
    const std::string a = to_string(questions[q].antecedent);
    switch (answer.verdict) {
      case Verdict::Holds:
        r.vacuous = false;
        r.vacuity = "not vacuous: the antecedent " + a + " is reachable (EF " + a + " holds, " +
                    "witness of " + std::to_string(answer.trace ? answer.trace->steps.size() : 0) +
                    " situations)";
        break;
      case Verdict::Violated:
        r.vacuous = true;
        r.vacuity = "VACUOUS: the antecedent " + a + " is never true in a reachable state (EF " +
                    a + " is violated)";
        break;
      default:
        r.vacuity = "vacuity unknown: EF " + a + " is " + std::string(to_string(answer.verdict));
        break;
    }
  }
  report.results.erase(
      report.results.begin() + static_cast<std::ptrdiff_t>(num_properties),
      report.results.begin() + static_cast<std::ptrdiff_t>(num_properties + questions.size()));
}

}  // namespace sfcv::logic
