#include "report/text_encoding.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sfcv::report {
namespace {

const std::string kFffd = "\xEF\xBF\xBD";  // U+FFFD, the replacement character

TEST(TextEncoding, ValidUtf8IsKeptAsIs) {
  for (const std::string s : {"", "S1", "caf\xC3\xA9", "\xE2\x82\xAC 5", "\xF0\x9F\x98\x80",
                              "\xED\x9F\xBF", "\xF4\x8F\xBF\xBF", "tab\there"}) {
    EXPECT_TRUE(is_valid_utf8(s)) << s;
    EXPECT_EQ(valid_utf8(s), s);
  }
}

TEST(TextEncoding, EachInvalidByteBecomesOneReplacementCharacter) {
  struct Case {
    std::string in, out;
  };
  const Case cases[] = {
      {"S\xFF"
       "1",
       "S" + kFffd + "1"},                // never a UTF-8 byte
      {"pl\xE4nt", "pl" + kFffd + "nt"},  // Latin-1
      {"\xC3", kFffd},                    // truncated at the end
      {"\xE2\x82"
       "x",
       kFffd + kFffd + "x"},                                // truncated before an ASCII byte
      {"\xC0\x80", kFffd + kFffd},                          // overlong NUL
      {"\xE0\x80\xAF", kFffd + kFffd + kFffd},              // overlong '/'
      {"\xED\xA0\x80", kFffd + kFffd + kFffd},              // a UTF-16 surrogate
      {"\xF4\x90\x80\x80", kFffd + kFffd + kFffd + kFffd},  // past U+10FFFF
      {"\x80"
       "a\xBF",
       kFffd + "a" + kFffd},  // continuation bytes alone
  };
  for (const auto& c : cases) {
    EXPECT_FALSE(is_valid_utf8(c.in)) << c.in;
    EXPECT_EQ(valid_utf8(c.in), c.out) << c.in;
    EXPECT_TRUE(is_valid_utf8(valid_utf8(c.in)));
  }
}

TEST(TextEncoding, XmlTextReplacesWhatXml10Excludes) {
  // XML 1.0 Char: tab, line feed, carriage return, U+0020 and above but U+FFFE and U+FFFF.
  EXPECT_EQ(xml_text("a\tb\nc\rd"), "a\tb\nc\rd");
  EXPECT_EQ(xml_text(std::string("a\0b", 3)), "a" + kFffd + "b");
  EXPECT_EQ(xml_text("bell\x07 esc\x1B"), "bell" + kFffd + " esc" + kFffd);
  EXPECT_EQ(xml_text("\xEF\xBF\xBE\xEF\xBF\xBF"), kFffd + kFffd);  // U+FFFE, U+FFFF
  EXPECT_EQ(xml_text("S\xFF"), "S" + kFffd);
  EXPECT_EQ(xml_text("caf\xC3\xA9 <&>"), "caf\xC3\xA9 <&>");  // escaping is the writer's job
}

TEST(TextEncoding, JsonStringsAndKeysBecomeValidSoTheDocumentDumps) {
  nlohmann::json j;
  j["name"] = "S\xFF";
  j["steps"] = nlohmann::json::array({"ok", "X\xC3"});
  j["values"]["in\xE4"] = 1;
  EXPECT_THROW((void)j.dump(), nlohmann::json::type_error);  // why every writer needs it
  make_valid_utf8(j);
  const auto text = j.dump();
  const auto back = nlohmann::json::parse(text);
  EXPECT_EQ(back["name"], "S" + kFffd);
  EXPECT_EQ(back["steps"][1], "X" + kFffd);
  EXPECT_EQ(back["values"]["in" + kFffd], 1);
  nlohmann::ordered_json o = {{"message", "step \xFF"}};
  make_valid_utf8(o);
  EXPECT_EQ(o["message"], "step " + kFffd);
}

}  // namespace
}  // namespace sfcv::report
