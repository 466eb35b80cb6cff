#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// What this binary is: `sfcv --version` and the provenance every report of a run carries
// (report/provenance.hpp), filled from the command line.

#include <string>
#include <vector>

#include "report/provenance.hpp"

namespace sfcv::cli {

/// The BuDDy and CaDiCaL versions this binary was built with: {"buddy", "2.4"}, ...
report::Settings library_versions();

/// `sfcv --version`: "sfcv 0.1.0" then the commit and the libraries, one per line.
std::string version_text();

/// The provenance of this run: version, commit, libraries, the command line (argv as given),
/// now; the command fills in its inputs, engine and settings.
report::Provenance run_provenance();

}  // namespace sfcv::cli
