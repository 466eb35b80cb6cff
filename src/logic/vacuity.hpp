#pragma once
// Vacuity: a property AG (a -> f) that holds because `a` is never true in a reachable state says
// nothing. For each such property the check also asks the witness question EF a, and reports
// the answer with the property (PropertyResult::vacuous).

#include <cstddef>
#include <vector>

#include "logic/check_result.hpp"
#include "logic/check_task.hpp"

namespace sfcv::logic {

/// The antecedent `a` of AG (a -> f) with `a` propositional; null for any other shape.
FormulaPtr vacuity_antecedent(const Formula& f);

struct VacuityQuestion {
  std::size_t property = 0;  ///< index of the AG (a -> f) property in the task
  FormulaPtr antecedent;
};

/// Appends EF a to task.properties for every AG (a -> f) property; returns the questions (the
/// appended properties are the last questions.size() ones).
std::vector<VacuityQuestion> add_vacuity_questions(CheckTask& task);

/// Answers the questions in the report of the task add_vacuity_questions extended (whose
/// property results come first, in order): sets vacuous/vacuity on the properties that hold and
/// removes the questions' own results.
void answer_vacuity(CheckReport& report, const std::vector<VacuityQuestion>& questions,
                    std::size_t num_properties);

}  // namespace sfcv::logic
