#include "cli/action_order.hpp"

#include <cctype>
#include <fstream>
#include <sstream>

#include "model/errors.hpp"

namespace sfcv::cli {

namespace {

bool name_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  return std::isalnum(u) || c == '_' || c == '.';
}

}  // namespace

std::vector<semantics::ActionPair> parse_action_pairs(const std::string& text,
                                                      const std::string& file) {
  std::vector<semantics::ActionPair> out;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    auto at = [&](std::size_t col) {
      model::SourceLocation w;
      w.file = file;
      w.line = number;
      w.column = static_cast<int>(col) + 1;
      return w;
    };
    // One chain `A < B < C` per line: the pairs A < B and B < C.
    std::string prev;
    model::SourceLocation prev_at;
    std::size_t i = 0;
    bool expect_name = true;
    int names = 0;
    while (true) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      if (i >= line.size() || line[i] == '#' || line.compare(i, 2, "//") == 0) break;
      if (expect_name) {
        const auto start = i;
        while (i < line.size() && name_char(line[i])) ++i;
        if (i == start)
          throw InputError(std::string("expected an action name, found '") + line[start] + "'",
                           at(start));
        const auto name = line.substr(start, i - start);
        if (!prev.empty()) out.push_back({prev, name, prev_at});
        prev = name;
        prev_at = at(start);
        ++names;
        expect_name = false;
      } else {
        if (line[i] != '<')
          throw InputError(std::string("expected '<' between two actions, found '") + line[i] + "'",
                           at(i));
        ++i;
        expect_name = true;
      }
    }
    if (expect_name && !prev.empty())
      throw InputError("expected an action name after '<'", at(line.size()));
    if (names == 1) throw InputError("expected 'A < B': a line names one action only", prev_at);
  }
  return out;
}

void parse_action_order(const std::string& value, semantics::Iec61131Options& options) {
  options.action_pairs.clear();
  if (value.empty() || value == "declaration") {
    options.action_order = semantics::ActionOrder::Declaration;
  } else if (value == "alphabetical") {
    options.action_order = semantics::ActionOrder::Alphabetical;
  } else if (value == "unordered") {
    options.action_order = semantics::ActionOrder::Unordered;
  } else {
    std::ifstream f(value, std::ios::binary);
    if (!f)
      throw InputError("--action-order: '" + value +
                       "' is neither declaration, alphabetical, unordered nor a readable file");
    std::ostringstream text;
    text << f.rdbuf();
    options.action_order = semantics::ActionOrder::Partial;
    options.action_pairs = parse_action_pairs(text.str(), value);
  }
}

}  // namespace sfcv::cli
