#include "logic/requirements.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <nlohmann/json.hpp>
#include <regex>

#include "model/names.hpp"

namespace sfcv::logic {

namespace {

using json = nlohmann::json;

struct Located {
  int line = 1, column = 1;
};

// One requirement before translation: a pattern call and what reports carry.
struct Requirement {
  std::string id, text, justification;
  std::string pattern;  ///< `name(arg, ...)` in sfcv's pattern syntax
  Located where;
};

class Reader {
 public:
  Reader(std::string_view text, const std::string& file, const PatternOptions& options)
      : text_(text), file_(file), options_(options) {}

  ParsedRequirements read() {
    const auto first = text_.find_first_not_of(" \t\r\n");
    try {
      if (first != std::string_view::npos && (text_[first] == '{' || text_[first] == '['))
        read_json();
      else
        read_yaml();
    } catch (const Failure&) {
      // reported
    }
    for (auto& r : requirements_) translate(r);
    return std::move(out_);
  }

 private:
  struct Failure {};

  [[noreturn]] void fail(Located at, std::string message) {
    error(at, std::move(message));
    throw Failure{};
  }
  void error(Located at, std::string message) {
    model::Diagnostic d;
    d.where.file = file_;
    d.where.line = at.line;
    d.where.column = at.column;
    d.message = std::move(message);
    out_.diagnostics.push_back(std::move(d));
  }
  Located at_offset(std::size_t offset) const {
    Located l;
    for (std::size_t i = 0; i < offset && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++l.line;
        l.column = 1;
      } else {
        ++l.column;
      }
    }
    return l;
  }
  // The k-th (0-based) occurrence of `key` in the text: where the k-th requirement's entry is
  // (nlohmann's values keep no positions).
  Located nth(std::string_view key, std::size_t k) const {
    std::size_t at = 0;
    for (std::size_t i = 0;; ++i) {
      const auto found = text_.find(key, at);
      if (found == std::string_view::npos) return {};
      if (i == k) return at_offset(found);
      at = found + key.size();
    }
  }

  // --- PLCverif JSON ---
  void read_json() {
    json doc;
    try {
      // Bounded depth (docs/reliability.md): a document nested deeper than any requirement
      // would be is refused before its tree (destroyed recursively) is built.
      constexpr int kMaxDepth = 256;
      bool too_deep = false;
      doc = json::parse(text_.begin(), text_.end(),
                        [&too_deep](int depth, json::parse_event_t, json&) {
                          if (depth > kMaxDepth) too_deep = true;
                          return !too_deep;
                        });
      if (too_deep)
        fail(at_offset(0),
             "the JSON is nested more than " + std::to_string(kMaxDepth) + " levels deep");
    } catch (const json::parse_error& e) {
      fail(at_offset(e.byte > 0 ? e.byte - 1 : 0), std::string("malformed JSON: ") + e.what());
    }
    std::string prefix;
    const json* list = &doc;
    if (doc.is_object() && doc.contains("properties_to_be_validated")) {
      if (doc.contains("id") && doc["id"].is_string()) prefix = doc["id"].get<std::string>() + "/";
      list = &doc["properties_to_be_validated"];
    }
    std::vector<const json*> entries;
    if (list->is_array()) {
      for (const auto& e : *list) entries.push_back(&e);
    } else if (list->is_object()) {
      entries.push_back(list);
    } else {
      fail({},
           "expected a requirement object, an array of them, or a task with "
           "\"properties_to_be_validated\"");
    }
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const json& e = *entries[k];
      Requirement r;
      r.where = nth("\"job_req\"", k);
      r.id = prefix + std::to_string(k + 1);
      if (!e.is_object() || !e.contains("property") || !e["property"].is_object()) {
        error(nth("{", k + (list == &doc ? 0 : 1)),
              "requirement " + std::to_string(k + 1) + ": expected an object with \"property\"");
        continue;
      }
      const json& p = e["property"];
      if (e.contains("id") && e["id"].is_string()) r.id = e["id"].get<std::string>();
      if (e.contains("property_description") && e["property_description"].is_string())
        r.text = e["property_description"].get<std::string>();
      if (e.contains("justification") && e["justification"].is_string())
        r.justification = e["justification"].get<std::string>();
      const std::string job = p.value("job_req", "");
      if (job == "assertion") {
        error(r.where, "requirement " + r.id +
                           ": \"job_req\": \"assertion\" asks for the program's assertions, and "
                           "sfcv reads none (no ASSERT statement, PLCverif's //#ASSERT comments "
                           "are not read): write the asserted condition as pattern-invariant");
        continue;
      }
      if (job != "pattern") {
        error(r.where, "requirement " + r.id + ": unknown \"job_req\" '" + job +
                           "' (expected \"pattern\" or \"assertion\")");
        continue;
      }
      const std::string id = p.value("pattern_id", "");
      const auto name = plcverif_pattern(id);
      if (name.empty()) {
        error(r.where, "requirement " + r.id + ": unknown pattern_id '" + id +
                           "' (known: pattern-invariant, pattern-forbidden, pattern-implication, "
                           "pattern-statechange-duringcycle, pattern-statechange-betweencycles, "
                           "pattern-reachability, pattern-repeatability, pattern-leadsto)");
        continue;
      }
      const PatternInfo* info = nullptr;
      for (const auto& c : pattern_catalogue())
        if (c.name == name) info = &c;
      const std::size_t arity = (info->arguments.size() + 2) / 3;
      std::vector<std::string> args;
      const json params = p.value("pattern_params", json::object());
      for (std::size_t a = 1; a <= arity; ++a) {
        const auto key = std::to_string(a);
        if (!params.is_object() || !params.contains(key) || !params[key].is_string()) {
          error(r.where, "requirement " + r.id + ": " + id + " needs the parameter \"" + key +
                             "\" (a string)");
          break;
        }
        args.push_back(plcverif_expression(params[key].get<std::string>()));
      }
      if (args.size() != arity) continue;
      r.pattern = call(name, args);
      requirements_.push_back(std::move(r));
    }
  }
  // PLCverif names the verified block's variables `instance.x`: here they are the program's.
  static std::string plcverif_expression(const std::string& e) {
    static const std::regex instance(R"((^|[^A-Za-z0-9_.])instance\.)");
    return std::regex_replace(e, instance, "$1");
  }
  static std::string call(std::string_view name, const std::vector<std::string>& args) {
    std::string s(name);
    s += '(';
    for (std::size_t i = 0; i < args.size(); ++i) s += (i ? ", (" : "(") + args[i] + ")";
    return s + ")";
  }

