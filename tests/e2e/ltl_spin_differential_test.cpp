// LTL verdicts of sfcv's explicit engine against Spin on the Promela export: random charts
// (bench::random_chart_iec) and random X-free LTL formulas over their steps and Boolean
// variables. Each chart is exported once with all its formulas as `ltl sfcv_ltl_<k>` claims,
// compiled once (spin -a; cc -DNOREDUCE: the claims read the process's label remotely, which
// partial-order reduction does not respect), and each claim is checked by `pan -a -N`
// (acceptance cycles; no weak fairness: the model is one process, there is nothing to be fair
// to). Spin's claim moves once per atomic cycle, so it reads exactly sfcv's states (one per
// cycle): checked per chart by an extra claim `[] at-cycle-start`. Every disagreement fails
// with the chart and the formula. Skipped, visibly, without spin or a C compiler.

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <random>

#include "chart_families.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/external/export_model.hpp"
#include "engine/external/external_tool.hpp"
#include "engine/external/spin_runner.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "logic/formula.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::engine {
namespace {

/// Random LTL without X over `atoms`: mostly the shapes requirements take (response,
/// recurrence, persistence, precedence), nested with Boolean operators and U R W.
class LtlGenerator {
 public:
  LtlGenerator(std::vector<std::string> atoms, std::uint64_t seed)
      : rng_(seed), atoms_(std::move(atoms)) {}
  std::string prop(int depth) {
    if (depth == 0 || pick(3) == 0) return (pick(4) == 0 ? "!" : "") + atom();
    static const char* binary[] = {" & ", " | ", " -> "};
    return "(" + prop(depth - 1) + binary[pick(3)] + prop(depth - 1) + ")";
  }
  std::string ltl(int depth) {
    if (depth == 0) return (pick(2) ? "F " : "G ") + prop(1);  // temporal at the top
    switch (pick(12)) {
      case 0:
        return "G (" + prop(1) + " -> F " + prop(1) + ")";
      case 1:
        return "G F " + prop(1);
      case 2:
        return "F G " + prop(1);
      case 3:
        return "G " + prop(2);
      case 4:
        return "(" + prop(1) + " W " + prop(1) + ")";
      case 5:
        return "!(" + ltl(depth - 1) + ")";
      case 6:
        return "G (" + prop(1) + " -> (" + ltl(depth - 1) + "))";
      case 7:
        return "(" + ltl(depth - 1) + " U " + ltl(depth - 1) + ")";
      case 8:
        return "(" + ltl(depth - 1) + " R " + ltl(depth - 1) + ")";
      case 9:
        return "(" + ltl(depth - 1) + (pick(2) ? " & " : " | ") + ltl(depth - 1) + ")";
      case 10:
        return "F (" + ltl(depth - 1) + ")";
      default:
        return "G (" + ltl(depth - 1) + ")";
    }
  }

