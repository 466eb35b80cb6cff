#include "report/concise_text.hpp"

#include <cctype>
#include <filesystem>

namespace sfcv::report {

namespace {

/// The end (one past ')') of an XML element path that starts at `open` ('('), or npos.
std::size_t element_path_end(std::string_view text, std::size_t open) {
  if (open + 2 >= text.size() || text[open + 1] != '/' ||
      !std::isalpha(static_cast<unsigned char>(text[open + 2])))
    return std::string_view::npos;
  char quote = 0;
  int depth = 0;
  for (std::size_t i = open; i < text.size(); ++i) {
    const char c = text[i];
    if (quote) {
      if (c == quote) quote = 0;
      continue;
    }
    // A space outside quotes: words or a file location ("/a/b.xml:3:4 (/project...)"), not
    // an element path (which has spaces only inside its quoted names).
    if (c == ' ' || c == '\n') return std::string_view::npos;
    if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '(') {
      ++depth;
    } else if (c == ')' && --depth == 0) {
      return i + 1;
    }
  }
  return std::string_view::npos;
}

}  // namespace

std::string concise_text(std::string_view text, std::string_view cwd) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == ' ' && i + 1 < text.size() && text[i + 1] == '(') {
      const auto end = element_path_end(text, i + 1);
      if (end != std::string_view::npos) {
        i = end;
        continue;
      }
    }
    if (text[i] == '(') {  // "(/project...)" right after a location, without a space
      const auto end = element_path_end(text, i);
      if (end != std::string_view::npos && i > 0 && text[i - 1] != ' ') {
        i = end;
        continue;
      }
    }
    // The working folder followed by a slash: a path below it, written relative.
    if (!cwd.empty() && text.compare(i, cwd.size(), cwd) == 0 && i + cwd.size() < text.size() &&
        text[i + cwd.size()] == '/' &&
        (i == 0 || text[i - 1] == ' ' || text[i - 1] == '(' || text[i - 1] == '\'' ||
         text[i - 1] == '\n')) {
      i += cwd.size() + 1;
      continue;
    }
    out += text[i++];
  }
  return out;
}

std::string working_directory() {
  std::error_code ec;
  const auto cwd = std::filesystem::current_path(ec);
  if (ec) return {};
  auto text = cwd.string();
  if (text == "/") return {};  // every absolute path would lose its first slash
  return text;
}

}  // namespace sfcv::report
