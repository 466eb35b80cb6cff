// The provenance of a report (issue 48): SHA-256 against FIPS 180-2's examples, the data
// type's JSON both ways, the text block, the command line as shell words, the stable ids.

#include "report/provenance.hpp"

#include <gtest/gtest.h>

#include <regex>

#include "report/check_render.hpp"
#include "report/sha256.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::report {
namespace {

// FIPS 180-2, appendix B: one block, two blocks, a million 'a'; and the empty message.
TEST(Sha256, StandardExamples) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  Sha256 h;
  const std::string thousand(1000, 'a');
  for (int i = 0; i < 1000; ++i) h.update(thousand);  // blocks split across updates
  std::string hex;
  for (auto b : h.finish()) {
    static const char* digits = "0123456789abcdef";
    hex += digits[b >> 4];
    hex += digits[b & 15];
  }
  EXPECT_EQ(hex, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Provenance, FileDigestIsTheContentsDigest) {
  const auto path = test::write_temp("PROGRAM p\nEND_PROGRAM\n", ".st");
  const auto d = digest_file(path);
  EXPECT_EQ(d.path, path);
  EXPECT_EQ(d.sha256, sha256_hex("PROGRAM p\nEND_PROGRAM\n"));
  EXPECT_EQ(d.bytes, 22u);
  EXPECT_EQ(digest_file("/nonexistent/x.st").sha256, "");  // unreadable: no digest, no throw
}

TEST(Provenance, DateIsUtcIso8601) {
  EXPECT_TRUE(std::regex_match(utc_now_iso8601(),
                               std::regex("20[0-9]{2}-[01][0-9]-[0-3][0-9]T[0-2][0-9]:[0-5][0-9]:"
                                          "[0-6][0-9]Z")))
      << utc_now_iso8601();
}

TEST(Provenance, CommandLineAsShellWords) {
  EXPECT_EQ(shell_words({"sfcv", "check", "a b.st", "--ctl", "AG !(V2 & V4)", "it's", ""}),
            "sfcv check 'a b.st' --ctl 'AG !(V2 & V4)' 'it'\\''s' ''");
}

Provenance sample() {
  auto p = make_provenance({"sfcv", "check", "plant.st", "--ctl", "AG !x"},
                           {{"buddy", "2.4"}, {"cadical", "sc2021"}});
  p.inputs.push_back({"plant.st", std::string(64, 'a'), 10});
  p.inputs.push_back({"gone.spec", "", 0});
  p.engine = "auto";
  p.settings = {{"semantics", "iec61131"}, {"timeout", "none"}};
  return p;
}

TEST(Provenance, JsonBothWays) {
  const auto p = sample();
  EXPECT_EQ(p.version, build_version());
  EXPECT_EQ(p.commit, build_commit());
  EXPECT_FALSE(p.commit.empty());
  const auto j = provenance_json(p);
  EXPECT_EQ(j["tool"], "sfcv");
  EXPECT_EQ(j["inputs"][0]["sha256"], std::string(64, 'a'));
  EXPECT_TRUE(j["inputs"][1]["sha256"].is_null());
  EXPECT_EQ(j["settings"]["semantics"], "iec61131");
  EXPECT_EQ(j["libraries"]["buddy"], "2.4");
  const auto back = provenance_from_json(j);
  EXPECT_EQ(back.command_line, p.command_line);
  EXPECT_EQ(back.date, p.date);
  EXPECT_EQ(back.commit, p.commit);
  EXPECT_EQ(back.engine, "auto");
  ASSERT_EQ(back.inputs.size(), 2u);
  EXPECT_EQ(back.inputs[0].sha256, p.inputs[0].sha256);
  EXPECT_EQ(back.inputs[0].bytes, 10u);
  EXPECT_EQ(provenance_json(back), j);
}

TEST(Provenance, TextBlock) {
  const auto text = provenance_text(sample());
  EXPECT_EQ(text.rfind("# sfcv " + build_version() + " (commit " + build_commit() +
                           ", buddy 2.4, cadical sc2021), ",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("\n# command: sfcv check plant.st --ctl 'AG !x'\n"), std::string::npos);
  EXPECT_NE(text.find("\n# input: plant.st sha256:" + std::string(64, 'a') + "\n"),
            std::string::npos);
  EXPECT_NE(text.find("\n# input: gone.spec (unreadable)\n"), std::string::npos);
  EXPECT_NE(text.find("\n# engine: auto; settings: semantics=iec61131 timeout=none\n"),
            std::string::npos)
      << text;
}

TEST(Provenance, RunDigestIgnoresTheProgramPathOnly) {
  auto a = sample();
  auto b = sample();
  b.command_line[0] = "/usr/bin/sfcv";
  EXPECT_EQ(run_digest(a), run_digest(b));
  EXPECT_EQ(run_digest(a).size(), 8u);
  b.command_line.back() = "AG !y";
  EXPECT_NE(run_digest(a), run_digest(b));
}

// Stable ids: a standard check by its name, a spec property by its name, a command-line
// property by its kind and its text without spaces (never the raw formula text).
TEST(PropertyId, StableAndFreeOfFormulaText) {
  logic::PropertyResult r;
  r.check = "reachable";
  r.name = "reachable";
  EXPECT_EQ(property_id(r), "check/reachable");
  EXPECT_EQ(property_file_stem(r), "check-reachable");
  logic::PropertyResult ctl;
  ctl.name = ctl.formula = "AG !(V2 & V4)";
  ctl.where.file = "--ctl";
  const auto id = property_id(ctl);
  EXPECT_TRUE(std::regex_match(id, std::regex("property/ctl-[0-9a-f]{12}"))) << id;
  auto spaced = ctl;
  spaced.name = "AG  !(V2&V4)";
  EXPECT_EQ(property_id(spaced), id);
  auto other = ctl;
  other.name = "AG !(V1 & V3)";
  EXPECT_NE(property_id(other), id);
  auto ltl = ctl;
  ltl.where.file = "--ltl";
  EXPECT_EQ(property_id(ltl).rfind("property/ltl-", 0), 0u);
  logic::PropertyResult named;
  named.name = "t2 never/in";
  named.where.file = "plant.spec";
  named.where.line = 3;
  EXPECT_EQ(property_id(named), "property/t2_never_in");
  EXPECT_TRUE(from_command_line(ctl));
  EXPECT_FALSE(from_command_line(named));
}

}  // namespace
}  // namespace sfcv::report
