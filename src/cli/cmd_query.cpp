// sfcv query: evaluates set queries (docs/queries.md) on the reachable situations graph and
// prints the sets themselves: all faulty situations, all evolutions leading into them.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "cli/run_limits.hpp"
#include "cli/system_options.hpp"
#include "engine/bdd/bdd_manager.hpp"
#include "engine/bdd/symbolic_query_evaluator.hpp"
#include "engine/explicit/canonical_order.hpp"
#include "engine/explicit/query_evaluator.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "logic/query_compile.hpp"
#include "report/check_html.hpp"
#include "semantics/iec61131_circuit.hpp"
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
  std::string html;
  bool assert_empty = false;
  SystemOptions system;
  LimitOptions limits;
  std::string engine = "explicit";
};

// --engine auto: as `sfcv check`, the explicit graph up to this many situations, then BDDs.
constexpr std::uint64_t kAutoExplicitStates = 200'000;

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

/// A set ready to print, the same whichever engine computed it: situations numbered by
/// (breadth-first depth, canonical order), evolutions by (source, target) number, both sorted.
struct Listing {
  struct State {
    std::uint64_t id = 0;
    std::vector<semantics::StateWord> state;
  };
  struct Edge {
    std::uint64_t id = 0;
    State source, target;
    semantics::InputCondition condition;
    std::vector<std::uint32_t> fired;
  };
  logic::Sort sort = logic::Sort::Empty;
  std::vector<State> states;
  std::vector<Edge> edges;
  std::vector<std::uint32_t> steps;
  std::uint64_t count() const { return states.size() + edges.size() + steps.size(); }
};

struct Printer {
  const semantics::TransitionSystem& ts;
  std::uint64_t max_elements = 0;

  std::string state(const Listing::State& s) const {
    return "#" + std::to_string(s.id) + " " + describe_state(ts, s.state);
  }
  std::string edge(const Listing::Edge& e) const {
    return state(e.source) + " --[" + e.condition.to_string(ts.inputs()) + "]--> " +
           state(e.target);
  }
  void text(const Listing& l, std::ostream& out) const {
    const auto n = l.count();
    out << "  " << n << " " << sort_noun(l.sort, n);
    if (l.sort == logic::Sort::States && n) {
      // RSG states also hold the input values; say how many situations they are.
      std::set<std::vector<std::uint32_t>> situations;
      const auto& obs = ts.observables();
      for (const auto& s : l.states) {
        std::vector<std::uint32_t> active;
        for (std::uint32_t o = 0; o < obs.size(); ++o)
          if (obs[o].kind == semantics::ObservableKind::Step && ts.observe(s.state, o))
            active.push_back(o);
        situations.insert(std::move(active));
      }
      if (situations.size() != n) out << " (" << situations.size() << " distinct step sets)";
    }
    out << (n ? ":" : "") << "\n";
    std::uint64_t shown = 0;
    auto room = [&] { return !max_elements || shown++ < max_elements; };
    for (const auto& s : l.states)
      if (room()) out << "    " << state(s) << "\n";
    for (const auto& e : l.edges)
      if (room()) out << "    " << edge(e) << "\n";
    for (const auto o : l.steps)
      if (room()) out << "    " << ts.observables()[o].name << "\n";
    if (max_elements && n > max_elements)
      out << "    ... and " << n - max_elements << " more (--max-elements)\n";
  }
  nlohmann::json json(const Listing& l) const {
    auto arr = nlohmann::json::array();
    const auto& obs = ts.observables();
    for (const auto& s : l.states) {
      nlohmann::json steps = nlohmann::json::array(), outputs = nlohmann::json::object();
      for (std::uint32_t o = 0; o < obs.size(); ++o) {
        if (obs[o].kind == semantics::ObservableKind::Step) {
          if (ts.observe(s.state, o)) steps.push_back(obs[o].name);
        } else if (obs[o].is_output) {
          outputs[obs[o].name] = ts.observe(s.state, o);
        }
      }
      arr.push_back({{"id", s.id}, {"steps", steps}, {"outputs", outputs}, {"text", state(s)}});
    }
    for (const auto& e : l.edges) {
      nlohmann::json fired = nlohmann::json::array();
      for (auto t : e.fired) fired.push_back(ts.transitions()[t].name);
      arr.push_back({{"id", e.id},
                     {"source", e.source.id},
                     {"target", e.target.id},
                     {"condition", e.condition.to_string(ts.inputs())},
                     {"fired", fired},
                     {"text", edge(e)}});
    }
    for (const auto o : l.steps) arr.push_back(obs[o].name);
    return arr;
  }
};

