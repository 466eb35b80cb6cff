#include "engine/external/spin_runner.hpp"

#include <fstream>
#include <sstream>

#include "engine/external/external_tool.hpp"

namespace sfcv::engine {

std::optional<std::string> find_spin() {
  return find_on_path({"spin"});
}

namespace {

// "@cycle x=1 y=0" lines printed by the replayed trail.
std::vector<std::vector<bool>> read_cycles(const std::string& text, const semantics::Aig& aig) {
  std::vector<std::vector<bool>> frames;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto at = line.find("@cycle");
    if (at == std::string::npos) continue;
    std::vector<bool> frame(aig.inputs().size(), false);
    std::istringstream words(line.substr(at + 6));
    std::string word;
    std::size_t i = 0;
    while (words >> word && i < frame.size()) {
      const auto eq = word.rfind('=');
      if (eq != std::string::npos) frame[i++] = word.substr(eq + 1) == "1";
    }
    frames.push_back(std::move(frame));
  }
  return frames;
}

}  // namespace

SpinVerdict check_with_spin(const std::string& spin, const CircuitExport& model,
                            std::size_t bad_index, double timeout_seconds, std::string cc) {
  SpinVerdict v;
  if (cc.empty()) {
    const auto found = find_on_path({"cc", "gcc", "clang"});
    if (!found) {
      v.log = "no C compiler found to build Spin's verifier";
      return v;
    }
    cc = *found;
  }
  TempDir dir;
  {
    std::ofstream f(dir.path() + "/model.pml");
    write_promela(f, model, bad_index);
  }
  auto step = [&](const std::vector<std::string>& argv) {
    const auto run = run_tool(argv, dir.path(), timeout_seconds);
    v.log += run.output;
    return run;
  };
  if (step({spin, "-a", "model.pml"}).exit_code != 0) return v;
  if (step({cc, "-O2", "-DSAFETY", "-DMEMLIM=8192", "-w", "-o", "pan", "pan.c"}).exit_code != 0)
    return v;
  const auto pan = step({dir.path() + "/pan", "-m10000000"});
  if (pan.timed_out) return v;
  const auto& out = pan.output;
  if (out.find("assertion violated") != std::string::npos) {
    v.kind = SpinVerdict::Kind::Violated;
    const auto trail = step({spin, "-t", "model.pml"});
    v.frames = read_cycles(trail.output, model.aig);
  } else if (out.find("errors: 0") != std::string::npos &&
             out.find("max search depth too small") == std::string::npos) {
    v.kind = SpinVerdict::Kind::Holds;
  }
  return v;
}

}  // namespace sfcv::engine
