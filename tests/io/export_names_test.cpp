// The model writers and names they cannot say (issue 53, item 6): IEC text has no quoted
// identifiers, so a name that is none is refused; PLCopen XML quotes every name in attributes
// but not in ST text; .g7 quotes names but cannot hold a line break. Never written so that the
// file reads back as something else.

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>

#include "io/g7_writer.hpp"
#include "io/iec_text_writer.hpp"
#include "io/load.hpp"
#include "io/plcopen_writer.hpp"
#include "io/st_names.hpp"
#include "model/errors.hpp"
#include "support/hostile_names.hpp"
#include "support/model_builder.hpp"

namespace sfcv::io {
namespace {

std::string refusal(const std::function<std::string()>& write) {
  try {
    write();
  } catch (const UnsupportedConstruct& e) {
    return e.what();
  }
  return "";
}

TEST(StNames, IdentifiersOnly) {
  EXPECT_TRUE(is_st_identifier("_a1"));
  EXPECT_TRUE(is_st_dotted_name("inst.Q"));
  for (const char* bad : {"", "1a", "a b", "x,y", "IF", "end_var", "a\nb", "a(*", "\xc3\xbc"})
    EXPECT_FALSE(is_st_identifier(bad)) << bad;
  EXPECT_FALSE(is_st_dotted_name("a..b"));
  EXPECT_FALSE(is_st_dotted_name("a.b c"));
}

// Every hostile name as a variable read by a transition: IEC text and PLCopen XML refuse it.
TEST(ExportNames, IecTextAndPlcopenRefuseANameInStText) {
  for (const auto& name : test::hostile_names()) {
    SCOPED_TRACE(name);
    if (is_st_identifier(name)) continue;  // MODULE, next, ...: IEC identifiers, written as such
    test::PouBuilder b("P");
    b.input(name, "BOOL");
    b.chart("main").initial("S1").step("S2").trans({"S1"}, {"S2"}, model::make_name(name));
    const auto project = b.project();
    const auto iec = refusal([&] { return write_iec_text(project); });
    EXPECT_NE(iec.find("is not an IEC identifier"), std::string::npos) << iec;
    const auto xml = refusal([&] { return write_plcopen_xml(project); });
    EXPECT_NE(xml.find("is not an IEC identifier"), std::string::npos) << xml;
  }
}

// Declared only (an attribute in PLCopen XML), a hostile name is written and read back as it is.
TEST(ExportNames, PlcopenKeepsAHostileNameInAnAttribute) {
  test::PouBuilder b("P");
  for (const auto& name : test::hostile_names()) b.var(name, "BOOL");
  b.input("go", "BOOL");
  b.chart("main").initial("S1").step("S2").trans({"S1"}, {"S2"}, model::make_name("go"));
  const auto xml = write_plcopen_xml(b.project());
  const auto back = load_plcopen_xml(xml, "back.xml");
  ASSERT_TRUE(back.ok());
  std::vector<std::string> names;
  for (const auto& v : back.project->pous.at(0).variables) names.push_back(v.name);
  // (The reader trims spaces around a name, as it does for every PLCopen name.)
  auto trimmed = [](std::string s) {
    s.erase(0, s.find_first_not_of(" \t\r\n"));
    s.erase(s.find_last_not_of(" \t\r\n") + 1);
    return s;
  };
  for (const auto& name : test::hostile_names())
    EXPECT_NE(std::find(names.begin(), names.end(), trimmed(name)), names.end()) << name;
}

// .g7: quoted names round-trip; a line break (the reader's quoted names are on one line) or
// an empty name is refused.
TEST(ExportNames, G7QuotesNamesAndRefusesLineBreaks) {
  test::PouBuilder b("G");
  b.input("a\"b\\c,d", "BOOL");
  b.chart("G0").initial("MODULE").step("x */ y").trans({"MODULE"}, {"x */ y"},
                                                       model::make_name("a\"b\\c,d"));
  const auto text = write_g7(b.project(model::Dialect::Grafcet));
  const auto back = load_g7(text, "back.g7");
  ASSERT_TRUE(back.ok()) << text;
  EXPECT_EQ(back.project->pous.at(0).variables.at(0).name, "a\"b\\c,d");
  EXPECT_EQ(back.project->pous.at(0).charts.at(0).steps.at(1).name, "x */ y");

  test::PouBuilder n("G");
  n.chart("G0").initial("one\nstep 2 initial");
  const auto why = refusal([&] { return write_g7(n.project(model::Dialect::Grafcet)); });
  EXPECT_NE(why.find("line break"), std::string::npos) << why;
}

}  // namespace
}  // namespace sfcv::io
