// "Did you mean": the closest known name to a misspelled one (model/suggest.hpp).

#include "model/suggest.hpp"

#include <gtest/gtest.h>

namespace sfcv::model {
namespace {

TEST(Suggest, EditDistanceCountsInsertionsDeletionsReplacementsAndSwaps) {
  EXPECT_EQ(edit_distance("check", "check"), 0u);
  EXPECT_EQ(edit_distance("chek", "check"), 1u);
  EXPECT_EQ(edit_distance("--clt", "--ctl"), 1u);  // two neighbours swapped: one edit
  EXPECT_EQ(edit_distance("Boing", "boin"), 1u);   // case does not count
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(Suggest, TheClosestNameWithinAThirdOfItsLength) {
  const std::vector<std::string> commands = {"check", "info", "lint", "rsg", "query"};
  EXPECT_EQ(closest_name("chek", commands), "check");
  EXPECT_EQ(closest_name("lnit", commands), "lint");
  EXPECT_EQ(closest_name("frobnicate", commands), "");  // nothing close: no guess
  EXPECT_EQ(closest_name("xyz", commands), "");         // 3 edits of 3 letters is no guess
  EXPECT_EQ(did_you_mean("chek", commands), " (did you mean 'check'?)");
  EXPECT_EQ(did_you_mean("zzzz", commands), "");
}

TEST(Suggest, ANameWithoutItsInstancePathMatchesTheTail) {
  const std::vector<std::string> observables = {"Main.Mag.Start", "Main.Crane.Lift", "Main.go"};
  EXPECT_EQ(closest_name("Lift", observables), "Main.Crane.Lift");  // the last part itself
  EXPECT_EQ(closest_name("Lfit", observables), "Main.Crane.Lift");  // a typo of the last part
  EXPECT_EQ(closest_name("Crane.Lfit", observables), "Main.Crane.Lift");
  EXPECT_EQ(closest_name("Main.Crane.Lift", observables), "");  // the same name is no suggestion
}

}  // namespace
}  // namespace sfcv::model
