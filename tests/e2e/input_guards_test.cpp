// Inputs that are not files, or too deep to read back, end at once with exit 2 and a message
// naming them: `check /dev/zero` and a result JSON naming /dev/zero once read forever, and a
// 100,000-deep array in a result JSON crashed `sfcv report`.

#include <gtest/gtest.h>

#include <string>

#include "support/sfcv_test.hpp"

namespace {

using sfcv::test::run_sfcv;
using sfcv::test::write_temp;

TEST(InputGuards, DevicesAndDirectoriesAreRefusedInEverySubcommand) {
  for (const char* cmd : {"check", "info", "lint", "rsg", "export --to dot"}) {
    for (const char* path : {"/dev/zero", "/tmp"}) {
      const auto r = run_sfcv(std::string(cmd) + " " + path);
      const std::string said = r.out + r.err;  // lint reports on standard output
      EXPECT_EQ(r.exit_code, 2) << cmd << " " << path << ": " << said;
      EXPECT_NE(said.find(path), std::string::npos) << cmd << ": " << said;
      EXPECT_TRUE(said.find("device or socket") != std::string::npos ||
                  said.find("directory") != std::string::npos)
          << said;
    }
  }
  const std::string chart = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  const auto spec = run_sfcv("check " + chart + " --spec /dev/zero");
  EXPECT_EQ(spec.exit_code, 2) << spec.err;
  EXPECT_NE(spec.err.find("the spec file is a device"), std::string::npos) << spec.err;
  const auto trace = run_sfcv("simulate " + chart + " --inputs /dev/zero");
  EXPECT_EQ(trace.exit_code, 2) << trace.err;
}

TEST(InputGuards, AResultJsonTooDeepOrNamingADeviceIsRefused) {
  const std::string deep =
      "{\"properties\": [], \"model\": \"x.st\", \"extra\": " + std::string(100000, '[') +
      std::string(100000, ']') + "}";
  const auto r =
      run_sfcv("report " + write_temp(deep, ".json") + " --html " + write_temp("", ".html"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("nested more than"), std::string::npos) << r.err;

  const auto dev =
      run_sfcv("report " + write_temp("{\"properties\": [], \"model\": \"/dev/zero\"}", ".json") +
               " --html " + write_temp("", ".html"));
  EXPECT_EQ(dev.exit_code, 2) << dev.err;
  EXPECT_NE(dev.err.find("/dev/zero"), std::string::npos) << dev.err;
}

}  // namespace
