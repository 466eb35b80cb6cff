#pragma once
// How far a random sweep goes. The release build runs each sweep's full range; a build under
// AddressSanitizer, whose engines run 5 to 8 times slower, runs its first quarter: the seeds'
// residues still choose every feature a sweep makes, and CI's sanitizer pass stays within its
// time (docs/reliability.md, "CI time").

#include <algorithm>
#include <cstdint>

namespace sfcv::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr std::uint64_t kSweepDivisor = 4;
#else
inline constexpr std::uint64_t kSweepDivisor = 1;
#endif

/// The last seed of a sweep whose full range is 1..`full_last`.
constexpr std::uint64_t sweep_last(std::uint64_t full_last) {
  return std::max<std::uint64_t>(1, full_last / kSweepDivisor);
}

/// A floor the full sweep of `full_seeds` seeds passes, for a sweep of its first `seeds_run`:
/// in proportion, and four fifths of that for a part (the first seeds make smaller charts, with
/// fewer answers of each kind: the first quarter of the random grafcets gives 116 traces, a
/// quarter of the full floor being 125).
constexpr double sweep_floor(double full_floor, std::uint64_t seeds_run, std::uint64_t full_seeds) {
  const double share = static_cast<double>(seeds_run) / static_cast<double>(full_seeds);
  return full_floor * share * (seeds_run < full_seeds ? 0.8 : 1.0);
}

}  // namespace sfcv::test
