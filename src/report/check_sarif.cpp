#include "report/check_sarif.hpp"

#include <cctype>
#include <filesystem>
#include <map>
#include <regex>

#include "logic/standard_checks.hpp"
#include "report/check_render.hpp"
#include "report/provenance.hpp"
#include "report/sha256.hpp"
#include "report/text_encoding.hpp"

namespace sfcv::report {

namespace {

using nlohmann::json;

/// A path as a URI reference: every byte but the unreserved ones and '/' percent-encoded
/// (RFC 3986), so that spaces, '#', '?' and non-ASCII names survive.
std::string uri_path(const std::string& path) {
  static const char* hex = "0123456789ABCDEF";
  std::string uri;
  for (char c : path) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      uri += c;
    } else {
      uri += '%';
      uri += hex[u >> 4];
      uri += hex[u & 15];
    }
  }
  return uri;
}

/// Locations relative to the SARIF root (--sarif-root; the repository a code-scanning upload
/// resolves them against): a file below it is a relative URI with uriBaseId SRCROOT; one
/// outside it stays an absolute file:// URI, which code scanning does not show.
class Locator {
 public:
  Locator(const std::string& root, std::string model) : model_(std::move(model)) {
    if (root.empty()) return;
    std::error_code ec;
    root_ = std::filesystem::weakly_canonical(std::filesystem::absolute(root, ec), ec);
    if (ec) root_.clear();
  }

  const std::filesystem::path& root() const { return root_; }

  json artifact(const std::string& file) const {
    json a;
    if (!root_.empty()) {
      std::error_code ec;
      const auto abs = std::filesystem::weakly_canonical(std::filesystem::absolute(file, ec), ec);
      const auto rel = abs.lexically_relative(root_);
      if (!ec && !rel.empty() && *rel.begin() != "..") {
        a["uri"] = uri_path(rel.generic_string());
        a["uriBaseId"] = "SRCROOT";
        return a;
      }
      a["uri"] = "file://" + uri_path(abs.generic_string());
      return a;
    }
    a["uri"] = !file.empty() && file[0] == '/' ? "file://" + uri_path(file) : uri_path(file);
    return a;
  }

  /// `where` in the model (or its own file); a location without a line gets line 1, since
  /// code scanning needs a region on every location.
  json physical(const model::SourceLocation& where) const {
    json loc;
    loc["artifactLocation"] = artifact(where.file.empty() ? model_ : where.file);
    loc["region"]["startLine"] = where.line > 0 ? where.line : 1;
    if (where.line > 0 && where.column > 0) loc["region"]["startColumn"] = where.column;
    return loc;
  }

 private:
  std::filesystem::path root_;
  std::string model_;
};

/// The text of a message without the locations the engines write into findings, so that a
/// fingerprint survives the model's lines moving.
std::string without_locations(const std::string& text) {
  static const std::regex where(R"(\([^()\s]+?:[0-9]+(?::[0-9]+)?\))");
  return std::regex_replace(text, where, "()");
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
  return property_id(r);
}

/// The rule's texts: the check catalogue's line for a standard check, the English of a
/// pattern, the formula of a property; help says how to reproduce and where it is explained.
void describe_rule(json& rule, const logic::PropertyResult& r, std::string_view check_text) {
  std::string short_text, full, help;
  if (!r.check.empty()) {
    short_text = std::string(check_text.empty() ? r.name : check_text);
    full = "Standard check '" + r.check + "' of sfcv: " + short_text +
           ". A violation names each element found, located in the model.";
    help = short_text + ".\n\nReproduce: sfcv check MODEL --checks " + r.check +
           "\nThe standard checks are defined in sfcv's docs/semantics.md (section 3) and "
           "docs/properties.md.";
  } else if (!r.description.empty()) {
    short_text = r.description;
    full =
        "Requirement pattern: " + r.description + " Checked as the CTL formula " + r.formula + ".";
    help = r.description + "\n\nCTL: " + r.formula + "\nReproduce: sfcv check MODEL --pattern '" +
           r.name + "' (docs/properties.md lists the patterns).";
  } else {
    const std::string kind = r.where.file == "--ltl" ? "LTL" : "CTL";
    short_text =
        kind + " property " + (r.name == r.formula ? r.formula : r.name + ": " + r.formula);
    full = short_text +
           ". A violation comes with a counterexample: the input sequence that "
           "breaks it, one situation per step of the code flow.";
    help = short_text + "\n\nReproduce: sfcv check MODEL " +
           (from_command_line(r) ? (kind == "LTL" ? "--ltl '" : "--ctl '") + r.name + "'"
                                 : "--spec " + r.where.file) +
           "\nThe property language is described in docs/properties.md.";
  }
  rule["shortDescription"]["text"] = short_text;
  rule["fullDescription"]["text"] = full;
  rule["help"]["text"] = help;
  std::string markdown = help;
  rule["help"]["markdown"] = markdown;
}

}  // namespace

