// sfcv query: evaluates set queries (docs/queries.md) on the reachable situations graph and
// prints the sets themselves: all faulty situations, all evolutions leading into them.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "cli/system_options.hpp"
#include "engine/explicit/query_evaluator.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "logic/query_compile.hpp"
#include "semantics/iec61131_system.hpp"  // SemanticsLimitError

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
  bool assert_empty = false;
  SystemOptions system;
  std::uint64_t max_states = 0;
  double timeout = 0;
};

/// The shipped library: <prefix>/share/sfcv next to an installed binary, else the source tree.
std::string default_library_path() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = exe.parent_path().parent_path() / "share" / "sfcv" / "properties.sfq";
    if (fs::exists(installed, ec)) return installed.string();
  }
  const fs::path source = fs::path(SFCV_SHARE_DIR) / "properties.sfq";
  if (!std::string(SFCV_SHARE_DIR).empty() && fs::exists(source, ec)) return source.string();
  return {};
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

/// Steps and true Boolean outputs (TransitionSystem::describe), then the other true Boolean
/// variables (for Grafcet: the input values the stable situation was reached with), which tell
/// apart states with the same situation.
std::string describe_state(const semantics::TransitionSystem& ts, semantics::StateView s) {
  std::string out = ts.describe(s), rest;
  const auto& obs = ts.observables();
  for (std::uint32_t i = 0; i < obs.size(); ++i) {
    if (obs[i].kind != semantics::ObservableKind::Variable || obs[i].is_output) continue;
    const auto v = ts.observe(s, i);
    if (obs[i].type.kind == model::TypeKind::Bool) {
      if (v) rest += " " + obs[i].name;
    } else {
      rest += " " + obs[i].name + "=" + std::to_string(v);
    }
  }
  return rest.empty() ? out : out + " |" + rest;
}

std::string sort_noun(logic::Sort s, std::uint64_t n) {
  switch (s) {
    case logic::Sort::States: return n == 1 ? "situation" : "situations";
    case logic::Sort::Evolutions: return n == 1 ? "evolution" : "evolutions";
    case logic::Sort::Steps: return n == 1 ? "step" : "steps";
    default: return n == 1 ? "element" : "elements";
  }
}

std::string sort_key(logic::Sort s) {
  switch (s) {
    case logic::Sort::States: return "situations";
    case logic::Sort::Evolutions: return "evolutions";
    case logic::Sort::Steps: return "steps";
    case logic::Sort::Empty: return "empty";
    case logic::Sort::Bool: return "test";
    case logic::Sort::Int: return "number";
  }
  return "?";
}

struct Printer {
  const engine::ReachableSituationGraph& g;
  const engine::QueryEvaluator& ev;
  std::uint64_t max_elements = 0;

