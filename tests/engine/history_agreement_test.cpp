// Inputs and previous values in properties (semantics/history_system.hpp): the explicit engine
// (HistorySystem's successors) and the BDD engine (the circuit's history latches) agree on
// random charts and random formulas over inputs, prev(), rise() and fall(); identities that
// define prev hold on both; traces replay through `simulate`.

#include <gtest/gtest.h>

#include <random>

#include "chart_families.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "logic/formula.hpp"
#include "semantics/history_system.hpp"
#include "semantics/iec61131_system.hpp"
#include "semantics/simulate.hpp"

namespace sfcv::engine {
namespace {

/// Random CTL whose atoms are Boolean observables, inputs, and prev/rise/fall of either.
class HistoryFormulas {
 public:
  HistoryFormulas(const semantics::TransitionSystem& ts, std::uint64_t seed) : rng_(seed) {
    for (const auto& o : ts.observables())
      if (o.type.kind == model::TypeKind::Bool) names_.push_back(o.name);
    for (const auto& in : ts.inputs())
      if (!in.pseudo && in.type.kind == model::TypeKind::Bool) {
        names_.push_back(in.name);
        inputs_.push_back(in.name);
      }
  }
  std::string name() { return names_[pick(static_cast<std::uint32_t>(names_.size()))]; }
  std::string input() { return inputs_[pick(static_cast<std::uint32_t>(inputs_.size()))]; }
  std::string atom() {
    switch (pick(6)) {
      case 0:
        return "prev(" + name() + ")";
      case 1:
        return "rise(" + name() + ")";
      case 2:
        return "fall(" + name() + ")";
      case 3:
        return input();
      default:
        return name();
    }
  }
  std::string formula(int depth) {
    if (depth == 0 || pick(4) == 0) return atom();
    static const char* unary[] = {"!", "EX ", "AX ", "EF ", "AF ", "EG ", "AG "};
    static const char* binary[] = {" & ", " | ", " -> "};
    switch (pick(3)) {
      case 0:
        return std::string(unary[pick(7)]) + "(" + formula(depth - 1) + ")";
      case 1:
        return "(" + formula(depth - 1) + binary[pick(3)] + formula(depth - 1) + ")";
      default:
        return std::string(pick(2) ? "E[" : "A[") + formula(depth - 1) + " U " +
               formula(depth - 1) + "]";
    }
  }

