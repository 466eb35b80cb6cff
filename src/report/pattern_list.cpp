#include "report/pattern_list.hpp"

#include <nlohmann/json.hpp>

namespace sfcv::report {

std::string pattern_list_text(const std::vector<logic::PatternInfo>& catalogue) {
  std::string out =
      "Requirement patterns (--pattern 'NAME(ARGS)', or 'pattern name: NAME(ARGS);' in a "
      "--spec file; cookbook: docs/properties.md)\n";
  bool dwyer_heading = false;
  out += "\nCycle templates (the values at the end of each PLC cycle):\n";
  for (const auto& p : catalogue) {
    if (p.scoped && !dwyer_heading) {
      out +=
          "\nDwyer's patterns, with an optional last argument that scopes them:\n"
          "  globally (default) | before R | after Q | between Q and R | after Q until R\n";
      dwyer_heading = true;
    }
    out += "\n  " + std::string(p.name) + "(" + std::string(p.arguments) +
           (p.bounded  ? "[, scope | within N cycles | within T ms|s]"
            : p.scoped ? "[, scope]"
                       : "") +
           ")\n";
    out += "    " + std::string(p.english) + "\n";
    out += "    " + std::string(p.formula) + "\n";
  }
  out +=
      "\nA[x W y] is the weak until: x holds until y, or for ever. A bound in time needs "
      "--time discrete (cycles of --cycle).\n";
  return out;
}

std::string pattern_list_json(const std::vector<logic::PatternInfo>& catalogue) {
  using nlohmann::json;
  static const std::pair<const char*, const char*> plcverif[] = {
      {"pattern-invariant", "always"},
      {"pattern-forbidden", "never"},
      {"pattern-implication", "implies"},
      {"pattern-statechange-duringcycle", "statechange_duringcycle"},
      {"pattern-statechange-betweencycles", "between_cycles"},
      {"pattern-reachability", "reachable"},
      {"pattern-repeatability", "repeatable"},
      {"pattern-leadsto", "leadsto"}};
  static const std::pair<const char*, const char*> esbmc[] = {{"mutual_exclusion", "never"},
                                                              {"invariant", "always"},
                                                              {"absence", "never"},
                                                              {"reachability", "reachable"},
                                                              {"response", "response"}};
  json patterns = json::array();
  for (const auto& p : catalogue) {
    json e;
    e["name"] = p.name;
    json params = json::array();
    std::string args(p.arguments);
    for (std::size_t i = 0; i < args.size(); i += 3) params.push_back(args.substr(i, 1));
    e["parameters"] = params;
    e["english"] = p.english;
    e["formula"] = p.formula;
    e["logic"] = "CTL";
    e["scoped"] = p.scoped;
    e["bounded"] = p.bounded;
    json ids = json::array(), kinds = json::array();
    for (const auto& [id, name] : plcverif)
      if (p.name == name) ids.push_back(id);
    for (const auto& [kind, name] : esbmc)
      if (p.name == name) kinds.push_back(kind);
    if (!ids.empty()) e["plcverif_pattern_ids"] = ids;
    if (!kinds.empty()) e["esbmc_kinds"] = kinds;
    e["usage"] = std::string(p.name) + "(" + std::string(p.arguments) + ")";
    patterns.push_back(std::move(e));
  }
  json out;
  out["patterns"] = patterns;
  out["scopes"] =
      json::array({"globally", "before R", "after Q", "between Q and R", "after Q until R"});
  out["bounds"] = json::array({"within N cycles", "within T ms", "within T s"});
  out["arguments"] =
      "propositional formulas: & | ! -> <-> xor, AND OR XOR NOT, comparisons = <> != < <= > >= "
      "of expressions with + - * / MOD, prev() rise() fall() (docs/properties.md)";
  return out.dump(2) + "\n";
}

}  // namespace sfcv::report
