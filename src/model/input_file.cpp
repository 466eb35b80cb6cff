#include "model/input_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "model/errors.hpp"
#include "model/source_location.hpp"

namespace sfcv::model {

namespace {

std::string size_text(std::size_t bytes) {
  return bytes % (std::size_t{1} << 30) == 0 ? std::to_string(bytes >> 30) + " GiB"
                                             : std::to_string(bytes) + " bytes";
}

}  // namespace

std::optional<std::string> try_read_input_file(const std::string& path, const std::string& what,
                                               std::string& text, std::size_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return "cannot open " + what + " (" + std::strerror(errno) + ")";
  if (S_ISDIR(st.st_mode)) return what + " is a directory, not a file";
  if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode))
    return what + " is a device or socket, not a file";
  if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > max_bytes)
    return what + " has " + std::to_string(st.st_size) + " bytes, more than the " +
           size_text(max_bytes) + " sfcv reads";
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot open " + what;
  // Read in blocks, so that a pipe (whose size is not known ahead) also stops at the cap.
  text.clear();
  if (S_ISREG(st.st_mode)) text.reserve(static_cast<std::size_t>(st.st_size));
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    text.append(block, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes)
      return what + " is larger than the " + size_text(max_bytes) + " sfcv reads";
  }
  if (in.bad()) return "cannot read " + what;
  return std::nullopt;
}

std::string read_input_file(const std::string& path, const std::string& what,
                            std::size_t max_bytes) {
  std::string text;
  if (auto reason = try_read_input_file(path, what, text, max_bytes)) {
    SourceLocation where;
    where.file = path;
    throw InputError(*reason, where);
  }
  return text;
}

}  // namespace sfcv::model