  std::string state(std::uint64_t s) const {
    return describe_state(g.system(), g.states().at(static_cast<std::uint32_t>(s)));
  }
  std::string edge(std::uint64_t e) const {
    return "#" + std::to_string(ev.source(e)) + " " + state(ev.source(e)) + " --[" +
           g.condition(e).to_string(g.system().inputs()) + "]--> #" +
           std::to_string(g.target(e)) + " " + state(g.target(e));
  }
  void text(logic::Sort sort, const engine::DynamicBitset& set, std::ostream& out) const {
    const auto n = set.count();
    out << "  " << n << " " << sort_noun(sort, n);
    if (sort == logic::Sort::States && n) {
      // RSG states also hold the input values; say how many situations they are.
      std::set<std::vector<std::uint32_t>> situations;
      const auto& obs = g.system().observables();
      set.for_each([&](std::uint64_t i) {
        const auto st = g.states().at(static_cast<std::uint32_t>(i));
        std::vector<std::uint32_t> active;
        for (std::uint32_t o = 0; o < obs.size(); ++o)
          if (obs[o].kind == semantics::ObservableKind::Step && g.system().observe(st, o))
            active.push_back(o);
        situations.insert(std::move(active));
      });
      if (situations.size() != n) out << " (" << situations.size() << " distinct step sets)";
    }
    out << (n ? ":" : "") << "\n";
    std::uint64_t shown = 0;
    set.for_each([&](std::uint64_t i) {
      if (max_elements && shown++ >= max_elements) return;
      switch (sort) {
        case logic::Sort::States: out << "    #" << i << " " << state(i) << "\n"; break;
        case logic::Sort::Evolutions: out << "    " << edge(i) << "\n"; break;
        case logic::Sort::Steps: out << "    " << g.system().observables()[i].name << "\n"; break;
        default: break;
      }
    });
    if (max_elements && n > max_elements)
      out << "    ... and " << n - max_elements << " more (--max-elements)\n";
  }
  nlohmann::json json(logic::Sort sort, const engine::DynamicBitset& set) const {
    auto arr = nlohmann::json::array();
    const auto& ts = g.system();
    const auto& obs = ts.observables();
    set.for_each([&](std::uint64_t i) {
      if (sort == logic::Sort::States) {
        const auto st = g.states().at(static_cast<std::uint32_t>(i));
        nlohmann::json steps = nlohmann::json::array(), outputs = nlohmann::json::object();
        for (std::uint32_t o = 0; o < obs.size(); ++o) {
          if (obs[o].kind == semantics::ObservableKind::Step) {
            if (ts.observe(st, o)) steps.push_back(obs[o].name);
          } else if (obs[o].is_output) {
            outputs[obs[o].name] = ts.observe(st, o);
          }
        }
        arr.push_back({{"id", i}, {"steps", steps}, {"outputs", outputs}, {"text", state(i)}});
      } else if (sort == logic::Sort::Evolutions) {
        nlohmann::json fired = nlohmann::json::array();
        for (auto t : g.fired(i)) fired.push_back(ts.transitions()[t].name);
        arr.push_back({{"id", i},
                       {"source", ev.source(i)},
                       {"target", g.target(i)},
                       {"condition", g.condition(i).to_string(ts.inputs())},
                       {"fired", fired},
                       {"text", edge(i)}});
      } else if (sort == logic::Sort::Steps) {
        arr.push_back(obs[i].name);
      }
    });
    return arr;
  }
};

