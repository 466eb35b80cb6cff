#include "engine/external/abc_runner.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "engine/external/aiger_writer.hpp"
#include "engine/external/external_tool.hpp"

namespace sfcv::engine {

using semantics::Aig;

std::optional<std::string> find_abc() {
  return find_on_path({"berkeley-abc", "abc"});
}

namespace {

Aig with_single_property(const Aig& aig, std::size_t bad_index) {
  Aig single = aig;
  single.clear_bad();
  single.add_bad(aig.bad().at(bad_index).name, aig.bad().at(bad_index).literal);
  return single;
}

// "in3@3=1" lines of `write_cex -n`.
std::vector<std::vector<bool>> read_cex(const std::string& text, const Aig& aig) {
  std::vector<std::vector<bool>> frames;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto at = line.rfind('@'), eq = line.rfind('=');
    if (at == std::string::npos || eq == std::string::npos || eq < at) continue;
    const std::string name = line.substr(0, at);
    const auto frame = static_cast<std::size_t>(std::stoul(line.substr(at + 1, eq - at - 1)));
    const bool value = line.substr(eq + 1) == "1";
    // Inputs are named in<k> in the file ABC reads (write_aiger, positional_names).
    if (name.rfind("in", 0) != 0 || name.size() == 2 ||
        name.find_first_not_of("0123456789", 2) != std::string::npos)
      continue;  // a flop's initial value (la3@0=0)
    const auto input = static_cast<std::size_t>(std::stoul(name.substr(2)));
    if (input >= aig.inputs().size()) continue;
    if (frames.size() <= frame) frames.resize(frame + 1, std::vector<bool>(aig.inputs().size()));
    frames[frame][input] = value;
  }
  return frames;
}

}  // namespace

AbcVerdict check_with_abc(const std::string& abc, const Aig& aig, std::size_t bad_index,
                          const std::string& command, double timeout_seconds) {
  // Debian's ABC reads AIGER constraints as extra outputs (plain `pdr` then reports them as
  // violated) and `fold` applies them in the last frame too: constraints must be encoded as a
  // validity latch instead (engine/external/export_model.hpp does).
  if (!aig.constraints().empty())
    throw std::invalid_argument("check_with_abc: encode the circuit's constraints as a latch");
  TempDir dir;
  {
    std::ofstream f(dir.path() + "/model.aig", std::ios::binary);
    write_aiger(f, with_single_property(aig, bad_index), AigerMode::Binary, {}, true);
  }
  const auto run =
      run_tool({abc, "-c", "read_aiger model.aig; " + command + "; write_cex -n cex.txt"},
               dir.path(), timeout_seconds);
  AbcVerdict v;
  v.log = run.output;
  if (run.timed_out) return v;
  const auto& out = run.output;
  if (out.find("was asserted in frame") != std::string::npos) {
    v.kind = AbcVerdict::Kind::Violated;
    std::ifstream f(dir.path() + "/cex.txt");
    std::stringstream ss;
    ss << f.rdbuf();
    v.frames = read_cex(ss.str(), aig);
  } else if (out.find("Property proved") != std::string::npos ||
             out.find("Networks are equivalent") != std::string::npos ||
             out.find("all 2^") != std::string::npos) {
    // "Networks are equivalent" (dprove) and BMC's exhaustion of all reachable states both
    // mean that the bad state is unreachable.
    v.kind = AbcVerdict::Kind::Holds;
  }
  return v;
}

}  // namespace sfcv::engine
