// model::read_input_file: the guards every reader shares (devices, directories, size cap).

#include "model/input_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "model/errors.hpp"
#include "support/sfcv_test.hpp"

namespace {

using sfcv::model::read_input_file;
using sfcv::model::try_read_input_file;

std::string reason(const std::string& path, std::size_t max_bytes = sfcv::model::kMaxInputBytes) {
  std::string text;
  return try_read_input_file(path, "the model", text, max_bytes).value_or("");
}

TEST(InputFile, ReadsARegularFileWhole) {
  const std::string body(200'000, 'x');
  const auto path = sfcv::test::write_temp(body, ".st");
  EXPECT_EQ(read_input_file(path, "the model"), body);
}

TEST(InputFile, RefusesDevicesDirectoriesAndMissingFiles) {
  EXPECT_NE(reason("/dev/zero").find("device or socket"), std::string::npos);
  EXPECT_NE(reason("/tmp").find("directory"), std::string::npos);
  EXPECT_NE(reason("/nonexistent/model.st").find("cannot open the model"), std::string::npos);
  try {
    read_input_file("/dev/zero", "the spec file");
    ADD_FAILURE() << "/dev/zero was read";
  } catch (const sfcv::InputError& e) {
    EXPECT_EQ(e.where().file, "/dev/zero");
    EXPECT_NE(std::string(e.what()).find("the spec file"), std::string::npos) << e.what();
  }
}

TEST(InputFile, RefusesAFileOverTheCapAndReadsOneAtIt) {
  const auto path = sfcv::test::write_temp(std::string(1000, 'x'), ".st");
  EXPECT_EQ(reason(path, 1000), "");
  EXPECT_NE(reason(path, 999).find("more than the 999 bytes"), std::string::npos)
      << reason(path, 999);
}

}  // namespace
