#include "engine/query/query_service.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>

#include "engine/bdd/bdd_manager.hpp"
#include "engine/bdd/symbolic_query_evaluator.hpp"
#include "engine/explicit/canonical_order.hpp"
#include "engine/explicit/query_evaluator.hpp"
#include "engine/explicit/reachable_situation_graph.hpp"
#include "model/errors.hpp"
#include "semantics/iec61131_circuit.hpp"
#include "semantics/iec61131_system.hpp"  // SemanticsLimitError

namespace sfcv::engine {

namespace {

using logic::QueryAnswer;
using logic::QueryListing;

void sort_by_id(QueryListing& l) {
  std::sort(l.states.begin(), l.states.end(), [](auto& a, auto& b) { return a.id < b.id; });
  std::sort(l.edges.begin(), l.edges.end(), [](auto& a, auto& b) { return a.id < b.id; });
}

/// An evaluator's result (explicit bitsets or BDD sets) with its sets listed by `listing`.
template <typename Result, typename Listing>
QueryAnswer to_answer(const Result& r, Listing&& listing) {
  QueryAnswer a;
  a.sort = r.sort;
  a.truth = r.truth;
  a.number = r.number;
  if (r.sort != logic::Sort::Bool && r.sort != logic::Sort::Int) a.set = listing(r.sort, r.set);
  a.witness_sort = r.witness_sort;
  if (r.witness_sort) a.witness = listing(*r.witness_sort, r.witness);
  return a;
}

/// The explicit engine: the RSG, bitsets, listings in canonical order.
class ExplicitQueryService final : public QueryService {
 public:
  explicit ExplicitQueryService(ReachableSituationGraph g)
      : graph_(std::move(g)), ev_(graph_), numbering_(canonical_numbering(graph_, ev_.sources())) {
    summary_.situations = graph_.num_states();
    summary_.evolutions = graph_.num_edges();
    summary_.complete = graph_.complete();
    summary_.limit = graph_.limit_reached();
    summary_.anomalies = graph_.anomalies();
  }

  std::string_view name() const override { return "explicit"; }
  const logic::QueryGraphSummary& graph() const override { return summary_; }
  const ReachableSituationGraph& situation_graph() const { return graph_; }

  QueryAnswer answer(const logic::CompiledQuery& q) override {
    return to_answer(ev_.evaluate(q),
                     [this](logic::Sort sort, const auto& set) { return listing(sort, set); });
  }

 private:
  QueryListing::State state(std::uint32_t s) const {
    const auto v = graph_.states().at(s);
    return {numbering_.state[s], {v.begin(), v.end()}};
  }
  QueryListing listing(logic::Sort sort, const DynamicBitset& set) const {
    QueryListing l;
    l.sort = sort;
    set.for_each([&](std::uint64_t i) {
      if (sort == logic::Sort::States) {
        l.states.push_back(state(static_cast<std::uint32_t>(i)));
      } else if (sort == logic::Sort::Evolutions) {
        const auto f = graph_.fired(i);
        l.edges.push_back({numbering_.edge[i],
                           state(ev_.source(i)),
                           state(graph_.target(i)),
                           graph_.condition(i),
                           {f.begin(), f.end()}});
      } else if (sort == logic::Sort::Steps) {
        l.steps.push_back(static_cast<std::uint32_t>(i));
      }
    });
    sort_by_id(l);
    return l;
  }

  ReachableSituationGraph graph_;
  QueryEvaluator ev_;
  CanonicalNumbering numbering_;
  logic::QueryGraphSummary summary_;
};

/// The symbolic engine: BDD sets, enumerated for listing; labels come from the semantics.
class SymbolicQueryService final : public QueryService {
 public:
  static constexpr std::uint64_t kMaxListed = 10'000'000;

  SymbolicQueryService(const semantics::TransitionSystem& ts, semantics::TransitionCircuit circuit,
                       const SymbolicQueryOptions& options, const model::Budget& budget)
      : cancel_(budget.cancel),
        deadline_(budget.deadline, cancel_.get()),
        sys_(ts, std::move(circuit), symbolic_options(budget)),
        ev_(sys_, options) {
    summary_.situations = static_cast<std::uint64_t>(ev_.num_states());
    summary_.evolutions = static_cast<std::uint64_t>(ev_.num_evolutions());
    summary_.anomalies = anomalies();
  }

