// sfcv merge: joins the --json results of `sfcv check --shard I/N` into the report a single run
// would have given (docs/distributed.md). It checks that the shards come from the same model,
// options and split and cover every unit once, then runs the check command itself on the
// shards' command line with their answers in place of the engines (cli/check_shards.hpp), so
// every report (text, JSON, JUnit, SARIF, HTML, traces) and the exit code are a single run's.

#include <CLI/CLI.hpp>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli/check_shards.hpp"
#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/json_input.hpp"
#include "report/provenance.hpp"
#include "report/shard_result.hpp"

namespace sfcv::cli {

namespace {

using nlohmann::json;

struct MergeOptions {
  std::vector<std::string> results;
  bool json = false;
  std::string junit, sarif, html, trace, trace_file, trace_dir, sarif_root;
};

struct Shard {
  std::string file;
  json doc;
  std::uint32_t index = 0, count = 0;
  bool diversify = false;
  std::vector<std::string> covers;
  logic::CheckReport report;
  report::Provenance provenance;
};

std::string shard_name(std::uint32_t i, std::uint32_t n) {
  return "shard " + std::to_string(i) + "/" + std::to_string(n);
}

/// The options of `sfcv check` that only choose where and how the answers are shown: merge
/// takes its own. Those after which a value follows are marked true.
const std::map<std::string, bool>& output_options() {
  static const std::map<std::string, bool> options = {
      {"--shard", true},     {"--diversify", false}, {"--json", false},      {"--junit", true},
      {"--sarif", true},     {"--html", true},       {"--trace", true},      {"--trace-file", true},
      {"--trace-dir", true}, {"--sarif-root", true}, {"--certificate", true}};
  return options;
}

/// The shard's command line without --shard and the output options: the check it split.
std::vector<std::string> check_words(const std::vector<std::string>& command_line) {
  std::vector<std::string> out;
  const auto& skip = output_options();
  for (std::size_t i = 0; i < command_line.size(); ++i) {
    const auto& w = command_line[i];
    const auto eq = w.find('=');
    const auto name = w.substr(0, eq);
    if (const auto s = skip.find(name); s != skip.end() && w.starts_with("--")) {
      if (s->second && eq == std::string::npos) ++i;  // its value follows
      continue;
    }
    out.push_back(w);
  }
  return out;
}

/// The run's command line as a single run would have had it: the shard's without --shard I/N
/// and --diversify (the outputs stay: the merged reports are those the shards were asked for).
std::vector<std::string> single_run_words(const std::vector<std::string>& command_line) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < command_line.size(); ++i) {
    const auto& w = command_line[i];
    if (w == "--shard") {
      ++i;
      continue;
    }
    if (w.starts_with("--shard=") || w == "--diversify") continue;
    out.push_back(w);
  }
  return out;
}

Shard read_shard(const std::string& file) {
  Shard s;
  s.file = file;
  s.doc = read_json_file(file, "the shard result", "not a JSON result of 'sfcv check --json'");
  const auto sh = s.doc.find("shard");
  if (!s.doc.is_object() || sh == s.doc.end() || !sh->is_object())
    throw UsageError(file + ": not the --json result of 'sfcv check --shard I/N' (no \"shard\")");
  try {
    s.index = sh->at("index");
    s.count = sh->at("count");
    s.diversify = sh->at("diversify");
    s.covers = sh->at("covers").get<std::vector<std::string>>();
    s.report = report::report_from_json(sh->at("result"));
    s.provenance = report::provenance_from_json(s.doc.at("provenance"));
    // In the order the check wrote them (the text report's order), not a JSON object's.
    s.provenance.settings = sh->at("settings").get<report::Settings>();
    s.provenance.libraries = sh->at("libraries").get<report::Settings>();
  } catch (const std::exception& e) {
    throw InputError(file + ": a bad \"shard\" object (" + e.what() + ")");
  }
  if (s.report.results.size() != s.covers.size())
    throw InputError(file + ": " + std::to_string(s.report.results.size()) + " answers for " +
                     std::to_string(s.covers.size()) + " units");
  return s;
}

