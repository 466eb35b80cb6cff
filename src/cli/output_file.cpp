#include "cli/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/exit_code.hpp"
#include "cli/interrupt.hpp"

namespace sfcv::cli {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const OutputPath& out, const std::string& why) {
  throw UsageError(out.option + " " + out.path + ": " + why);
}

std::string error_text(int error) {
  return error ? std::string(std::strerror(error)) : std::string("write error");
}

/// How a path is written. Atomic: a regular file (new or existing), replaced by a rename.
/// Direct: a file that cannot be renamed over (a device, a FIFO, anything under /dev or /proc).
enum class Kind { StandardOutput, StandardError, Direct, Atomic };

struct Target {
  Kind kind = Kind::Atomic;
  fs::path file;  ///< Atomic: the file replaced (a symbolic link's target: the link stays)
};

bool under_system_folder(const std::string& path) {
  return path.rfind("/dev/", 0) == 0 || path.rfind("/proc/", 0) == 0;
}

Target resolve(const OutputPath& out) {
  if (out.path == "-" || out.path == "/dev/stdout") return {Kind::StandardOutput, {}};
  if (out.path == "/dev/stderr") return {Kind::StandardError, {}};
  const fs::path path(out.path);
  std::error_code ec;
  const auto status = fs::status(path, ec);  // follows symbolic links
  if (fs::exists(status)) {
    if (fs::is_directory(status)) fail(out, "is a directory");
    if (!fs::is_regular_file(status) || under_system_folder(out.path)) return {Kind::Direct, path};
    const auto real = fs::canonical(path, ec);
    if (ec) fail(out, "cannot resolve the path: " + ec.message());
    return {Kind::Atomic, real};
  }
  if (fs::is_symlink(fs::symlink_status(path, ec)))
    fail(out, "is a symbolic link to a file that does not exist");
  return {Kind::Atomic, path};
}

fs::path folder_of(const fs::path& file) {
  return file.has_parent_path() ? file.parent_path() : fs::path(".");
}

void check_writable(const OutputPath& out, const Target& target) {
  if (target.kind == Kind::StandardOutput || target.kind == Kind::StandardError) return;
  if (target.kind == Kind::Direct) {
    if (::access(target.file.c_str(), W_OK) != 0) fail(out, "not writable: " + error_text(errno));
    return;
  }
  const auto folder = folder_of(target.file);
  std::error_code ec;
  const auto status = fs::status(folder, ec);
  if (!fs::exists(status)) fail(out, "the directory " + folder.string() + " does not exist");
  if (!fs::is_directory(status)) fail(out, folder.string() + " is not a directory");
  // The temporary file is created there, then renamed: the directory must be writable.
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    fail(out, "the directory " + folder.string() + " is not writable: " + error_text(errno));
  if (fs::exists(target.file, ec) && ::access(target.file.c_str(), W_OK) != 0)
    fail(out, "not writable: " + error_text(errno));
}

/// Writes all of `text` to `fd`; false with errno set on an error.
bool write_all(int fd, const std::string& text) {
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const auto n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

void write_stream(const OutputPath& out, std::ostream& stream, std::FILE* file,
                  const std::string& text) {
  errno = 0;
  stream << text;
  stream.flush();
  int error = errno;
  if (std::fflush(file) != 0 && !error) error = errno;
  if (!stream || std::ferror(file)) fail(out, "cannot write: " + error_text(error));
}

void write_direct(const OutputPath& out, const fs::path& file, const std::string& text) {
  // O_APPEND: a /dev/fd/N or /proc/self/fd/N that is a regular file is not truncated from its
  // start; for devices and FIFOs it changes nothing.
  const int fd = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd < 0) fail(out, "cannot open: " + error_text(errno));
  const bool written = write_all(fd, text);
  const int write_error = errno;
  if (!written) {
    ::close(fd);
    fail(out, "cannot write: " + error_text(write_error));
  }
  if (::close(fd) != 0) fail(out, "cannot write: " + error_text(errno));
}

/// The mode a new file gets from open(): 0666 less the umask.
mode_t new_file_mode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return static_cast<mode_t>(0666 & ~mask);
}

