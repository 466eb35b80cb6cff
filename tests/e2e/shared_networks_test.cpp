// FBD/LD networks are DAGs: an element whose output feeds several inputs is evaluated once,
// never unfolded into a tree (a 20-deep network of blocks taking both inputs from one source
// took 6.5 s / 790 MB to lint and 50 s under `check --timeout 2`; 30 deep was killed at 40 s).
// A shared Boolean element is a hidden temporary that holds nothing between cycles; a shared
// non-Boolean value too large to unfold is refused with a located error.

#include <gtest/gtest.h>

#include <string>

#include "support/cpu_run.hpp"
#include "support/plcopen_text.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

std::string in_variable(int id, const std::string& name) {
  return "<inVariable localId=\"" + std::to_string(id) +
         "\"><position x=\"0\" y=\"0\"/><connectionPointOut/><expression>" + name +
         "</expression></inVariable>";
}

std::string wired(const std::string& pin, int from) {
  return "<variable formalParameter=\"" + pin + "\"><connectionPointIn><connection refLocalId=\"" +
         std::to_string(from) + "\"/></connectionPointIn></variable>";
}

std::string block(int id, const std::string& type, int in1, int in2) {
  return "<block localId=\"" + std::to_string(id) + "\" typeName=\"" + type +
         "\"><position x=\"0\" y=\"0\"/><inputVariables>" + wired("IN1", in1) + wired("IN2", in2) +
         "</inputVariables><inOutVariables/><outputVariables><variable formalParameter=\"OUT\">"
         "<connectionPointOut/></variable></outputVariables></block>";
}

std::string out_variable(int id, int from, const std::string& name) {
  return "<outVariable localId=\"" + std::to_string(id) +
         "\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"" +
         std::to_string(from) + "\"/></connectionPointIn><expression>" + name +
         "</expression></outVariable>";
}

/// Main in FBD: x1 = a AND b, then `depth` levels each taking both inputs from the level
/// below (AND, OR alternately, or `type` for every level when given): q = a AND b.
/// `n` counts the cycles in ST after the network, so that the chart has more than one state.
std::string deep_fbd(int depth, const std::string& type = "",
                     const std::string& var_type = "<BOOL/>") {
  std::string fbd =
      in_variable(1, "a") + in_variable(2, "b") + block(3, type.empty() ? "AND" : type, 1, 2);
  int last = 3;
  for (int i = 0; i < depth; ++i) {
    const std::string t = !type.empty() ? type : i % 2 ? "OR" : "AND";
    fbd += block(10 + i, t, last, last);
    last = 10 + i;
  }
  fbd += out_variable(5, last, "q");
  return kPlcopenHeader + "<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"a", "b"}, var_type) +
         plcopen_vars("outputVars", {"q"}, var_type) + "</interface><body><FBD>" + fbd +
         "</FBD></body></pou>\n" + kPlcopenFooter;
}

std::string st_twin() {
  return kPlcopenHeader + "<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"a", "b"}) + plcopen_vars("outputVars", {"q"}) +
         "</interface><body>" + plcopen_st("q := a AND b;") + "</body></pou>\n" + kPlcopenFooter;
}

/// An LD rung of `depth` contacts, each fed twice (two parallel branches) by the one before:
/// the coil q is a AND b AND c ... on every level.
std::string deep_ld(int depth) {
  std::string ld =
      "<leftPowerRail localId=\"1\"><position x=\"0\" y=\"0\"/><connectionPointOut "
      "formalParameter=\"\"/></leftPowerRail>"
      "<contact localId=\"2\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection "
      "refLocalId=\"1\"/></connectionPointIn><connectionPointOut/><variable>a</variable></contact>";
  int last = 2;
  for (int i = 0; i < depth; ++i) {
    const int id = 10 + i;
    ld += "<contact localId=\"" + std::to_string(id) +
          "\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"" +
          std::to_string(last) + "\"/><connection refLocalId=\"" + std::to_string(last) +
          "\"/></connectionPointIn><connectionPointOut/><variable>" + (i % 2 ? "b" : "a") +
          "</variable></contact>";
    last = id;
  }
  ld +=
      "<coil localId=\"5\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection "
      "refLocalId=\"" +
      std::to_string(last) +
      "\"/></connectionPointIn><connectionPointOut/><variable>q</variable></coil>";
  return kPlcopenHeader + "<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"a", "b"}) + plcopen_vars("outputVars", {"q"}) +
         "</interface><body><LD>" + ld + "</LD></body></pou>\n" + kPlcopenFooter;
}

