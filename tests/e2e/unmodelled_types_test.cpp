// Values of types sfcv does not model (REAL): a PLCopen project that computes a REAL for its
// HMI, which no control decision reads, is checked with that write left out; a read of the
// value, or a write whose right side does more than compute it, keeps the POU refused with the
// type named (docs/semantics.md 1.7b).

#include <gtest/gtest.h>

#include <string>

#include "support/plcopen_text.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

/// Average (pure: REAL result of its inputs) and Bump (VAR_IN_OUT: not pure), then Main, whose
/// ST body is `body` over go : BOOL, k : INT, avg : REAL.
std::string project(const std::string& body) {
  return kPlcopenHeader +
         "<pou name=\"Average\" pouType=\"function\"><interface><returnType><REAL/></returnType>" +
         plcopen_vars("inputVars", {"a", "b"}, "<INT/>") +
         plcopen_vars("localVars", {"n"}, "<REAL/>") + "</interface><body>" +
         plcopen_st("n := 2.0; Average := INT_TO_REAL(a + b) / n;") + "</body></pou>\n" +
         "<pou name=\"Bump\" pouType=\"function\"><interface><returnType><REAL/></returnType>" +
         plcopen_vars("inOutVars", {"c"}, "<INT/>") + "</interface><body>" +
         plcopen_st("c := c + 1; Bump := INT_TO_REAL(c);") + "</body></pou>\n" +
         "<pou name=\"Main\" pouType=\"program\"><interface>" + plcopen_vars("inputVars", {"go"}) +
         plcopen_vars("localVars", {"k"}, "<INT/>") +
         plcopen_vars("localVars", {"avg"}, "<REAL/>") + "</interface><body>" + plcopen_st(body) +
         "</body></pou>\n" + kPlcopenFooter;
}

TEST(UnmodelledTypes, AWriteNothingReadsIsLeftOut) {
  const auto file = write_temp(
      project("IF go AND k &lt; 3 THEN k := k + 1; avg := Average(k, 2); END_IF;"), ".xml");
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    const auto r = run_sfcv("check " + file + " --engine " + engine +
                            " --checks none --ctl 'EF k = 3' --ctl 'AG k <= 3' --ctl 'AG k <= 2'"
                            " --trace none");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("EF k = 3   holds"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("AG k <= 3  holds"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("AG k <= 2  violated"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("note: assignment to 'avg' (REAL, a type sfcv does not model) left out"),
              std::string::npos)
        << r.err;
  }
  // The value is not in the model: a property cannot name it.
  const auto named = run_sfcv("check " + file + " --checks none --ctl 'AG avg = 0'");
  EXPECT_EQ(named.exit_code, 2) << named.out << named.err;
}

TEST(UnmodelledTypes, AReadOrAWriteWithEffectsStaysRefused) {
  auto refusal = [](const std::string& body) {
    const auto r =
        run_sfcv("check " + write_temp(project(body), ".xml") + " --checks none --ctl 'AG TRUE'");
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    return r.err;
  };
  // Read by a decision.
  const auto read = refusal("avg := Average(k, 2); IF avg &gt; k THEN k := 0; END_IF;");
  EXPECT_NE(read.find("assignment to undeclared variable 'avg' (declared as REAL, a type sfcv "
                      "does not model"),
            std::string::npos)
      << read;
  EXPECT_EQ(read.find("left out: its right side"), std::string::npos) << read;
  EXPECT_NE(read.find("POU 'Main': its ST body is not modelled"), std::string::npos) << read;
  // Written through a function that also writes its VAR_IN_OUT (k): not left out.
  const auto bump = refusal("avg := Bump(c := k);");
  EXPECT_NE(bump.find("assignment to undeclared variable 'avg' (declared as REAL"),
            std::string::npos)
      << bump;
}

}  // namespace
}  // namespace sfcv::test
