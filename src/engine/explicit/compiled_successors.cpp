#include "engine/explicit/compiled_successors.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "semantics/iec61131_circuit.hpp"
#include "semantics/iec61131_system.hpp"

namespace sfcv::engine {

using semantics::Aig;
using semantics::AigLit;
using semantics::StateView;
using semantics::StateWord;

namespace {

using Word = std::uint64_t;

/// Input bits enumerated per state at most (2^12 valuations, 64 passes); beyond that the lazy
/// decisions of the interpreter are cheaper.
constexpr std::uint32_t kMaxRelevantBits = 12;

/// Lane patterns: bit l of kLane[i] is bit i of l, so 64 lanes hold all valuations of 6 bits.
constexpr Word kLane[6] = {0xAAAAAAAAAAAAAAAAULL, 0xCCCCCCCCCCCCCCCCULL, 0xF0F0F0F0F0F0F0F0ULL,
                           0xFF00FF00FF00FF00ULL, 0xFFFF0000FFFF0000ULL, 0xFFFFFFFF00000000ULL};

/// Words evaluated at once by targets_of(): a vector the compiler maps to the machine's SIMD
/// registers (two SSE2 operations per AND on plain x86-64).
constexpr std::uint32_t kBlockWords = 4;
using Block = Word __attribute__((vector_size(8 * kBlockWords)));

/// A gate: value = (val[a] ^ neg a) & (val[b] ^ neg b), on compact literals (2 * id + negation).
struct Gate {
  std::uint32_t a, b;
};

/// A latch whose next-state function reads inputs: copied lane by lane into the targets.
struct DynamicBit {
  std::uint32_t lit;
  std::uint32_t word;
  Word bit;
};

class CompiledEnumerator final : public TargetEnumerator {
 public:
  /// `initial`: every initial state, packed (empty: too many to list, no latch is merged).
  CompiledEnumerator(const semantics::TransitionSystem& ts, const semantics::TransitionCircuit& c,
                     const model::Budget& limits, const std::vector<StateWord>& initial)
      : ts_(ts),
        limits_(limits),
        fallback_(make_interpreted_enumerator(ts, limits_)),
        full_words_(std::max<std::uint32_t>(ts.layout().words(), 1)),
        words_(full_words_) {
    compile(ts, c, initial);
  }

  const StateCodec* codec() const override { return codec_.get(); }

  // A copy has its own scratch words and its own interpreted fallback (the system serialises
  // the calls into its scratch machine).
  std::unique_ptr<TargetEnumerator> clone() const override {
    auto copy = std::make_unique<CompiledEnumerator>(*this);
    copy->fallback_ = make_interpreted_enumerator(ts_, limits_);
    return copy;
  }

