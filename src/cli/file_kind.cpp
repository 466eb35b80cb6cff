#include "cli/file_kind.hpp"

#include <sys/stat.h>

#include <cctype>
#include <fstream>

#include "cli/exit_code.hpp"

namespace sfcv::cli {

namespace {

bool starts_with_nocase(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
  return true;
}

std::string_view skip_space(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
    text.remove_prefix(1);
  return text;
}

bool contains(std::string_view text, std::string_view part) {
  return text.find(part) != std::string_view::npos;
}

/// JSON: an object whose first key is quoted, or an array. An IEC pragma `{attribute ...}` also
/// starts with a brace, but never with a quote after it.
bool looks_like_json(std::string_view text) {
  if (text.empty() || (text.front() != '{' && text.front() != '[')) return false;
  const auto rest = skip_space(text.substr(1));
  if (text.front() == '{') return !rest.empty() && (rest.front() == '"' || rest.front() == '}');
  return !rest.empty() &&
         (rest.front() == '{' || rest.front() == '"' || rest.front() == ']' || rest.front() == '[');
}

}  // namespace

std::optional<std::string> foreign_file_kind(std::string_view head) {
  if (head.rfind("\xEF\xBB\xBF", 0) == 0) head.remove_prefix(3);  // a UTF-8 byte order mark
  const auto text = skip_space(head);
  if (looks_like_json(text)) {
    if (contains(text, "sarif") || (contains(text, "\"runs\"") && contains(text, "\"version\"")))
      return "a SARIF log";
    if (contains(text, "\"results\"") || contains(text, "\"engine\""))
      return "a JSON result of 'sfcv check --json' ('sfcv report FILE --html OUT' draws it)";
    return "a JSON file";
  }
  // VCD: its sections are keywords that start with '$' ($date, $version, $timescale, $scope).
  if (!text.empty() && text.front() == '$') return "a VCD waveform";
  if (starts_with_nocase(text, "<!doctype html") || starts_with_nocase(text, "<html"))
    return "an HTML page";
  if (starts_with_nocase(text, "<?xml")) {
    const auto root = text.find('<', 1);
    if (root != std::string_view::npos) {
      auto after = text.substr(root);
      // Skip comments and processing instructions before the root element.
      while (after.rfind("<!--", 0) == 0 || after.rfind("<?", 0) == 0) {
        const auto next = after.find('<', 1);
        if (next == std::string_view::npos) break;
        after = after.substr(next);
      }
      if (after.rfind("<testsuites", 0) == 0 || after.rfind("<testsuite", 0) == 0)
        return "a JUnit XML report";
      if (starts_with_nocase(after, "<!doctype html") || starts_with_nocase(after, "<html"))
        return "an HTML page";
      if (after.rfind("<svg", 0) == 0) return "an SVG image";
    }
  }
  return std::nullopt;
}

void refuse_foreign_file(const std::string& path) {
  // Regular files only: reading a pipe's head would take it from the loader, and opening a
  // FIFO without a writer blocks (the loader refuses those, model/input_file.hpp).
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
  std::ifstream in(path, std::ios::binary);
  if (!in) return;
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (const auto kind = foreign_file_kind(head))
    throw InputError(path + ": this is " + *kind +
                     ", not a model (expected PLCopen XML, IEC 61131-3 text, .g7 or AGRAFE "
                     ".grafcet)");
}

}  // namespace sfcv::cli