/// Same model (SHA-256 of every input), options, engine, questions and split as `first`.
void expect_same_run(const Shard& first, const Shard& s) {
  auto digests = [](const Shard& x) {
    std::vector<std::string> d;
    for (const auto& in : x.provenance.inputs) d.push_back(in.sha256);
    return d;
  };
  if (digests(s) != digests(first))
    throw UsageError(s.file + ": another model than " + first.file +
                     " (the input files' SHA-256 differ): shards must check the same files");
  if (s.count != first.count || s.diversify != first.diversify)
    throw UsageError(s.file + ": " + shard_name(s.index, s.count) +
                     (s.diversify ? " --diversify" : "") + " is not of the split of " + first.file +
                     " (" + shard_name(first.index, first.count) +
                     (first.diversify ? " --diversify" : "") + ")");
  if (s.provenance.settings != first.provenance.settings ||
      s.provenance.engine != first.provenance.engine ||
      check_words(s.provenance.command_line) != check_words(first.provenance.command_line))
    throw UsageError(s.file + ": other options or properties than " + first.file +
                     " (their command lines differ beyond --shard and the outputs)");
  if (s.doc["shard"]["units"] != first.doc["shard"]["units"])
    throw UsageError(s.file + ": other work units than " + first.file);
  if (s.provenance.version != first.provenance.version ||
      s.provenance.commit != first.provenance.commit)
    throw UsageError(s.file + ": written by another sfcv (" + s.provenance.version + " " +
                     s.provenance.commit + ") than " + first.file);
}

/// Whether `a` counts more states than `b` (decimal strings of BigCount).
bool more_states(const logic::CheckReport& a, const logic::CheckReport& b) {
  if (a.states_known != b.states_known) return a.states_known;
  const auto x = a.states.str(), y = b.states.str();
  return x.size() != y.size() ? x.size() > y.size() : x > y;
}

bool definite(logic::Verdict v) {
  return v == logic::Verdict::Holds || v == logic::Verdict::Violated;
}

/// The report of the whole run: each unit's answer from the shard that ran it (a swarm: the
/// first definite answer in shard order, else the last shard's), the counts of the shard that
/// explored most and the deepest depth (a single run explores at least what each of its shards
/// did), complete only if every shard was.
logic::CheckReport merged_report(const std::vector<Shard>& shards, const json& units) {
  const Shard* primary = nullptr;
  for (const auto& s : shards)
    if (!s.covers.empty() && (!primary || more_states(s.report, primary->report))) primary = &s;
  logic::CheckReport out;
  if (primary) {
    out = primary->report;
    out.results.clear();
  }
  for (const auto& s : shards) {
    if (s.covers.empty()) continue;
    out.seconds = std::max(out.seconds, s.report.seconds);
    out.depth = std::max(out.depth, s.report.depth);  // BMC, IC3: the deepest any shard went
    if (!s.report.complete && out.complete) {
      out.complete = false;
      out.limit = s.report.limit;
    }
  }
  for (const auto& u : units) {
    const auto id = u.at("id").get<std::string>();
    const logic::PropertyResult* chosen = nullptr;
    const Shard* from = nullptr;
    for (const auto& s : shards)
      for (std::size_t k = 0; k < s.covers.size(); ++k) {
        if (s.covers[k] != id) continue;
        const auto& r = s.report.results[k];
        if (!chosen || (!definite(chosen->verdict) && (definite(r.verdict) || s.diversify))) {
          chosen = &r;
          from = &s;
        }
      }
    auto r = *chosen;
    if (r.decided_by.empty() && from->report.engine != out.engine)
      r.decided_by = from->report.engine;
    out.results.push_back(std::move(r));
  }
  return out;
}

