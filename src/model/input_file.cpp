#include "model/input_file.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
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

/// SFCV_MAX_INPUT_BYTES (a number of bytes) lowers the cap, so that tests need not write a
/// gigabyte; it never raises it.
std::size_t input_cap(std::size_t max_bytes) {
  const char* env = std::getenv("SFCV_MAX_INPUT_BYTES");
  if (!env || !*env) return max_bytes;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(env, &end, 10);
  if (*end != '\0' || v == 0) return max_bytes;
  return std::min<std::size_t>(max_bytes, static_cast<std::size_t>(v));
}

/// A pipe or FIFO, read without blocking forever: a FIFO no one opens for writing within
/// `kWriterWait` is refused (an `open` would wait for a writer for ever), and once a writer is
/// there its data is read until it closes, up to the cap.
std::optional<std::string> read_pipe(const std::string& path, const std::string& what,
                                     std::string& text, std::size_t max_bytes) {
  constexpr auto kWriterWait = std::chrono::seconds(2);
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return "cannot open " + what + " (" + std::strerror(errno) + ")";
  const auto start = std::chrono::steady_clock::now();
  bool writer_seen = false;
  std::optional<std::string> failure;
  char block[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, block, sizeof block);
    if (n > 0) {
      writer_seen = true;
      text.append(block, static_cast<std::size_t>(n));
      if (text.size() > max_bytes) {
        failure = what + " is larger than the " + size_text(max_bytes) + " sfcv reads";
        break;
      }
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
      failure = "cannot read " + what + " (" + std::strerror(errno) + ")";
      break;
    }
    if (n < 0) writer_seen = true;     // EAGAIN: a writer holds the pipe open, no data yet
    if (n == 0 && writer_seen) break;  // end of file: the writer closed it
    if (n == 0 && std::chrono::steady_clock::now() - start > kWriterWait) {
      failure = what + " is a named pipe that no process writes to";
      break;
    }
    pollfd p{fd, POLLIN, 0};
    ::poll(&p, 1, n == 0 ? 10 : 100);  // no writer yet: poll returns at once, so sleep a bit
    if (n == 0) ::usleep(10000);
  }
  ::close(fd);
  return failure;
}

}  // namespace

std::optional<std::string> try_read_input_file(const std::string& path, const std::string& what,
                                               std::string& text, std::size_t max_bytes) {
  max_bytes = input_cap(max_bytes);
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return "cannot open " + what + " (" + std::strerror(errno) + ")";
  if (S_ISDIR(st.st_mode)) return what + " is a directory, not a file";
  if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode))
    return what + " is a device or socket, not a file";
  if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > max_bytes)
    return what + " has " + std::to_string(st.st_size) + " bytes, more than the " +
           size_text(max_bytes) + " sfcv reads";
  text.clear();
  if (S_ISFIFO(st.st_mode)) return read_pipe(path, what, text, max_bytes);
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
