// Inputs that are not files, or too deep to read back, end at once with exit 2 and a message
// naming them: `check /dev/zero` and a result JSON naming /dev/zero once read forever, and a
// 100,000-deep array in a result JSON crashed `sfcv report`.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
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

TEST(InputGuards, ANamedPipeNoOneWritesToIsRefusedInsteadOfWaitedFor) {
  // open() of a FIFO without a writer blocks for ever: sfcv gives a writer 2 s, then refuses.
  const std::string fifo = write_temp("", ".fifo");
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_sfcv("lint '" + fifo + "'");
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE((r.out + r.err).find("named pipe that no process writes to"), std::string::npos)
      << r.out << r.err;
  EXPECT_LT(wall, 10);
  // A FIFO with a writer is read to its end, as before.
  const std::string chart = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  ASSERT_EQ(std::system(("(sleep 0.3; cat '" + chart + "' > '" + fifo + "') &").c_str()), 0);
  const auto piped = run_sfcv("lint '" + fifo + "' --format iec");
  EXPECT_EQ(piped.exit_code, 0) << piped.out << piped.err;
  std::remove(fifo.c_str());
}

TEST(InputGuards, AFileOverTheCapIsRefusedWithTheCapNamed) {
  // The cap is 1 GiB; SFCV_MAX_INPUT_BYTES lowers it so that the test need not write 1 GiB.
  const std::string chart = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  ::setenv("SFCV_MAX_INPUT_BYTES", "100", 1);
  const auto r = run_sfcv("lint '" + chart + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE((r.out + r.err).find("more than the 100 bytes sfcv reads"), std::string::npos)
      << r.out << r.err;
  const auto spec = write_temp("property p: AG TRUE;\n", ".spec");
  ::setenv("SFCV_MAX_INPUT_BYTES", "10", 1);
  const auto s = run_sfcv("check '" + chart + "' --spec '" + spec + "'");
  ::unsetenv("SFCV_MAX_INPUT_BYTES");
  EXPECT_EQ(s.exit_code, 2) << s.err;
}

TEST(InputGuards, RequirementsJsonIsReadWithBoundedDepth) {
  const std::string chart = sfcv::test::source_path("examples/chemical_plant/chemical_plant.st");
  const auto deep =
      write_temp("{\"properties_to_be_validated\": [], \"x\": " + std::string(100000, '[') +
                     std::string(100000, ']') + "}",
                 ".json");
  const auto r = run_sfcv("check '" + chart + "' --requirements '" + deep + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("nested more than 256 levels"), std::string::npos) << r.err;
}

}  // namespace