  std::string_view name() const override { return "bdd"; }
  const logic::QueryGraphSummary& graph() const override { return summary_; }

  QueryAnswer answer(const logic::CompiledQuery& q) override {
    return to_answer(ev_.evaluate(q),
                     [this](logic::Sort sort, const auto& set) { return listing(sort, set); });
  }

 private:
  QueryListing listing(logic::Sort sort, const SymbolicSet& set) const {
    const auto& ts = sys_.system();
    QueryListing l;
    l.sort = sort;
    if (sort == logic::Sort::States) {
      for (auto& s : ev_.states_of(set.bdd, kMaxListed))
        l.states.push_back({ev_.state_id(s), std::move(s)});
    } else if (sort == logic::Sort::Evolutions) {
      std::map<std::vector<semantics::StateWord>, std::uint64_t> ids;
      auto id = [&](const std::vector<semantics::StateWord>& s) {
        auto it = ids.find(s);
        if (it == ids.end()) it = ids.emplace(s, ev_.state_id(s)).first;
        return it->second;
      };
      for (auto& [src, dst] : ev_.evolutions_of(set.bdd, kMaxListed)) {
        auto label = evolution_label(ts, src, dst);
        l.edges.push_back({ev_.evolution_id(src, dst),
                           {id(src), src},
                           {id(dst), dst},
                           std::move(label.condition),
                           std::move(label.fired)});
      }
    } else if (sort == logic::Sort::Steps) {
      set.steps.for_each(
          [&](std::uint64_t o) { l.steps.push_back(static_cast<std::uint32_t>(o)); });
    }
    sort_by_id(l);
    return l;
  }
  /// The anomalies the explicit graph would record: those of the initial states and of every
  /// reachable situation that raises a range error, from the semantics itself.
  std::vector<semantics::Anomaly> anomalies() const {
    struct Sink final : semantics::SuccessorSink {
      std::vector<semantics::Anomaly> found;
      void successor(const semantics::Successor&) override {}
      void anomaly(const semantics::Anomaly& a) override { found.push_back(a); }
    } sink;
    const auto& ts = sys_.system();
    ts.initial_states(sink);
    auto errors = ev_.states_of(ev_.range_error_states(), kMaxListed);
    std::vector<std::pair<std::uint64_t, std::vector<semantics::StateWord>>> ordered;
    for (auto& s : errors) ordered.emplace_back(ev_.state_id(s), std::move(s));
    std::sort(ordered.begin(), ordered.end());
    for (const auto& [id, s] : ordered) ts.successors(s, sink);
    return std::move(sink.found);
  }

