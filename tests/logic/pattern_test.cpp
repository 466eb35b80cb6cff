// Requirement patterns: parsing, the CTL each pattern and scope translates to, the English
// sentence, and errors with their locations (also inside a spec file).

#include "logic/pattern.hpp"

#include <gtest/gtest.h>

#include "logic/check_inputs.hpp"
#include "logic/formula.hpp"
#include "logic/parser.hpp"

namespace sfcv::logic {
namespace {

std::string ctl(const std::string& pattern, const PatternOptions& options = {}) {
  auto r = parse_pattern(pattern, "--pattern", options);
  for (const auto& d : r.diagnostics) ADD_FAILURE() << d.str();
  return r.ok() ? to_string(r.formula) : "";
}

std::string english(const std::string& pattern) {
  return parse_pattern(pattern, "--pattern").english;
}

std::string error(const std::string& pattern, const PatternOptions& options = {}) {
  auto r = parse_pattern(pattern, "--pattern", options);
  EXPECT_FALSE(r.ok()) << pattern;
  return r.diagnostics.empty() ? "" : r.diagnostics.front().str();
}

TEST(PatternTranslation, CycleTemplates) {
  EXPECT_EQ(ctl("always(a)"), "AG a");
  EXPECT_EQ(ctl("never(a & b)"), "AG !(a & b)");
  EXPECT_EQ(ctl("implies(estop, !M)"), "AG (estop -> !M)");
  EXPECT_EQ(ctl("next_cycle(a, b)"), "AG (a -> AX b)");
  EXPECT_EQ(ctl("between_cycles(a, b, c)"), "AG (a -> AX (b -> c))");
  EXPECT_EQ(ctl("infinitely_often(a)"), "AG AF a");
  EXPECT_EQ(ctl("never_before(a, b)"), "!E[!b U a & !b]");
  EXPECT_EQ(ctl("reachable(level > 3)"), "EF (level > 3)");
  EXPECT_EQ(ctl("repeatable(a)"), "AG EF a");
}

// Dwyer, Avrunin, Corbett's CTL, with A[x W y] written !E[!y U !x & !y].
TEST(PatternTranslation, DwyerPatternsAndScopes) {
  EXPECT_EQ(ctl("absence(p)"), "AG !p");
  EXPECT_EQ(ctl("absence(p, globally)"), "AG !p");
  EXPECT_EQ(ctl("absence(p, before r)"), "!E[!r U !(!p | AG !r) & !r]");
  EXPECT_EQ(ctl("absence(p, after q)"), "AG (q -> AG !p)");
  EXPECT_EQ(ctl("absence(p, between q and r)"), "AG (q & !r -> !E[!r U !(!p | AG !r) & !r])");
  EXPECT_EQ(ctl("absence(p, after q until r)"), "AG (q & !r -> !E[!r U p & !r])");
  EXPECT_EQ(ctl("universality(p)"), "AG p");
  EXPECT_EQ(ctl("universality(p, before r)"), "!E[!r U !(p | AG !r) & !r]");
  EXPECT_EQ(ctl("universality(p, after q until r)"), "AG (q & !r -> !E[!r U !p & !r])");
  EXPECT_EQ(ctl("existence(p)"), "AF p");
  EXPECT_EQ(ctl("existence(p, before r)"), "!E[!(p & !r) U r & !(p & !r)]");
  EXPECT_EQ(ctl("existence(p, after q)"), "!E[!(q & AF p) U q & !(q & AF p)]");
  EXPECT_EQ(ctl("existence(p, after q until r)"), "AG (q & !r -> A[!r U p & !r])");
  EXPECT_EQ(ctl("precedence(s, p)"), "!E[!s U p & !s]");
  EXPECT_EQ(ctl("precedence(s, p, before r)"), "!E[!(s | r) U !(!p | AG !r) & !(s | r)]");
  EXPECT_EQ(ctl("response(p, s)"), "AG (p -> AF s)");
  EXPECT_EQ(ctl("response(p, s, after q)"),
            "!E[!(q & AG (p -> AF s)) U q & !(q & AG (p -> AF s))]");
  EXPECT_EQ(ctl("response(p, s, after q until r)"),
            "AG (q & !r -> !E[!r U !(p -> A[!r U s & !r]) & !r])");
}

TEST(PatternTranslation, BoundedResponseNestsAStrongNext) {
  EXPECT_EQ(ctl("response(a, b, within 0 cycles)"), "AG (a -> b)");
  EXPECT_EQ(ctl("response(a, b, within 2 cycles)"),
            "AG (a -> b | EX TRUE & AX (b | EX TRUE & AX b))");
  PatternOptions ten_ms;
  ten_ms.cycle_ms = 10;
  EXPECT_EQ(ctl("response(a, b, within 25 ms)", ten_ms), ctl("response(a, b, within 2 cycles)"));
  EXPECT_EQ(ctl("response(a, b, within 1 s)", PatternOptions{100}),
            ctl("response(a, b, within 10 cycles)"));
  EXPECT_EQ(english("response(start, V1, within 3 cycles)"),
            "Whenever start is true, V1 is true then or within the next 3 cycles.");
}

TEST(PatternTranslation, EnglishSentences) {
  EXPECT_EQ(english("implies(estop, !M)"),
            "If estop is true at the end of a cycle, !M is true at the end of the same cycle.");
  EXPECT_EQ(english("absence(V1 & V3, between s1 and s9)"),
            "From each s1 up to the next s9 (if s9 comes), V1 & V3 is never true.");
  EXPECT_EQ(english("existence(p, before r)"), "Before the first r (if r comes), p becomes true.");
  EXPECT_EQ(english("precedence(s, p, after q)"),
            "From the first q on, p is never true before s is.");
  EXPECT_EQ(english("response(p, s, after q until r)"),
            "From each q up to the next r (or for ever if no r comes), whenever p is true, s is "
            "true then or later.");
}

TEST(PatternTranslation, ArgumentsMayNestParenthesesCommentsAndHistory) {
  EXPECT_EQ(ctl("  Response ( (a | b) & c ,  rise(d) -- the trigger\n , after (e) ) ;"),
            "!E[!(e & AG ((a | b) & c -> AF (d & !prev(d)))) U e & !(e & AG ((a | b) & c -> AF (d "
            "& !prev(d))))]");
}

TEST(PatternErrors, NamesArityScopesAndBoundsWithLocations) {
  EXPECT_EQ(error("respond(a, b)"),
            "--pattern:1:1: error: unknown pattern 'respond' (known: always, never, "
            "implies, next_cycle, between_cycles, statechange_duringcycle, leadsto, "
            "infinitely_often, never_before, "
            "reachable, repeatable, absence, universality, existence, precedence, response)");
  EXPECT_EQ(error("response(a)"),
            "--pattern:1:1: error: pattern 'response' takes 2 arguments, found 1: "
            "response(P, S[, scope | within N cycles])");
  EXPECT_EQ(error("never(a, b)"),
            "--pattern:1:10: error: pattern 'never' takes 1 argument, found 2: never(A)");
  EXPECT_EQ(error("never()"),
            "--pattern:1:1: error: pattern 'never' takes 1 argument, found 0: never(A)");
  EXPECT_EQ(error("never(a, after b)"),
            "--pattern:1:10: error: pattern 'never' takes no scope: never(A)");
  EXPECT_EQ(error("absence(a, within 3 cycles)"),
            "--pattern:1:12: error: pattern 'absence' takes no bound: absence(P[, scope])");
  EXPECT_EQ(error("absence(after b, a)"),
            "--pattern:1:9: error: a scope or bound ('after ...') must be the last argument of a "
            "pattern");
  EXPECT_EQ(error("absence(a, between b)"), "--pattern:1:21: error: expected 'between Q and R'");
  EXPECT_EQ(error("absence(a & , before b)"),
            "--pattern:1:12: error: expected a formula, found end of input; operators accepted: ! "
            "NOT, & AND, | OR, xor XOR, ->, <->, EX AX EF AF EG AG, E[p U q] A[p U q], = <> != < "
            "<= > >=, + - * / MOD, prev() rise() fall()");
  EXPECT_EQ(error("absence(AG a)"),
            "--pattern:1:9: error: a pattern's arguments are propositional formulas (no temporal "
            "operator): AG a");
  EXPECT_EQ(error("response(a, b, within 2 s)"),
            "--pattern:1:23: error: a bound in time needs a cycle time: use --time discrete (and "
            "--cycle, 10ms by default), or give the bound in cycles ('within N cycles')");
  EXPECT_EQ(error("response(a, b, within 61 cycles)"),
            "--pattern:1:23: error: a bounded response is checked for at most 60 cycles; this "
            "bound is 61 cycles");
  EXPECT_EQ(error("response(a, b, within 3 hours)"),
            "--pattern:1:25: error: expected 'cycles', 'ms' or 's' after the number in 'within'");
  EXPECT_EQ(error("response(a, b"),
            "--pattern:1:14: error: expected ')' at the end of the pattern");
  EXPECT_EQ(error("response(a, b) x"), "--pattern:1:16: error: unexpected 'x' after the pattern");
  EXPECT_EQ(error("never a"), "--pattern:1:7: error: expected '(' after the pattern name 'never'");
}

TEST(PatternSpec, PatternStatementsCarryTheirSentenceAndLocations) {
  const auto r = parse_spec(
      "property p1: AG !(V1 & V3);\n"
      "-- a comment\n"
      "pattern fills: response(start,\n"
      "                        V1, within 5 cycles);\n"
      "pattern bad:   absence(V1, between s1 nd s9);\n"
      "pattern p1: never(a);\n",
      "plant.spec");
  ASSERT_EQ(r.spec.properties.size(), 2u);
  EXPECT_EQ(r.spec.properties[1].name, "fills");
  EXPECT_EQ(r.spec.properties[1].description,
            "Whenever start is true, V1 is true then or within the next 5 cycles.");
  EXPECT_EQ(r.spec.properties[1].where.line, 3);
  // The argument V1 keeps its place in the file (for unknown-name errors at resolution).
  EXPECT_EQ(r.spec.properties[1].formula->args[0]->args[1]->args[0]->line, 4);
  EXPECT_EQ(r.spec.properties[1].formula->args[0]->args[1]->args[0]->column, 25);
  ASSERT_EQ(r.diagnostics.size(), 2u);
  EXPECT_EQ(r.diagnostics[0].str(), "plant.spec:5:44: error: expected 'between Q and R'");
  EXPECT_EQ(r.diagnostics[1].str(),
            "plant.spec:6:1: error: property 'p1' is defined twice (first at line 1)");
}

TEST(PatternSpec, CommandLinePatternsAreNamedByTheirText) {
  CheckInputs in;
  in.patterns = {"never(V1 & V3)", "never(("};
  const auto parsed = parse_check_inputs(in);
  ASSERT_EQ(parsed.spec.properties.size(), 1u);
  EXPECT_EQ(parsed.spec.properties[0].name, "never(V1 & V3)");
  EXPECT_EQ(parsed.spec.properties[0].where.file, "--pattern");
  EXPECT_EQ(parsed.spec.properties[0].description, "V1 & V3 is never true at the end of a cycle.");
  ASSERT_EQ(parsed.diagnostics.size(), 1u);
  EXPECT_EQ(parsed.diagnostics[0].where.file, "--pattern 'never(('");
}

TEST(PatternCatalogue, EveryEntryParsesWithItsLetters) {
  for (const auto& p : pattern_catalogue()) {
    const std::string text = std::string(p.name) + "(" + std::string(p.arguments) + ")";
    auto r = parse_pattern(text, "catalogue");
    EXPECT_TRUE(r.ok()) << text;
    EXPECT_FALSE(r.english.empty());
  }
}

}  // namespace
}  // namespace sfcv::logic
