// `sfcv equiv --html FILE`: the equivalence result as one self-contained page, from the
// `sfcv equiv --json` document, with the check report's parts (html_page.hpp): the verdict per
// question and each counterexample side by side, a row per cycle with the inputs read, OLD's and
// NEW's active steps, and each compared signal as an OLD and a NEW column, red where they differ.

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "report/equivalence_render.hpp"
#include "report/html_page.hpp"
#include "report/markup.hpp"
#include "report/numbers.hpp"
#include "report/text_encoding.hpp"

namespace sfcv::report {

namespace {

using nlohmann::json;

std::string joined(const json& list, const char* sep) {
  std::string out;
  if (list.is_array())
    for (const auto& item : list)
      if (item.is_string()) out += (out.empty() ? "" : sep) + item.get<std::string>();
  return out;
}

std::string value_cell(const json& v) {
  if (v.is_null()) return "?";  // a compared signal its side never writes
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  return v.dump();
}

std::string signal_label(const json& compared) {
  const std::string o = json_text(compared, "old"), n = json_text(compared, "new");
  return o == n ? o : o + " / " + n;
}

/// The inputs a cycle read, as the text table writes them: `start`, `level=3`; "-" for none.
std::string inputs_cell(const json& cycle) {
  if (cycle.value("cycle", 0) == 0) return "(initial)";
  std::string out;
  for (const auto& [name, v] : cycle["inputs"].items())
    out += (out.empty() ? "" : " ") + (v == 1 ? name : name + "=" + v.dump());
  return out.empty() ? "-" : out;
}

/// One counterexample side by side.
std::string side_table(const json& trace, const json& compared, std::size_t result) {
  std::string head1 =
      "<tr><th rowspan=\"2\">cycle</th><th rowspan=\"2\">inputs</th>"
      "<th rowspan=\"2\" class=\"old\">OLD steps</th><th rowspan=\"2\">NEW steps</th>";
  std::string head2 = "<tr>";
  for (const auto& c : compared) {
    head1 += "<th colspan=\"2\" class=\"old\">" + html_escape(signal_label(c)) + "</th>";
    head2 += "<th class=\"old\">OLD</th><th>NEW</th>";
  }
  std::string rows;
  for (const auto& cycle : trace["cycles"]) {
    std::string row = "<tr><td>" + std::to_string(cycle.value("cycle", 0)) + "</td><td>" +
                      html_escape(inputs_cell(cycle)) + "</td><td class=\"old\">" +
                      html_escape(joined(cycle["old"]["steps"], ", ")) + "</td><td>" +
                      html_escape(joined(cycle["new"]["steps"], ", ")) + "</td>";
    for (const auto& c : compared) {
      const std::string o = json_text(c, "old"), n = json_text(c, "new");
      bool differs = false;
      for (const auto& d : cycle["differs"]) differs = differs || d == o;
      const auto& ov = cycle["old"]["signals"];
      const auto& nv = cycle["new"]["signals"];
      row += std::string(differs ? "<td class=\"old differs\">" : "<td class=\"old\">") +
             html_escape(value_cell(ov.contains(o) ? ov[o] : json())) + "</td>" +
             (differs ? "<td class=\"differs\">" : "<td>") +
             html_escape(value_cell(nv.contains(n) ? nv[n] : json())) + "</td>";
    }
    rows += row + "</tr>\n";
  }
  return "<div class=\"scroll\"><table class=\"summary side\" id=\"difference-" +
         std::to_string(result) + "\">\n" + head1 + "</tr>\n" + head2 + "</tr>\n" + rows +
         "</table></div>\n<p class=\"note\">Signals at the end of each cycle, OLD's then NEW's; "
         "red where they differ.</p>\n";
}

}  // namespace

std::string equivalence_html(const nlohmann::json& result_in) {
  json r = result_in;
  make_valid_utf8(r);  // names of the programs: bytes
  const std::string title = json_text(r, "old") + " vs " + json_text(r, "new");
  std::vector<std::pair<std::string, std::string>> nav = {{"verdicts", "Verdicts"}};
  const auto& results = r["results"];
  for (std::size_t i = 0; i < results.size(); ++i)
    if (results[i].contains("trace"))
      nav.emplace_back("trace-" + std::to_string(i),
                       "Difference: " + json_text(results[i], "signal"));
  std::string out = html_page_head("sfcv equiv: " + title) + html_page_nav(nav);
  out += "<h1>sfcv equiv: " + html_escape(title) + "</h1>\n<p class=\"meta\">" +
         html_verdict(json_text(r, "verdict")) + " &middot; " +
         html_escape(json_text(r, "engine")) + " engine";
  if (r.contains("seconds") && r["seconds"].is_number()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f s", r["seconds"].get<double>());
    out += std::string(" &middot; ") + buf;
  }
  if (r.value("within", 0) > 0)
    out += " &middot; NEW may lag by up to " + counted(r["within"].get<std::uint64_t>(), "cycle");
  out += "</p>\n<dl class=\"cycle\"><dt>compared (" + std::to_string(r["compared"].size()) +
         ")</dt><dd>";
  std::string names;
  for (const auto& c : r["compared"])
    names += (names.empty() ? "" : ", ") + std::string("<code>") + html_escape(signal_label(c)) +
             "</code>" + (c.value("internal", false) ? " (internal)" : "");
  out += names + "</dd><dt>shared inputs (" + std::to_string(r["shared_inputs"].size()) +
         ")</dt><dd>" + html_escape(joined(r["shared_inputs"], ", ")) + "</dd></dl>\n";
  for (const auto& n : r["notes"])
    out += "<p class=\"note\">note: " + html_escape(n.get<std::string>()) + "</p>\n";

  out +=
      "<h2 id=\"verdicts\">Verdicts</h2>\n<div class=\"scroll\"><table class=\"summary\" "
      "id=\"verdict-table\">\n<tr><th>compared</th><th>verdict</th><th>engine</th><th>time</th>"
      "<th>what was found</th></tr>\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& res = results[i];
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f s", res.value("seconds", 0.0));
    std::string what = html_escape(json_text(res, "message"));
    if (res.contains("trace"))
      what = "<a class=\"play\" href=\"#trace-" + std::to_string(i) + "\">differ after " +
             counted(res["trace"].value("length", 0ULL), "cycle") + "</a>";
    out += "<tr><td class=\"name\">" + html_escape(json_text(res, "signal")) + "</td><td>" +
           html_verdict(json_text(res, "verdict")) + "</td><td>" +
           html_escape(json_text(res, "engine")) + "</td><td class=\"time\">" + buf + "</td><td>" +
           what + "</td></tr>\n";
  }
  out += "</table></div>\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& res = results[i];
    if (!res.contains("trace")) continue;
    const auto& cycles = res["trace"]["cycles"];
    const std::string first =
        cycles.empty() ? std::string() : joined(cycles.back()["differs"], ", ");
    out += "<section id=\"trace-" + std::to_string(i) + "\">\n<h2>" +
           html_escape(json_text(res, "signal") == "all"
                           ? std::string("The first difference")
                           : "The first difference of " + json_text(res, "signal")) +
           ": " + html_escape(first) + " after " +
           counted(res["trace"].value("length", 0ULL), "cycle") + "</h2>\n" +
           side_table(res["trace"], r["compared"], i) + "</section>\n";
  }
  out += html_layout_probe() + "</body>\n</html>\n";
  return valid_utf8(out);
}

}  // namespace sfcv::report
