// The exit-code contract: each error kind the library throws becomes its exit code, with its
// message, in one place (cli/exit_code.hpp).

#include "cli/exit_code.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "semantics/iec61131_system.hpp"  // SemanticsLimitError

namespace sfcv::cli {
namespace {

struct Outcome {
  int code;
  std::string err;
};

template <typename F>
Outcome run(F f) {
  std::ostringstream err;
  const int code = run_with_exit_codes(f, err);
  return {code, err.str()};
}

TEST(ExitCodes, ACommandsOwnCodeIsKept) {
  for (int code : {0, 1, 3}) {
    const auto o = run([code] { return code; });
    EXPECT_EQ(o.code, code);
    EXPECT_EQ(o.err, "");
  }
}

TEST(ExitCodes, BadInputAndUsageAreTwo) {
  auto o = run([]() -> int { throw InputError("no such step", {"a.st", 3, 7, ""}); });
  EXPECT_EQ(o.code, kBadInput);
  EXPECT_NE(o.err.find("sfcv: error: a.st:3:7: no such step"), std::string::npos) << o.err;
  o = run([]() -> int { throw UnsupportedConstruct("IL body"); });
  EXPECT_EQ(o.code, kBadInput);
  o = run([]() -> int { throw UsageError("bad --timeout"); });
  EXPECT_EQ(o.code, kBadInput);
  EXPECT_NE(o.err.find("bad --timeout"), std::string::npos);
}

TEST(ExitCodes, LimitsAndOutOfMemoryAreUnknown) {
  auto o = run([]() -> int { throw LimitReached(Limit::Time, "time limit reached"); });
  EXPECT_EQ(o.code, kUnknown);
  EXPECT_NE(o.err.find("verdict unknown"), std::string::npos) << o.err;
  o = run([]() -> int { throw semantics::SemanticsLimitError("input n is enumerated"); });
  EXPECT_EQ(o.code, kUnknown);
  o = run([]() -> int { throw std::bad_alloc(); });
  EXPECT_EQ(o.code, kUnknown);
  EXPECT_NE(o.err.find("out of memory"), std::string::npos);
}

TEST(ExitCodes, EverythingElseIsAnInternalErrorWithABugReportRequest) {
  for (const auto& thrower : std::vector<std::function<int()>>{
           []() -> int { throw InternalError("broken invariant"); },
           []() -> int { throw std::logic_error("vector::at"); },
           []() -> int { throw std::invalid_argument("stoi"); }, []() -> int { throw 42; }}) {
    const auto o = run(thrower);
    EXPECT_EQ(o.code, kInternalError);
    EXPECT_NE(o.err.find("sfcv: internal error: "), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("This is a bug in sfcv"), std::string::npos) << o.err;
    EXPECT_EQ(o.err.find("sfcv: error:"), std::string::npos) << o.err;  // not "bad input"
  }
}

// Issue 48: under --json an error is also one JSON object on standard output, its kind named,
// the exit code unchanged; without --json nothing is written there.
TEST(ExitCodes, UnderJsonAnErrorIsAlsoAJsonObject) {
  struct Case {
    std::function<int()> command;
    const char* kind;
    int code;
  };
  const std::vector<Case> cases = {
      {[]() -> int {
         throw InputError("no such step", {"a.st", 3, 7, ""});
       },
       "input", kBadInput},
      {[]() -> int { throw UnsupportedConstruct("IL body"); }, "unsupported", kBadInput},
      {[]() -> int { throw UsageError("bad --engine 'x'"); }, "usage", kBadInput},
      {[]() -> int { throw LimitReached(Limit::States, "state limit 3 reached"); }, "limit",
       kUnknown},
      {[]() -> int { throw std::logic_error("vector::at"); }, "internal", kInternalError}};
  for (const auto& c : cases) {
    std::ostringstream err, out;
    EXPECT_EQ(run_with_exit_codes(c.command, err, &out), c.code);
    const auto j = nlohmann::json::parse(out.str());  // one document
    EXPECT_EQ(j["error"]["kind"], c.kind) << out.str();
    EXPECT_FALSE(j["error"]["message"].get<std::string>().empty());
    EXPECT_EQ(j["exit_code"], c.code);
    EXPECT_EQ(j["schema_version"], "1.0");
    EXPECT_FALSE(err.str().empty());  // the text is still on standard error
  }
  std::ostringstream err, out;
  EXPECT_EQ(run_with_exit_codes([] { return 1; }, err, &out), 1);
  EXPECT_EQ(out.str(), "");  // no error, no error object
}

TEST(ExitCodes, WantsJsonOnlyForTheWord) {
  const char* with[] = {"sfcv", "check", "m.st", "--json"};
  const char* without[] = {"sfcv", "check", "m.st", "--json-file"};
  EXPECT_TRUE(wants_json(4, const_cast<char**>(with)));
  EXPECT_FALSE(wants_json(4, const_cast<char**>(without)));
}

}  // namespace
}  // namespace sfcv::cli
