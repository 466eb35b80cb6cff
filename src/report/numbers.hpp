#pragma once
// Numbers in text for people: counts grouped by thousands ("12,036,255,745 states") or, past a
// trillion, in scientific notation ("3.5·10^13 states"); singular and plural ("1 situation").

#include <cstdint>
#include <string>
#include <string_view>

namespace sfcv::report {

/// A count written as decimal digits ("65970697666560", any length): grouped by thousands below
/// 10^12 ("1,080,754,177"), else two significant digits and a power of ten ("6.6·10^13"). Other
/// text is returned as it is.
std::string count_text(std::string_view decimal);
std::string count_text(std::uint64_t n);

/// "1 situation", "2 situations", "1,024 states": the count and the word, singular for one.
std::string counted(std::uint64_t n, std::string_view singular, std::string_view plural = {});
std::string counted(std::string_view decimal, std::string_view singular,
                    std::string_view plural = {});

}  // namespace sfcv::report
