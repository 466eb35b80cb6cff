// sfcv query: evaluates set queries (docs/queries.md) on the reachable situations graph and
// prints the sets themselves: all faulty situations, all evolutions leading into them.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "cli/output_file.hpp"
#include "cli/run_guard.hpp"
#include "cli/shipped_files.hpp"
#include "cli/system_options.hpp"
#include "engine/bdd/symbolic_query_evaluator.hpp"  // SymbolicQueryError
#include "engine/explicit/query_evaluator.hpp"      // QueryEvaluationError
#include "engine/query/query_service.hpp"
#include "logic/query_compile.hpp"
#include "report/check_html.hpp"
#include "report/query_render.hpp"
#include "report/schema_versions.hpp"
#include "report/text_encoding.hpp"

#ifndef SFCV_SHARE_DIR
#define SFCV_SHARE_DIR ""
#endif

namespace sfcv::cli {

namespace {

struct QueryOptions {
  std::string model;
  std::string format = "auto";
  std::vector<std::string> queries;
  std::uint64_t max_elements = 0;
  std::vector<std::string> uses;
  std::vector<std::string> libraries;
  bool no_default_library = false;
  bool list = false;
  bool json = false;
  std::string html;
  bool assert_empty = false;
  SystemOptions system;
  LimitOptions limits;
  std::string engine = "explicit";
};

/// The shipped library: <prefix>/share/sfcv next to an installed binary, else the source tree.
std::string default_library_path() {
  return shipped_file("properties.sfq");
}

/// "query:1:5: message" followed by the query line and a caret under the column.
std::string located(const logic::QueryError& e, const std::string& text,
                    const std::string& source_name) {
  std::string out = e.what();
  if (!e.pos().source || *e.pos().source != source_name) return out;
  std::size_t line_start = 0;
  for (std::uint32_t l = 1; l < e.pos().line; ++l) {
    const auto nl = text.find('\n', line_start);
    if (nl == std::string::npos) return out;
    line_start = nl + 1;
  }
  const auto line_end = text.find('\n', line_start);
  out += "\n  " + text.substr(line_start, line_end == std::string::npos ? std::string::npos
                                                                        : line_end - line_start);
  out += "\n  " + std::string(e.pos().column > 0 ? e.pos().column - 1 : 0, ' ') + "^";
  return out;
}

int run_query(const QueryOptions& o, const RunGuard& guard) {
  const OutputPath html{o.html, "--html"};
  check_output_paths({html});
  const model::Budget& budget = guard.budget();  // one budget for every phase
  // Library first: its errors are the user's files, independent of the model.
  logic::QueryLibrary library;
  std::string default_lib;
  try {
    if (!o.no_default_library) {
      default_lib = default_library_path();
      if (!default_lib.empty()) library.add_file(default_lib);
    }
    for (const auto& f : o.libraries) library.add_file(f);
  } catch (const logic::QueryError& e) {
    throw InputError(e.what());
  }
  if (o.list) {
    for (const auto& [key, d] : library.definitions()) {
      std::string params;
      for (const auto& p : d.params) params += (params.empty() ? "" : ", ") + p;
      std::cout << d.name << "(" << params << ") = " << logic::to_string(*d.body) << ";\n";
      std::string doc = d.doc;
      for (std::size_t at = 0; !doc.empty() && at < doc.size();) {
        const auto nl = doc.find('\n', at);
        std::cout << "    // " << doc.substr(at, nl - at) << "\n";
        at = nl == std::string::npos ? doc.size() : nl + 1;
      }
    }
    if (o.model.empty()) return kHolds;
  }

  struct Item {
    std::string text, source;
  };
  std::vector<Item> items;
  for (const auto& q : o.queries) items.push_back({q, "query"});
  for (const auto& u : o.uses) items.push_back({u, "--use"});
  if (items.empty()) {
    if (o.list) return kHolds;
    throw InputError(
        "give a query, e.g. 'Y - Pred(Y0, T)', or --use NAME(ARGS) (--list shows "
        "the library)");
  }
  if (o.model.empty()) throw InputError("a model file is required");

  const auto project = load_model_or_throw(o.model, parse_format(o.format), false, &budget);
  const auto built = build_system(project, o.system, {}, "sfcv query",
                                  semantics::ActionOrder::Declaration, &budget);
  const auto& ts = built.system;
  const std::string& kind = built.semantics;

  // Compile every query before exploring: name and sort errors come without waiting.
  std::vector<logic::CompiledQuery> compiled;
  for (const auto& it : items) {
    try {
      compiled.push_back(logic::compile_query(it.text, library, *ts, it.source));
    } catch (const logic::QueryError& e) {
      std::string msg = located(e, it.text, it.source);
      if (default_lib.empty() && !o.no_default_library &&
          e.message().find("unknown operator or definition") != std::string::npos)
        msg += "\n  note: the shipped library share/sfcv/properties.sfq was not found";
      throw InputError(msg);
    }
    if (o.assert_empty && compiled.back().root.sort == logic::Sort::Int)
      throw InputError("--assert: '" + it.text + "' is a number; assert a test or a set");
  }

  // The engine: explicit (the RSG) or symbolic (BDDs, IEC 61131-3 only for now).
  engine::QueryServiceOptions so;
  so.budget = &budget;
  if (o.engine == "explicit") {
    so.engine = engine::QueryEngineChoice::Explicit;
  } else if (o.engine == "bdd") {
    so.engine = engine::QueryEngineChoice::Bdd;
  } else if (o.engine == "auto") {
    so.engine = engine::QueryEngineChoice::Auto;
    so.note = [](const std::string& text) { std::cerr << "sfcv: --engine auto: " << text << "\n"; };
  } else {
    throw InputError("unknown --engine '" + o.engine + "' (expected explicit, bdd or auto)");
  }
  engine::QueryServicePtr service;
  try {
    service = engine::make_query_service(*ts, so);
  } catch (const UnsupportedConstruct& e) {
    throw InputError(std::string("sfcv query --engine bdd: ") + e.what());
  } catch (const LimitReached& e) {
    std::cerr << "sfcv query: unknown: " << guard.reason(e).what() << "\n";
    return kUnknown;
  }
  const auto& graph = service->graph();
  const report::QueryPrinter pr(*ts, o.max_elements);
  for (const auto& line : pr.graph_warnings(graph)) std::cerr << line << "\n";

  nlohmann::json jout;
  const bool want_json = o.json || !o.html.empty();  // --html renders the JSON answers
  if (want_json) {
    jout["schema_version"] = report::kSummaryJsonSchemaVersion;
    jout["model"] = o.model;
    jout["semantics"] = kind;
    jout["graph"] = pr.graph_json(graph);
    jout["queries"] = nlohmann::json::array();
  }
  if (!o.json) std::cout << pr.graph_line(graph, kind) << "\n";

  bool any_violated = false, any_unknown = false;
  for (std::size_t i = 0; i < compiled.size(); ++i) {
    logic::QueryAnswer r;
    try {
      r = service->answer(compiled[i]);
    } catch (const engine::QueryEvaluationError& e) {
      throw InputError(items[i].text + ": " + e.what());
    } catch (const engine::SymbolicQueryError& e) {
      throw InputError(items[i].text + ": " + e.what());
    } catch (const std::length_error& e) {
      throw InputError(items[i].text + ": the set is too large to list (" + e.what() + ")");
    } catch (const LimitReached& e) {
      // The answers so far are printed; the rest is unknown.
      std::cerr << "sfcv query: unknown: " << guard.reason(e).what() << "\n";
      if (o.json) {
        jout["limit"] = guard.reason(e).what();
        report::make_valid_utf8(jout);
        std::cout << jout.dump(2) << "\n";
      }
      return kUnknown;
    }
    // --assert: a test gives its verdict; a set is asserted empty (library properties are the
    // sets of faulty elements).
    std::optional<logic::Verdict> verdict;
    if (o.assert_empty) {
      verdict = report::query_verdict(r, graph);
      any_violated |= verdict == logic::Verdict::Violated;
      any_unknown |= verdict == logic::Verdict::Unknown;
    }
    if (want_json) jout["queries"].push_back(pr.answer_json(items[i].text, r, verdict));
    if (!o.json) pr.answer_text(items[i].text, r, verdict, graph, std::cout);
  }
  report::make_valid_utf8(jout);  // the model's path is bytes too
  if (o.json) std::cout << jout.dump(2) << "\n";
  if (!o.html.empty()) {
    guard.check("writing the HTML report");
    write_output(html, report::query_html(
                           jout, report::html_pictures(project, *ts, {}, picture_limits(budget))));
  }
  int exit_code = kHolds;
  if (o.assert_empty) exit_code = any_violated ? kViolated : any_unknown ? kUnknown : kHolds;
  if (!graph.complete && exit_code == kHolds) exit_code = kUnknown;
  return exit_code;
}

}  // namespace

void add_query_command(CLI::App& app, CommandRunner& selected) {
  auto opts = std::make_shared<QueryOptions>();
  auto* sub = app.add_subcommand(
      "query", "Evaluate set queries over the reachable situations graph (docs/queries.md)");
  sub->add_option("model", opts->model, "Chart file (PLCopen XML, IEC text, .g7, AGRAFE .grafcet)");
  sub->add_option("query", opts->queries, "Queries, e.g. 'Y - Pred(Y0, T)' (each is evaluated)");
  sub->add_option("--max-elements", opts->max_elements,
                  "Print at most N elements of each set (0, the default: all)");
  sub->add_option("--use", opts->uses,
                  "A library property, e.g. 'mutex(V1, V2)' (repeatable; each is evaluated)");
  sub->add_option("--library", opts->libraries,
                  "An extra library file of 'def name(args) = query;' (repeatable; later "
                  "definitions replace earlier ones)");
  sub->add_flag("--no-default-library", opts->no_default_library,
                "Do not load the shipped share/sfcv/properties.sfq");
  sub->add_flag("--list", opts->list, "List the library definitions");
  sub->add_flag("--json", opts->json, "Print the results as JSON");
  sub->add_option("--html", opts->html,
                  "Write the answers, the chart and the situation graph as one HTML page");
  sub->add_flag("--assert", opts->assert_empty,
                "Verdicts: a test must be true, a set must be empty (exit 0 holds, 1 violated, "
                "3 unknown)");
  add_system_options(*sub, opts->system);
  sub->add_option("--engine", opts->engine,
                  "explicit (default: the graph), bdd (symbolic, IEC 61131-3 charts) or auto "
                  "(explicit up to " +
                      std::to_string(engine::kAutoProbeStates) + " situations, then bdd)");
  add_limit_options(*sub, opts->limits, "the graph is incomplete");
  sub->add_option("--format", opts->format, kFormatHelp);
  sub->callback([opts, &selected] {
    selected = [opts] {
      return run_limited(opts->limits, [&](const RunGuard& g) { return run_query(*opts, g); });
    };
  });
}

}  // namespace sfcv::cli
