#include "report/pattern_list.hpp"

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

}  // namespace sfcv::report
