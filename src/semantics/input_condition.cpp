#include "semantics/input_condition.hpp"

#include <algorithm>

namespace sfcv::semantics {

bool InputCondition::is_true() const {
  for (const auto& c : cubes)
    if (c.literals.empty()) return true;
  return false;
}

std::vector<std::int64_t> InputCondition::witness(const std::vector<InputVariable>& inputs) const {
  std::vector<std::int64_t> v(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i)
    v[i] = inputs[i].type.kind == model::TypeKind::Bool ? 0 : inputs[i].type.lo;
  if (cubes.empty()) return v;
  for (const auto& lit : cubes.front().literals) v[lit.input] = lit.lo;
  return v;
}

bool InputCondition::holds(const std::vector<std::int64_t>& valuation) const {
  for (const auto& c : cubes) {
    bool ok = true;
    for (const auto& lit : c.literals) {
      const auto x = valuation[lit.input];
      if (x < lit.lo || x > lit.hi) {
        ok = false;
        break;
      }
    }
    if (ok) return true;
  }
  return false;
}

std::string InputCondition::to_string(const std::vector<InputVariable>& inputs) const {
  if (cubes.empty()) return "FALSE";
  std::string out;
  for (std::size_t c = 0; c < cubes.size(); ++c) {
    if (c) out += " | ";
    const auto& lits = cubes[c].literals;
    if (lits.empty()) {
      out += "TRUE";
      continue;
    }
    for (std::size_t i = 0; i < lits.size(); ++i) {
      if (i) out += " & ";
      const auto& in = inputs[lits[i].input];
      if (in.type.kind == model::TypeKind::Bool) {
        out += (lits[i].lo ? "" : "!") + in.name;
      } else if (lits[i].lo == lits[i].hi) {
        out += in.name + " = " + std::to_string(lits[i].lo);
      } else if (lits[i].lo == in.type.lo) {
        out += in.name + " <= " + std::to_string(lits[i].hi);
      } else if (lits[i].hi == in.type.hi) {
        out += in.name + " >= " + std::to_string(lits[i].lo);
      } else {
        out += std::to_string(lits[i].lo) + " <= " + in.name + " <= " + std::to_string(lits[i].hi);
      }
    }
  }
  return out;
}

namespace {
std::uint64_t hash_cube(const InputCube& c) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const auto& l : c.literals)
    for (const std::uint64_t v : {std::uint64_t{l.input}, static_cast<std::uint64_t>(l.lo),
                                  static_cast<std::uint64_t>(l.hi)})
      h = (h ^ v) * 1099511628211ULL;
  h ^= h >> 33;  // a final mix: the literals differ in few bits
  h *= 0xff51afd7ed558ccdULL;
  return h ^ (h >> 33);
}
}  // namespace

void ConditionBuilder::add(const InputCube& cube) {
  constexpr std::size_t kSearchUpTo = 16;
  auto& cubes = condition_.cubes;
  if (cubes.size() < kSearchUpTo) {
    if (std::find(cubes.begin(), cubes.end(), cube) == cubes.end()) cubes.push_back(cube);
    return;
  }
  if (hashes_.empty())
    for (const auto& c : cubes) hashes_.insert(hash_cube(c));
  // A new hash is a new cube; a known one is searched (a repeat, or a rare collision).
  if (hashes_.insert(hash_cube(cube)).second ||
      std::find(cubes.begin(), cubes.end(), cube) == cubes.end())
    cubes.push_back(cube);
}

std::uint64_t InputCondition::memory_bytes() const {
  std::uint64_t bytes = cubes.capacity() * sizeof(InputCube);
  for (const auto& c : cubes) bytes += c.literals.capacity() * sizeof(InputLiteral);
  return bytes;
}

}  // namespace sfcv::semantics