  void targets(StateView state, std::vector<StateWord>& out) override {
    // Latches, then the gates that read no input: once per state.
    for (std::size_t i = 0; i < latch_pos_.size(); ++i) {
      const auto& p = latch_pos_[i];
      set(first_latch_ + i, Word{0} - ((state[p.word] & p.bit) != 0));
    }
    run(0, static_state_gates_);
    std::fill(base_.begin(), base_.end(), 0);
    for (const auto& s : static_bits_)
      if (value(s.lit) & 1U) base_[s.word] |= s.bit;
    if (!(value(allowed_) & ~value(range_error_) & 1U) && allowed_static_) return;  // no lane

    const auto inputs = static_cast<std::uint32_t>(input_ids_.size());
    if (inputs <= 6) {
      for (std::uint32_t k = 0; k < inputs; ++k) set(input_ids_[k], kLane[k]);
      run(static_state_gates_, gates_.size());
      emit(lanes(inputs), out);
      return;
    }
    // Which input bits this state's cycle reads: an AND with a FALSE fan-in needs neither side.
    std::fill(mask_.begin() + first_input_, mask_.begin() + first_input_ + inputs, 0);
    for (std::uint32_t k = 0; k < inputs; ++k) mask_[input_ids_[k]] = Word{1} << k;
    for (std::size_t g = static_state_gates_; g < gates_.size(); ++g) {
      const auto& gt = gates_[g];
      const auto out_id = first_gate_ + g;
      const Word ma = mask_[gt.a >> 1], mb = mask_[gt.b >> 1];
      if ((ma == 0 && value(gt.a) == 0) || (mb == 0 && value(gt.b) == 0)) {
        mask_[out_id] = 0;
        set(out_id, 0);
      } else {
        mask_[out_id] = ma | mb;
        if ((ma | mb) == 0) set(out_id, ~Word{0});
      }
    }
    Word relevant = mask_[allowed_ >> 1] | mask_[range_error_ >> 1];
    for (const auto& d : dynamic_bits_) relevant |= mask_[d.lit >> 1];
    const auto r = static_cast<std::uint32_t>(std::popcount(relevant));
    if (r > kMaxRelevantBits) {
      interpret(state, out);
      return;
    }
    std::uint32_t order[64];
    std::uint32_t n = 0;
    for (Word m = relevant; m; m &= m - 1)
      order[n++] = static_cast<std::uint32_t>(std::countr_zero(m));
    for (std::uint32_t k = 0; k < inputs; ++k) set(input_ids_[k], 0);  // not read: any value
    const std::uint32_t low = std::min<std::uint32_t>(r, 6);
    for (std::uint32_t k = 0; k < low; ++k) set(input_ids_[order[k]], kLane[k]);
    const std::uint32_t passes = r > 6 ? 1U << (r - 6) : 1U;
    for (std::uint32_t pass = 0; pass < passes; ++pass) {
      for (std::uint32_t k = 6; k < r; ++k)
        set(input_ids_[order[k]], Word{0} - ((pass >> (k - 6)) & 1U));
      run(static_state_gates_, gates_.size());
      emit(lanes(low), out);
    }
  }

