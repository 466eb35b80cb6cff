// The one checked conversion of numeric literals (model/literal.hpp, issue 53 item 5): the
// limits of each range are accepted, one past them is an error naming the type and its range.

#include "model/literal.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace sfcv::model {
namespace {

constexpr auto kMin = std::numeric_limits<std::int64_t>::min();
constexpr auto kMax = std::numeric_limits<std::int64_t>::max();

std::string error_of(const Converted<std::int64_t>& c) {
  return c ? "<value " + std::to_string(*c) + ">" : c.error;
}

TEST(Literal, IntegerLimitsOfLintAreAcceptedAndOnePastIsAnError) {
  EXPECT_EQ(*integer_literal("9223372036854775807"), kMax);
  EXPECT_EQ(*integer_literal("-9223372036854775808"), kMin);
  EXPECT_EQ(*integer_literal("LINT#-9223372036854775808"), kMin);
  EXPECT_EQ(*integer_literal("-16#8000000000000000"), kMin);
  EXPECT_EQ(error_of(integer_literal("9223372036854775808")),
            "integer literal 9223372036854775808 is outside LINT "
            "(-9223372036854775808..9223372036854775807)");
  EXPECT_EQ(error_of(integer_literal("-9223372036854775809")),
            "integer literal -9223372036854775809 is outside LINT "
            "(-9223372036854775808..9223372036854775807)");
  EXPECT_FALSE(integer_literal("99999999999999999999999999"));
  EXPECT_FALSE(integer_literal("16#8000000000000000"));
}

TEST(Literal, BasesUnderscoresAndSigns) {
  EXPECT_EQ(*integer_literal("16#FF"), 255);
  EXPECT_EQ(*integer_literal("2#1010_1010"), 170);
  EXPECT_EQ(*integer_literal("8#777"), 511);
  EXPECT_EQ(*integer_literal("1_000"), 1000);
  EXPECT_EQ(*integer_literal("-3"), -3);
  EXPECT_EQ(*integer_literal("+3"), 3);
  EXPECT_EQ(*integer_literal("INT#-5"), -5);
  EXPECT_EQ(*integer_literal("DINT#16#7FFFFFFF"), 2147483647);
  for (const char* bad :
       {"", "abc", "1.5", "1__0", "_1", "1_", "2#102", "3#1", "16#", "BOOL#1", "TIME#5", "--1"})
    EXPECT_FALSE(integer_literal(bad)) << bad;
}

TEST(Literal, AWrittenTypeChecksItsRange) {
  EXPECT_EQ(*integer_literal("INT#32767"), 32767);
  EXPECT_EQ(*integer_literal("INT#-32768"), -32768);
  EXPECT_EQ(error_of(integer_literal("INT#40000")), "INT#40000 is outside INT (-32768..32767)");
  EXPECT_EQ(error_of(integer_literal("UINT#-1")), "UINT#-1 is outside UINT (0..65535)");
  EXPECT_EQ(error_of(integer_literal("SINT#16#80")), "SINT#16#80 is outside SINT (-128..127)");
  EXPECT_EQ(*integer_literal("USINT#255"), 255);
}

TEST(Literal, RangeErrorNamesTheTypeAndItsRange) {
  EXPECT_EQ(range_error(40000, *elementary_type("INT"), "initial value 40000"),
            "initial value 40000 is outside INT (-32768..32767)");
  EXPECT_EQ(range_error(32767, *elementary_type("INT"), "x"), "");
  EXPECT_EQ(range_error(11, Type::integer("INT(0..10)", 0, 10), "initial value 11"),
            "initial value 11 is outside INT(0..10)");
  EXPECT_EQ(range_text(Type::time()), "TIME (T#0ms..T#24d20h31m23s647ms)");
}

TEST(Literal, DurationsInEveryUnitWithFractionsAndUnderscores) {
  EXPECT_EQ(*time_literal("T#1d"), 86400000);
  EXPECT_EQ(*time_literal("T#1h_30m"), 5400000);
  EXPECT_EQ(*time_literal("TIME#1m30s"), 90000);
  EXPECT_EQ(*time_literal("t#1.5s"), 1500);
  EXPECT_EQ(*time_literal("T#2S"), 2000);
  EXPECT_EQ(*time_literal("LTIME#1_000ms"), 1000);
  EXPECT_EQ(*time_literal("T#1000us"), 1);
  EXPECT_EQ(*time_literal("T#1000000ns"), 1);
  EXPECT_EQ(*time_literal("T#0.5ms500us"), 1);
  EXPECT_EQ(*time_literal("T#-250ms"), -250);
  EXPECT_EQ(*time_literal("T#1.000000000000000000000000000000s"), 1000);
  EXPECT_EQ(error_of(time_literal("T#1us")), "unsupported: TIME literal finer than a millisecond");
  EXPECT_EQ(error_of(time_literal("T#1.0000000001s")), "TIME literal finer than a nanosecond");
  EXPECT_EQ(error_of(time_literal("T#5")), "TIME literal: missing unit (d, h, m, s, ms)");
  EXPECT_EQ(error_of(time_literal("T#5x")), "TIME literal: unknown unit 'x'");
  EXPECT_EQ(error_of(time_literal("T#")), "malformed TIME literal");
  // Not a TIME literal at all (a variable's name): no value and no error.
  EXPECT_FALSE(time_literal("delay"));
  EXPECT_EQ(time_literal("delay").error, "");
}

// The issue's case: 9223372036854775807 ms wrapped around to -1 ms in the PLCopen reader.
TEST(Literal, DurationsPastTimesRangeAreErrorsNotWrappedValues) {
  EXPECT_EQ(*time_literal("T#24d20h31m23s647ms"), kMaxTimeMs);
  EXPECT_EQ(*time_literal("T#2147483647ms"), kMaxTimeMs);
  EXPECT_EQ(*time_literal("T#-2147483647ms"), -kMaxTimeMs);
  EXPECT_EQ(error_of(time_literal("T#2147483648ms")),
            "TIME literal T#2147483648ms is outside TIME (T#0ms..T#24d20h31m23s647ms)");
  EXPECT_EQ(error_of(time_literal("T#9223372036854775807ms")),
            "TIME literal T#9223372036854775807ms is outside TIME (T#0ms..T#24d20h31m23s647ms)");
  for (const char* big : {"T#99999999999999999999999999d", "T#106751991167d", "T#24d20h31m24s",
                          "T#9223372036854775807d", "T#1000000000000000000000ns"})
    EXPECT_FALSE(time_literal(big)) << big;
}

TEST(Literal, DurationComponentsAsOtherFormatsWriteThem) {
  DurationLiteral d("'500ms'");
  ASSERT_TRUE(d.add("500", "", 1000000));
  EXPECT_EQ(*d.milliseconds(false), 500);
  DurationLiteral big("'3000000000s'");
  ASSERT_TRUE(big.add("3000000000", "", 1000000000));
  EXPECT_EQ(big.milliseconds(false).error,
            "TIME literal '3000000000s' is outside TIME (T#0ms..T#24d20h31m23s647ms)");
  EXPECT_EQ(time_text(90000), "T#1m30s");
  EXPECT_EQ(time_text(0), "T#0ms");
}

}  // namespace
}  // namespace sfcv::model
