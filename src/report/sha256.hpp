#pragma once
// SHA-256 (FIPS 180-4), for the input files' digests in the provenance of every report. Written
// here rather than linked from a crypto library: it is used for identification, not security,
// and one small function keeps the dependency list short.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace sfcv::report {

class Sha256 {
 public:
  Sha256();
  void update(std::string_view bytes);
  /// The digest of everything updated so far; the object is spent afterwards.
  std::array<std::uint8_t, 32> finish();

 private:
  void block(const std::uint8_t* p);
  std::array<std::uint32_t, 8> h_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t length_ = 0;  ///< bytes
};

/// The digest of `bytes` as 64 lower-case hex digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace sfcv::report
