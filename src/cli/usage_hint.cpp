#include "cli/usage_hint.hpp"

#include <CLI/CLI.hpp>

#include "model/suggest.hpp"

namespace sfcv::cli {

namespace {

std::vector<std::string> long_options(const CLI::App& app) {
  std::vector<std::string> names;
  for (const auto* o : app.get_options())
    for (const auto& n : o->get_lnames()) names.push_back("--" + n);
  return names;
}

bool is_option_of(const CLI::App& app, const std::string& word) {
  for (const auto& n : long_options(app))
    if (n == word) return true;
  return false;
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const auto& w : words) text += (text.empty() ? "" : ", ") + w;
  return text;
}

}  // namespace

std::optional<std::string> usage_hint(const CLI::App& app, const std::vector<std::string>& args) {
  std::vector<std::string> commands;
  for (const auto* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    commands.push_back(sub->get_name());
  const CLI::App* sub = nullptr;
  for (const auto& word : args) {
    if (word == "--") break;
    if (word.rfind("-", 0) == 0) {
      if (word.rfind("--", 0) != 0) continue;  // short flags: CLI11's message is clear
      const std::string name = word.substr(0, word.find('='));
      if (is_option_of(app, name) || (sub && is_option_of(*sub, name))) continue;
      auto known = long_options(app);
      if (sub)
        for (auto& n : long_options(*sub)) known.push_back(n);
      const auto guess = model::closest_name(name, known);
      const std::string where = sub ? "sfcv " + sub->get_name() : std::string("sfcv");
      return "unknown option '" + name + "' of " + where +
             (guess.empty() ? " (see " + where + " --help)" : ": did you mean '" + guess + "'?");
    }
    if (sub) continue;  // operands of the subcommand
    for (const auto& c : commands)
      if (c == word) sub = app.get_subcommand(c);
    if (sub) continue;
    const auto guess = model::closest_name(word, commands);
    return "unknown subcommand '" + word + "'" +
           (guess.empty() ? " (the subcommands: " + joined(commands) + ")"
                          : ": did you mean '" + guess + "'?");
  }
  return std::nullopt;
}

}  // namespace sfcv::cli
