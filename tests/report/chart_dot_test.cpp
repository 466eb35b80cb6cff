#include "report/chart_dot.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "report/graphviz_svg.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::report {
namespace {

using namespace sfcv::model;

// S0 -> (A, B) -> join -> S0, with an N action on A and a nested chart action on B.
Project sample() {
  Project p;
  p.name = "Sample";
  Pou pou;
  pou.name = "Main";
  Chart c;
  c.name = "Main";
  auto step = [](std::string name, bool initial) {
    Step s;
    s.name = std::move(name);
    s.initial = initial;
    return s;
  };
  c.steps = {step("S0", true), step("A", false), step("B", false)};
  Transition fork;
  fork.sources = {"S0"};
  fork.targets = {"A", "B"};
  fork.guard = make_name("start");
  Transition join;
  join.sources = {"A", "B"};
  join.targets = {"S0"};
  join.guard = make_binary(ExprKind::Gt, make_member("A", "T"), make_time(2000));
  join.priority = 1;
  c.transitions = {fork, join};
  pou.charts.push_back(c);
  Chart nested;
  nested.name = "Sub";
  nested.parent_action = "Sub";
  nested.steps = {step("N0", true)};
  pou.charts.push_back(nested);
  ActionAssociation a;
  a.chart = "Main";
  a.step = "A";
  a.action = "V1";
  a.qualifier = Qualifier::N;
  ActionAssociation b = a;
  b.step = "B";
  b.action = "Sub";
  b.qualifier = Qualifier::SD;
  b.duration_ms = 500;
  pou.associations = {a, b};
  p.pous.push_back(pou);
  return p;
}

TEST(ChartDot, DrawsStepsTransitionsBarsAndActionBlocks) {
  std::ostringstream out;
  print_chart_dot(out, sample());
  const std::string dot = out.str();
  EXPECT_NE(dot.find("label=\"S0\", peripheries=2"), std::string::npos) << dot;
  // The guard sits in the transition's node beside its bar, so the layout keeps guards apart.
  EXPECT_NE(dot.find("bgcolor=\"black\"></td><td align=\"left\"> start</td>"), std::string::npos)
      << dot;
  EXPECT_NE(dot.find("<td align=\"left\"> (1) A.T &gt; T#2s</td>"), std::string::npos);
  EXPECT_NE(dot.find("p0c0s0 -> p0c0t0:bar [arrowhead=none]"), std::string::npos);
  EXPECT_EQ(dot.find("xlabel"), std::string::npos);
  EXPECT_NE(dot.find("p0c0t0fork"), std::string::npos);  // simultaneous divergence
  EXPECT_NE(dot.find("p0c0t1join"), std::string::npos);  // simultaneous convergence
  EXPECT_NE(dot.find("<td>N</td><td>V1</td>"), std::string::npos);
  EXPECT_NE(dot.find("<td>SD, T#500ms</td><td>Sub</td>"), std::string::npos);
  EXPECT_NE(dot.find("cluster_p0c1"), std::string::npos);  // the nested chart
  EXPECT_NE(dot.find("lhead=cluster_p0c1"), std::string::npos);
}

TEST(ChartDot, RendersWithGraphviz) {
  if (std::system("command -v dot >/dev/null 2>&1") != 0) GTEST_SKIP() << "graphviz not installed";
  std::ostringstream out;
  print_chart_dot(out, sample());
  const auto in = test::write_temp(out.str(), ".dot");
  const auto svg = in + ".svg";
  ASSERT_EQ(std::system(("dot -Tsvg '" + in + "' -o '" + svg + "' 2>/dev/null").c_str()), 0);
  std::ifstream f(svg);
  std::stringstream ss;
  ss << f.rdbuf();
  EXPECT_NE(ss.str().find("<svg"), std::string::npos);
  std::remove(in.c_str());
  std::remove(svg.c_str());
}

TEST(ChartDot, NodeIdsSurviveIntoTheSvg) {
  std::ostringstream out;
  print_chart_dot(out, sample());
  EXPECT_NE(out.str().find("p0c0s1 [id=\"p0c0s1\", class=\"step\""), std::string::npos)
      << out.str();
  if (std::system("command -v dot >/dev/null 2>&1") != 0) GTEST_SKIP() << "graphviz not installed";
  const auto svg = dot_to_svg(out.str());
  ASSERT_TRUE(svg.error.empty()) << svg.error;
  EXPECT_EQ(svg.svg.rfind("<svg", 0), 0u);  // the element, without prolog or DOCTYPE
  EXPECT_NE(svg.svg.find("<g id=\"p0c0s1\" class=\"node step\">"), std::string::npos) << svg.svg;
  EXPECT_NE(svg.svg.find("<g id=\"p0c0t0\" class=\"node transition\">"), std::string::npos);
}

TEST(ChartDot, GrafcetFramesAreNamedAfterTheirPartialGrafcet) {
  const auto r =
      test::run_sfcv("export '" + test::source_path("examples/pistons/pistons.g7") + "' --to dot");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("label=\"piston1\";"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("label=\"piston2\";"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sfcv::report
