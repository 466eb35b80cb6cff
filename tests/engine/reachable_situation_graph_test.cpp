#include "engine/explicit/reachable_situation_graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "support/toy_system.hpp"

namespace sfcv::engine {
namespace {

using test::ToySystem;

// 0 --inc--> 1 --inc--> 2 --inc--> 0, each state stays under !inc; state 3 is unreachable.
ToySystem counter() {
  ToySystem ts(4, {"inc"});
  ts.set_initial({0});
  for (std::uint32_t s = 0; s < 3; ++s) {
    ts.add_arc(s, (s + 1) % 3, ToySystem::lit(0, true), {s});
    ts.add_arc(s, s, ToySystem::lit(0, false));
  }
  ts.add_arc(3, 0);
  return ts;
}

TEST(ReachableSituationGraph, CountsStatesAndEdges) {
  const auto ts = counter();
  const auto g = build_reachable_situation_graph(ts);
  EXPECT_TRUE(g.complete());
  EXPECT_EQ(g.num_states(), 3u);
  EXPECT_EQ(g.num_edges(), 6u);
  ASSERT_EQ(g.initial_states().size(), 1u);
  for (std::uint32_t s = 0; s < g.num_states(); ++s)
    EXPECT_EQ(g.edges_end(s) - g.edges_begin(s), 2u);
}

TEST(ReachableSituationGraph, KeepsConditionsAndFiredTransitions) {
  const auto ts = counter();
  const auto g = build_reachable_situation_graph(ts);
  const auto e = g.edges_begin(0);
  EXPECT_EQ(g.condition(e).to_string(ts.inputs()), "inc");
  ASSERT_EQ(g.fired(e).size(), 1u);
  EXPECT_EQ(g.fired(e)[0], 0u);
  EXPECT_EQ(g.condition(e + 1).to_string(ts.inputs()), "!inc");
  EXPECT_TRUE(g.fired(e + 1).empty());
  EXPECT_TRUE(g.fired_somewhere()[2]);
}

TEST(ReachableSituationGraph, ShortestPathsFollowBfsParents) {
  const auto ts = counter();
  const auto g = build_reachable_situation_graph(ts);
  // BFS numbering: 0, 1, 2 are the toy states 0, 1, 2.
  const auto path = g.shortest_path_edges(2);
  ASSERT_EQ(path.size(), 2u);
  EXPECT_EQ(g.source(path[0]), 0u);
  EXPECT_EQ(g.target(path[1]), 2u);
  EXPECT_EQ(g.depth(2), 2u);
  EXPECT_EQ(g.path_initial(2), 0u);
}

TEST(ReachableSituationGraph, MergesSuccessorsWithTheSameTarget) {
  ToySystem ts(2, {"a", "b"});
  ts.set_initial({0});
  ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
  ts.add_arc(0, 1, ToySystem::lit(1, true), {1});
  const auto g = build_reachable_situation_graph(ts);
  ASSERT_EQ(g.num_edges(), 1u);
  EXPECT_EQ(g.condition(0).to_string(ts.inputs()), "a | b");
  EXPECT_EQ(g.fired(0).size(), 2u);
}

TEST(ReachableSituationGraph, StateLimitGivesIncompleteGraph) {
  ToySystem ts(100, {});
  ts.set_initial({0});
  for (std::uint32_t s = 0; s + 1 < 100; ++s) ts.add_arc(s, s + 1);
  ExplorationOptions opts;
  opts.max_states = 10;
  const auto g = build_reachable_situation_graph(ts, opts);
  EXPECT_FALSE(g.complete());
  EXPECT_EQ(g.limit_reached(), "states");
  // States the limit left unexpanded have no known edges.
  for (std::uint32_t s = 0; s < g.num_states(); ++s) {
    if (!g.expanded(s)) {
      EXPECT_EQ(g.edges_begin(s), g.edges_end(s));
    }
  }
  const auto full = build_reachable_situation_graph(ts);
  EXPECT_TRUE(full.complete());
  EXPECT_EQ(full.num_states(), 100u);
}

TEST(ReachableSituationGraph, PredecessorsInvertEdges) {
  const auto ts = counter();
  const auto g = build_reachable_situation_graph(ts);
  const auto& off = g.predecessor_offsets();
  const auto& pe = g.predecessor_edges();
  for (std::uint32_t s = 0; s < g.num_states(); ++s)
    for (auto i = off[s]; i < off[s + 1]; ++i) EXPECT_EQ(g.target(pe[i]), s);
  EXPECT_EQ(off[g.num_states()], g.num_edges());
}

TEST(StateStore, InsertsFindsAndGrows) {
  StateStore store(2);
  for (std::uint64_t i = 0; i < 5000; ++i) {
    const StateWord w[2] = {i, i * 7};
    EXPECT_TRUE(store.insert(w).second);
  }
  for (std::uint64_t i = 0; i < 5000; ++i) {
    const StateWord w[2] = {i, i * 7};
    EXPECT_EQ(store.find(w), static_cast<std::uint32_t>(i));
    EXPECT_FALSE(store.insert(w).second);
  }
  const StateWord absent[2] = {1, 1};
  EXPECT_EQ(store.find(absent), StateStore::kAbsent);
}

TEST(StateStore, OneWordStatesKeepTheirIndicesWhenTheSlotTagsStop) {
  // Past `tagged_states` one-word states the slots stop holding hash bits: every state must
  // still be found with its index, whether it was inserted alone or with others.
  StateStore store(1, 1000);
  auto word = [](std::uint64_t i) { return (i * 0x9e3779b97f4a7c15ULL) >> 1; };
  for (std::uint64_t i = 0; i < 3000; ++i) {
    const StateWord w[1] = {word(i)};
    EXPECT_EQ(store.insert(w), std::make_pair(static_cast<std::uint32_t>(i), true));
  }
  StateStore batched(1, 1000);
  std::vector<StateWord> buffer;
  std::vector<std::uint64_t> hashes;
  for (std::uint64_t i = 0; i < 3000; ++i) {
    buffer.push_back(word(i));
    hashes.push_back(batched.state_hash(StateView(&buffer.back(), 1)));
  }
  for (std::size_t first = 0; first < 3000; first += 600)
    ASSERT_EQ(batched.insert_new_states(buffer.data(), hashes.data(), first, first + 600, 3000,
                                        ~std::uint64_t{0}),
              first + 600);
  for (auto* st : {&store, &batched})
    for (std::uint64_t i = 0; i < 3000; ++i) {
      const StateWord w[1] = {word(i)};
      EXPECT_EQ(st->find(w), static_cast<std::uint32_t>(i));
      EXPECT_FALSE(st->insert(w).second);
      EXPECT_EQ(st->insert_if_new(w, st->state_hash(w)), StateStore::kAbsent);
    }
  const StateWord absent[1] = {1};
  EXPECT_EQ(store.find(absent), StateStore::kAbsent);
}

// The quotient form: a store asked only membership holds each one-word state in its slot once
// the remainder fits. Every state must be found, whether inserted alone or with others, as the
// table grows from the indexed form into the quotient form.
TEST(StateStore, MembershipStoreHoldsStatesAsQuotientsAndFindsEveryOne) {
  constexpr std::uint32_t kBits = 41;  // indexed below 2^17 slots, quotients from there on
  auto word = [](std::uint64_t i) { return (i * 0x9e3779b97f4a7c15ULL) >> (64 - kBits); };
  constexpr std::uint64_t kCount = 300000;
  StateStore inserted(1, StateStore::kTaggedStates, kBits);
  EXPECT_FALSE(inserted.quotient_form());
  for (std::uint64_t i = 0; i < kCount; ++i) {
    const StateWord w[1] = {word(i)};
    ASSERT_EQ(inserted.insert(w), std::make_pair(static_cast<std::uint32_t>(i), true));
  }
  EXPECT_TRUE(inserted.quotient_form());
  StateStore batched(1, StateStore::kTaggedStates, kBits);
  std::vector<StateWord> buffer;
  std::vector<std::uint64_t> hashes;
  for (std::uint64_t i = 0; i < kCount; ++i) {
    buffer.push_back(word(i));
    hashes.push_back(batched.state_hash(StateView(&buffer.back(), 1)));
  }
  for (std::size_t first = 0; first < kCount; first += 50000)
    ASSERT_EQ(batched.insert_new_states(buffer.data(), hashes.data(), first, first + 50000, kCount,
                                        ~std::uint64_t{0}),
              first + 50000);
  EXPECT_TRUE(batched.quotient_form());
  for (auto* st : {&inserted, &batched}) {
    for (std::uint64_t i = 0; i < kCount; ++i) {
      const StateWord w[1] = {word(i)};
      ASSERT_EQ(st->insert(w), std::make_pair(StateStore::kAbsent, false));
      ASSERT_EQ(st->at(static_cast<std::uint32_t>(i))[0], word(i));
    }
    // Words one bit away from stored ones (same home for some, other remainders) are absent.
    for (std::uint64_t i = 0; i < 100; ++i) {
      const StateWord w[1] = {word(i) ^ (std::uint64_t{1} << (i % kBits))};
      if (std::find(buffer.begin(), buffer.end(), w[0]) != buffer.end()) continue;
      const auto size = st->size();
      EXPECT_EQ(st->insert_if_new(w, st->state_hash(w)), size);
    }
  }
  EXPECT_THROW((void)inserted.find(StateView(buffer.data(), 1)), std::logic_error);
}

// The hash is a bijection of the state's bits: every one of the 2^20 states of 20 bits is new
// once, then found (two states of one hash would be taken for each other).
TEST(StateStore, MembershipStoreTellsEveryStateOfItsWidthApart) {
  constexpr std::uint32_t kBits = 20;
  StateStore store(1, StateStore::kTaggedStates, kBits);
  for (StateWord w = 0; w < (StateWord{1} << kBits); ++w) {
    const StateWord one[1] = {w};
    ASSERT_TRUE(store.insert(one).second) << w;
  }
  EXPECT_TRUE(store.quotient_form());
  for (StateWord w = 0; w < (StateWord{1} << kBits); ++w) {
    const StateWord one[1] = {w};
    ASSERT_FALSE(store.insert(one).second) << w;
  }
}

// A probe farther from home than a quotient can record (states chosen with one home) leaves the
// quotient form for the indexed one, for good; no state is lost on the way.
TEST(StateStore, MembershipStoreLeavesTheQuotientFormWhenAProbeRunsTooFar) {
  constexpr std::uint32_t kBits = 20;
  StateStore store(1, StateStore::kTaggedStates, kBits);
  ASSERT_TRUE(store.quotient_form());
  std::vector<StateWord> same_home;
  for (StateWord w = 0; w < (StateWord{1} << kBits) && same_home.size() < 300; ++w) {
    const StateWord one[1] = {w};
    if ((store.state_hash(one) & 1023) == 7) same_home.push_back(w);
  }
  ASSERT_EQ(same_home.size(), 300U);
  for (std::uint32_t i = 0; i < same_home.size(); ++i) {
    const StateView v(same_home.data() + i, 1);
    ASSERT_EQ(store.insert(v), std::make_pair(i, true));
  }
  EXPECT_FALSE(store.quotient_form());
  for (std::uint32_t i = 0; i < same_home.size(); ++i) {
    const StateView v(same_home.data() + i, 1);
    ASSERT_EQ(store.insert_if_new(v, store.state_hash(v)), StateStore::kAbsent);
  }
  EXPECT_EQ(store.size(), 300U);
  // A state wider than promised would share a narrower one's slot: refused.
  const StateWord wide[1] = {StateWord{1} << kBits};
  EXPECT_THROW((void)store.insert(wide), std::logic_error);
}

// A remainder of 24 bits and the distance fill a slot's 32 bits: states far from their home
// (the distance's top bit, the slot's bit 31, set) are found again and told apart from others,
// one by one (insert_if_new()) and a source's targets at once (insert_new_states(), which reads
// the first four slots of a path together), from a home in the table and from one among its
// last three slots (a path that wraps).
TEST(StateStore, MembershipStoreUsesEveryBitOfASlot) {
  constexpr std::uint32_t kBits = 34;  // 1024 slots: a remainder of 24 bits
  for (const std::uint64_t home : {7U, 1022U}) {
    SCOPED_TRACE(home);
    StateStore single(1, StateStore::kTaggedStates, kBits),
        batch(1, StateStore::kTaggedStates, kBits);
    ASSERT_TRUE(single.quotient_form());
    std::vector<StateWord> same_home, other;
    for (StateWord w = 0; same_home.size() < 250 || other.size() < 250; ++w) {
      const StateWord one[1] = {w};
      auto& list = (single.state_hash(one) & 1023) == home ? same_home : other;
      if (list.size() < 250) list.push_back(w);
    }
    auto hashes_of = [&](const std::vector<StateWord>& words) {
      std::vector<std::uint64_t> h(words.size());
      batch.state_hashes(words, words.size(), h.data());
      return h;
    };
    const auto same_hashes = hashes_of(same_home), other_hashes = hashes_of(other);
    for (std::uint32_t i = 0; i < same_home.size(); ++i)
      ASSERT_EQ(single.insert(StateView(same_home.data() + i, 1)), std::make_pair(i, true));
    ASSERT_EQ(batch.insert_new_states(same_home.data(), same_hashes.data(), 0, 250, 250,
                                      ~std::uint64_t{0}),
              250U);
    for (auto* store : {&single, &batch}) {
      ASSERT_TRUE(store->quotient_form());  // 249 slots from home at most: within the distance
      ASSERT_EQ(store->size(), 250U);
      for (std::uint32_t i = 0; i < same_home.size(); ++i) {
        const StateView v(same_home.data() + i, 1);
        ASSERT_EQ(store->insert_if_new(v, store->state_hash(v)), StateStore::kAbsent) << i;
      }
    }
    ASSERT_EQ(batch.insert_new_states(same_home.data(), same_hashes.data(), 0, 250, 250,
                                      ~std::uint64_t{0}),
              250U);
    ASSERT_EQ(batch.size(), 250U);
    // The other states, some of whose homes lie on that long path (which pushes some of them
    // too far from home: the form is left), are new once, then found.
    for (std::uint32_t i = 0; i < other.size(); ++i) {
      const StateView v(other.data() + i, 1);
      ASSERT_EQ(single.insert_if_new(v, single.state_hash(v)), 250 + i);
    }
    ASSERT_EQ(
        batch.insert_new_states(other.data(), other_hashes.data(), 0, 250, 250, ~std::uint64_t{0}),
        250U);
    for (auto* store : {&single, &batch}) {
      for (const auto* list : {&same_home, &other})
        for (std::size_t i = 0; i < list->size(); ++i) {
          const StateView v(list->data() + i, 1);
          ASSERT_EQ(store->insert_if_new(v, store->state_hash(v)), StateStore::kAbsent) << i;
        }
      EXPECT_EQ(store->size(), 500U);
    }
    for (std::uint32_t i = 0; i < 500; ++i) ASSERT_EQ(batch.at(i)[0], single.at(i)[0]);
  }
}

// insert_new_states() is the serial search's insertion of a source's targets: it must number
// them as insert_if_new() one by one does, through growths, the change to the quotient form
// (41-bit states: from 2^17 slots on) or none (64-bit states), and stop where the search's
// state limit stops it.
TEST(StateStore, InsertsASourcesTargetsAsOneByOneInsertions) {
  for (const std::uint32_t bits : {41U, 64U}) {
    SCOPED_TRACE(bits);
    StateStore batch(1, StateStore::kTaggedStates, bits),
        single(1, StateStore::kTaggedStates, bits);
    const bool starts_quotient = batch.quotient_form();
    std::uint64_t seed = 12345;
    auto next = [&] {
      seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
      return seed >> 11;
    };
    const StateWord mask = bits == 64 ? ~StateWord{0} : (StateWord{1} << bits) - 1;
    // Half the targets repeat a word of a pool already (mostly) stored, or one of their group.
    std::vector<StateWord> pool;
    std::vector<StateWord> words;
    std::vector<std::uint64_t> hashes;
    std::uint64_t stopped_groups = 0;
    while (single.size() < 300000) {
      words.clear();
      const std::size_t count = 1 + next() % 30;
      for (std::size_t k = 0; k < count; ++k) {
        const bool repeat = !pool.empty() && next() % 2 == 0;
        const StateWord w =
            repeat ? pool[next() % pool.size()] : (next() * 0x9E3779B97F4A7C15ULL) & mask;
        words.push_back(w);
        if (!repeat) pool.push_back(w);
      }
      hashes.clear();
      for (const StateWord w : words) hashes.push_back(batch.state_hash(StateView(&w, 1)));
      std::vector<std::uint64_t> together(count);  // state_hashes() as state_hash() one by one
      batch.state_hashes(words, count, together.data());
      ASSERT_EQ(together, hashes);
      // Every 50th group meets a limit a few states on.
      const bool capped = next() % 50 == 0;
      const std::uint64_t cap = capped ? single.size() + next() % 4 : ~std::uint64_t{0};
      std::size_t expected_stop = count;
      for (std::size_t k = 0; k < count; ++k) {
        if (single.size() >= cap) {
          expected_stop = k;
          break;
        }
        const auto index = single.insert_if_new(StateView(&words[k], 1), hashes[k]);
        if (index != StateStore::kAbsent) {
          ASSERT_EQ(index, single.size() - 1);
        }
      }
      const std::uint32_t before = batch.size();
      ASSERT_EQ(batch.insert_new_states(words.data(), hashes.data(), 0, count, count, cap),
                expected_stop);
      ASSERT_EQ(batch.size(), single.size());
      for (std::uint32_t i = before; i < batch.size(); ++i)
        ASSERT_EQ(batch.at(i)[0], single.at(i)[0]);
      stopped_groups += expected_stop < count ? 1 : 0;
    }
    EXPECT_GT(stopped_groups, 0U);
    EXPECT_EQ(batch.quotient_form(), bits == 41);
    EXPECT_FALSE(starts_quotient);
    // The table finds every state stored.
    for (std::uint32_t i = 0; i < single.size(); ++i) {
      const StateView v = single.at(i);
      ASSERT_EQ(batch.insert_if_new(v, batch.state_hash(v)), StateStore::kAbsent);
    }
  }
  // A probe past the farthest distance a quotient records: the store leaves the form and the
  // states are numbered all the same.
  constexpr std::uint32_t kBits = 20;
  StateStore store(1, StateStore::kTaggedStates, kBits);
  ASSERT_TRUE(store.quotient_form());
  std::vector<StateWord> same_home;
  std::vector<std::uint64_t> hashes;
  for (StateWord w = 0; w < (StateWord{1} << kBits) && same_home.size() < 300; ++w) {
    const auto h = store.state_hash(StateView(&w, 1));
    if ((h & 1023) != 7) continue;
    same_home.push_back(w);
    hashes.push_back(h);
  }
  ASSERT_EQ(same_home.size(), 300U);
  EXPECT_EQ(
      store.insert_new_states(same_home.data(), hashes.data(), 0, 300, 300, ~std::uint64_t{0}),
      300U);
  EXPECT_EQ(store.size(), 300U);
  EXPECT_FALSE(store.quotient_form());
  for (std::uint32_t i = 0; i < 300; ++i) ASSERT_EQ(store.at(i)[0], same_home[i]);
}

}  // namespace
}  // namespace sfcv::engine