  static SymbolicOptions symbolic_options(const model::Budget& budget) {
    SymbolicOptions o;
    if (budget.max_memory_bytes > 0)
      o.max_nodes = static_cast<int>(std::clamp<std::uint64_t>(
          budget.max_memory_bytes / bdd::kBytesPerNode, 1, 2'000'000'000));
    o.timeout_seconds = budget.seconds_left();
    o.deadline = budget.deadline;
    o.max_circuit_bytes = budget.max_memory_bytes;
    return o;
  }

  // Every BDD operation of the service (building the relation, the fixpoints, the listings)
  // polls the run's deadline: one and_exist on tanks 12 ran 400 s past --timeout 5.
  std::shared_ptr<std::atomic<bool>> cancel_;
  bdd::DeadlineScope deadline_;
  SymbolicSystem sys_;
  SymbolicQueryEvaluator ev_;
  logic::QueryGraphSummary summary_;
};

std::unique_ptr<ExplicitQueryService> explore(
    const semantics::TransitionSystem& ts, const model::Budget& budget, std::uint64_t max_states,
    std::uint64_t max_valuations = 0,
    std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt) {
  ExplorationOptions eo;
  eo.max_states = max_states;
  eo.max_valuations = max_valuations;
  eo.deadline = deadline ? deadline : budget.deadline;
  eo.keep_conditions = true;
  eo.keep_fired = true;  // Tclear
  return std::make_unique<ExplicitQueryService>(build_reachable_situation_graph(ts, eo));
}

}  // namespace

QueryServicePtr make_query_service(const semantics::TransitionSystem& ts,
                                   const QueryServiceOptions& options) {
  const model::Budget no_limit;
  const model::Budget& budget = options.budget ? *options.budget : no_limit;
  auto note = [&](const std::string& text) {
    if (options.note) options.note(text);
  };

  // The circuit the BDD engine needs (IEC 61131-3 only for now), and why there is none.
  std::optional<semantics::TransitionCircuit> circuit;
  std::string why;
  if (options.engine != QueryEngineChoice::Explicit) {
    if (ts.kind() != semantics::SemanticsKind::Iec61131) {
      why = "the BDD engine does not support the Grafcet semantics yet";
    } else {
      try {
        circuit = semantics::build_iec61131_circuit(ts, budget.deadline, budget.max_memory_bytes);
      } catch (const semantics::CircuitUnsupported& e) {
        why = std::string("the BDD engine cannot encode ") + e.what();
      } catch (const LimitReached& e) {
        // Out of memory for the circuit: the explicit engine may still fit (auto); out of time
        // (or asked for the BDD engine): unknown.
        if (e.which() != Limit::Memory || options.engine == QueryEngineChoice::Bdd) throw;
        why = std::string("the BDD engine's circuit does not fit: ") + e.what();
      }
    }
    if (options.engine == QueryEngineChoice::Bdd && !circuit)
      throw UnsupportedConstruct(why + " (use --engine explicit)");
  }

  bool use_bdd = options.engine == QueryEngineChoice::Bdd;
  std::unique_ptr<ExplicitQueryService> explicit_service;
  if (options.engine == QueryEngineChoice::Auto) {
    if (!circuit) {
      note("using the explicit engine (" + why + ")");
    } else {
      // The one auto policy (engine/auto_policy.hpp), as for sfcv check: the explicit graph
      // within the probe's states, input valuations per state and share of the time left; a
      // chart past one of them goes to the BDD engine, which answers exactly or not at all.
      const auto probe = auto_probe(budget);
      std::optional<std::chrono::steady_clock::time_point> probe_deadline;
      if (budget.deadline)
        probe_deadline =
            std::chrono::steady_clock::now() +
            std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                std::chrono::duration<double>(budget.seconds_left() * kAutoProbeTimeShare));
      try {
        explicit_service =
            explore(ts, budget, probe.max_states, kAutoProbeValuations, probe_deadline);
        const auto& g = explicit_service->situation_graph();
        const auto limit = g.limit_reached();
        const bool too_many = limit == to_string(Limit::States) && !probe.user_bound;
        const bool too_wide = limit == to_string(Limit::Valuations);
        // Its share spent with time left in the run (the run's own deadline: unknown).
        const bool too_slow = limit == to_string(Limit::Time) && !budget.expired();
        if (g.complete() || !(too_many || too_wide || too_slow)) {
          note("using the explicit engine");
        } else {
          note((too_many   ? "more than " + std::to_string(kAutoProbeStates) + " situations"
                : too_wide ? "a situation has more than " + std::to_string(kAutoProbeValuations) +
                                 " input valuations"
                           : "the explicit engine used its share of the time (" +
                                 std::to_string(g.num_states()) + " situations)") +
               ": switching to the bdd engine");
          explicit_service.reset();
          use_bdd = true;
        }
      } catch (const semantics::SemanticsLimitError& e) {
        note(std::string(e.what()) + ": switching to the bdd engine");
        use_bdd = true;
      }
    }
  }

  if (use_bdd) {
    SymbolicQueryOptions so;
    so.max_states = budget.max_states;
    so.timeout_seconds = budget.seconds_left();  // what is left of the one budget
    return std::make_unique<SymbolicQueryService>(ts, std::move(*circuit), so, budget);
  }
  if (explicit_service) return explicit_service;
  try {
    return explore(ts, budget, budget.max_states);
  } catch (const semantics::SemanticsLimitError& e) {
    // An input the explicit graph would have to enumerate value by value: the model is out of
    // this engine's reach, which the user fixes in the model (or with --engine bdd).
    throw InputError(e.what());
  }
}

}  // namespace sfcv::engine