/// A query's answer, with its sets as listings.
struct Answer {
  logic::Sort sort = logic::Sort::Empty;
  Listing set;
  bool truth = false;
  std::int64_t number = 0;
  std::optional<logic::Sort> witness_sort;
  Listing witness;
};

/// What an engine says about the whole graph, and how it answers one query.
struct QueryEngine {
  std::uint64_t situations = 0, evolutions = 0;
  bool complete = true;
  std::string limit;
  std::vector<semantics::Anomaly> anomalies;
  std::function<Answer(const logic::CompiledQuery&)> answer;
};

/// The explicit engine: the RSG, bitsets, listings in canonical order.
struct ExplicitEngine {
  engine::ReachableSituationGraph graph;
  engine::QueryEvaluator ev;
  engine::CanonicalNumbering numbering;

  ExplicitEngine(engine::ReachableSituationGraph g)
      : graph(std::move(g)), ev(graph), numbering(engine::canonical_numbering(graph, ev.sources())) {}

  Listing::State state(std::uint32_t s) const {
    const auto v = graph.states().at(s);
    return {numbering.state[s], {v.begin(), v.end()}};
  }
  Listing listing(logic::Sort sort, const engine::DynamicBitset& set) const {
    Listing l;
    l.sort = sort;
    set.for_each([&](std::uint64_t i) {
      if (sort == logic::Sort::States) {
        l.states.push_back(state(static_cast<std::uint32_t>(i)));
      } else if (sort == logic::Sort::Evolutions) {
        const auto f = graph.fired(i);
        l.edges.push_back({numbering.edge[i], state(ev.source(i)), state(graph.target(i)),
                           graph.condition(i), {f.begin(), f.end()}});
      } else if (sort == logic::Sort::Steps) {
        l.steps.push_back(static_cast<std::uint32_t>(i));
      }
    });
    std::sort(l.states.begin(), l.states.end(), [](auto& a, auto& b) { return a.id < b.id; });
    std::sort(l.edges.begin(), l.edges.end(), [](auto& a, auto& b) { return a.id < b.id; });
    return l;
  }
  Answer answer(const logic::CompiledQuery& q) {
    engine::QueryResult r;
    r = ev.evaluate(q);
    Answer a;
    a.sort = r.sort;
    a.truth = r.truth;
    a.number = r.number;
    if (r.sort != logic::Sort::Bool && r.sort != logic::Sort::Int) a.set = listing(r.sort, r.set);
    a.witness_sort = r.witness_sort;
    if (r.witness_sort) a.witness = listing(*r.witness_sort, r.witness);
    return a;
  }
};

/// The symbolic engine: BDD sets, enumerated for listing; labels come from the semantics.
struct SymbolicEngine {
  static constexpr std::uint64_t kMaxListed = 10'000'000;
  engine::SymbolicSystem sys;
  engine::SymbolicQueryEvaluator ev;

  SymbolicEngine(const semantics::TransitionSystem& ts, semantics::TransitionCircuit circuit,
                 const engine::SymbolicQueryOptions& options)
      : sys(ts, std::move(circuit)), ev(sys, options) {}

