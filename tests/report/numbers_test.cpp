// Numbers in text for people (issue 48): "65970697666560 states" and "1 situations" were seen.

#include "report/numbers.hpp"

#include <gtest/gtest.h>

#include "report/concise_text.hpp"

namespace sfcv::report {
namespace {

TEST(Numbers, CountsAreGroupedThenScientific) {
  EXPECT_EQ(count_text(0), "0");
  EXPECT_EQ(count_text(728), "728");
  EXPECT_EQ(count_text(1024), "1024");
  EXPECT_EQ(count_text(65536), "65,536");
  EXPECT_EQ(count_text(1080754177), "1,080,754,177");
  EXPECT_EQ(count_text(999999999999ULL), "999,999,999,999");
  EXPECT_EQ(count_text(65970697666560ULL), "6.6\u00b710^13");
  EXPECT_EQ(count_text(35184372088832ULL), "3.5\u00b710^13");
  EXPECT_EQ(count_text(9960000000000ULL), "1.0\u00b710^13");  // rounding carries
  // Beyond 64 bits, from the decimal text of a BigCount.
  EXPECT_EQ(count_text("340282366920938463463374607431768211456"), "3.4\u00b710^38");
  EXPECT_EQ(count_text("not a number"), "not a number");
}

TEST(Numbers, OneIsSingular) {
  EXPECT_EQ(counted(1, "situation"), "1 situation");
  EXPECT_EQ(counted(2, "situation"), "2 situations");
  EXPECT_EQ(counted(0, "state"), "0 states");
  EXPECT_EQ(counted("1", "edge"), "1 edge");
  EXPECT_EQ(counted(12345, "state"), "12,345 states");
}

TEST(ConciseText, DropsXmlPathsAndMakesPathsRelative) {
  const std::string finding =
      "step Main.Mag.Start (/work/c/07.xml:1166:14 "
      "(/project/types/pous/pou[@name='Magazin']/body/SFC/step[@name='Start'])) is never active";
  EXPECT_EQ(concise_text(finding, "/work/c"),
            "step Main.Mag.Start (07.xml:1166:14) is never active");
  EXPECT_EQ(concise_text(finding, "/elsewhere"),
            "step Main.Mag.Start (/work/c/07.xml:1166:14) is never active");
  // A name with a parenthesis inside the path's quotes.
  EXPECT_EQ(concise_text("x (a.xml:1:2 (/project/pou[@name='a)b'])) y", ""), "x (a.xml:1:2) y");
  // Words in parentheses are not a path.
  EXPECT_EQ(concise_text("held (read in Main, line 3)", "/w"), "held (read in Main, line 3)");
  EXPECT_EQ(concise_text("/work/c/07.xml:2:2 (/project): note: n", "/work/c"),
            "07.xml:2:2: note: n");
}

}  // namespace
}  // namespace sfcv::report
