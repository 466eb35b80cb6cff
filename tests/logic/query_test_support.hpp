#pragma once
// A small hand-built graph with known sets, shared by the query tests.
//
//   state  steps     outputs     arcs
//   0      X1                    0 -[a]-> 1
//   1      X2        O1          1 -[b]-> 2, 1 -[a & !b]-> 3
//   2      X3        O2          2 -[!a]-> 0
//   3      X2 X3     O1 O2       3 -[b]-> 4
//   4      (none)                (global deadlock)
// Initial: 0. Inputs a, b. The RSG numbers states in BFS order, which here is 0,1,2,3,4.

#include <set>
#include <string>
#include <utility>

#include "engine/explicit/query_evaluator.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "logic/query_compile.hpp"
#include "support/toy_system.hpp"

namespace sfcv::test {

inline semantics::InputCondition cube(std::vector<semantics::InputLiteral> lits) {
  return semantics::InputCondition{{semantics::InputCube{std::move(lits)}}};
}

inline ToySystem make_query_toy() {
  ToySystem ts(5, {"a", "b"}, {"X1", "X2", "X3"});
  const auto o1 = ts.add_output("O1"), o2 = ts.add_output("O2");
  ts.set_true(0, 0);
  ts.set_true(1, 1), ts.set_true(1, o1);
  ts.set_true(2, 2), ts.set_true(2, o2);
  ts.set_true(3, 1), ts.set_true(3, 2), ts.set_true(3, o1), ts.set_true(3, o2);
  ts.set_initial({0});
  ts.add_arc(0, 1, ToySystem::lit(0, true), {0});
  ts.add_arc(1, 2, ToySystem::lit(1, true), {1});
  ts.add_arc(1, 3, cube({{0, 1, 1}, {1, 0, 0}}), {2});
  ts.add_arc(2, 0, ToySystem::lit(0, false), {3});
  ts.add_arc(3, 4, ToySystem::lit(1, true), {4});
  return ts;
}

/// Evaluates queries on a toy system; sets come back as toy state numbers / (from, to) pairs /
/// observable names.
class QueryFixture {
 public:
  explicit QueryFixture(ToySystem ts)
      : ts_(std::move(ts)), g_(engine::build_reachable_situation_graph(ts_)), eval_(g_) {}

  engine::QueryResult run(const std::string& q) {
    return eval_.evaluate(logic::compile_query(q, lib_, ts_));
  }
  std::set<std::uint32_t> states(const engine::DynamicBitset& b) const {
    std::set<std::uint32_t> r;
    b.for_each([&](std::uint64_t s) {
      r.insert(ts_.state_of(g_.states().at(static_cast<std::uint32_t>(s))));
    });
    return r;
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges(const engine::DynamicBitset& b) const {
    std::set<std::pair<std::uint32_t, std::uint32_t>> r;
    b.for_each([&](std::uint64_t e) {
      r.emplace(ts_.state_of(g_.states().at(eval_.source(e))),
                ts_.state_of(g_.states().at(g_.target(e))));
    });
    return r;
  }
  std::set<std::string> steps(const engine::DynamicBitset& b) const {
    std::set<std::string> r;
    b.for_each([&](std::uint64_t o) { r.insert(ts_.observables()[o].name); });
    return r;
  }
  std::set<std::uint32_t> S(const std::string& q) {
    auto r = run(q);
    EXPECT_EQ(r.sort, logic::Sort::States) << q;
    return states(r.set);
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> E(const std::string& q) {
    auto r = run(q);
    EXPECT_EQ(r.sort, logic::Sort::Evolutions) << q;
    return edges(r.set);
  }
  std::set<std::string> St(const std::string& q) {
    auto r = run(q);
    EXPECT_EQ(r.sort, logic::Sort::Steps) << q;
    return steps(r.set);
  }
  bool B(const std::string& q) {
    auto r = run(q);
    EXPECT_EQ(r.sort, logic::Sort::Bool) << q;
    return r.truth;
  }

  logic::QueryLibrary& library() { return lib_; }
  const ToySystem& system() const { return ts_; }
  const engine::ReachableSituationGraph& graph() const { return g_; }

 private:
  ToySystem ts_;
  logic::QueryLibrary lib_;
  engine::ReachableSituationGraph g_;
  engine::QueryEvaluator eval_;
};

}  // namespace sfcv::test