  // Up to 6 input bits, a state needs 2^inputs lanes: 64 / 2^inputs states share a word, and
  // kBlockWords words are evaluated at once (a vector of words: one gate's operands are read
  // once for all of them), state g in lanes [g * 2^inputs, (g + 1) * 2^inputs) of the block,
  // valuation j in its lane j as in targets(). Each target starts as a copy of its state and
  // only the latches whose next value differs from the current one are flipped: a cycle
  // changes few of them.
  void targets_of(StateView states, std::uint32_t count, std::vector<StateWord>& out,
                  std::vector<std::uint32_t>& ends) override {
    const auto inputs = static_cast<std::uint32_t>(input_ids_.size());
    if (inputs > 6) {
      TargetEnumerator::targets_of(states, count, out, ends);
      return;
    }
    const std::uint32_t group = 1U << inputs;  // lanes per state
    const std::uint32_t per = 64 / group;      // states per word
    const Word fill = lanes(inputs);           // the lanes of a word's state 0
    Block* block = block_.data();
    for (std::uint32_t k = 0; k < inputs; ++k) {
      const Block pattern = Block{} | kLane[k];  // period group, in every word
      block[2 * input_ids_[k]] = pattern;
      block[2 * input_ids_[k] + 1] = ~pattern;
    }
    const std::size_t num_latches = latch_pos_.size();
    Block* latches = block + 2 * first_latch_;
    for (std::uint32_t first = 0; first < count; first += per * kBlockWords) {
      const std::uint32_t n = std::min(per * kBlockWords, count - first);
      const StateWord* s = states.data() + static_cast<std::size_t>(first) * words_;
      // The latches: about half of them are set in a state, so only the set bits are visited.
      for (std::size_t i = 0; i < num_latches; ++i) latches[2 * i] = Block{};
      for (std::uint32_t g = 0; g < n; ++g) {
        const Word lanes_of_g = fill << ((g % per) * group);
        const std::uint32_t word = g / per;
        for (std::uint32_t w = 0; w < words_; ++w)
          for (Word m = s[static_cast<std::size_t>(g) * words_ + w] & held_[w]; m; m &= m - 1)
            block[latch_at_[w * 64 + static_cast<std::uint32_t>(std::countr_zero(m))]][word] |=
                lanes_of_g;
      }
      for (std::size_t i = 0; i < num_latches; ++i) latches[2 * i + 1] = ~latches[2 * i];
      run_block();
      Word valid[kBlockWords];
      const Block ok = block[allowed_] & ~block[range_error_];
      for (std::uint32_t word = 0; word < kBlockWords; ++word) {
        const std::uint32_t states_here =
            n > word * per ? std::min(per, n - word * per) : 0;  // states in this word
        const std::uint32_t used = states_here * group;
        valid[word] = ok[word] & (used >= 64 ? ~Word{0} : (Word{1} << used) - 1);
      }
      std::uint32_t total = 0;
      for (const Word v : valid) total += static_cast<std::uint32_t>(std::popcount(v));
      const std::size_t base = out.size();
      out.resize(base + static_cast<std::size_t>(total) * words_);
      StateWord* t = out.data() + base;
      std::uint32_t k = 0;  // targets so far
      for (std::uint32_t g = 0; g < n; ++g) {
        const StateWord* state = s + static_cast<std::size_t>(g) * words_;
        const std::uint32_t word = g / per, shift = (g % per) * group;
        for (Word m = (valid[word] >> shift) & fill; m; m &= m - 1) {
          rank_[word * 64 + shift + static_cast<std::uint32_t>(std::countr_zero(m))] = k;
          if (words_ == 1) {
            t[k] = state[0] & held_[0];
          } else {
            for (std::uint32_t w = 0; w < words_; ++w)
              t[static_cast<std::size_t>(k) * words_ + w] = state[w] & held_[w];
          }
          ++k;
        }
        ends.push_back(static_cast<std::uint32_t>(base + static_cast<std::size_t>(k) * words_));
      }
      for (const auto& u : updates_) {
        const Block differ = block[u.next] ^ block[u.current];
        for (std::uint32_t word = 0; word < kBlockWords; ++word) {
          Word m = differ[word] & valid[word];
          if (!m) continue;
          const Word bit = u.bit;
          StateWord* column = t + u.word;
          const std::uint32_t* rank = rank_ + word * 64;
          if (words_ == 1) {
            for (; m; m &= m - 1) column[rank[std::countr_zero(m)]] ^= bit;
          } else {
            for (; m; m &= m - 1)
              column[static_cast<std::size_t>(rank[std::countr_zero(m)]) * words_] ^= bit;
          }
        }
      }
    }
  }

 private:
  /// A latch as targets_of() updates it: the compact literals of its next and current value
  /// and its place in the packed state.
  struct LatchUpdate {
    std::uint32_t next, current, word;
    Word bit;
  };
  struct Position {
    std::uint32_t word;
    Word bit;
  };
  struct Exception {
    Word lanes;  ///< the valid lanes where the bit differs from the common part
    std::uint32_t word;
    Word bit;
  };

  /// The interpreter's targets of `state`, in the stored form.
  void interpret(StateView state, std::vector<StateWord>& out) {
    fallback_->set_memory_in_use(memory_in_use_);
    if (!codec_) {
      fallback_->targets(state, out);
      return;
    }
    full_.resize(full_words_);
    codec_->to_full(state.data(), full_.data());
    full_targets_.clear();
    fallback_->targets(full_, full_targets_);
    const std::size_t first = out.size();
    out.resize(first + full_targets_.size() / full_words_ * words_);
    for (std::size_t t = 0; t * full_words_ < full_targets_.size(); ++t)
      if (!codec_->to_stored(full_targets_.data() + t * full_words_,
                             out.data() + first + t * words_))
        throw std::logic_error(
            "compiled successors: an interpreted target breaks a latch equivalence of the "
            "circuit (the circuit and the interpreter disagree)");
  }

