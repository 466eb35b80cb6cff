#pragma once
// Print / re-load round trips shared by the io tests: print a model with a writer, load the
// text with the matching importer, and compare with model::first_difference.

#include <gtest/gtest.h>

#include <string>

#include "io/iec_text_writer.hpp"
#include "io/load.hpp"
#include "io/plcopen_writer.hpp"
#include "model/compare.hpp"

namespace sfcv::test {

inline std::string diagnostics_text(const model::Diagnostics& d) {
  std::string s;
  for (const auto& x : d) s += x.str() + "\n";
  return s;
}

/// Loads `text` with `load`, expects no error and no difference from `p`; returns `text`.
template <class Load>
std::string expect_reloads_equal(const model::Project& p, const std::string& text, Load load,
                                 const std::string& file) {
  const io::LoadResult again = load(text, file, nullptr);  // no budget
  EXPECT_TRUE(again.ok()) << diagnostics_text(again.diagnostics) << text;
  if (!again.project) return text;
  const auto diff = model::first_difference(p, *again.project);
  EXPECT_FALSE(diff.has_value()) << *diff << "\n" << text;
  return text;
}

/// IEC 61131-3 text round trip; returns the printed text.
inline std::string iec_round_trip(const model::Project& p) {
  return expect_reloads_equal(p, io::write_iec_text(p), io::load_iec_text, "printed.sfc");
}

/// PLCopen TC6 XML round trip; returns the printed document.
inline std::string plcopen_round_trip(const model::Project& p) {
  return expect_reloads_equal(p, io::write_plcopen_xml(p), io::load_plcopen_xml, "printed.xml");
}

}  // namespace sfcv::test