json check_sarif(const logic::CheckReport& report, const semantics::TransitionSystem& ts,
                 const model::Project* project, const RenderOptions& options) {
  const auto& obs = ts.observables();
  const auto& trs = ts.transitions();
  std::map<std::uint32_t, model::SourceLocation> step_where;
  model::SourceLocation first_step;
  for (const auto& s : logic::step_refs(ts, project))
    if (s.where.known()) {
      step_where[s.observable] = s.where;
      if (!first_step.known() && s.where.line > 0) first_step = s.where;
    }
  std::map<std::string, std::string_view> descriptions;
  for (const auto& c : logic::standard_checks()) descriptions[std::string(c.name)] = c.description;

  const Locator locator(options.sarif_root, options.model);
  json rules = json::array();
  json results = json::array();
  for (std::size_t i = 0; i < report.results.size(); ++i) {
    const auto& r = report.results[i];
    json rule;
    rule["id"] = rule_id(r);
    rule["name"] = r.name;
    const auto d = descriptions.find(r.check);
    describe_rule(rule, r, d != descriptions.end() ? d->second : std::string_view());
    if (!r.justification.empty()) {
      // A requirement file's justification (--requirements) belongs with the rule's text.
      const std::string full = rule.contains("fullDescription")
                                   ? rule["fullDescription"]["text"].get<std::string>()
                                   : rule["shortDescription"]["text"].get<std::string>();
      rule["fullDescription"]["text"] = full + " Justification: " + r.justification;
    }
    rule["defaultConfiguration"]["level"] = "error";
    rule["properties"]["tags"] =
        json::array({"sfcv", r.check.empty() ? (r.description.empty() ? "property" : "pattern")
                                             : "standard-check"});
    rule["properties"]["precision"] = "very-high";  // a model checker's verdict, not a heuristic
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
    if (r.verdict == logic::Verdict::Violated)  // the engine whose answer this is
      base["properties"]["decidedBy"] = r.decided_by.empty() ? report.engine : r.decided_by;
    // Where the property was written (a spec file), else the model.
    const bool from_spec = !from_command_line(r);
    // Where the question is located when nothing better is known (an unknown verdict, a
    // property without a trace): its line in a spec file, else the chart's first step.
    model::SourceLocation primary = from_spec ? r.where : first_step;

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
              rel["physicalLocation"] = locator.physical(w->second);
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
        // Every location needs a file and a line in code scanning: the step or transition,
        // else where the question is located.
        tfl["location"]["physicalLocation"] = locator.physical(at ? *at : primary);
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
    // Code scanning follows an alert across commits by its fingerprint: the rule, the file
    // and the message without line numbers, so that an edit above it keeps the alert.
    auto fingerprint = [&](json& res) {
      const auto& loc = res["locations"][0]["physicalLocation"]["artifactLocation"];
      res["partialFingerprints"]["sfcvResult/v1"] =
          sha256_hex(res["ruleId"].get<std::string>() + "\n" + loc["uri"].get<std::string>() +
                     "\n" + without_locations(res["message"]["text"].get<std::string>()))
              .substr(0, 32);
    };
    auto emit = [&](const std::string& text, const model::SourceLocation& where) {
      json res = base;
      res["message"]["text"] = text;
      res["locations"] = json::array({json{{"physicalLocation", locator.physical(where)}}});
      results.push_back(std::move(res));
      fingerprint(results.back());
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
          fingerprint(results.back());
          continue;
        }
        emit(head + ": " + f, located_in(f).value_or(primary));
      }
      if (const auto cut = findings_cut_note(r); !cut.empty() && !results.empty()) {
        results.back()["message"]["text"] =
            results.back()["message"]["text"].get<std::string>() + " (" + cut + ")";
        fingerprint(results.back());
      }
    }
  }

  json driver;
  driver["name"] = "sfcv";
  driver["version"] = build_version();
  driver["semanticVersion"] = build_version();
  // Only a URI the build was given (CMake's SFCV_INFORMATION_URI); none is invented.
  if (const auto uri = build_information_uri(); !uri.empty()) driver["informationUri"] = uri;
  driver["properties"]["commit"] = build_commit();
  driver["rules"] = rules;
  json run;
  run["tool"]["driver"] = driver;
  if (const auto& p = options.provenance) {
    // Who ran what, when (SARIF's invocation), and the inputs with their digests (artifacts).
    json inv;
    inv["commandLine"] = shell_words(p->command_line);
    inv["arguments"] =
        p->command_line.size() > 1
            ? json(std::vector<std::string>(p->command_line.begin() + 1, p->command_line.end()))
            : json::array();
    inv["startTimeUtc"] = p->date;
    inv["executionSuccessful"] = true;  // the run ended with verdicts (exit 0, 1 or 3)
    inv["exitCode"] = logic::exit_code(report);
    run["invocations"] = json::array({inv});
    json artifacts = json::array();
    for (const auto& in : p->inputs) {
      json a;
      a["location"] = locator.artifact(in.path);
      a["length"] = in.bytes;
      if (!in.sha256.empty()) a["hashes"]["sha-256"] = in.sha256;
      artifacts.push_back(std::move(a));
    }
    run["artifacts"] = artifacts;
  }
  if (!locator.root().empty()) {
    auto root = "file://" + uri_path(locator.root().generic_string());
    if (root.back() != '/') root += '/';  // a base URI names a directory
    run["originalUriBaseIds"]["SRCROOT"]["uri"] = root;
  }
  run["results"] = results;
  run["columnKind"] = "unicodeCodePoints";
  run["properties"] = {{"engine", report.engine},
                       // null: the engine does not count states (SAT engines, auto's race)
                       {"states", report.states_known ? count_json(report.states) : json(nullptr)},
                       {"complete", report.complete},
                       {"semantics", options.semantics}};
  if (options.provenance) run["properties"]["provenance"] = provenance_json(*options.provenance);
  json log;
  log["$schema"] = "https://json.schemastore.org/sarif-2.1.0.json";
  log["version"] = "2.1.0";
  log["runs"] = json::array({run});
  make_valid_utf8(log);  // names are bytes; SARIF is UTF-8 JSON
  return log;
}

}  // namespace sfcv::report
