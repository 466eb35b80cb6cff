#include "cli/diagnostic_lines.hpp"

#include <ostream>
#include <string>

#include "cli/commands.hpp"
#include "report/concise_text.hpp"

namespace sfcv::cli {

namespace {
constexpr std::size_t kNotesShown = 3;    ///< notes in short before the rest are counted
constexpr std::size_t kNoteLength = 200;  ///< characters of a note's line in short
}  // namespace

void print_diagnostic_lines(const model::Diagnostics& diagnostics, bool quiet, std::ostream& err) {
  const bool verbose = global_options().verbose;
  const auto cwd = report::working_directory();
  std::size_t notes = 0, hidden = 0;
  for (const auto& d : diagnostics) {
    if (d.severity == model::Severity::Error) {
      err << d.str() << "\n";
      continue;
    }
    if (quiet) continue;
    if (verbose) {
      err << d.str() << "\n";
      continue;
    }
    std::string line = report::concise_text(d.str(), cwd);
    if (d.severity == model::Severity::Note) {
      if (++notes > kNotesShown) {
        ++hidden;
        continue;
      }
      if (line.size() > kNoteLength) line = line.substr(0, kNoteLength - 3) + "...";
    }
    err << line << "\n";
  }
  if (hidden > 0)
    err << "sfcv: " << hidden << (hidden == 1 ? " more note" : " more notes")
        << " (--verbose prints every note in full; 'sfcv lint' and 'sfcv info' list them)\n";
}

}  // namespace sfcv::cli
