#pragma once
// The benchmark families (bench/gen, the sfcv-gen binary) as test inputs. SFCV_GEN is defined
// for the test executables by cmake/SfcvTargets.cmake.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "support/sfcv_test.hpp"

namespace sfcv::test {

/// Runs sfcv-gen with `args` into a fresh temporary file with suffix `ext`; returns its path.
inline std::string generate(const std::string& args, const std::string& ext) {
  const std::string path = write_temp("", ext);
  const std::string cmd = std::string("'") + SFCV_GEN + "' " + args + " -o '" + path + "'";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return path;
}

}  // namespace sfcv::test