  static Word lanes(std::uint32_t bits) {
    return bits >= 6 ? ~Word{0} : (Word{1} << (1U << bits)) - 1;
  }
  // val_ holds both polarities of every node, indexed by literal: a gate is one AND.
  Word value(std::uint32_t lit) const { return val_[lit]; }
  void set(std::uint32_t id, Word w) {
    val_[2 * id] = w;
    val_[2 * id + 1] = ~w;
  }
  /// Every gate, on blocks: block_ holds both polarities of every node, as val_ does.
  void run_block() {
    Block* v = block_.data() + 2 * first_gate_;
    const Block* in = block_.data();
    const Gate* g = gates_.data();
    for (std::size_t i = 0, end = gates_.size(); i < end; ++i) {
      const Block x = in[g[i].a] & in[g[i].b];
      v[2 * i] = x;
      v[2 * i + 1] = ~x;
    }
  }
  void run(std::size_t from, std::size_t to) {
    Word* v = val_.data() + 2 * first_gate_;
    const Word* in = val_.data();
    const Gate* g = gates_.data();
    for (std::size_t i = from; i < to; ++i) {
      const Word x = in[g[i].a] & in[g[i].b];
      v[2 * i] = x;
      v[2 * i + 1] = ~x;
    }
  }
  /// Appends the targets of the valid lanes. Most input-reading latches take one value in
  /// almost every lane (a selector changes one branch per valuation): each bit goes into the
  /// common part with its majority value, and only the lanes where it differs are patched.
  void emit(Word lane_mask, std::vector<StateWord>& out) {
    const Word valid = value(allowed_) & ~value(range_error_) & lane_mask;
    if (!valid) return;
    // Where each valid lane's target goes: its rank among the valid lanes.
    std::uint32_t lanes = 0;
    if ((valid & (valid + 1)) == 0) {
      lanes = static_cast<std::uint32_t>(std::countr_one(valid));
      for (std::uint32_t l = 0; l < lanes; ++l) rank_[l] = l;
    } else {
      for (Word m = valid; m; m &= m - 1) rank_[std::countr_zero(m)] = lanes++;
    }
    const auto first_lane = static_cast<unsigned>(std::countr_zero(valid));
    std::copy(base_.begin(), base_.end(), common_.begin());
    exceptions_.clear();
    for (const auto& d : dynamic_bits_) {
      const Word v = value(d.lit);
      Word differ = v & valid;
      if ((v >> first_lane) & 1U) {
        common_[d.word] |= d.bit;
        differ = valid & ~v;
      }
      if (differ) exceptions_.push_back({differ, d.word, d.bit});
    }
    const std::size_t first = out.size();
    out.resize(first + static_cast<std::size_t>(lanes) * words_);
    StateWord* t = out.data() + first;
    if (words_ == 1) {
      std::fill(t, t + lanes, common_[0]);
    } else {
      for (std::uint32_t l = 0; l < lanes; ++l)
        std::copy(common_.begin(), common_.end(), t + l * words_);
    }
    for (const auto& e : exceptions_)
      for (Word m = e.lanes; m; m &= m - 1)
        t[static_cast<std::size_t>(rank_[std::countr_zero(m)]) * words_ + e.word] ^= e.bit;
  }

  /// Which latches another one determines. Two latches whose next-state literals share a node
  /// are equal (or opposite) after every cycle; if they are also equal (opposite) in every
  /// initial state, they are in every reachable state, and only the first is stored. A latch
  /// whose next state is a constant it already holds initially is not stored at all.
  struct LatchMerge {
    std::vector<std::uint32_t> rep;   ///< per latch: the stored latch it follows; kNone: constant
    std::vector<std::uint8_t> flip;   ///< per latch: opposite to its stored latch (or the value)
    std::vector<std::uint32_t> kept;  ///< the stored latches, in latch order

    /// Every latch stored, none following another.
    static LatchMerge none(std::size_t count) {
      LatchMerge m{std::vector<std::uint32_t>(count), std::vector<std::uint8_t>(count, 0), {}};
      for (std::uint32_t i = 0; i < count; ++i) m.rep[i] = i;
      m.kept = m.rep;
      return m;
    }
  };
  static constexpr std::uint32_t kNone = ~0U;

