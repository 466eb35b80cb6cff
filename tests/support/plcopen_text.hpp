#pragma once
// Pieces of a small CODESYS-like PLCopen TC6 document, for e2e tests that write one: the
// document around the POUs, a variable section and an ST body.

#include <string>
#include <vector>

namespace sfcv::test {

inline const std::string kPlcopenHeader =
    "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">\n"
    "<fileHeader companyName=\"t\" productName=\"CODESYS\" productVersion=\"3.5\" "
    "creationDateTime=\"2024-01-01T00:00:00\"/>\n<contentHeader name=\"plant\"/>\n"
    "<types><dataTypes/><pous>\n";
inline const std::string kPlcopenFooter =
    "</pous></types>\n<instances><configurations/></instances>\n</project>\n";

/// `<section>` (e.g. "inputVars") declaring `names`, each of `type`.
inline std::string plcopen_vars(const std::string& section, const std::vector<std::string>& names,
                                const std::string& type = "<BOOL/>") {
  std::string s = "<" + section + ">";
  for (const auto& n : names)
    s += "<variable name=\"" + n + "\"><type>" + type + "</type></variable>";
  return s + "</" + section + ">";
}

/// An ST body element holding `text`.
inline std::string plcopen_st(const std::string& text) {
  return "<ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">" + text + "</xhtml></ST>";
}

}  // namespace sfcv::test
