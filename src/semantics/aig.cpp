#include "semantics/aig.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "model/errors.hpp"

namespace sfcv::semantics {

Aig::Aig() {
  nodes_.push_back(Node{});
}

AigLit Aig::add_input(std::string name) {
  const auto lit = static_cast<AigLit>(nodes_.size() * 2);
  nodes_.push_back({NodeKind::Input, 0, 0, static_cast<std::uint32_t>(inputs_.size())});
  inputs_.push_back({std::move(name), lit});
  return lit;
}

AigLit Aig::add_latch(std::string name, bool initial) {
  const auto lit = static_cast<AigLit>(nodes_.size() * 2);
  nodes_.push_back({NodeKind::Latch, 0, 0, static_cast<std::uint32_t>(latches_.size())});
  latches_.push_back({std::move(name), lit, lit, initial});
  return lit;
}

void Aig::set_next(std::uint32_t latch_index, AigLit next) {
  if (latch_index >= latches_.size()) throw std::out_of_range("Aig::set_next: no such latch");
  latches_[latch_index].next = next;
}

AigLit Aig::make_and(AigLit a, AigLit b) {
  if (deadline_ && (++calls_ & 0xFFFFU) == 0 && std::chrono::steady_clock::now() > *deadline_)
    throw LimitReached(Limit::Time, "time limit reached while building the circuit");
  if (a > b) std::swap(a, b);
  if (a == kFalse) return kFalse;
  if (a == kTrue) return b;
  if (a == b) return a;
  if (a == make_not(b)) return kFalse;
  const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | b;
  if (auto it = strash_.find(key); it != strash_.end()) return it->second;
  const auto lit = static_cast<AigLit>(nodes_.size() * 2);
  nodes_.push_back({NodeKind::And, a, b, 0});
  ++num_ands_;
  strash_.emplace(key, lit);
  if (memory_limit_ > 0 && (num_ands_ & 0xFFFU) == 0 && memory_bytes() > memory_limit_)
    throw LimitReached(Limit::Memory, "memory limit reached while building the circuit (" +
                                          std::to_string(num_ands_) + " And nodes, " +
                                          std::to_string(memory_bytes() >> 20) + " MB)");
  return lit;
}

std::uint64_t Aig::memory_bytes() const {
  // An unordered_map entry: its key and value, the next pointer and the cached hash, rounded
  // up to the allocator's 16 bytes; plus one pointer per bucket.
  constexpr std::uint64_t kStrashEntry = 32;
  std::uint64_t names = 0;
  for (const auto& l : latches_) names += sizeof(Latch) + l.name.capacity();
  for (const auto& i : inputs_) names += sizeof(Input) + i.name.capacity();
  return nodes_.capacity() * sizeof(Node) + strash_.size() * kStrashEntry +
         strash_.bucket_count() * sizeof(void*) + names;
}

AigLit Aig::make_xor(AigLit a, AigLit b) {
  return make_or(make_and(a, make_not(b)), make_and(make_not(a), b));
}

AigLit Aig::make_ite(AigLit c, AigLit t, AigLit e) {
  if (t == e) return t;
  return make_or(make_and(c, t), make_and(make_not(c), e));
}

AigLit Aig::make_and(const std::vector<AigLit>& lits) {
  AigLit r = kTrue;
  for (auto l : lits) r = make_and(r, l);
  return r;
}

AigLit Aig::make_or(const std::vector<AigLit>& lits) {
  AigLit r = kFalse;
  for (auto l : lits) r = make_or(r, l);
  return r;
}

AigLit Aig::cofactor(AigLit root, AigLit var, bool value) {
  // Rebuild the cone of `root` bottom-up in node order (which is topological).
  const std::uint32_t top = node_of(root);
  std::vector<AigLit> image(top + 1);
  for (std::uint32_t n = 0; n <= top; ++n) {
    const AigLit self = n * 2;
    if (self == (var & ~1U)) {
      image[n] = value ? kTrue : kFalse;
    } else if (nodes_[n].kind == NodeKind::And) {
      const Node node = nodes_[n];  // copy: make_and may grow nodes_
      const AigLit l = image[node_of(node.left)] ^ (node.left & 1U);
      const AigLit r = image[node_of(node.right)] ^ (node.right & 1U);
      image[n] = make_and(l, r);
    } else {
      image[n] = self;
    }
  }
  return image[top] ^ (root & 1U);
}

std::vector<bool> Aig::evaluate(const std::vector<bool>& input_values,
                                const std::vector<bool>& latch_values) const {
  std::vector<bool> v(nodes_.size(), false);
  for (std::size_t i = 1; i < nodes_.size(); ++i) {
    const auto& n = nodes_[i];
    switch (n.kind) {
      case NodeKind::Constant:
        break;
      case NodeKind::Input:
        v[i] = input_values.at(n.index);
        break;
      case NodeKind::Latch:
        v[i] = latch_values.at(n.index);
        break;
      case NodeKind::And:
        v[i] = value_of(v, n.left) && value_of(v, n.right);
        break;
    }
  }
  return v;
}

BitVector bv_constant(std::int64_t value, std::uint32_t width) {
  BitVector r(width);
  for (std::uint32_t i = 0; i < width; ++i)
    r[i] = (i < 64 && ((static_cast<std::uint64_t>(value) >> i) & 1U)) ? Aig::kTrue : Aig::kFalse;
  return r;
}

BitVector bv_add(Aig& aig, const BitVector& a, const BitVector& b) {
  BitVector r(a.size());
  AigLit carry = Aig::kFalse;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const AigLit x = aig.make_xor(a[i], b[i]);
    r[i] = aig.make_xor(x, carry);
    carry = aig.make_or(aig.make_and(a[i], b[i]), aig.make_and(x, carry));
  }
  return r;
}

