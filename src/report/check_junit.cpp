#include "report/check_junit.hpp"

#include <cstdio>
#include <filesystem>
#include <pugixml.hpp>
#include <sstream>

#include "report/text_encoding.hpp"
#include "report/trace_render.hpp"

namespace sfcv::report {

namespace {

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6f", s);
  return buf;
}

/// The body of a failure or error: what was found, then the trace as a table.
std::string details(const logic::PropertyResult& r, const semantics::TransitionSystem& ts) {
  std::string out;
  if (!r.formula.empty()) out += "formula: " + r.formula + "\n";
  if (!r.message.empty()) out += r.message + "\n";
  for (const auto& f : r.findings) out += "- " + f + "\n";
  if (const auto cut = findings_cut_note(r); !cut.empty()) out += "(" + cut + ")\n";
  if (r.trace) {
    const bool cex = r.trace->kind == logic::TraceKind::Counterexample;
    out += std::string(cex ? "counterexample" : "witness") + " (" +
           std::to_string(r.trace->steps.size()) + " situations):\n" + trace_table(*r.trace, ts);
  }
  return out;
}

}  // namespace

std::string check_junit(const logic::CheckReport& report, const semantics::TransitionSystem& ts,
                        const RenderOptions& options) {
  std::size_t failures = 0, errors = 0, skipped = 0;
  for (const auto& r : report.results) {
    failures += r.verdict == logic::Verdict::Violated;
    // Not checked counts as unknown (an error, as in the exit code); a question without
    // meaning on the system is skipped.
    errors += r.verdict == logic::Verdict::Unknown || r.verdict == logic::Verdict::NotChecked;
    skipped += r.verdict == logic::Verdict::NotApplicable;
  }
  const std::string suite = options.model.empty()
                                ? std::string("sfcv")
                                : std::filesystem::path(options.model).filename().string();
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  auto suites = doc.append_child("testsuites");
  suites.append_attribute("name") = "sfcv check";
  suites.append_attribute("tests") = static_cast<unsigned long long>(report.results.size());
  suites.append_attribute("failures") = static_cast<unsigned long long>(failures);
  suites.append_attribute("errors") = static_cast<unsigned long long>(errors);
  suites.append_attribute("skipped") = static_cast<unsigned long long>(skipped);
  suites.append_attribute("time") = seconds(report.seconds).c_str();
  auto ts_node = suites.append_child("testsuite");
  ts_node.append_attribute("name") = xml_text(suite).c_str();
  ts_node.append_attribute("tests") = static_cast<unsigned long long>(report.results.size());
  ts_node.append_attribute("failures") = static_cast<unsigned long long>(failures);
  ts_node.append_attribute("errors") = static_cast<unsigned long long>(errors);
  ts_node.append_attribute("skipped") = static_cast<unsigned long long>(skipped);
  ts_node.append_attribute("time") = seconds(report.seconds).c_str();
  auto props = ts_node.append_child("properties");
  auto property = [&props](const char* name, const std::string& value) {
    auto p = props.append_child("property");
    p.append_attribute("name") = name;
    p.append_attribute("value") = xml_text(value).c_str();
  };
  property("model", options.model);
  property("semantics", options.semantics);
  property("engine", report.engine);
  if (report.states_known) property("states", report.states.str());  // SAT engines count none
  property("complete", report.complete ? "true" : "false");
  if (!report.complete) property("limit", report.limit);

  for (const auto& r : report.results) {
    auto tc = ts_node.append_child("testcase");
    tc.append_attribute("classname") =
        xml_text(suite + (r.check.empty() ? ".properties" : ".standard_checks")).c_str();
    tc.append_attribute("name") = xml_text(r.name).c_str();
    tc.append_attribute("time") = seconds(r.seconds).c_str();
    // A property from the command line (where.file "--ctl") or a standard check belongs to
    // the model file; a spec file property to its line there.
    const bool from_spec =
        !r.where.file.empty() && r.where.file != "--ctl" && r.where.file != "--pattern";
    const std::string file = from_spec ? r.where.file : options.model;
    if (!file.empty()) {
      tc.append_attribute("file") = xml_text(file).c_str();
      if (from_spec && r.where.line > 0) tc.append_attribute("line") = r.where.line;
    }
    // A vacuous pass is still a pass; CI servers show system-out with the test case.
    // A pattern's English sentence goes there too, first.
    std::string out = r.description;
    for (const auto& more :
         {r.justification.empty() ? std::string() : "justification: " + r.justification, r.vacuity})
      if (!more.empty()) out += (out.empty() ? "" : "\n") + more;
    if (!out.empty())
      tc.append_child("system-out")
          .append_child(pugi::node_pcdata)
          .set_value(xml_text(out).c_str());
    const char* element = nullptr;
    switch (r.verdict) {
      case logic::Verdict::Holds:
        break;
      case logic::Verdict::Violated:
        element = "failure";
        break;
      case logic::Verdict::Unknown:
      case logic::Verdict::NotChecked:
        element = "error";
        break;
      case logic::Verdict::NotApplicable:
        element = "skipped";
        break;
    }
    if (!element) continue;
    auto e = tc.append_child(element);
    const std::string verdict(logic::to_string(r.verdict));
    e.append_attribute("message") =
        xml_text(r.message.empty() ? verdict : verdict + ": " + r.message).c_str();
    if (r.verdict != logic::Verdict::NotApplicable) {
      e.append_attribute("type") = verdict.c_str();
      e.append_child(pugi::node_pcdata).set_value(xml_text(details(r, ts)).c_str());
    }
  }
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

}  // namespace sfcv::report
