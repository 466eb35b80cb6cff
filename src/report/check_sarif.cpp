#include "report/check_sarif.hpp"

#include <map>
#include <regex>

#include "logic/standard_checks.hpp"
#include "report/check_render.hpp"
#include "report/text_encoding.hpp"

namespace sfcv::report {

namespace {

using nlohmann::json;

/// A relative path stays a relative URI reference (code-scanning views resolve it against the
/// repository); an absolute one becomes a file:// URI.
std::string file_uri(const std::string& path) {
  std::string uri;
  for (char c : path) {
    if (c == ' ')
      uri += "%20";
    else if (c == '%')
      uri += "%25";
    else
      uri += c;
  }
  return !uri.empty() && uri[0] == '/' ? "file://" + uri : uri;
}

json physical(const model::SourceLocation& where, const std::string& fallback_file) {
  json loc;
  loc["artifactLocation"]["uri"] = file_uri(where.file.empty() ? fallback_file : where.file);
  if (where.line > 0) {
    loc["region"]["startLine"] = where.line;
    if (where.column > 0) loc["region"]["startColumn"] = where.column;
  }
  return loc;
}

/// Findings are "one located line per defect": the engines write the element's location in
/// parentheses, "step S9 (plant.st:39:3), once inactive, ...".
std::optional<model::SourceLocation> located_in(const std::string& finding) {
  static const std::regex where(R"(\(([^()\s]+?):([0-9]+)(?::([0-9]+))?\))");
  std::smatch m;
  if (!std::regex_search(finding, m, where)) return std::nullopt;
  model::SourceLocation loc;
  loc.file = m[1];
  loc.line = std::stoi(m[2]);
  if (m[3].matched) loc.column = std::stoi(m[3]);
  return loc;
}

std::string rule_id(const logic::PropertyResult& r) {
  return r.check.empty() ? "property/" + r.name : "check/" + r.name;
}

}  // namespace

json check_sarif(const logic::CheckReport& report, const semantics::TransitionSystem& ts,
                 const model::Project* project, const RenderOptions& options) {
  const auto& obs = ts.observables();
  const auto& trs = ts.transitions();
  std::map<std::uint32_t, model::SourceLocation> step_where;
  for (const auto& s : logic::step_refs(ts, project))
    if (s.where.known()) step_where[s.observable] = s.where;
  std::map<std::string, std::string_view> descriptions;
  for (const auto& c : logic::standard_checks()) descriptions[std::string(c.name)] = c.description;

  json rules = json::array();
  json results = json::array();
  for (std::size_t i = 0; i < report.results.size(); ++i) {
    const auto& r = report.results[i];
    json rule;
    rule["id"] = rule_id(r);
    rule["name"] = r.name;
    const auto d = descriptions.find(r.check);
    rule["shortDescription"]["text"] =
        !r.description.empty() ? r.description + " (CTL " + r.formula + ")"
        : r.check.empty()      ? "CTL property " + r.formula
                               : std::string(d != descriptions.end() ? d->second : r.name);
    if (!r.justification.empty())
      rule["fullDescription"]["text"] = rule["shortDescription"]["text"].get<std::string>() +
                                        " Justification: " + r.justification;
    rule["defaultConfiguration"]["level"] = "error";
    rules.push_back(std::move(rule));
    if (r.verdict == logic::Verdict::Holds) continue;

    json base;
    base["ruleId"] = rule_id(r);
    base["ruleIndex"] = i;
    // Not checked counts as unknown (a warning); a question without meaning on the system is
    // SARIF's own "notApplicable" kind, which takes level "none".
    base["level"] = r.verdict == logic::Verdict::Violated        ? "error"
                    : r.verdict == logic::Verdict::NotApplicable ? "none"
                                                                 : "warning";
    if (r.verdict == logic::Verdict::NotApplicable) base["kind"] = "notApplicable";
    // Where the property was written (a spec file), else the model.
    const bool from_spec =
        !r.where.file.empty() && r.where.file != "--ctl" && r.where.file != "--pattern";
    model::SourceLocation primary = from_spec ? r.where : model::SourceLocation{};

    if (r.trace) {
      const auto& t = *r.trace;
      json related = json::array();
      std::map<std::uint32_t, int> related_id;
      json flow = json::array();
      for (std::size_t k = 0; k < t.steps.size(); ++k) {
        const auto& st = t.steps[k];
        std::string active, values;
        std::optional<model::SourceLocation> at;
        for (std::uint32_t o = 0; o < obs.size(); ++o) {
          const auto v = ts.observe(st.state, o);
          if (obs[o].kind == semantics::ObservableKind::Step) {
            if (!v) continue;
            active += (active.empty() ? "" : " ") + obs[o].name;
            const auto w = step_where.find(o);
            if (w == step_where.end()) continue;
            if (!at) at = w->second;
            if (related_id.emplace(o, static_cast<int>(related.size())).second) {
              json rel;
              rel["id"] = related.size();
              rel["physicalLocation"] = physical(w->second, options.model);
              rel["message"]["text"] =
                  "step " + obs[o].name + ", first active in situation " + std::to_string(k);
              related.push_back(std::move(rel));
            }
          } else if (obs[o].is_output && (obs[o].type.kind != model::TypeKind::Bool || v)) {
            values += (values.empty() ? "" : " ") + obs[o].name +
                      (obs[o].type.kind == model::TypeKind::Bool ? "" : "=" + std::to_string(v));
          }
        }
        std::string fired;
        for (auto f : st.fired) {
          if (f >= trs.size()) continue;
          fired += (fired.empty() ? "" : ", ") + trs[f].name;
          if (trs[f].where.line > 0) at = trs[f].where;  // the transition that led here
        }
        std::string inputs;
        for (std::size_t n = 0; n < ts.inputs().size() && n < st.inputs.size(); ++n)
          if (k == 0 ? st.inputs[n] != 0 : st.inputs[n] != t.steps[k - 1].inputs[n])
            inputs += (inputs.empty() ? "" : " ") + ts.inputs()[n].name + "=" +
                      std::to_string(st.inputs[n]);
        std::string text = "situation " + std::to_string(k) + ": ";
        if (!fired.empty()) text += "fired " + fired + "; ";
        text += "active " + (active.empty() ? std::string("none") : active);
        if (!values.empty()) text += "; outputs " + values;
        if (!inputs.empty()) text += "; inputs " + inputs;
        json tfl;
        tfl["executionOrder"] = k;
        tfl["location"]["message"]["text"] = text;
        if (at) tfl["location"]["physicalLocation"] = physical(*at, options.model);
        flow.push_back(std::move(tfl));
        if (k + 1 == t.steps.size() && at && !from_spec) primary = *at;  // where it went wrong
      }
      if (!related.empty()) base["relatedLocations"] = related;
      json thread;
      thread["locations"] = flow;
      json code_flow;
      code_flow["message"]["text"] =
          std::string(t.kind == logic::TraceKind::Counterexample ? "counterexample" : "witness") +
          (t.note.empty() ? "" : ": " + t.note);
      code_flow["threadFlows"] = json::array({thread});
      base["codeFlows"] = json::array({code_flow});
    }
    auto emit = [&](const std::string& text, const model::SourceLocation& where) {
      json res = base;
      res["message"]["text"] = text;
      res["locations"] = json::array({json{{"physicalLocation", physical(where, options.model)}}});
      results.push_back(std::move(res));
    };
    const std::string verdict(logic::to_string(r.verdict));
    const std::string head = !r.description.empty() ? "'" + r.description + "' is " + verdict
                             : r.check.empty()      ? "'" + r.formula + "' is " + verdict
                                                    : r.name + ": " + verdict;
    if (r.findings.empty()) {
      emit(head + (r.message.empty() ? "" : ": " + r.message), primary);
    } else {
      for (const auto& f : r.findings) {
        // "(and 21 more such situations)" sums up the findings left out: it belongs to the last.
        if (f.starts_with("(and ") && !results.empty() && results.back()["ruleId"] == rule_id(r)) {
          results.back()["message"]["text"] =
              results.back()["message"]["text"].get<std::string>() + " " + f;
          continue;
        }
        emit(head + ": " + f, located_in(f).value_or(primary));
      }
      if (const auto cut = findings_cut_note(r); !cut.empty() && !results.empty())
        results.back()["message"]["text"] =
            results.back()["message"]["text"].get<std::string>() + " (" + cut + ")";
    }
  }

  json driver;
  driver["name"] = "sfcv";
  driver["rules"] = rules;
  json run;
  run["tool"]["driver"] = driver;
  run["results"] = results;
  run["columnKind"] = "unicodeCodePoints";
  run["properties"] = {{"engine", report.engine},
                       // null: the engine does not count states (SAT engines, auto's race)
                       {"states", report.states_known ? count_json(report.states) : json(nullptr)},
                       {"complete", report.complete},
                       {"semantics", options.semantics}};
  json log;
  log["$schema"] = "https://json.schemastore.org/sarif-2.1.0.json";
  log["version"] = "2.1.0";
  log["runs"] = json::array({run});
  make_valid_utf8(log);  // names are bytes; SARIF is UTF-8 JSON
  return log;
}

}  // namespace sfcv::report
