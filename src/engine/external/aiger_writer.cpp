#include "engine/external/aiger_writer.hpp"

#include <cstdio>
#include <stdexcept>
#include <unordered_set>
#include <vector>

#include "engine/external/identifiers.hpp"
#include "model/errors.hpp"

namespace sfcv::engine {

using semantics::Aig;
using semantics::AigLit;

namespace {

void write_varint(std::ostream& out, std::uint32_t x) {
  while (x & ~0x7fU) {
    out.put(static_cast<char>((x & 0x7fU) | 0x80U));
    x >>= 7;
  }
  out.put(static_cast<char>(x));
}

}  // namespace

std::string aiger_symbol(const std::string& name) {
  std::string r;
  for (char c : comment_text(name)) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x80) {
      r += c;
      continue;
    }
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02x", u);
    r += hex;
  }
  return r;
}

AigerSymbols aiger_symbols(const Aig& aig) {
  AigerSymbols s;
  std::unordered_set<std::string> used;
  auto unique = [&used](const std::string& name) {
    const std::string symbol = aiger_symbol(name);
    std::string candidate = symbol;
    for (int k = 2; !used.insert(candidate).second; ++k)
      candidate = symbol + "#" + std::to_string(k);
    return candidate;
  };
  for (const auto& i : aig.inputs()) s.inputs.push_back(unique(i.name));
  for (const auto& l : aig.latches()) s.latches.push_back(unique(l.name));
  for (const auto& o : aig.outputs()) s.outputs.push_back(unique(o.name));
  for (const auto& b : aig.bad()) s.bad.push_back(unique(b.name));
  for (const auto& c : aig.constraints()) s.constraints.push_back(unique(c.name));
  return s;
}

void write_aiger(std::ostream& out, const Aig& aig, AigerMode mode, const std::string& comment,
                 bool positional_names) {
  const auto& nodes = aig.nodes();
  const std::uint32_t num_inputs = static_cast<std::uint32_t>(aig.inputs().size());
  const std::uint32_t num_latches = static_cast<std::uint32_t>(aig.latches().size());
  if (num_inputs == 0)
    throw UnsupportedConstruct("write_aiger: the circuit needs at least one input");

  // AIGER numbering: inputs 1..I, latches I+1..I+L, and gates after, in creation order (which is
  // topological, so every gate's fan-ins get smaller numbers, as the binary format requires).
  std::vector<std::uint32_t> var(nodes.size(), 0);
  for (std::uint32_t i = 0; i < num_inputs; ++i) var[Aig::node_of(aig.inputs()[i].literal)] = i + 1;
  for (std::uint32_t l = 0; l < num_latches; ++l)
    var[Aig::node_of(aig.latches()[l].current)] = num_inputs + l + 1;
  std::uint32_t next_var = num_inputs + num_latches + 1;
  std::vector<std::uint32_t> gates;
  for (std::uint32_t n = 1; n < nodes.size(); ++n)
    if (nodes[n].kind == Aig::NodeKind::And) {
      var[n] = next_var++;
      gates.push_back(n);
    }
  auto lit = [&var](AigLit l) { return 2 * var[Aig::node_of(l)] + (Aig::is_negated(l) ? 1U : 0U); };

  const std::uint32_t max_var = next_var - 1;
  out << (mode == AigerMode::Binary ? "aig " : "aag ") << max_var << ' ' << num_inputs << ' '
      << num_latches << ' ' << aig.outputs().size() << ' ' << gates.size();
  if (!aig.bad().empty() || !aig.constraints().empty())
    out << ' ' << aig.bad().size() << ' ' << aig.constraints().size();
  out << '\n';
  if (mode == AigerMode::Ascii)
    for (const auto& in : aig.inputs()) out << lit(in.literal) << '\n';
  for (const auto& l : aig.latches()) {
    if (mode == AigerMode::Ascii) out << lit(l.current) << ' ';
    out << lit(l.next);
    if (l.initial) out << " 1";
    out << '\n';
  }
  for (const auto& o : aig.outputs()) out << lit(o.literal) << '\n';
  for (const auto& b : aig.bad()) out << lit(b.literal) << '\n';
  for (const auto& c : aig.constraints()) out << lit(c.literal) << '\n';
  for (auto n : gates) {
    const std::uint32_t lhs = 2 * var[n];
    std::uint32_t r0 = lit(nodes[n].left), r1 = lit(nodes[n].right);
    if (r0 < r1) std::swap(r0, r1);
    if (mode == AigerMode::Ascii) {
      out << lhs << ' ' << r0 << ' ' << r1 << '\n';
    } else {
      write_varint(out, lhs - r0);
      write_varint(out, r0 - r1);
    }
  }
  const AigerSymbols symbols = positional_names ? AigerSymbols{} : aiger_symbols(aig);
  auto symbol = [positional_names](const std::vector<std::string>& names, const char* tag,
                                   std::size_t k) {
    return positional_names ? tag + std::to_string(k) : names[k];
  };
  for (std::uint32_t i = 0; i < num_inputs; ++i)
    out << 'i' << i << ' ' << symbol(symbols.inputs, "in", i) << '\n';
  for (std::uint32_t l = 0; l < num_latches; ++l)
    out << 'l' << l << ' ' << symbol(symbols.latches, "la", l) << '\n';
  for (std::size_t o = 0; o < aig.outputs().size(); ++o)
    out << 'o' << o << ' ' << symbol(symbols.outputs, "out", o) << '\n';
  for (std::size_t b = 0; b < aig.bad().size(); ++b)
    out << 'b' << b << ' ' << symbol(symbols.bad, "bad", b) << '\n';
  for (std::size_t c = 0; c < aig.constraints().size(); ++c)
    out << 'c' << c << ' ' << symbol(symbols.constraints, "con", c) << '\n';
  if (!comment.empty()) out << "c\n" << comment << (comment.back() == '\n' ? "" : "\n");
}

}  // namespace sfcv::engine
