// sfcv-gen: writes a chart of a scalable family (bench/gen/chart_families.hpp) to standard output
// or a file: IEC textual SFC, or a Grafcet .g7 for the transfer line.

#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>

#include "chart_families.hpp"

int main(int argc, char** argv) {
  CLI::App app{"sfcv-gen: scalable chart families for benchmarks", "sfcv-gen"};
  std::string family, output;
  std::uint32_t n = 4, inputs = 4, unused = 0, level = 10;
  std::uint64_t seed = 1;
  bool flawed = false, selector = false;
  app.add_option("family", family,
                 "parallel | tanks | levels | nested | random | transfer | counter")
      ->required()
      ->check(CLI::IsMember(
          {"parallel", "tanks", "levels", "nested", "random", "transfer", "counter"}));
  app.add_option("n", n, "Size: branches, reactors, nesting depth, steps (random), stations");
  app.add_flag("--selector", selector, "parallel: one integer input selects the toggling branch");
  app.add_flag("--flawed", flawed, "tanks: keep the seed's V2/V4 flaw");
  app.add_option("--inputs", inputs, "random: number of Boolean inputs");
  app.add_option("--seed", seed, "random: seed");
  sfcv::bench::RandomChartFeatures features;
  app.add_flag("--timed", features.timed_qualifiers,
               "random: also timed qualifiers L, D, SD, DS, SL");
  app.add_flag("--nested", features.nested_chart, "random: an action holding a nested chart");
  app.add_option("--level", level, "levels: the highest level of a tank (default 10)");
  app.add_option("--unused", unused, "transfer: extra inputs the grafcet never reads");
  app.add_option("-o,--output", output, "Output file (default: standard output)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  std::string text;
  if (family == "parallel")
    text = sfcv::bench::parallel_branches_iec(n, selector);
  else if (family == "tanks")
    text = sfcv::bench::tanks_iec(n, flawed);
  else if (family == "levels")
    text = sfcv::bench::level_tanks_iec(n, level);
  else if (family == "counter")
    text = sfcv::bench::counter_iec(n);
  else if (family == "nested")
    text = sfcv::bench::nested_charts_iec(n);
  else if (family == "transfer")
    text = sfcv::bench::transfer_line_g7(n, unused);
  else
    text = sfcv::bench::random_chart_iec(n, inputs, seed, features);
  if (output.empty()) {
    std::cout << text;
  } else {
    std::ofstream f(output);
    if (!f) {
      std::cerr << "sfcv-gen: cannot write " << output << "\n";
      return 2;
    }
    f << text;
  }
  return 0;
}