 private:
  std::string atom() { return atoms_[pick(static_cast<std::uint32_t>(atoms_.size()))]; }
  std::uint32_t pick(std::uint32_t n) { return static_cast<std::uint32_t>(rng_() % n); }
  std::mt19937_64 rng_;
  std::vector<std::string> atoms_;
};

struct Chart {
  model::Project project;
  semantics::TransitionSystemPtr ts;
};

Chart load(const std::string& text) {
  Chart c;
  auto loaded = io::load_iec_text(text, "chart.st");
  EXPECT_TRUE(loaded.ok());
  c.project = std::move(*loaded.project);
  model::Diagnostics diags;
  c.ts = semantics::make_iec61131_system(c.project, {}, diags);
  EXPECT_TRUE(c.ts);
  return c;
}

TEST(LtlSpinDifferential, RandomChartsAndFormulasAgree) {
  const auto spin = find_spin();
  const auto cc = find_on_path({"cc", "gcc", "clang"});
  if (!spin || !cc) GTEST_SKIP() << "spin or a C compiler is not installed";
  const auto start = std::chrono::steady_clock::now();
  constexpr std::uint64_t kCharts = 16;
  constexpr int kFormulasPerChart = 20;
  std::size_t pairs = 0, holds = 0, violated = 0;
  for (std::uint64_t seed = 1; seed <= kCharts; ++seed) {
    const auto text = bench::random_chart_iec(6 + static_cast<std::uint32_t>(seed % 6),
                                              2 + static_cast<std::uint32_t>(seed % 2), seed);
    SCOPED_TRACE("chart (random_chart_iec seed " + std::to_string(seed) + "):\n" + text);
    const auto chart = load(text);
    ASSERT_TRUE(chart.ts);
    std::vector<std::string> atoms;
    for (const auto& o : chart.ts->observables())
      if (o.type.kind == model::TypeKind::Bool && o.kind != semantics::ObservableKind::Action)
        atoms.push_back(o.name);
    LtlGenerator gen(atoms, seed * 7919);
    logic::CheckInputs in;
    for (int k = 0; k < kFormulasPerChart; ++k) in.ltl.push_back(gen.ltl(k % 3));
    auto parsed = logic::parse_check_inputs(in);
    for (const auto& d : parsed.diagnostics) ADD_FAILURE() << d.str();
    logic::CheckTask task;
    task.system = chart.ts.get();
    task.project = &chart.project;
    model::Diagnostics diags;
    logic::resolve_into(parsed.spec, *chart.ts, task, diags);
    for (const auto& d : diags) ADD_FAILURE() << d.str();
    ASSERT_EQ(task.properties.size(), in.ltl.size());
    const auto report = make_explicit_model_checker()->check(task);

    ExportRequest request;
    request.target = ExportTarget::Circuit;
    request.properties = task.properties;
    const auto exported = build_export(*chart.ts, request);
    ASSERT_EQ(exported.model.ltl.size(), in.ltl.size());
    // The claims read sfcv's states only if Spin's claim moves once per cycle: checked by a
    // last claim, "always at the start of a cycle".
    auto model = exported.model;
    model.ltl.emplace_back("claims read cycle starts only", "[] {b}");
    TempDir dir;
    {
      std::ofstream f(dir.path() + "/model.pml");
      write_promela(f, model);
    }
    auto run = [&](const std::vector<std::string>& argv) {
      return run_tool(argv, dir.path(), 120);
    };
    const auto a = run({*spin, "-a", "model.pml"});
    ASSERT_EQ(a.exit_code, 0) << a.output;
    const auto c = run({*cc, "-O0", "-DNOREDUCE", "-DMEMLIM=2048", "-w", "-o", "pan", "pan.c"});
    ASSERT_EQ(c.exit_code, 0) << c.output;
    const auto cycle_starts =
        run({dir.path() + "/pan", "-a", "-N", "sfcv_ltl_" + std::to_string(in.ltl.size())});
    ASSERT_NE(cycle_starts.output.find("errors: 0"), std::string::npos) << cycle_starts.output;
    for (std::size_t k = 0; k < in.ltl.size(); ++k) {
      const auto pan = run(
          {dir.path() + "/pan", "-a", "-m100000", "-w18", "-N", "sfcv_ltl_" + std::to_string(k)});
      const auto& out = pan.output;
      ASSERT_FALSE(pan.timed_out);
      ASSERT_EQ(out.find("max search depth too small"), std::string::npos) << out;
      const bool spin_violated = out.find("errors: 0") == std::string::npos;
      // The claim chosen is the one asked for; a violation is an acceptance cycle, or a
      // violated assertion inside the claim (Spin's never claim for a safety formula).
      ASSERT_NE(out.find("ltl formula sfcv_ltl_" + std::to_string(k) + "\n"), std::string::npos)
          << out;
      if (spin_violated) {
        ASSERT_TRUE(out.find("acceptance cycle") != std::string::npos ||
                    out.find("assertion violated") != std::string::npos)
            << out;
      }
      const auto& r = report.results.at(k);
      ASSERT_TRUE(r.verdict == logic::Verdict::Holds || r.verdict == logic::Verdict::Violated)
          << r.formula << ": " << r.message;
      const bool sfcv_violated = r.verdict == logic::Verdict::Violated;
      EXPECT_EQ(sfcv_violated, spin_violated)
          << "disagreement on '" << in.ltl[k] << "': sfcv " << logic::to_string(r.verdict)
          << ", spin " << (spin_violated ? "violated" : "holds")
          << "\nclaim: " << exported.model.ltl[k].second;
      ++pairs;
      (sfcv_violated ? violated : holds) += 1;
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "[ NOTE ] " << pairs << " (chart, formula) pairs: " << holds << " hold, " << violated
            << " violated; " << seconds << " s\n";
  EXPECT_GE(pairs, 300u);
  EXPECT_GE(holds, 60u);
  EXPECT_GE(violated, 60u);
}

}  // namespace
}  // namespace sfcv::engine