namespace sfcv::engine {
namespace {

// A system whose single initial call enumerates a huge number of states: the limits must stop
// it from inside the sink (a Grafcet stabilised under every initial input valuation does this).
class Flood final : public semantics::TransitionSystem {
 public:
  Flood() { field_ = layout_.add_field("x", semantics::FieldKind::Variable, 0, (1LL << 40)); }
  semantics::SemanticsKind kind() const override { return semantics::SemanticsKind::Grafcet; }
  const semantics::StateLayout& layout() const override { return layout_; }
  const std::vector<semantics::InputVariable>& inputs() const override { return inputs_; }
  const std::vector<semantics::Observable>& observables() const override { return obs_; }
  const std::vector<semantics::TransitionInfo>& transitions() const override { return trs_; }
  void initial_states(semantics::SuccessorSink& sink) const override {
    std::vector<semantics::StateWord> s(layout_.words());
    const auto always = semantics::InputCondition::always();
    for (std::int64_t i = 0; i < (1LL << 40); ++i) {
      layout_.set(s, field_, i);
      sink.successor({s, always, {}});
    }
  }
  void successors(semantics::StateView, semantics::SuccessorSink&) const override {}
  std::int64_t observe(semantics::StateView, std::uint32_t) const override { return 0; }

 private:
  semantics::StateLayout layout_;
  std::uint32_t field_;
  std::vector<semantics::InputVariable> inputs_;
  std::vector<semantics::Observable> obs_;
  std::vector<semantics::TransitionInfo> trs_;
};

TEST(ReachableSituationGraph, LimitsStopAnEnumerationInsideOneCall) {
  Flood flood;
  ExplorationOptions by_states;
  by_states.max_states = 5000;
  const auto g = build_reachable_situation_graph(flood, by_states);
  EXPECT_FALSE(g.complete());
  EXPECT_EQ(g.limit_reached(), "states");
  EXPECT_LE(g.num_states(), 5002u);

  ExplorationOptions by_time;
  by_time.timeout_seconds = 0.2;
  const auto t = build_reachable_situation_graph(flood, by_time);
  EXPECT_FALSE(t.complete());
  EXPECT_EQ(t.limit_reached(), "time");
}

}  // namespace
}  // namespace sfcv::engine