TEST(SharedNetworks, ADeepFbdNetworkOfSharedInputsLoadsAndChecksAtOnceOnEveryEngine) {
  const auto file = write_temp(deep_fbd(30), ".xml");
  for (const char* cmd : {"lint", "info", "export --to nusmv"}) {
    const auto r = cpu_run(std::string(cmd) + " '" + file + "'");
    EXPECT_NE(r.run.exit_code, 2) << cmd << ": " << r.run.err;
    EXPECT_NE(r.run.exit_code, 4) << cmd << ": " << r.run.err;
    EXPECT_LT(r.cpu, 2.0 * kSlowdown) << cmd;
  }
  for (const char* engine : {"explicit", "bdd", "bmc", "kind", "ic3"}) {
    // q = a AND b at every cycle end: q implies a, and q does come on.
    const auto holds = cpu_run("check '" + file + "' --engine " + engine +
                               " --ctl 'AG (q -> a & b)' --ctl 'AG (a & b -> q)' --ctl 'EF q' "
                               "--timeout 2 --quiet");
    EXPECT_EQ(holds.run.exit_code, engine == std::string("bmc") ? 3 : 0)
        << engine << ": " << holds.run.out << holds.run.err;
    EXPECT_LT(holds.cpu, 4.0 * kSlowdown) << engine;
    const auto violated =
        run_sfcv("check '" + file + "' --engine " + engine + " --ctl 'AG !q' --timeout 2 --quiet");
    EXPECT_EQ(violated.exit_code, 1) << engine << ": " << violated.out << violated.err;
  }
}

TEST(SharedNetworks, TheTemporariesAddNoStates) {
  // The FBD network and its one-line ST twin have the same reachable states: a shared element's
  // temporary is reset after the body, so it never distinguishes two states.
  const auto fbd = run_sfcv("check '" + write_temp(deep_fbd(12), ".xml") +
                            "' --engine explicit --ctl 'AG (q -> a)' --json");
  const auto st = run_sfcv("check '" + write_temp(st_twin(), ".xml") +
                           "' --engine explicit --ctl 'AG (q -> a)' --json");
  ASSERT_EQ(fbd.exit_code, 0) << fbd.err;
  ASSERT_EQ(st.exit_code, 0) << st.err;
  const auto states = [](const std::string& json) {
    const auto at = json.find("\"states\"");
    return at == std::string::npos ? std::string("none")
                                   : json.substr(at, json.find_first_of(",}", at) - at);
  };
  EXPECT_NE(states(st.out), "none") << st.out;
  EXPECT_EQ(states(fbd.out), states(st.out));
}

TEST(SharedNetworks, ADeepLdRungOfParallelBranchesLoadsAndChecks) {
  const auto file = write_temp(deep_ld(40), ".xml");
  const auto r =
      cpu_run("check '" + file +
              "' --engine explicit --ctl 'AG (q -> a & b)' --ctl 'EF q' --timeout 2 --quiet");
  EXPECT_EQ(r.run.exit_code, 0) << r.run.out << r.run.err;
  EXPECT_LT(r.cpu, 2.0 * kSlowdown);
}

TEST(SharedNetworks, ASharedIntegerValueTooLargeToUnfoldIsALocatedError) {
  // ADD(x, x) thirty levels deep: 2^30 additions as a tree; not modelled, said where.
  const auto file = write_temp(deep_fbd(30, "ADD", "<INT/>"), ".xml");
  const auto r = cpu_run("check '" + file + "' --timeout 2 --quiet");
  EXPECT_EQ(r.run.exit_code, 2) << r.run.out << r.run.err;
  EXPECT_NE(r.run.err.find("unfolds into more than"), std::string::npos) << r.run.err;
  EXPECT_NE(r.run.err.find("outVariable"), std::string::npos) << r.run.err;
  EXPECT_LT(r.cpu, 2.0 * kSlowdown);
  // A shallow one is read and computed as written: q = 2^6 * (a + b), in range for small inputs.
  const auto shallow = run_sfcv("info '" + write_temp(deep_fbd(6, "ADD", "<INT/>"), ".xml") + "'");
  EXPECT_EQ(shallow.exit_code, 0) << shallow.err;
}

}  // namespace
}  // namespace sfcv::test
