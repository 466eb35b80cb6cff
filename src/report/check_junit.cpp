#include "report/check_junit.hpp"

#include <cstdio>
#include <filesystem>
#include <pugixml.hpp>
#include <sstream>

#include "report/numbers.hpp"
#include "report/provenance.hpp"
#include "report/text_encoding.hpp"
#include "report/trace_render.hpp"

namespace sfcv::report {

namespace {

std::string junit_time(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", s);  // Jenkins' junit-10.xsd: at most 3 decimals
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
           counted(r.trace->steps.size(), "situation") + "):\n" + trace_table(*r.trace, ts);
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
  // Several runs on one model (other properties, another engine) must not share a suite name:
  // CI servers merge test cases by suite and name. The run's digest tells them apart.
  std::string suite = options.model.empty()
                          ? std::string("sfcv")
                          : std::filesystem::path(options.model).filename().string();
  if (options.provenance && options.provenance->command_line.size() > 1)
    suite += " [" + options.provenance->engine + " " + run_digest(*options.provenance) + "]";
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  auto suites = doc.append_child("testsuites");
  suites.append_attribute("name") = "sfcv check";
  suites.append_attribute("tests") = static_cast<unsigned long long>(report.results.size());
  suites.append_attribute("failures") = static_cast<unsigned long long>(failures);
  suites.append_attribute("errors") = static_cast<unsigned long long>(errors);
  suites.append_attribute("time") = junit_time(report.seconds).c_str();
  auto ts_node = suites.append_child("testsuite");
  ts_node.append_attribute("name") = xml_text(suite).c_str();
  ts_node.append_attribute("tests") = static_cast<unsigned long long>(report.results.size());
  ts_node.append_attribute("failures") = static_cast<unsigned long long>(failures);
  ts_node.append_attribute("errors") = static_cast<unsigned long long>(errors);
  ts_node.append_attribute("skipped") = static_cast<unsigned long long>(skipped);
  ts_node.append_attribute("time") = junit_time(report.seconds).c_str();
  if (options.provenance) ts_node.append_attribute("timestamp") = options.provenance->date.c_str();
  auto props = ts_node.append_child("properties");
  auto property = [&props](const std::string& name, const std::string& value) {
    auto p = props.append_child("property");
    p.append_attribute("name") = xml_text(name).c_str();
    p.append_attribute("value") = xml_text(value).c_str();
  };
  property("model", options.model);
  property("semantics", options.semantics);
  property("engine", report.engine);
  if (report.states_known) property("states", report.states.str());  // SAT engines count none
  property("complete", report.complete ? "true" : "false");
  if (!report.complete) property("limit", report.limit);
  if (const auto& p = options.provenance) {
    property("sfcv.version", p->version);
    property("sfcv.commit", p->commit);
    for (const auto& [name, version] : p->libraries) property("sfcv.library." + name, version);
    property("sfcv.command_line", shell_words(p->command_line));
    property("sfcv.date", p->date);
    for (const auto& in : p->inputs)
      property("sfcv.input." + in.path, in.sha256.empty() ? "unreadable" : "sha256:" + in.sha256);
    property("sfcv.engine", p->engine);
    for (const auto& [name, value] : p->settings) property("sfcv.setting." + name, value);
  }

  for (const auto& r : report.results) {
    auto tc = ts_node.append_child("testcase");
    tc.append_attribute("classname") =
        xml_text(suite + (r.check.empty() ? ".properties" : ".standard_checks")).c_str();
    tc.append_attribute("name") = xml_text(r.name).c_str();
    tc.append_attribute("time") = junit_time(r.seconds).c_str();
    // Jenkins' junit-10.xsd has no file or line on a test case: where the property was
    // written (a spec file's line; the model for --ctl and the standard checks) goes to
    // system-out, with the id, the deciding engine, a pattern's English sentence and whether
    // a pass is vacuous (still a pass). CI servers show system-out with the test case.
    std::string out = "id: " + property_id(r) + "\n";
    if (!from_command_line(r) && r.check.empty())
      out += "where: " + r.where.str() + "\n";
    else if (!options.model.empty())
      out += "where: " + options.model + "\n";
    const bool definite =
        r.verdict == logic::Verdict::Holds || r.verdict == logic::Verdict::Violated;
    if (definite)
      out += "decided by: " + (r.decided_by.empty() ? report.engine : r.decided_by) + "\n";
    if (!r.description.empty()) out += r.description + "\n";
    if (!r.justification.empty()) out += "justification: " + r.justification + "\n";
    if (!r.vacuity.empty()) out += r.vacuity + "\n";
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
    // The verdict's element first, then system-out, as Maven Surefire writes them.
    if (element) {
      auto e = tc.append_child(element);
      const std::string verdict(logic::to_string(r.verdict));
      e.append_attribute("message") =
          xml_text(r.message.empty() ? verdict : verdict + ": " + r.message).c_str();
      if (r.verdict != logic::Verdict::NotApplicable) {
        e.append_attribute("type") = verdict.c_str();
        e.append_child(pugi::node_pcdata).set_value(xml_text(details(r, ts)).c_str());
      }
    }
    tc.append_child("system-out").append_child(pugi::node_pcdata).set_value(xml_text(out).c_str());
  }
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

}  // namespace sfcv::report
