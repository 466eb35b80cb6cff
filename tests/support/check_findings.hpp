#pragma once
// Two engines' answers to one standard check: the same verdict, message and findings. A
// finding's situation ("... situation S0=1 ...") is the one each engine met first, so findings
// are compared up to their first "situation" and as a sorted list. Instability findings
// describe each engine's own anomaly data (the explicit one lists each event, the BDD one each
// kind): only their verdict is compared.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "logic/check_result.hpp"

namespace sfcv::test {

inline std::vector<std::string> findings_without_situations(const logic::PropertyResult& r) {
  std::vector<std::string> out;
  for (const auto& f : r.findings) out.push_back(f.substr(0, f.find("situation")));
  std::sort(out.begin(), out.end());
  return out;
}

inline void expect_same_check(const logic::PropertyResult& a, const logic::PropertyResult& b) {
  SCOPED_TRACE("check " + a.name);
  EXPECT_EQ(a.verdict, b.verdict);
  if (a.check == "instability") return;
  EXPECT_EQ(a.findings_total, b.findings_total);
  EXPECT_EQ(a.message, b.message);
  EXPECT_EQ(findings_without_situations(a), findings_without_situations(b));
  EXPECT_EQ(a.trace.has_value(), b.trace.has_value());
}

}  // namespace sfcv::test