  static LatchMerge merge_latches(const semantics::TransitionCircuit& c,
                                  const std::vector<std::uint32_t>& latch_bit,
                                  const std::vector<StateWord>& initial, std::uint32_t words) {
    const auto& latches = c.aig.latches();
    const std::size_t count = latches.size();
    LatchMerge m{std::vector<std::uint32_t>(count), std::vector<std::uint8_t>(count, 0), {}};
    const std::size_t states = initial.size() / words;
    auto bit = [&](std::size_t state, std::uint32_t latch) {
      const auto b = latch_bit[latch];
      return ((initial[state * words + b / 64] >> (b % 64)) & 1U) != 0;
    };
    // The stored latches so far, by the node of their next-state literal (a map: the circuit
    // may have millions of nodes and a few latches).
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> by_node;
    for (std::uint32_t i = 0; i < count; ++i) {
      const AigLit next = latches[i].next;
      const auto node = Aig::node_of(next);
      m.rep[i] = i;
      if (states > 0 && node == 0) {
        const bool value = (next & 1U) != 0;
        bool constant = true;
        for (std::size_t s = 0; s < states && constant; ++s) constant = bit(s, i) == value;
        if (constant) {
          m.rep[i] = kNone;
          m.flip[i] = value;
          continue;
        }
      }
      if (states > 0 && node != 0) {
        for (const auto r : by_node[node]) {
          const bool flip = ((next ^ latches[r].next) & 1U) != 0;
          bool follows = true;
          for (std::size_t s = 0; s < states && follows; ++s)
            follows = bit(s, i) == (bit(s, r) != flip);
          if (follows) {
            m.rep[i] = r;
            m.flip[i] = flip;
            break;
          }
        }
      }
      if (m.rep[i] == i) {
        m.kept.push_back(i);
        by_node[node].push_back(i);
      }
    }
    return m;
  }