BitVector bv_neg(Aig& aig, const BitVector& a) {
  BitVector inv(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) inv[i] = Aig::make_not(a[i]);
  return bv_add(aig, inv, bv_constant(1, static_cast<std::uint32_t>(a.size())));
}

BitVector bv_sub(Aig& aig, const BitVector& a, const BitVector& b) {
  return bv_add(aig, a, bv_neg(aig, b));
}

BitVector bv_mux(Aig& aig, AigLit c, const BitVector& t, const BitVector& e) {
  BitVector r(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) r[i] = aig.make_ite(c, t[i], e[i]);
  return r;
}

AigLit bv_equal(Aig& aig, const BitVector& a, const BitVector& b) {
  AigLit r = Aig::kTrue;
  for (std::size_t i = 0; i < a.size(); ++i) r = aig.make_and(r, aig.make_xnor(a[i], b[i]));
  return r;
}

AigLit bv_less_unsigned(Aig& aig, const BitVector& a, const BitVector& b) {
  // From the least significant bit up: a < b iff at the highest differing bit, b has the 1.
  AigLit less = Aig::kFalse;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const AigLit differ = aig.make_xor(a[i], b[i]);
    less = aig.make_ite(differ, b[i], less);
  }
  return less;
}

AigLit bv_less_signed(Aig& aig, const BitVector& a, const BitVector& b) {
  if (a.empty()) return Aig::kFalse;
  // Flipping the sign bits turns signed order into unsigned order.
  BitVector fa = a, fb = b;
  fa.back() = Aig::make_not(fa.back());
  fb.back() = Aig::make_not(fb.back());
  return bv_less_unsigned(aig, fa, fb);
}

BitVector bv_resize(const BitVector& a, std::uint32_t width, bool is_signed) {
  BitVector r(width);
  for (std::uint32_t i = 0; i < width; ++i)
    r[i] = i < a.size() ? a[i] : (is_signed && !a.empty() ? a.back() : Aig::kFalse);
  return r;
}

}  // namespace sfcv::semantics
