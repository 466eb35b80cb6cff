// export_for_bench: writes the Promela and AIGER exports of one invariant of an IEC 61131-3
// chart, for bench/run to time Spin and ABC on the same circuit sfcv's BDD engine uses. The
// invariant is "never all of these observables at once" (--never A,B), i.e. AG !(A & B).
// Written before `sfcv export --to promela|aiger` landed; it only calls library functions.

#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <sstream>

#include "engine/external/aiger_writer.hpp"
#include "engine/external/circuit_export.hpp"
#include "io/load.hpp"
#include "model/names.hpp"
#include "semantics/iec61131_circuit.hpp"
#include "semantics/iec61131_system.hpp"

namespace {

std::optional<std::uint32_t> find_observable(const sfcv::semantics::TransitionSystem& ts,
                                             const std::string& name) {
  const auto want = sfcv::model::to_upper(name);
  for (std::uint32_t i = 0; i < ts.observables().size(); ++i) {
    const auto& o = ts.observables()[i];
    if (sfcv::model::to_upper(o.name) == want) return i;
    for (const auto& a : o.aliases)
      if (sfcv::model::to_upper(a) == want) return i;
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace sfcv;
  CLI::App app{"export_for_bench: Promela and AIGER exports of one invariant", "export_for_bench"};
  std::string model_path, never, promela, aiger;
  app.add_option("model", model_path, "IEC 61131-3 chart")->required();
  app.add_option("--never", never, "Comma-separated Boolean observables never true together")
      ->required();
  app.add_option("--promela", promela, "Promela output file");
  app.add_option("--aiger", aiger, "Binary AIGER output file");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  auto loaded = io::load_file(model_path);
  for (const auto& d : loaded.diagnostics) std::cerr << d.str() << "\n";
  if (!loaded.project) return 2;
  model::Diagnostics diags;
  auto ts = semantics::make_iec61131_system(*loaded.project, semantics::Iec61131Options{}, diags);
  for (const auto& d : diags) std::cerr << d.str() << "\n";
  if (!ts) return 2;
  auto circuit = semantics::build_iec61131_circuit(*ts);
  auto& aig = circuit.aig;

  std::vector<semantics::AigLit> all;
  std::istringstream names(never);
  std::string name;
  while (std::getline(names, name, ',')) {
    const auto i = find_observable(*ts, name);
    if (!i || circuit.observable_bits[*i].size() != 1) {
      std::cerr << "export_for_bench: no Boolean observable '" << name << "'\n";
      return 2;
    }
    all.push_back(circuit.observable_bits[*i][0]);
  }
  aig.clear_bad();
  aig.add_bad("never_" + never, aig.make_and(all));
  // The same restriction the BDD engine applies: inputs in range and no range error.
  aig.add_constraint("allowed",
                     aig.make_and(circuit.allowed, semantics::Aig::make_not(circuit.range_error)));
  if (aig.inputs().empty()) aig.add_input("dummy");  // ABC needs at least one input

  if (!promela.empty()) {
    std::ofstream f(promela);
    engine::CircuitExport m;
    m.aig = aig;
    m.header.push_back("export_for_bench " + model_path + " --never " + never);
    engine::write_promela(f, m, 0);
  }
  if (!aiger.empty()) {
    std::ofstream f(aiger, std::ios::binary);
    engine::write_aiger(f, aig, engine::AigerMode::Binary, "export_for_bench " + model_path);
  }
  return 0;
}
