// Instruction List bodies (issue 18, docs/semantics.md 1.9.2): read as the ST statements they
// execute, with the current result followed symbolically. A program in IL gives the same
// model, state for state, verdict for verdict and trace for trace, as its ST twin on every
// engine; what the translation cannot keep exact is refused by name and place.

#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "support/plcopen_text.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::test {
namespace {

/// Program Main (inputs a, b; n : INT; q, r, s : BOOL; t : TON) with `body` in `language`.
std::string program(const std::string& language, const std::string& body) {
  return kPlcopenHeader + "<pou name=\"Main\" pouType=\"program\"><interface>" +
         plcopen_vars("inputVars", {"a", "b"}) + plcopen_vars("localVars", {"n"}, "<INT/>") +
         plcopen_vars("localVars", {"q", "r", "s"}) +
         plcopen_vars("localVars", {"t"}, "<derived name=\"TON\"/>") + "</interface><body><" +
         language + "><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">" + body + "</xhtml></" +
         language + "></body></pou>\n" + kPlcopenFooter;
}

// Counts n up to 5 while a (not once q), resets on b; r latched by a and (b or r), cleared
// when n = 0 and a; a timer on q. Jumps (conditional, negated, unconditional), a return, a
// parenthesis, a function as an operator, a call, set/reset, comments and labels.
const std::string kIl =
    "(* reset wins *)\n"
    "LD b\n"
    "JMPC reset\n"
    "LD a\n"
    "ANDN q\n"
    "JMPCN skip\n"
    "LD n\n"
    "ADD 1\n"
    "MIN 5 // at most five\n"
    "ST n\n"
    "skip: LD n\n"
    "GE 3\n"
    "ST q\n"
    "LD a\n"
    "AND( b\n"
    "OR r\n"
    ")\n"
    "S r\n"
    "LD n\n"
    "EQ 0\n"
    "AND a\n"
    "R r\n"
    "CAL t(IN := q,\n"
    "      PT := T#1s)\n"
    "LD t.Q\n"
    "ST s\n"
    "RET\n"
    "reset:\n"
    "LD 0\n"
    "ST n\n"
    "LDN b\n"
    "ST q\n";

const std::string kSt =
    "IF b THEN n := 0; q := NOT b;\n"
    "ELSE\n"
    "  IF a AND NOT q THEN n := MIN(n + 1, 5); END_IF;\n"
    "  q := n &gt;= 3;\n"
    "  IF a AND (b OR r) THEN r := TRUE; END_IF;\n"
    "  IF n = 0 AND a THEN r := FALSE; END_IF;\n"
    "  t(IN := q, PT := T#1s);\n"
    "  s := t.Q;\n"
    "END_IF;\n";

// `sfcv check`'s text without its closing provenance block (the "# " lines: version, command
// line, date, input digests), which names each run's own input file (issue 48).
std::string without_provenance(const std::string& out) {
  std::string kept;
  std::size_t at = 0;
  while (at < out.size()) {
    auto end = out.find('\n', at);
    end = end == std::string::npos ? out.size() : end + 1;
    if (out.compare(at, 2, "# ") != 0) kept.append(out, at, end - at);
    at = end;
  }
  return kept;
}

std::string without_times(const std::string& out) {
  return std::regex_replace(without_provenance(out), std::regex("[0-9]+\\.[0-9]+s"), "");
}

TEST(Il, ProgramAgreesWithItsStTwinOnEveryEngine) {
  const auto il = write_temp(program("IL", kIl), ".xml");
  const auto st = write_temp(program("ST", kSt), ".xml");
  const std::string props =
      " --checks none --ctl 'EF n = 5' --ctl 'AG n <= 4' --ctl 'AG (s -> q)' --ctl 'EF r' "
      "--ctl 'AG !(r & b)' --ctl 'EF (s & !a)' --ctl 'AG (q -> n >= 3)'";
  const auto expected = run_sfcv("check " + st + " --engine explicit" + props);
  ASSERT_EQ(expected.exit_code, 1) << expected.out << expected.err;
  for (const char* engine : {"explicit", "bdd", "ic3"}) {
    SCOPED_TRACE(engine);
    const auto from_il = run_sfcv("check " + il + " --engine " + engine + props);
    const auto from_st = run_sfcv("check " + st + " --engine " + engine + props);
    EXPECT_EQ(from_il.exit_code, 1) << from_il.out << from_il.err;
    EXPECT_EQ(without_times(from_il.out), without_times(from_st.out)) << from_il.out << from_st.out;
  }
}

TEST(Il, WhatCannotBeKeptExactIsRefusedByNameAndPlace) {
  auto error_of = [](const std::string& body) {
    const auto r = run_sfcv("check " + write_temp(program("IL", body), ".xml") +
                            " --pou Main --checks none --ctl 'AG TRUE'");
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    return r.err;
  };
  const std::pair<const char*, const char*> cases[] = {
      {"LD a\nJMPC nowhere\n", "IL: unknown label 'nowhere'"},
      {"top: LD a\nST q\nJMPC top\n", "IL: backward jump to 'top' (a loop) is not modelled"},
      {"CAL t(IN := a, PT := T#1s)\nAND b\nST q\n",
       "IL: 'AND' reads the current result, which is undefined after a CAL"},
      {"LD q\nR q\nST s\n",
       "IL: 'ST' reads the current result, which is stale: 'R q' changed q, which it reads"},
      {"LD b\nAND( a\nST b\n)\nST q\n",
       "IL: ')' combines the result saved at 'AND(', which is stale: 'ST b' changed b"},
      {"LD a\nAND( b\nST q\n", "IL: a parenthesis is not closed"},
      {"LD a\nPUSH b\nST q\n", "PUSH"},
  };
  for (const auto& [body, message] : cases) {
    SCOPED_TRACE(body);
    const auto err = error_of(body);
    EXPECT_NE(err.find(message), std::string::npos) << err;
    EXPECT_NE(err.find("(/project/types/pous/pou[@name='Main']/body/IL)"), std::string::npos)
        << err;
  }
}

}  // namespace
}  // namespace sfcv::test