int run_query(const QueryOptions& o) {
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
    throw InputError("give a query, e.g. 'Y - Pred(Y0, T)', or --use NAME(ARGS) (--list shows "
                     "the library)");
  }
  if (o.model.empty()) throw InputError("a model file is required");

  const auto project = load_model_or_throw(o.model, parse_format(o.format));
  const auto built = build_system(project, o.system, {}, "sfcv query");
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

  engine::ExplorationOptions eo;
  eo.max_states = o.max_states;
  eo.timeout_seconds = o.timeout;
  eo.keep_conditions = true;
  eo.keep_fired = true;  // Tclear
  engine::ReachableSituationGraph graph = [&] {
    try {
      return engine::build_reachable_situation_graph(*ts, eo);
    } catch (const semantics::SemanticsLimitError& e) {
      throw InputError(e.what());
    }
  }();
  engine::QueryEvaluator ev(graph);
  const Printer pr{graph, ev, o.max_elements};

  const bool complete = graph.complete();
  const bool exact = complete && graph.anomalies().empty();
  if (!complete)
    std::cerr << "warning: the graph is incomplete (limit reached: " << graph.limit_reached()
              << "): the sets below are computed on a partial graph and may be wrong in both "
                 "directions\n";
  for (const auto& a : graph.anomalies())
    std::cerr << "warning: " << a.message << " (under " << a.condition.to_string(ts->inputs())
              << "): the evolutions it cuts are missing from the graph\n";

  nlohmann::json jout;
  if (o.json) {
    jout["model"] = o.model;
    jout["semantics"] = kind;
    jout["graph"] = {{"situations", graph.num_states()},
                     {"evolutions", graph.num_edges()},
                     {"complete", complete},
                     {"limit", graph.limit_reached()},
                     {"anomalies", graph.anomalies().size()}};
    jout["queries"] = nlohmann::json::array();
  } else {
    std::cout << "graph: " << graph.num_states() << " situations, " << graph.num_edges()
              << " evolutions (" << kind << (complete ? ", complete" : ", INCOMPLETE") << ")\n";
  }

  int exit_code = kHolds;
  bool any_violated = false, any_unknown = false;
  for (std::size_t i = 0; i < compiled.size(); ++i) {
    const auto& q = compiled[i];
    engine::QueryResult r;
    try {
      r = ev.evaluate(q);
    } catch (const engine::QueryEvaluationError& e) {
      throw InputError(items[i].text + ": " + e.what());
    }
    // --assert: a test gives its verdict; a set is asserted empty (library properties are the
    // sets of faulty elements). Only an exact graph gives a verdict.
    std::string verdict;
    if (o.assert_empty) {
      const bool holds = r.sort == logic::Sort::Bool ? r.truth : r.set.none();
      verdict = !exact ? "unknown" : holds ? "holds" : "violated";
      any_violated |= verdict == "violated";
      any_unknown |= verdict == "unknown";
    }
    if (o.json) {
      nlohmann::json jq;
      jq["query"] = items[i].text;
      jq["sort"] = sort_key(r.sort);
      if (r.sort == logic::Sort::Bool) {
        jq["value"] = r.truth;
        if (r.witness_sort) {
          jq["witness_sort"] = sort_key(*r.witness_sort);
          jq["count"] = r.witness.count();
          jq["elements"] = pr.json(*r.witness_sort, r.witness);
        }
      } else if (r.sort == logic::Sort::Int) {
        jq["value"] = r.number;
      } else {
        jq["count"] = r.set.count();
        jq["elements"] = pr.json(r.sort, r.set);
      }
      if (!verdict.empty()) jq["verdict"] = verdict;
      jout["queries"].push_back(jq);
      continue;
    }
    std::cout << "query: " << items[i].text << "\n";
    if (r.sort == logic::Sort::Bool) {
      std::cout << "  " << (r.truth ? "true" : "false") << "\n";
      if (r.witness_sort) pr.text(*r.witness_sort, r.witness, std::cout);
    } else if (r.sort == logic::Sort::Int) {
      std::cout << "  " << r.number << "\n";
    } else {
      pr.text(r.sort, r.set, std::cout);
    }
    if (verdict == "holds") std::cout << "  holds\n";
    if (verdict == "violated")
      std::cout << "  VIOLATED" << (r.sort == logic::Sort::Bool ? "" : " (the set is not empty)")
                << "\n";
    if (verdict == "unknown")
      std::cout << "  unknown: " << (complete ? "the graph has anomalies"
                                              : "the graph is incomplete")
                << "\n";
  }
  if (o.json) std::cout << jout.dump(2) << "\n";
  if (o.assert_empty) exit_code = any_violated ? kViolated : any_unknown ? kUnknown : kHolds;
  if (!complete && exit_code == kHolds) exit_code = kUnknown;
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
  sub->add_flag("--assert", opts->assert_empty,
                "Verdicts: a test must be true, a set must be empty (exit 0 holds, 1 violated, "
                "3 unknown)");
  add_system_options(*sub, opts->system);
  sub->add_option("--max-states", opts->max_states, "Stop exploring after N situations");
  sub->add_option("--timeout", opts->timeout, "Stop exploring after S seconds");
  sub->add_option("--format", opts->format, "Input format: auto, xml, iec, g7, agrafe");
  sub->callback([opts, &selected] {
    selected = [opts] { return run_query(*opts); };
  });
}

}  // namespace sfcv::cli