  Listing listing(logic::Sort sort, const engine::SymbolicSet& set) const {
    const auto& ts = sys.system();
    Listing l;
    l.sort = sort;
    if (sort == logic::Sort::States) {
      for (auto& s : ev.states_of(set.bdd, kMaxListed))
        l.states.push_back({ev.state_id(s), std::move(s)});
    } else if (sort == logic::Sort::Evolutions) {
      std::map<std::vector<semantics::StateWord>, std::uint64_t> ids;
      auto id = [&](const std::vector<semantics::StateWord>& s) {
        auto it = ids.find(s);
        if (it == ids.end()) it = ids.emplace(s, ev.state_id(s)).first;
        return it->second;
      };
      for (auto& [src, dst] : ev.evolutions_of(set.bdd, kMaxListed)) {
        auto label = engine::evolution_label(ts, src, dst);
        l.edges.push_back({ev.evolution_id(src, dst),
                           {id(src), src},
                           {id(dst), dst},
                           std::move(label.condition),
                           std::move(label.fired)});
      }
    } else if (sort == logic::Sort::Steps) {
      set.steps.for_each([&](std::uint64_t o) { l.steps.push_back(static_cast<std::uint32_t>(o)); });
    }
    std::sort(l.states.begin(), l.states.end(), [](auto& a, auto& b) { return a.id < b.id; });
    std::sort(l.edges.begin(), l.edges.end(), [](auto& a, auto& b) { return a.id < b.id; });
    return l;
  }
  Answer answer(const logic::CompiledQuery& q) {
    const auto r = ev.evaluate(q);
    Answer a;
    a.sort = r.sort;
    a.truth = r.truth;
    a.number = r.number;
    if (r.sort != logic::Sort::Bool && r.sort != logic::Sort::Int) a.set = listing(r.sort, r.set);
    a.witness_sort = r.witness_sort;
    if (r.witness_sort) a.witness = listing(*r.witness_sort, r.witness);
    return a;
  }
  /// The anomalies the explicit graph would record: those of the initial states and of every
  /// reachable situation that raises a range error, from the semantics itself.
  std::vector<semantics::Anomaly> anomalies() const {
    struct Sink final : semantics::SuccessorSink {
      std::vector<semantics::Anomaly> found;
      void successor(const semantics::Successor&) override {}
      void anomaly(const semantics::Anomaly& a) override { found.push_back(a); }
    } sink;
    const auto& ts = sys.system();
    ts.initial_states(sink);
    auto errors = ev.states_of(ev.range_error_states(), kMaxListed);
    std::vector<std::pair<std::uint64_t, std::vector<semantics::StateWord>>> ordered;
    for (auto& s : errors) ordered.emplace_back(ev.state_id(s), std::move(s));
    std::sort(ordered.begin(), ordered.end());
    for (const auto& [id, s] : ordered) ts.successors(s, sink);
    return std::move(sink.found);
  }
};