/// The temporary file of write_atomic: removed unless renamed, and by the signal handler if a
/// signal ends the process while it exists.
class TemporaryFile {
 public:
  explicit TemporaryFile(const fs::path& target)
      : name_(folder_of(target) / ("." + target.filename().string() + ".sfcv-XXXXXX")) {
    const auto text = name_.string();
    buffer_.assign(text.begin(), text.end());
    buffer_.push_back('\0');
    guard_temporary_file(buffer_.data());
    fd_ = ::mkstemp(buffer_.data());
    created_ = fd_ >= 0;
  }
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (created_ && !renamed_) ::unlink(buffer_.data());
    release_temporary_file();
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  int fd() const { return fd_; }
  const char* path() const { return buffer_.data(); }
  /// Closes the file; false with errno set on an error (a delayed write error shows here).
  bool close() {
    const int fd = fd_;
    fd_ = -1;
    return ::close(fd) == 0;
  }
  void renamed() { renamed_ = true; }

 private:
  fs::path name_;
  std::vector<char> buffer_;
  int fd_ = -1;
  bool created_ = false;
  bool renamed_ = false;
};

void write_atomic(const OutputPath& out, const fs::path& target, const std::string& text) {
  struct stat existing {};
  const bool exists = ::stat(target.c_str(), &existing) == 0;
  TemporaryFile temp(target);
  if (temp.fd() < 0)
    fail(out, "cannot create a temporary file in " + folder_of(target).string() + ": " +
                  error_text(errno));
  // mkstemp's files are private (0600): give the file the mode the target had, or would get.
  const mode_t mode = exists ? static_cast<mode_t>(existing.st_mode & 07777) : new_file_mode();
  if (!write_all(temp.fd(), text)) fail(out, "cannot write: " + error_text(errno));
  if (::fchmod(temp.fd(), mode) != 0) fail(out, "cannot set the mode: " + error_text(errno));
  // On disk before the rename, so that a crash leaves the old file or the new one, whole.
  if (::fsync(temp.fd()) != 0) fail(out, "cannot write: " + error_text(errno));
  if (!temp.close()) fail(out, "cannot write: " + error_text(errno));
  if (std::rename(temp.path(), target.c_str()) != 0)
    fail(out, "cannot rename " + std::string(temp.path()) + " to it: " + error_text(errno));
  temp.renamed();
}

}  // namespace

void check_output_paths(const std::vector<OutputPath>& outputs) {
  std::vector<std::pair<fs::path, const OutputPath*>> files;
  for (const auto& out : outputs) {
    if (out.path.empty()) continue;
    const auto target = resolve(out);
    check_writable(out, target);
    if (target.kind != Kind::Atomic) continue;
    std::error_code ec;
    // Absolute first: weakly_canonical leaves a relative path whose folder is "." as it is.
    auto same = fs::weakly_canonical(fs::absolute(target.file, ec), ec);
    if (ec) same = target.file.lexically_normal();
    for (const auto& [file, other] : files)
      if (file == same) fail(out, "is also the file of " + other->option);
    files.emplace_back(same, &out);
  }
}

void write_output(const OutputPath& out, const std::string& text) {
  const auto target = resolve(out);
  switch (target.kind) {
    case Kind::StandardOutput:
      write_stream(out, std::cout, stdout, text);
      return;
    case Kind::StandardError:
      write_stream(out, std::cerr, stderr, text);
      return;
    case Kind::Direct:
      write_direct(out, target.file, text);
      return;
    case Kind::Atomic:
      check_writable(out, target);  // the directory may have gone during the run
      write_atomic(out, target.file, text);
      return;
  }
}

void flush_standard_output() {
  errno = 0;
  std::cout.flush();  // through stdout's buffer: its error, if any, sets errno here
  int error = errno;
  if (std::fflush(stdout) != 0 && !error) error = errno;
  if (!std::cout || std::ferror(stdout))
    throw UsageError("cannot write standard output" +
                     (error ? ": " + std::string(std::strerror(error)) : std::string()));
}

}  // namespace sfcv::cli