  // --- ESBMC-PLC YAML ---
  static Located at_mark(const YAML::Mark& m) {
    if (m.line < 0) return {};
    return {m.line + 1, m.column + 1};
  }
  // ESBMC's expressions use C's && || !: sfcv's are & | !.
  static std::string esbmc_expression(std::string e) {
    for (const auto* op : {"&&", "||"}) {
      for (auto at = e.find(op); at != std::string::npos; at = e.find(op, at)) e.erase(at, 1);
    }
    return e;
  }
  std::string field(const YAML::Node& n, const char* key, const Requirement& r, bool required) {
    const auto v = n[key];
    if (!v || !v.IsScalar()) {
      if (required)
        error(at_mark(n.Mark()), "requirement " + r.id + ": kind '" +
                                     n["kind"].as<std::string>("") + "' needs the field '" + key +
                                     "'");
      return {};
    }
    return v.as<std::string>();
  }
  void read_yaml() {
    YAML::Node doc;
    try {
      doc = YAML::Load(std::string(text_));
    } catch (const YAML::Exception& e) {
      fail(at_mark(e.mark), "malformed YAML: " + e.msg);
    }
    if (!doc.IsMap() || !doc["properties"] || !doc["properties"].IsSequence())
      fail(at_mark(doc.Mark()),
           "expected a JSON requirement (PLCverif) or a YAML map with a 'properties' list "
           "(ESBMC-PLC)");
    for (const auto& n : doc["properties"]) {
      Requirement r;
      r.where = at_mark(n.Mark());
      if (!n.IsMap()) {
        error(r.where, "expected a property (a map with id and kind)");
        continue;
      }
      r.id = n["id"] && n["id"].IsScalar() ? n["id"].as<std::string>() : "";
      if (r.id.empty()) {
        error(r.where, "a property needs an 'id'");
        continue;
      }
      for (const auto& other : requirements_)
        if (other.id == r.id) error(r.where, "property id '" + r.id + "' is used twice");
      r.text = field(n, "description", r, false);
      r.justification = field(n, "justification", r, false);
      const std::string kind = n["kind"] && n["kind"].IsScalar() ? n["kind"].as<std::string>() : "";
      const std::size_t before = out_.diagnostics.size();
      if (kind == "mutual_exclusion") {
        const auto vars = n["variables"];
        if (!vars || !vars.IsSequence() || vars.size() < 2) {
          error(r.where, "requirement " + r.id +
                             ": mutual_exclusion needs 'variables', a list of two or more");
          continue;
        }
        // Pairwise: no two of them true at once.
        std::string pairs;
        for (std::size_t i = 0; i < vars.size(); ++i)
          for (std::size_t j = i + 1; j < vars.size(); ++j)
            pairs += (pairs.empty() ? "" : " | ") + std::string("(") + vars[i].as<std::string>() +
                     " & " + vars[j].as<std::string>() + ")";
        r.pattern = call("never", {pairs});
      } else if (kind == "invariant" || kind == "absence" || kind == "reachability") {
        const auto e = field(n, "expression", r, true);
        if (kind == "reachability" && r.justification.empty())
          error(r.where, "requirement " + r.id + ": reachability needs a 'justification'");
        if (out_.diagnostics.size() != before) continue;
        r.pattern = call(kind == "invariant" ? "always"
                         : kind == "absence" ? "never"
                                             : "reachable",
                         {esbmc_expression(e)});
      } else if (kind == "response") {
        const auto trigger = field(n, "trigger", r, true);
        const auto response = field(n, "response", r, true);
        const auto scans = field(n, "max_scans", r, true);
        if (r.justification.empty())
          error(r.where, "requirement " + r.id + ": response needs a 'justification' of its bound");
        if (out_.diagnostics.size() != before) continue;
        if (scans.empty() ||
            !std::all_of(scans.begin(), scans.end(), [](char c) { return std::isdigit(c); })) {
          error(at_mark(n["max_scans"].Mark()),
                "requirement " + r.id + ": max_scans must be a whole number of scans");
          continue;
        }
        r.pattern = "response((" + esbmc_expression(trigger) + "), (" + esbmc_expression(response) +
                    "), within " + scans + " cycles)";
      } else {
        error(n["kind"] ? at_mark(n["kind"].Mark()) : r.where,
              "requirement " + r.id + ": unknown kind '" + kind +
                  "' (expected mutual_exclusion, invariant, absence, response or reachability)");
        continue;
      }
      requirements_.push_back(std::move(r));
    }
  }