int run_query(const QueryOptions& o) {
  const model::Budget budget = make_budget(o.limits);  // one deadline for every phase
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
  const auto built = build_system(project, o.system, {}, "sfcv query", semantics::ActionOrder::Declaration,
                                  &budget);
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
  std::string engine_name = o.engine;
  if (engine_name != "explicit" && engine_name != "bdd" && engine_name != "auto")
    throw InputError("unknown --engine '" + o.engine + "' (expected explicit, bdd or auto)");
  std::optional<semantics::TransitionCircuit> circuit;
  std::string why;
  if (engine_name != "explicit") {
    if (ts->kind() != semantics::SemanticsKind::Iec61131) {
      why = "the BDD engine does not support the Grafcet semantics yet";
    } else {
      try {
        circuit = semantics::build_iec61131_circuit(*ts);
      } catch (const semantics::CircuitUnsupported& e) {
        why = std::string("the BDD engine cannot encode ") + e.what();
      }
    }
    if (engine_name == "bdd" && !circuit)
      throw InputError("sfcv query --engine bdd: " + why + " (use --engine explicit)");
  }

  // --engine auto, as `sfcv check`: the explicit graph within kAutoExplicitStates situations,
  // the symbolic engine beyond (or when the semantics cannot enumerate a state explicitly).
  auto explore = [&](std::uint64_t max_states) {
    engine::ExplorationOptions eo;
    eo.max_states = max_states;
    eo.deadline = budget.deadline;
    eo.keep_conditions = true;
    eo.keep_fired = true;  // Tclear
    return std::make_unique<ExplicitEngine>(engine::build_reachable_situation_graph(*ts, eo));
  };
  std::unique_ptr<ExplicitEngine> explicit_engine;
  if (engine_name == "auto") {
    auto note = [](const std::string& text) { std::cerr << "sfcv: --engine auto: " << text << "\n"; };
    engine_name = "explicit";
    if (!circuit) {
      note("using the explicit engine (" + why + ")");
    } else {
      const bool user_bound = budget.max_states > 0 && budget.max_states <= kAutoExplicitStates;
      try {
        explicit_engine = explore(user_bound ? budget.max_states : kAutoExplicitStates);
        const auto& g = explicit_engine->graph;
        if (g.complete() || user_bound || g.limit_reached() != "states") {
          note("using the explicit engine");
        } else {
          note("more than " + std::to_string(kAutoExplicitStates) +
               " situations: switching to the bdd engine");
          explicit_engine.reset();
          engine_name = "bdd";
        }
      } catch (const semantics::SemanticsLimitError& e) {
        note(std::string(e.what()) + ": switching to the bdd engine");
        engine_name = "bdd";
      }
    }
  }

  QueryEngine qe;
  std::unique_ptr<SymbolicEngine> symbolic_engine;
  if (engine_name == "bdd") {
    engine::SymbolicQueryOptions so;
    so.max_states = budget.max_states;
    so.timeout_seconds = budget.seconds_left();  // what is left of the one budget
    try {
      symbolic_engine = std::make_unique<SymbolicEngine>(*ts, std::move(*circuit), so);
      qe.anomalies = symbolic_engine->anomalies();
    } catch (const LimitReached& e) {
      std::cerr << "sfcv query: unknown: " << e.what() << "\n";
      return kUnknown;
    }
    qe.situations = static_cast<std::uint64_t>(symbolic_engine->ev.num_states());
    qe.evolutions = static_cast<std::uint64_t>(symbolic_engine->ev.num_evolutions());
    qe.answer = [&](const logic::CompiledQuery& q) { return symbolic_engine->answer(q); };
  } else {
    try {
      if (!explicit_engine) explicit_engine = explore(budget.max_states);
    } catch (const semantics::SemanticsLimitError& e) {
      throw InputError(e.what());
    }
    const auto& graph = explicit_engine->graph;
    qe.situations = graph.num_states();
    qe.evolutions = graph.num_edges();
    qe.complete = graph.complete();
    qe.limit = graph.limit_reached();
    qe.anomalies = graph.anomalies();
    qe.answer = [&](const logic::CompiledQuery& q) { return explicit_engine->answer(q); };
  }
  const Printer pr{*ts, o.max_elements};

  const bool complete = qe.complete;
  const bool exact = complete && qe.anomalies.empty();
  if (!complete)
    std::cerr << "warning: the graph is incomplete (limit reached: " << qe.limit
              << "): the sets below are computed on a partial graph and may be wrong in both "
                 "directions\n";
  for (const auto& a : qe.anomalies)
    std::cerr << "warning: " << a.message << " (under " << a.condition.to_string(ts->inputs())
              << "): the evolutions it cuts are missing from the graph\n";

  nlohmann::json jout;
  const bool want_json = o.json || !o.html.empty();  // --html renders the JSON answers
  if (want_json) {
    jout["model"] = o.model;
    jout["semantics"] = kind;
    jout["graph"] = {{"situations", qe.situations},
                     {"evolutions", qe.evolutions},
                     {"complete", complete},
                     {"limit", qe.limit},
                     {"anomalies", qe.anomalies.size()}};
    jout["queries"] = nlohmann::json::array();
  }
  if (!o.json) {
    std::cout << "graph: " << qe.situations << " situations, " << qe.evolutions
              << " evolutions (" << kind << (complete ? ", complete" : ", INCOMPLETE") << ")\n";
  }

  int exit_code = kHolds;
  bool any_violated = false, any_unknown = false;
  for (std::size_t i = 0; i < compiled.size(); ++i) {
    const auto& q = compiled[i];
    Answer r;
    try {
      r = qe.answer(q);
    } catch (const engine::QueryEvaluationError& e) {
      throw InputError(items[i].text + ": " + e.what());
    } catch (const engine::SymbolicQueryError& e) {
      throw InputError(items[i].text + ": " + e.what());
    } catch (const std::length_error& e) {
      throw InputError(items[i].text + ": the set is too large to list (" + e.what() + ")");
    } catch (const LimitReached& e) {
      std::cerr << "sfcv query: unknown: " << e.what() << "\n";
      return kUnknown;
    }
    // --assert: a test gives its verdict; a set is asserted empty (library properties are the
    // sets of faulty elements). Only an exact graph gives a verdict.
    std::string verdict;
    if (o.assert_empty) {
      const bool holds = r.sort == logic::Sort::Bool ? r.truth : r.set.count() == 0;
      verdict = !exact ? "unknown" : holds ? "holds" : "violated";
      any_violated |= verdict == "violated";
      any_unknown |= verdict == "unknown";
    }
    if (want_json) {
      nlohmann::json jq;
      jq["query"] = items[i].text;
      jq["sort"] = sort_key(r.sort);
      if (r.sort == logic::Sort::Bool) {
        jq["value"] = r.truth;
        if (r.witness_sort) {
          jq["witness_sort"] = sort_key(*r.witness_sort);
          jq["count"] = r.witness.count();
          jq["elements"] = pr.json(r.witness);
        }
      } else if (r.sort == logic::Sort::Int) {
        jq["value"] = r.number;
      } else {
        jq["count"] = r.set.count();
        jq["elements"] = pr.json(r.set);
      }
      if (!verdict.empty()) jq["verdict"] = verdict;
      jout["queries"].push_back(jq);
      if (o.json) continue;
    }
    std::cout << "query: " << items[i].text << "\n";
    if (r.sort == logic::Sort::Bool) {
      std::cout << "  " << (r.truth ? "true" : "false") << "\n";
      if (r.witness_sort) pr.text(r.witness, std::cout);
    } else if (r.sort == logic::Sort::Int) {
      std::cout << "  " << r.number << "\n";
    } else {
      pr.text(r.set, std::cout);
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
  if (!o.html.empty()) {
    std::ofstream f(o.html);
    if (!f) throw InputError(o.html + ": cannot write the HTML report");
    f << report::query_html(jout, report::html_pictures(project, *ts));
  }
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
  sub->add_option("--html", opts->html,
                  "Write the answers, the chart and the situation graph as one HTML page");
  sub->add_flag("--assert", opts->assert_empty,
                "Verdicts: a test must be true, a set must be empty (exit 0 holds, 1 violated, "
                "3 unknown)");
  add_system_options(*sub, opts->system);
  sub->add_option("--engine", opts->engine,
                  "explicit (default: the graph), bdd (symbolic, IEC 61131-3 charts) or auto "
                  "(explicit up to " + std::to_string(kAutoExplicitStates) + " situations, then bdd)");
  add_limit_options(*sub, opts->limits, "the graph is incomplete", MemoryLimit::NotOffered);
  sub->add_option("--format", opts->format, "Input format: auto, xml, iec, g7, agrafe");
  sub->callback([opts, &selected] {
    selected = [opts] { return run_query(*opts); };
  });
}

}  // namespace sfcv::cli