  void compile(const semantics::TransitionSystem& ts, const semantics::TransitionCircuit& c,
               const std::vector<StateWord>& initial) {
    const auto& nodes = c.aig.nodes();
    const auto& fields = ts.layout().fields();
    const auto& latches = c.aig.latches();
    std::vector<AigLit> roots{c.allowed, c.range_error};
    for (const auto& l : latches) roots.push_back(l.next);
    // Cone of influence; node order is topological, so one backward sweep marks it.
    std::vector<std::uint8_t> needed(nodes.size(), 0), reads_input(nodes.size(), 0);
    for (auto r : roots) needed[Aig::node_of(r)] = 1;
    for (std::size_t n = nodes.size(); n-- > 1;)
      if (needed[n] && nodes[n].kind == Aig::NodeKind::And) {
        needed[Aig::node_of(nodes[n].left)] = 1;
        needed[Aig::node_of(nodes[n].right)] = 1;
      }
    for (std::size_t n = 1; n < nodes.size(); ++n) {
      if (nodes[n].kind == Aig::NodeKind::Input) reads_input[n] = 1;
      if (nodes[n].kind == Aig::NodeKind::And)
        reads_input[n] =
            reads_input[Aig::node_of(nodes[n].left)] | reads_input[Aig::node_of(nodes[n].right)];
    }
    // Where each latch lives in the full packed state.
    std::vector<std::uint32_t> latch_bit(latches.size(), 0);
    for (std::uint32_t f = 0; f < c.field_latches.size(); ++f)
      for (std::uint32_t k = 0; k < c.field_latches[f].size(); ++k)
        latch_bit[c.field_latches[f][k]] = fields[f].offset + k;
    auto merge = merge_latches(c, latch_bit, initial, full_words_);
    if (merge.kept.size() < latches.size()) {
      std::vector<StateCodec::Follower> followers;
      std::vector<StateWord> constant(full_words_, 0);
      std::vector<std::uint32_t> stored_bit(latches.size(), 0);
      for (std::uint32_t k = 0; k < merge.kept.size(); ++k) stored_bit[merge.kept[k]] = k;
      for (std::uint32_t i = 0; i < latches.size(); ++i) {
        if (merge.rep[i] == kNone) {
          if (merge.flip[i]) constant[latch_bit[i] / 64] |= Word{1} << (latch_bit[i] % 64);
          continue;
        }
        followers.push_back({stored_bit[merge.rep[i]], latch_bit[i], merge.flip[i] != 0});
      }
      auto codec = std::make_shared<const StateCodec>(full_words_,
                                                      static_cast<std::uint32_t>(merge.kept.size()),
                                                      std::move(followers), std::move(constant));
      const auto stored_words = codec->stored_words();
      // Every initial state must survive the round trip (a full-state bit no latch holds, set
      // in an initial state, would not): else every latch is stored.
      std::vector<StateWord> stored(stored_words);
      bool exact = true;
      for (std::size_t s = 0; exact && (s + 1) * full_words_ <= initial.size(); ++s) {
        const StateWord* full = initial.data() + s * full_words_;
        exact = codec->to_stored(full, stored.data());
      }
      if (exact) {
        codec_ = std::move(codec);
        words_ = stored_words;
      }
    }
    if (!codec_) merge = LatchMerge::none(latches.size());
    // Compact ids: 0 the constant, then every stored latch, every input, the static gates, the
    // input-reading gates. A latch that follows another reads its id (negated when opposite);
    // a constant one reads the constant.
    std::vector<std::uint32_t> id(nodes.size(), 0);
    std::vector<std::uint8_t> flip(nodes.size(), 0);
    std::uint32_t next = 1;
    first_latch_ = next;
    for (const auto i : merge.kept) id[Aig::node_of(latches[i].current)] = next++;
    for (std::uint32_t i = 0; i < latches.size(); ++i) {
      const auto node = Aig::node_of(latches[i].current);
      flip[node] = merge.flip[i];
      if (merge.rep[i] != i)
        id[node] = merge.rep[i] == kNone ? 0 : id[Aig::node_of(latches[merge.rep[i]].current)];
    }
    first_input_ = next;
    for (const auto& in : c.aig.inputs()) {
      id[Aig::node_of(in.literal)] = next;
      input_ids_.push_back(next++);
    }
    first_gate_ = next;
    auto compact = [&](AigLit l) {
      const auto n = Aig::node_of(l);
      return (id[n] * 2 + (l & 1U)) ^ flip[n];
    };
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t n = 1; n < nodes.size(); ++n)
        if (needed[n] && nodes[n].kind == Aig::NodeKind::And && reads_input[n] == pass) {
          id[n] = next++;
          gates_.push_back({compact(nodes[n].left), compact(nodes[n].right)});
          if (pass == 0) static_state_gates_ = gates_.size();
        }
    val_.assign(2 * static_cast<std::size_t>(next), 0);
    val_[1] = ~Word{0};  // TRUE
    block_.assign(2 * static_cast<std::size_t>(next), Block{});
    block_[1] = ~Block{};
    base_.assign(words_, 0);
    common_.assign(words_, 0);
    mask_.assign(next, 0);
    // Where each stored latch lives in the stored state.
    latch_pos_.resize(merge.kept.size());
    for (std::uint32_t k = 0; k < merge.kept.size(); ++k) {
      const auto bit = codec_ ? k : latch_bit[merge.kept[k]];
      latch_pos_[k] = {bit / 64, Word{1} << (bit % 64)};
    }
    held_.assign(words_, 0);
    latch_at_.assign(static_cast<std::size_t>(words_) * 64, 0);
    for (std::uint32_t k = 0; k < merge.kept.size(); ++k) {
      const auto& next_lit = latches[merge.kept[k]].next;
      const DynamicBit d{compact(next_lit), latch_pos_[k].word, latch_pos_[k].bit};
      (reads_input[Aig::node_of(next_lit)] ? dynamic_bits_ : static_bits_).push_back(d);
      updates_.push_back({d.lit, 2 * (first_latch_ + k), d.word, d.bit});
      held_[d.word] |= d.bit;
      latch_at_[d.word * 64 + static_cast<std::uint32_t>(std::countr_zero(d.bit))] =
          2 * (first_latch_ + k);
    }
    exceptions_.reserve(dynamic_bits_.size());
    allowed_ = compact(c.allowed);
    range_error_ = compact(c.range_error);
    allowed_static_ =
        !reads_input[Aig::node_of(c.allowed)] && !reads_input[Aig::node_of(c.range_error)];
  }

