#include "report/situation_graph_dot.hpp"

#include <gtest/gtest.h>

#include "support/grafcet_builder.hpp"

namespace sfcv::report {
namespace {

using namespace sfcv::test;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The grouped graph's situation nodes ("  g3 [id=\"sg3\", ..."; edges are \"se0\").
std::size_t situation_nodes(const std::string& dot) {
  return count(dot, " [id=\"sg");
}

// A ring of `n` steps, stepping on every change of a; y emitted in step 2.
model::Project ring(int n) {
  GrafcetBuilder b;
  b.input("a").output("y").chart("G");
  for (int i = 1; i <= n; ++i) b.step(std::to_string(i), i == 1);
  for (int i = 1; i <= n; ++i)
    b.transition({std::to_string(i)}, {std::to_string(i % n + 1)}, i % 2 ? v("a") : not_(v("a")));
  b.continuous("2", "y");
  return b.project();
}

TEST(SituationGraphDot, OneNodePerStepSituationWithItsFirings) {
  // X1 -> X2 needs a & b: {X1} is stable with a, with b and with neither, one node of three.
  GrafcetBuilder b;
  b.input("a").input("b").output("y").chart("G");
  b.step("1", true).step("2");
  b.transition({"1"}, {"2"}, and_(v("a"), v("b")));
  b.transition({"2"}, {"1"}, not_(v("a")));
  b.continuous("2", "y");
  const auto built = build_rsg(b.project());
  const auto r = situation_graph_dot(built.graph);
  EXPECT_GT(r.stable_situations, r.step_situations);
  EXPECT_EQ(r.step_situations, 2u);
  EXPECT_EQ(r.shown, 2u);
  EXPECT_EQ(r.edges, 2u);
  EXPECT_EQ(situation_nodes(r.dot), 2u) << r.dot;
  EXPECT_TRUE(r.truncation_note.empty());
  EXPECT_NE(r.dot.find("peripheries=2"), std::string::npos);  // the initial situation
  EXPECT_NE(r.dot.find(" stable situations"), std::string::npos) << r.dot;
  // The edges name the transitions fired, as IEC 60848 writes them.
  const auto& trs = built.system->transitions();
  for (const auto& t : trs)
    EXPECT_NE(r.dot.find(t.name + "\\l"), std::string::npos) << t.name << "\n" << r.dot;
  ASSERT_EQ(r.node_ids.size(), 2u);
  EXPECT_EQ(r.node_ids.begin()->second.rfind("sg", 0), 0u);
}

TEST(SituationGraphDot, CapDrawsTheFirstAndSaysHowManyAreLeftOut) {
  const auto built = build_rsg(ring(8));
  const auto all = situation_graph_dot(built.graph, {0, "--max-nodes", {}});
  EXPECT_EQ(all.step_situations, 8u);
  EXPECT_EQ(all.shown, 8u);
  EXPECT_EQ(situation_nodes(all.dot), 8u);
  EXPECT_TRUE(all.truncation_note.empty());

  const auto cut = situation_graph_dot(built.graph, {3, "--max-nodes", {}});
  EXPECT_EQ(cut.shown, 3u);
  EXPECT_EQ(cut.omitted(), 5u);
  EXPECT_EQ(situation_nodes(cut.dot), 3u) << cut.dot;
  EXPECT_EQ(cut.edges, 2u);  // X1 -> X2 -> X3; X3 -> X4 goes to the "more" node
  EXPECT_NE(cut.dot.find("5 more step situations"), std::string::npos) << cut.dot;
  EXPECT_NE(cut.dot.find("g2 -> omitted"), std::string::npos) << cut.dot;
  EXPECT_EQ(cut.truncation_note,
            "3 of 8 step situations are drawn (the first 3 breadth-first), 5 left out; "
            "--max-nodes N draws N, --max-nodes 0 every one");

  // A situation a trace visits is drawn beyond the cap.
  SituationGraphOptions keep{3, "--max-nodes", {"X6"}};
  const auto kept = situation_graph_dot(built.graph, keep);
  EXPECT_EQ(kept.shown, 4u);
  EXPECT_EQ(situation_nodes(kept.dot), 4u);
  ASSERT_TRUE(kept.node_ids.count("X6"));
  EXPECT_NE(kept.dot.find("[id=\"" + kept.node_ids.at("X6") + "\", label=\"{X6}\""),
            std::string::npos)
      << kept.dot;
  EXPECT_NE(
      kept.truncation_note.find("(the first 3 breadth-first, and 1 a trace visits), 4 left out"),
      std::string::npos)
      << kept.truncation_note;
}

}  // namespace
}  // namespace sfcv::report