 private:
  std::uint32_t pick(std::uint32_t n) { return static_cast<std::uint32_t>(rng_() % n); }
  std::mt19937_64 rng_;
  std::vector<std::string> names_, inputs_;
};

struct Checked {
  logic::CheckReport explicit_report, bdd_report;
  std::uint64_t base_states = 0;
};

Checked check_both(const std::string& chart, const std::vector<std::string>& ctl) {
  auto loaded = io::load_iec_text(chart, "generated.st");
  EXPECT_TRUE(loaded.ok());
  model::Diagnostics diags;
  const auto base = semantics::make_iec61131_system(*loaded.project, {}, diags);
  EXPECT_TRUE(base);
  logic::CheckInputs in;
  in.ctl = ctl;
  auto parsed = logic::parse_check_inputs(in);
  for (const auto& d : parsed.diagnostics) ADD_FAILURE() << d.str();
  const auto history = logic::history_system_for(parsed.spec, *base, diags);
  for (const auto& d : diags) ADD_FAILURE() << d.str();
  EXPECT_TRUE(history);
  logic::CheckTask task;
  task.system = history.get();
  task.project = &*loaded.project;
  logic::resolve_into(parsed.spec, *history, task, diags);
  for (const auto& d : diags) ADD_FAILURE() << d.str();
  Checked out;
  out.explicit_report = make_explicit_model_checker()->check(task);
  const auto bdd = make_bdd_model_checker({});
  EXPECT_TRUE(bdd->can_handle(task));
  out.bdd_report = bdd->check(task);
  logic::CheckTask plain;
  plain.system = base.get();
  out.base_states = make_explicit_model_checker()->check(plain).states.to_u64().value();
  // Every trace replays on the history system from an initial state.
  for (const auto* report : {&out.explicit_report, &out.bdd_report})
    for (const auto& r : report->results) {
      if (!r.trace) continue;
      std::vector<std::vector<std::int64_t>> inputs;
      for (std::size_t k = 1; k < r.trace->steps.size(); ++k)
        inputs.push_back(r.trace->steps[k].inputs);
      const auto run = semantics::simulate(*history, r.trace->steps.front().state, inputs);
      EXPECT_TRUE(run.ok) << run.error;
      if (!run.ok) continue;
      for (std::size_t k = 0; k < r.trace->steps.size(); ++k)
        EXPECT_EQ(run.states[k], r.trace->steps[k].state)
            << report->engine << " " << r.formula << " cycle " << k;
    }
  return out;
}

TEST(HistoryAgreement, RandomChartsWithInputAndPreviousAtoms) {
  int verdicts = 0, holds = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto chart = bench::random_chart_iec(8 + static_cast<std::uint32_t>(seed % 5), 3, seed);
    auto loaded = io::load_iec_text(chart, "generated.st");
    ASSERT_TRUE(loaded.ok());
    model::Diagnostics diags;
    const auto base = semantics::make_iec61131_system(*loaded.project, {}, diags);
    ASSERT_TRUE(base);
    HistoryFormulas gen(*base, seed);
    std::vector<std::string> ctl;
    for (int i = 0; i < 12; ++i) ctl.push_back(gen.formula(3));
    // Identities that define prev, rise and fall: they hold in every chart.
    const auto a = gen.name(), i = gen.input();
    const std::size_t identities = ctl.size();
    ctl.push_back("AG ((" + a + " -> AX prev(" + a + ")) & (!" + a + " -> AX !prev(" + a + ")))");
    ctl.push_back("AG (EX rise(" + a + ") <-> (!" + a + " & EX " + a + "))");
    ctl.push_back("AG (EX fall(" + a + ") <-> (" + a + " & EX !" + a + "))");
    ctl.push_back("AG (rise(" + i + ") -> !prev(" + i + "))");
    ctl.push_back("AG (EX " + i + " & EX !" + i + ")");        // every cycle may read either value
    ctl.push_back("!" + i + " & !prev(" + a + ") <-> !" + a);  // initial: no input read, prev = now
    const auto c = check_both(chart, ctl);
    EXPECT_GE(c.explicit_report.states.to_u64().value(), c.base_states);
    EXPECT_EQ(c.explicit_report.states, c.bdd_report.states);
    EXPECT_EQ(c.explicit_report.edges, c.bdd_report.edges);
    ASSERT_EQ(c.explicit_report.results.size(), c.bdd_report.results.size());
    for (std::size_t k = 0; k < c.explicit_report.results.size(); ++k) {
      const auto& e = c.explicit_report.results[k];
      SCOPED_TRACE(e.formula);
      EXPECT_EQ(e.verdict, c.bdd_report.results[k].verdict);
      if (k >= identities) {
        EXPECT_EQ(e.verdict, logic::Verdict::Holds);
      }
      ++verdicts;
      holds += e.verdict == logic::Verdict::Holds;
    }
  }
  // Both verdicts occur often enough for the agreement to mean something.
  EXPECT_GT(holds, 40);
  EXPECT_GT(verdicts - holds, 30);
}

TEST(HistoryAgreement, OnlyTheNamedHistoryEntersTheState) {
  const auto chart = bench::random_chart_iec(8, 3, 7);
  auto loaded = io::load_iec_text(chart, "generated.st");
  ASSERT_TRUE(loaded.ok());
  model::Diagnostics diags;
  const auto base = semantics::make_iec61131_system(*loaded.project, {}, diags);
  ASSERT_TRUE(base);
  logic::CheckInputs in;
  in.ctl = {"AG TRUE"};
  auto parsed = logic::parse_check_inputs(in);
  EXPECT_FALSE(logic::history_system_for(parsed.spec, *base, diags));  // nothing to keep
  const auto input = base->inputs().front().name;
  in.ctl = {"EF " + input, "EF prev(prev(" + input + "))", "EF rise(" + input + ")"};
  parsed = logic::parse_check_inputs(in);
  const auto history = logic::history_system_for(parsed.spec, *base, diags);
  ASSERT_TRUE(history);
  const auto* h = semantics::as_history(*history);
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->request().inputs.size(), 1u);
  EXPECT_EQ(h->request().previous.size(), 2u);  // prev(i) and prev(prev(i)), shared by rise(i)
  EXPECT_EQ(history->layout().fields().size(), base->layout().fields().size() + 3);
}

}  // namespace
}  // namespace sfcv::engine