int run_merge(const MergeOptions& o) {
  std::vector<Shard> shards;
  for (const auto& f : o.results) shards.push_back(read_shard(f));
  std::map<std::uint32_t, const Shard*> by_index;
  for (const auto& s : shards) {
    expect_same_run(shards.front(), s);
    if (const auto [it, fresh] = by_index.emplace(s.index, &s); !fresh)
      throw UsageError(shard_name(s.index, s.count) + " given twice (" + it->second->file + ", " +
                       s.file + ")");
  }
  const auto count = shards.front().count;
  std::string missing;
  for (std::uint32_t i = 1; i <= count; ++i)
    if (!by_index.count(i)) missing += (missing.empty() ? "" : ", ") + shard_name(i, count);
  if (!missing.empty()) throw UsageError(missing + " missing");
  // Shards in their order; each unit covered once (a swarm: by every shard).
  std::vector<Shard> ordered;
  for (const auto& [i, s] : by_index) ordered.push_back(*s);
  const auto& units = ordered.front().doc["shard"]["units"];
  std::map<std::string, int> covered;
  for (const auto& s : ordered)
    for (const auto& id : s.covers) ++covered[id];
  const int expected = ordered.front().diversify ? static_cast<int>(count) : 1;
  for (const auto& u : units) {
    const auto id = u.at("id").get<std::string>();
    if (covered[id] != expected)
      throw UsageError("unit " + id + " is covered " + std::to_string(covered[id]) +
                       " times by the shards (expected " + std::to_string(expected) + ")");
    covered.erase(id);
  }
  if (!covered.empty())
    throw UsageError("unit " + covered.begin()->first + " is not a unit of the run");
  // The model must be the one the shards checked: traces are packed states of its system.
  const auto& model = ordered.front().provenance.inputs;
  for (const auto& in : model)
    if (report::digest_file(in.path).sha256 != in.sha256)
      throw UsageError(in.path + " is not the file the shards checked (its SHA-256 changed)");

  StoredRun stored;
  stored.report = merged_report(ordered, units);
  stored.provenance = ordered.front().provenance;
  stored.provenance.command_line = single_run_words(stored.provenance.command_line);
  stored.diversified = ordered.front().diversify;

  // The check command on the shards' command line, with merge's outputs.
  auto argv_words = check_words(ordered.front().provenance.command_line);
  if (argv_words.size() < 2) throw InputError(ordered.front().file + ": no command line");
  argv_words[0] = global_options().argv.empty() ? "sfcv" : global_options().argv.front();
  auto add = [&](const char* option, const std::string& value) {
    if (value.empty()) return;
    argv_words.push_back(option);
    argv_words.push_back(value);
  };
  if (o.json) argv_words.push_back("--json");
  add("--junit", o.junit);
  add("--sarif", o.sarif);
  add("--html", o.html);
  add("--trace", o.trace);
  add("--trace-file", o.trace_file);
  add("--trace-dir", o.trace_dir);
  add("--sarif-root", o.sarif_root);
  if (global_options().quiet) argv_words.push_back("--quiet");
  if (global_options().verbose) argv_words.push_back("--verbose");
  std::vector<char*> argv;
  for (auto& w : argv_words) argv.push_back(w.data());
  argv.push_back(nullptr);
  set_stored_run(&stored);
  struct Reset {
    ~Reset() { set_stored_run(nullptr); }
  } reset;
  return run(static_cast<int>(argv_words.size()), argv.data());
}

}  // namespace

void add_merge_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<MergeOptions>();
  auto* sub = app.add_subcommand(
      "merge",
      "Join the --json results of 'sfcv check --shard I/N' into the report of a single run "
      "(docs/distributed.md)");
  sub->add_option("results", opts->results, "The shards' JSON results, one per shard")->required();
  sub->add_flag("--json", opts->json, "JSON output, as sfcv check --json");
  sub->add_option("--junit", opts->junit, "Also write a JUnit XML report there");
  sub->add_option("--sarif", opts->sarif, "Also write a SARIF 2.1.0 log there");
  sub->add_option("--html", opts->html, "Also write the HTML report there");
  sub->add_option("--trace", opts->trace, "Trace format, as sfcv check --trace");
  sub->add_option("--trace-file", opts->trace_file, "As sfcv check --trace-file");
  sub->add_option("--trace-dir", opts->trace_dir, "As sfcv check --trace-dir");
  sub->add_option("--sarif-root", opts->sarif_root, "As sfcv check --sarif-root");
  sub->footer(
      "Exit codes: as sfcv check on the whole run (0 all hold, 1 some violated, 3 unknown); 2 "
      "when a shard is missing or given twice, or the shards differ in model, options or "
      "split.");
  sub->callback([opts, &selected] { selected = [opts] { return run_merge(*opts); }; });
}

}  // namespace sfcv::cli