  void translate(const Requirement& r) {
    auto parsed = parse_pattern(r.pattern, file_ + ": requirement " + r.id, options_);
    if (!parsed.ok()) {
      // Located at the requirement, with the pattern it became.
      for (auto d : parsed.diagnostics) {
        d.message += " (in " + r.pattern + ")";
        d.where.file = file_;
        d.where.line = r.where.line;
        d.where.column = r.where.column;
        d.message = "requirement " + r.id + ": " + d.message;
        out_.diagnostics.push_back(std::move(d));
      }
      return;
    }
    NamedFormula nf;
    nf.name = r.id;
    nf.formula = parsed.formula;
    nf.where.file = file_;
    nf.where.line = r.where.line;
    nf.where.column = r.where.column;
    nf.description = r.text.empty() ? parsed.english : r.text + " — " + parsed.english;
    nf.justification = r.justification;
    out_.spec.properties.push_back(std::move(nf));
  }

  std::string_view text_;
  std::string file_;
  PatternOptions options_;
  std::vector<Requirement> requirements_;
  ParsedRequirements out_;
};

}  // namespace

std::string_view plcverif_pattern(std::string_view id) {
  static const std::pair<std::string_view, std::string_view> table[] = {
      {"pattern-invariant", "always"},
      {"pattern-forbidden", "never"},
      {"pattern-implication", "implies"},
      {"pattern-statechange-duringcycle", "statechange_duringcycle"},
      {"pattern-statechange-betweencycles", "between_cycles"},
      {"pattern-reachability", "reachable"},
      {"pattern-repeatability", "repeatable"},
      {"pattern-leadsto", "leadsto"},
  };
  for (const auto& [k, v] : table)
    if (k == id) return v;
  return {};
}

ParsedRequirements parse_requirements(std::string_view text, const std::string& file,
                                      const PatternOptions& options) {
  return Reader(text, file, options).read();
}

}  // namespace sfcv::logic