  const semantics::TransitionSystem& ts_;
  model::Budget limits_;  ///< the run's, copied: the fallback's valuation bound and deadline
  std::shared_ptr<TargetEnumerator> fallback_;  ///< replaced in every clone
  std::uint32_t full_words_;                    ///< of the system's layout
  std::uint32_t words_;                         ///< of the stored form (codec_), or full_words_
  std::shared_ptr<const StateCodec> codec_;  ///< null: states are stored as the layout packs them
  std::vector<StateWord> full_, full_targets_;  ///< scratch of interpret()
  std::uint32_t first_latch_ = 0, first_input_ = 0, first_gate_ = 0;
  std::vector<Position> latch_pos_;
  std::vector<std::uint32_t> input_ids_;
  std::vector<Gate> gates_;
  std::size_t static_state_gates_ = 0;  ///< gates_[0, this) read no input
  std::vector<DynamicBit> static_bits_, dynamic_bits_;
  std::vector<LatchUpdate> updates_;     ///< every latch
  std::vector<StateWord> held_;          ///< per state word: the bits some latch holds
  std::vector<std::uint32_t> latch_at_;  ///< per state bit held by a latch: its literal
  std::uint32_t allowed_ = 1, range_error_ = 0;
  bool allowed_static_ = false;
  std::vector<Word> val_, mask_;
  std::vector<Block> block_;  ///< targets_of()'s node values: kBlockWords words per literal
  std::vector<StateWord> base_, common_;
  std::vector<Exception> exceptions_;
  std::uint32_t rank_[64 * kBlockWords] = {};
};

/// Every initial state of `ts`, packed; empty when there are more than kMaxListedInitial
/// (then no latch is merged: the merge is proved on each initial state).
std::vector<StateWord> initial_states(const semantics::TransitionSystem& ts) {
  constexpr std::size_t kMaxListedInitial = 256;
  struct TooMany {};
  class List final : public semantics::SuccessorSink {
   public:
    void successor(const semantics::Successor& s) override {
      if (++count > kMaxListedInitial) throw TooMany{};
      states.insert(states.end(), s.target.begin(), s.target.end());
    }
    std::vector<StateWord> states;
    std::size_t count = 0;
  } list;
  try {
    ts.initial_states(list);
  } catch (const TooMany&) {
    return {};
  }
  return list.states;
}

}  // namespace

std::unique_ptr<TargetEnumerator> make_compiled_enumerator(const semantics::TransitionSystem& ts,
                                                           const model::Budget& limits) {
  if (ts.kind() != semantics::SemanticsKind::Iec61131) return nullptr;
  // An input the interpreter would refuse to enumerate (SemanticsLimitError) must still be
  // refused: leave such systems to it.
  for (const auto& in : ts.inputs())
    if (in.type.kind != model::TypeKind::Bool &&
        static_cast<std::uint64_t>(in.type.hi) - static_cast<std::uint64_t>(in.type.lo) >=
            static_cast<std::uint64_t>(semantics::kMaxEnumeratedValues))
      return nullptr;
  try {
    const auto circuit =
        semantics::build_iec61131_circuit(ts, limits.deadline, limits.max_memory_bytes);
    if (circuit.aig.inputs().size() > 64) return nullptr;
    // A cycle that may meet the loop bound: its successors are cut in the circuit, where the
    // interpreter stops with a LimitReached (unknown); leave such systems to it.
    if (circuit.loop_limit != Aig::kFalse) return nullptr;
    return std::make_unique<CompiledEnumerator>(ts, circuit, limits, initial_states(ts));
  } catch (const semantics::CircuitUnsupported&) {
    return nullptr;
  } catch (const LimitReached& e) {
    if (e.which() != Limit::Memory) throw;
    return nullptr;  // a speed-up the budget cannot afford: the interpreter stays within it
  } catch (const std::invalid_argument&) {
    return nullptr;  // an IEC system wrapped by another (e.g. the history system): no circuit
  }
}

}  // namespace sfcv::engine
