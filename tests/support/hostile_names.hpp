#pragma once
// Names that would change an export's meaning if written unescaped (issue 53, item 6): line
// breaks followed by a keyword, comment closers and openers of every target, quotes, '#define',
// keywords of NuSMV, Promela and AIGER's symbol table, unicode, spaces, CSV separators, the
// export's own `{k}` placeholder, HTML and DOT attribute text. hostile_chart() uses each once,
// as an input, a step or a variable, in a chart whose verdicts do not depend on the names.

#include <string>
#include <vector>

#include "model/expr.hpp"
#include "model/statement.hpp"
#include "support/model_builder.hpp"

namespace sfcv::test {

inline const std::vector<std::string>& hostile_names() {
  static const std::vector<std::string> names = {
      "z\nINIT FALSE\nVAR --",
      "a */\n#define assert(x) skip\n/* ",
      "-- dash",
      "// slash */",
      "q\"uote'",
      "back\\slash\\",
      "#define X 1",
      "MODULE",
      "VAR",
      "INIT",
      "TRUE",
      "next",
      "case",
      "esac",
      "proctype",
      "active",
      "assert",
      "skip",
      "i0 evil\nl0 evil\nc",
      "unicode \xc3\xbc\xe2\x86\x92 \xe6\xbc\xa2",
      "with space",
      "x,y",
      "%s%n",
      "{0}",
      "}",
      "<b>&amp;</b>",
      "\"URL=\"javascript:alert(1)",
      ";semi",
      " lead\r\n",
  };
  return names;
}

/// Start -> steps[0] -> ... -> steps[n-1] -> Bad: the transition out of Start needs inputs[0];
/// the one out of steps[k] needs inputs[k+1] (cyclically) and variables[k] (cyclically), which
/// an action of steps[k] sets. So `AG !Bad` is violated (n + 1 cycles at least) and
/// `AG !(Start & Bad)` holds. The hostile names: inputs, steps and variables in turn.
struct HostileChart {
  model::Project project;
  std::vector<std::string> inputs, steps, variables;
};

/// `rotate` (0, 1, 2) shifts the roles: over the three rotations every name is once an input,
/// once a step and once a variable.
inline HostileChart hostile_chart(std::size_t rotate = 0) {
  HostileChart h;
  const auto& names = hostile_names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto role = (i + rotate) % 3;
    (role == 0 ? h.inputs : role == 1 ? h.steps : h.variables).push_back(names[i]);
  }
  PouBuilder b("P");
  for (const auto& in : h.inputs) b.input(in, "BOOL");
  for (const auto& v : h.variables) b.var(v, "BOOL");
  b.chart("main").initial("Start");
  for (const auto& s : h.steps) b.step(s);
  b.step("Bad");
  const auto n = h.steps.size();
  b.trans({"Start"}, {h.steps[0]}, model::make_name(h.inputs[0]));
  for (std::size_t k = 0; k < n; ++k) {
    auto guard = model::make_nary(model::ExprKind::And,
                                  {model::make_name(h.inputs[(k + 1) % h.inputs.size()]),
                                   model::make_name(h.variables[k % h.variables.size()])});
    b.trans({h.steps[k]}, {k + 1 < n ? h.steps[k + 1] : std::string("Bad")}, guard);
    const std::string action = "Set" + std::to_string(k);
    b.action_st(action,
                {model::make_assign(h.variables[k % h.variables.size()], model::make_bool(true))});
    b.assoc("main", h.steps[k], action);
  }
  h.project = b.project();
  return h;
}

}  // namespace sfcv::test
