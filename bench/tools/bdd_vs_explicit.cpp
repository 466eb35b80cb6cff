// bdd_vs_explicit: the BDD engine's CPU time against the explicit engine's on the random
// charts of `sfcv-gen random N --seed S` (issue 17: no chart of N <= 60 above 10x), in one
// process: each engine's check() of the invariant `AG (S1 | !S1)` (holds: the whole reachable
// set), no standard check, timed with std::clock (process start-up left out on both sides).
// With --checks all: the ten standard checks instead of the invariant (same verdicts asked).
//
//   bdd_vs_explicit [--sizes 20,40,60] [--seeds 1-6] [--reorder none|once|dynamic] [--repeat K]
//                   [--checks none|all]
//
// Prints one Markdown row per chart: N, seed, states, explicit s, bdd s, ratio. With --repeat K
// each engine runs K times and the least CPU time is kept (the machine is shared). The engines
// must agree on states, edges (when the BDD engine counts them) and verdicts.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <sstream>

#include "chart_families.hpp"
#include "engine/bdd/bdd_model_checker.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "logic/standard_checks.hpp"
#include "semantics/iec61131_system.hpp"

namespace {

std::vector<std::uint64_t> parse_list(const std::string& text) {
  std::vector<std::uint64_t> out;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto dash = item.find('-');
    if (dash == std::string::npos) {
      out.push_back(std::stoull(item));
    } else {
      for (auto k = std::stoull(item.substr(0, dash)); k <= std::stoull(item.substr(dash + 1)); ++k)
        out.push_back(k);
    }
  }
  return out;
}

template <class F>
double cpu_seconds(int repeat, F&& run) {
  double best = 1e300;
  for (int k = 0; k < repeat; ++k) {
    const std::clock_t t0 = std::clock();
    run();
    best = std::min(best, static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace sfcv;
  CLI::App app{"bdd_vs_explicit: BDD and explicit engine CPU time on random charts",
               "bdd_vs_explicit"};
  std::string sizes = "20,40,60", seeds = "1-6", reorder = "dynamic", checks = "none";
  int repeat = 1;
  app.add_option("--sizes", sizes, "Chart sizes N (steps), comma-separated");
  app.add_option("--seeds", seeds, "Seeds: 1-6 or 1,3,5");
  app.add_option("--reorder", reorder, "BDD reordering: none, once or dynamic");
  app.add_option("--repeat", repeat, "Runs per engine; the least CPU time is kept");
  app.add_option("--checks", checks, "none: the invariant only; all: the standard checks instead")
      ->check(CLI::IsMember({"none", "all"}));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  const auto mode = engine::parse_reorder_mode(reorder);
  if (!mode) {
    std::cerr << "bdd_vs_explicit: unknown --reorder " << reorder << "\n";
    return 2;
  }
  std::cout << "| N | seed | states | explicit | bdd (" << reorder << ") | ratio |\n"
            << "|---|---|---|---|---|---|\n";
  for (auto n : parse_list(sizes)) {
    for (auto seed : parse_list(seeds)) {
      auto loaded = io::load_iec_text(
          bench::random_chart_iec(static_cast<std::uint32_t>(n), 4, seed), "random.st");
      if (!loaded.project) return 2;
      model::Diagnostics diags;
      auto ts =
          semantics::make_iec61131_system(*loaded.project, semantics::Iec61131Options{}, diags);
      if (!ts) return 2;
      logic::CheckInputs in;
      if (checks == "none") in.ctl = {"AG (S1 | !S1)"};
      auto parsed = logic::parse_check_inputs(in);
      logic::CheckTask task;
      task.system = ts.get();
      task.project = &*loaded.project;
      logic::resolve_into(parsed.spec, *ts, task, diags);
      if (checks == "all") task.checks = *logic::parse_check_selection("all", nullptr);
      logic::CheckReport ex, bd;
      const double t_ex =
          cpu_seconds(repeat, [&] { ex = engine::make_explicit_model_checker()->check(task); });
      engine::BddEngineOptions o;
      o.reorder = *mode;
      const double t_bdd =
          cpu_seconds(repeat, [&] { bd = engine::make_bdd_model_checker(o)->check(task); });
      bool agree = ex.states.str() == bd.states.str() && !ex.results.empty() &&
                   ex.results.size() == bd.results.size() &&
                   (!bd.edges_known || ex.edges.str() == bd.edges.str());
      for (std::size_t k = 0; agree && k < ex.results.size(); ++k)
        agree = ex.results[k].verdict == bd.results[k].verdict;
      if (!agree) {
        std::cerr << "bdd_vs_explicit: the engines disagree on N = " << n << " seed " << seed
                  << "\n";
        return 1;
      }
      char row[200];
      std::snprintf(row, sizeof row, "| %llu | %llu | %s | %.3f | %.3f | %.0fx |\n",
                    static_cast<unsigned long long>(n), static_cast<unsigned long long>(seed),
                    ex.states.str().c_str(), t_ex, t_bdd, t_bdd / std::max(t_ex, 0.0005));
      std::cout << row << std::flush;
    }
  }
  return 0;
}
