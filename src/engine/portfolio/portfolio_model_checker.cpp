#include "engine/portfolio/portfolio_model_checker.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "engine/auto_policy.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/sat/sat_model_checker.hpp"
#include "logic/standard_checks.hpp"

namespace sfcv::engine {

namespace {

using logic::CheckReport;
using logic::PropertyResult;
using logic::Verdict;
using Clock = std::chrono::steady_clock;

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", seconds);
  return text;
}

/// A final answer: holds, violated, or not applicable (a fact of the system, the same for every
/// engine: no engine can do better).
bool decided(const PropertyResult& r) {
  return r.verdict == Verdict::Holds || r.verdict == Verdict::Violated ||
         r.verdict == Verdict::NotApplicable;
}

/// A standard check is its name: an engine fills in its formula ("AG EF init") only once it
/// has checked it, so a decided answer's formula need not be the question's.
bool same_question(const PropertyResult& a, const PropertyResult& b) {
  return a.name == b.name && a.check == b.check && (!a.check.empty() || a.formula == b.formula);
}

/// The result for `question` in `report` (engines answer in the task's order; the name check
/// guards against one that does not).
const PropertyResult* find_result(const CheckReport& report, std::size_t index,
                                  const PropertyResult& question) {
  if (index < report.results.size() && same_question(report.results[index], question))
    return &report.results[index];
  for (const auto& r : report.results)
    if (same_question(r, question)) return &r;
  return nullptr;
}

/// One engine of the race: its report (none when it stopped on a limit before reporting, or
/// threw), the limit that stopped it, and what it threw.
struct Racer {
  std::string name;
  std::shared_ptr<const ModelChecker> engine;
  logic::CheckTask task;
  std::optional<CheckReport> report;
  std::string stopped;
  std::exception_ptr error;
};

/// Racer threads the portfolio stopped waiting for (PortfolioOptions::abandon_after) that have
/// not ended yet.
std::atomic<std::size_t> g_abandoned_racers{0};

/// The winners so far, one slot per result of the probe's report (the task's questions).
class Scoreboard {
 public:
  Scoreboard(const CheckReport& probe, std::shared_ptr<std::atomic<bool>> cancel)
      : questions_(probe.results),
        winners_(probe.results.size()),
        joined_(probe.results.size()),
        cancel_(std::move(cancel)) {
    // What the probe decided on its partial graph (a violation it met) stands; the steps and
    // transitions it reached count towards the join.
    for (std::size_t i = 0; i < questions_.size(); ++i)
      if (decided(questions_[i])) {
        winners_[i] = questions_[i];
        winners_[i]->decided_by = "explicit";
      } else {
        join(i, questions_[i], "explicit");
      }
  }

  bool all_decided() const {
    for (const auto& w : winners_)
      if (!w) return false;
    return true;
  }

  /// An engine's report: the first definite answer per question wins; once every question has
  /// one, the other engines are cancelled.
  void offer(const CheckReport& report, const std::string& engine) {
    const std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < questions_.size(); ++i) {
      if (winners_[i]) continue;
      const auto* r = find_result(report, i, questions_[i]);
      if (r && decided(*r)) {
        winners_[i] = *r;
        winners_[i]->decided_by = engine;
      } else if (r) {
        join(i, *r, engine);
      }
    }
    if (all_decided()) cancel_->store(true);
  }

  const std::vector<PropertyResult>& questions() const { return questions_; }
  const std::optional<PropertyResult>& winner(std::size_t i) const { return winners_[i]; }

 private:
  /// A check judged target by target (PropertyResult::target_answers) that no engine decided
  /// alone: the targets the engines cleared so far, and how many each cleared first.
  struct Joined {
    std::vector<logic::TargetAnswer> answers;
    std::vector<std::pair<std::string, std::size_t>> cleared_by;
  };

  /// Adds what `engine` cleared of question `i`'s targets; once every target is clear by one
  /// engine or another, the check holds. Every engine implements the same check (the
  /// differential tests hold them to it), so a step one engine reached is reachable whichever
  /// engine asked. Defects are not joined: an engine that proves one answers "violated" alone.
  void join(std::size_t i, const PropertyResult& r, const std::string& engine) {
    if (r.target_answers.empty()) return;
    auto& j = joined_[i];
    if (j.answers.empty())
      j.answers.assign(r.target_answers.size(), logic::TargetAnswer::Undecided);
    if (j.answers.size() != r.target_answers.size()) return;  // other targets: nothing to join
    std::size_t cleared = 0;
    for (std::size_t k = 0; k < j.answers.size(); ++k)
      if (j.answers[k] == logic::TargetAnswer::Undecided &&
          r.target_answers[k] == logic::TargetAnswer::Clear) {
        j.answers[k] = logic::TargetAnswer::Clear;
        ++cleared;
      }
    if (cleared > 0) j.cleared_by.emplace_back(engine, cleared);
    if (std::any_of(j.answers.begin(), j.answers.end(),
                    [](auto a) { return a != logic::TargetAnswer::Clear; }))
      return;
    PropertyResult holds = questions_[i];
    holds.verdict = Verdict::Holds;
    holds.findings.clear();
    holds.findings_total = 0;
    holds.trace.reset();
    holds.certificate.clear();
    holds.target_answers = j.answers;
    const auto n = std::to_string(j.answers.size());
    holds.message = (holds.check == logic::to_string(logic::StandardCheck::Reachable)
                         ? "all " + n + " steps are reachable"
                         : "all " + n + " transitions can fire") +
                    " (the engines together:";
    holds.decided_by.clear();
    for (const auto& [name, count] : j.cleared_by) {
      holds.message += (holds.decided_by.empty() ? " " : ", ") + name + " " + std::to_string(count);
      holds.decided_by += (holds.decided_by.empty() ? "" : "+") + name;
    }
    holds.message += ")";
    winners_[i] = std::move(holds);
  }

  std::mutex mutex_;
  std::vector<PropertyResult> questions_;
  std::vector<std::optional<PropertyResult>> winners_;
  std::vector<Joined> joined_;
  std::shared_ptr<std::atomic<bool>> cancel_;
};

class PortfolioModelChecker final : public ModelChecker {
 public:
  explicit PortfolioModelChecker(PortfolioOptions options)
      : options_(std::move(options)),
        explicit_(make_explicit_model_checker(options_.explicit_engine)),
        probe_(make_explicit_model_checker(probe_options(options_.explicit_engine))),
        bdd_(options_.bdd_racer ? options_.bdd_racer : make_bdd_model_checker(race_bdd_options())),
        ic3_(options_.ic3_racer ? options_.ic3_racer
                                : make_sat_model_checker({SatAlgorithm::Ic3, 200})),
        bmc_(options_.bmc_racer ? options_.bmc_racer
                                : make_sat_model_checker({SatAlgorithm::Bmc, kBmcDepth})) {}

  std::string_view name() const override { return "auto"; }

  bool can_handle(const logic::CheckTask& task, std::string* why) const override {
    std::string e, b;
    if (explicit_->can_handle(task, &e) || bdd_can(task, &b)) return true;
    if (why) *why = e;
    return false;
  }

  CheckReport check(const logic::CheckTask& task) const override {
    const auto start = Clock::now();
    std::string why;
    const bool bdd_can_check = bdd_can(task, &why);
    // The SAT engines encode the same circuit as the BDD engine: when it cannot, neither can IC3.
    if (!bdd_can_check) {
      note("using the explicit engine (the bdd engine cannot: " + why + ")");
      auto report = explicit_->check(task);
      for (auto& r : report.results)
        if (decided(r)) r.decided_by = "explicit";
      return report;
    }
    std::optional<CheckReport> probe;
    const auto policy = auto_probe(task.limits, options_.probe_states);
    const auto initial_states = estimate_initial_states(task);
    if (options_.probe_states == 0) {
      note("the bdd, ic3 and bmc engines race (no explicit probe)");
    } else if (auto_start(policy, initial_states) == AutoStart::Race) {
      note("about " + count_text(*initial_states) +
           " initial situations (estimated), more than the explicit probe's " +
           std::to_string(policy.max_states) +
           " states: the bdd, ic3 and bmc engines race (no explicit probe)");
    } else if (explicit_->can_handle(task, &why)) {
      logic::CheckTask bounded = task;
      bounded.limits.max_states = policy.max_states;
      // Too wide: a state whose successors take more input valuations than the probe may
      // enumerate stops it at once. Too slow: under --timeout the probe has a share of the time
      // left; a chart it cannot finish in it gets the symbolic engines for the rest.
      bounded.limits.max_valuations = options_.probe_valuations;
      bool probe_deadline = false;
      if (task.limits.deadline) {
        const auto share = std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(task.limits.seconds_left() * kAutoProbeTimeShare));
        bounded.limits.deadline = Clock::now() + share;
        probe_deadline = bounded.limits.deadline < task.limits.deadline;
      }
      probe = probe_->check(bounded);
      const bool too_many = probe->limit == to_string(Limit::States) && !policy.user_bound;
      const bool not_enumerable = probe->limit == to_string(Limit::Enumeration);
      const bool too_wide = probe->limit == to_string(Limit::Valuations);
      bool all_decided = true;
      for (const auto& r : probe->results) all_decided = all_decided && decided(r);
      // Its share spent, in the exploration or in the checks after it (both read its deadline),
      // with time left in the run.
      // Or foreseen: the probe stops on "time" before its deadline when the states waiting
      // cannot be expanded in the rest of its share (ExplorationOptions::forecast).
      const bool too_slow = probe_deadline && !all_decided && !task.limits.expired() &&
                            (probe->limit == to_string(Limit::Time) ||
                             (probe->complete && Clock::now() >= *bounded.limits.deadline));
      if (all_decided || task.limits.expired() ||
          !(too_many || not_enumerable || too_wide || too_slow)) {
        note("using the explicit engine");
        for (auto& r : probe->results)
          if (decided(r)) r.decided_by = "explicit";
        return *probe;
      }
      const std::string reason =
          too_many   ? "more than " + std::to_string(policy.max_states) + " states"
          : too_wide ? "a state has more than " + std::to_string(options_.probe_valuations) +
                           " input valuations (the explicit probe stopped after " +
                           probe->states.str() + (probe->states == 1 ? " state)" : " states)")
          : too_slow ? "the explicit engine would not finish in its share of the time (" +
                           probe->states.str() + " states in " + seconds_text(probe->seconds) + ")"
                     : (probe->results.empty() ? std::string("the explicit engine cannot enumerate")
                                               : probe->results.front().message);
      note(reason + ": the bdd, ic3 and bmc engines race on the rest");
    } else {
      note("the bdd, ic3 and bmc engines race (the explicit engine cannot: " + why + ")");
    }
    return race(task, probe, start);
  }

 private:
  void note(const std::string& text) const {
    if (options_.note) options_.note(text);
  }

  BddEngineOptions race_bdd_options() const {
    auto o = options_.bdd;
    o.relation_share = kRaceRelationShare;
    return o;
  }

  static ExplicitEngineOptions probe_options(ExplicitEngineOptions o) {
    o.forecast = true;
    return o;
  }

  /// The system's estimate of its initial states (a Grafcet's initial situations); none when
  /// it has none or the estimate meets a limit (then the probe runs as before).
  static std::optional<double> estimate_initial_states(const logic::CheckTask& task) {
    try {
      return task.system ? task.system->estimate_initial_states() : std::nullopt;
    } catch (const LimitReached&) {
      return std::nullopt;
    }
  }

  static std::string count_text(double n) {
    char text[32];
    std::snprintf(text, sizeof text, n < 1e7 ? "%.0f" : "%.2g", n);
    return text;
  }

  bool bdd_can(const logic::CheckTask& task, std::string* why) const {
    try {
      return bdd_->can_handle(task, why);  // builds the circuit: within the budget too
    } catch (const LimitReached& e) {
      if (why) *why = e.what();
      return false;
    }
  }

  /// What the race's threads share with it. Owned jointly, so that a racer the race stops
  /// waiting for (PortfolioOptions::abandon_after) still writes into memory that exists; once
  /// the race is `closed`, a racer's answers and progress are dropped.
  struct RaceState {
    std::vector<Racer> racers;
    std::optional<Scoreboard> board;
    std::mutex mutex;
    std::condition_variable ended;
    std::vector<bool> done, abandoned;
    std::shared_ptr<std::atomic<bool>> closed = std::make_shared<std::atomic<bool>>(false);
  };

  CheckReport race(const logic::CheckTask& task, const std::optional<CheckReport>& probe,
                   Clock::time_point start) const {
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    auto state = std::make_shared<RaceState>();
    auto& racers = state->racers;
    // The racers ask only what the probe left open: a check it decided would only take their
    // time (xPPU: the probe finds the stored actions and output conflicts, hundreds of targets
    // that IC3 then worked through in every round).
    const auto open = probe ? still_open(task, *probe) : task;
    racers.push_back({"bdd", bdd_, open, {}, {}, {}});
    racers.push_back({"ic3", ic3_, open, {}, {}, {}});
    racers.push_back({"bmc", bmc_, open, {}, {}, {}});
    state->done.assign(racers.size(), false);
    state->abandoned.assign(racers.size(), false);
    // Each racer reports under its own name (a literal: the pointer outlives the race), so that
    // the progress line shows every engine of the race and which ones have finished.
    static constexpr const char* kNames[] = {"bdd", "ic3", "bmc"};
    for (std::size_t i = 0; i < racers.size(); ++i) {
      auto& r = racers[i];
      r.task.limits.cancel = cancel;
      if (const auto progress = task.limits.progress)
        r.task.limits.progress = [progress, name = kNames[i],
                                  closed = state->closed](const logic::Progress& p) {
          if (closed->load()) return;  // the caller's progress line may be gone
          auto tagged = p;
          tagged.engine = name;
          progress(tagged);
        };
    }
    // One memory budget for the race, not one each: half for the BDD engine (its node table
    // is what grows), a quarter for each SAT engine's circuit.
    if (const auto budget = task.limits.max_memory_bytes; budget > 0) {
      racers[0].task.limits.max_memory_bytes = budget / 2;
      racers[1].task.limits.max_memory_bytes = budget / 4;
      racers[2].task.limits.max_memory_bytes = budget / 4;
    }

    // Without a probe the questions are the BDD engine's: it answers every one of the task,
    // unknown or not checked where it cannot.
    if (probe) state->board.emplace(*probe, cancel);
    if (!state->board) {
      // The BDD engine's questions, read before the race from a report of unknowns.
      CheckReport questions;
      for (const auto& p : task.properties) {
        PropertyResult r;
        r.name = p.name;
        r.formula = logic::to_string(p.formula);
        questions.results.push_back(std::move(r));
      }
      for (auto c : task.checks) {
        PropertyResult r;
        r.name = std::string(logic::to_string(c));
        r.check = r.name;
        questions.results.push_back(std::move(r));
      }
      state->board.emplace(questions, cancel);
    }

    std::vector<Racer> finished;
    {
      // The race has its own flag (a winner raises it); a cancel of the whole run from outside
      // (a portfolio inside another, a test) must still reach the racers.
      std::jthread relay;
      if (const auto outer = task.limits.cancel)
        relay = std::jthread([outer, cancel](std::stop_token stop) {
          while (!stop.stop_requested()) {
            if (outer->load(std::memory_order_relaxed)) {
              cancel->store(true);
              return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
          }
        });
      // jthread: if a thread cannot start, those already started are joined, not terminated.
      std::vector<std::jthread> threads;
      for (std::size_t i = 0; i < racers.size(); ++i)
        threads.emplace_back([state, i]() mutable {
          const bool abandoned = run_racer(*state, i);
          // Counted out only once its share of the race is freed: at zero, nothing of a race
          // left behind is still in use (a test may then free the system).
          state.reset();
          if (abandoned) --g_abandoned_racers;
        });
      finished = wait_for_racers(*state, task.limits, *cancel);
      cancel->store(true);  // a racer left behind stops at its next poll
      for (std::size_t i = 0; i < threads.size(); ++i) {
        if (state->abandoned[i])
          threads[i].detach();
        else
          threads[i].join();
      }
    }
    // An engine error is a bug, whoever won: never hidden behind another engine's answer.
    for (const auto& r : finished)
      if (r.error) std::rethrow_exception(r.error);
    return merge(task, *state->board, finished, probe, start);
  }

  /// `task` without the properties and checks `probe` decided (every row of a check: reentry
  /// has a second under fairness). Engines answer by name (find_result), not by position.
  static logic::CheckTask still_open(const logic::CheckTask& task, const CheckReport& probe) {
    logic::CheckTask open = task;
    std::erase_if(open.properties, [&](const logic::Property& p) {
      const auto formula = logic::to_string(p.formula);
      return std::any_of(probe.results.begin(), probe.results.end(), [&](const PropertyResult& r) {
        return r.check.empty() && r.name == p.name && r.formula == formula && decided(r);
      });
    });
    std::erase_if(open.checks, [&](logic::StandardCheck c) {
      const auto name = logic::to_string(c);
      bool asked = false, all_decided = true;
      for (const auto& r : probe.results)
        if (r.check == name) {
          asked = true;
          all_decided = all_decided && decided(r);
        }
      return asked && all_decided;
    });
    return open;
  }

  /// Runs racer `i` and offers its report; true when the race had left it behind by then.
  static bool run_racer(RaceState& state, std::size_t i) {
    auto& r = state.racers[i];  // its engine and task: this thread's alone while it runs
    std::optional<CheckReport> report;
    std::string stopped;
    std::exception_ptr error;
    try {
      report = r.engine->check(r.task);
    } catch (const LimitReached& e) {
      // Out of budget (or cancelled) before a report: no answer from this engine.
      stopped = e.what();
    } catch (...) {
      error = std::current_exception();
    }
    logic::Progress done;
    done.phase = "done";
    r.task.limits.report(done);
    bool abandoned = false;
    {
      const std::lock_guard lock(state.mutex);
      if (!state.closed->load()) {
        if (report) state.board->offer(*report, r.name);
        r.report = std::move(report);
        r.stopped = std::move(stopped);
        r.error = error;
      }
      state.done[i] = true;
      abandoned = state.abandoned[i];
    }
    state.ended.notify_all();
    return abandoned;
  }

  /// Waits until every racer has ended, or (with PortfolioOptions::abandon_after) until that
  /// many seconds past the deadline or past the moment every question was decided: a racer
  /// still running then is left behind, its questions unknown, so that a phase that does not
  /// poll (one long BDD operation on a loaded machine) cannot hold back the report. Closes the
  /// race and returns the racers as they ended.
  std::vector<Racer> wait_for_racers(RaceState& state, const logic::CheckLimits& limits,
                                     const std::atomic<bool>& cancel) const {
    std::unique_lock lock(state.mutex);
    std::string why, after;  // what the race waited past, for a racer left behind
    const auto all_done = [&state] {
      return std::all_of(state.done.begin(), state.done.end(), [](bool d) { return d; });
    };
    if (!options_.abandon_after) {
      state.ended.wait(lock, all_done);
    } else {
      const auto grace = std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(*options_.abandon_after));
      std::optional<Clock::time_point> give_up;
      while (!all_done()) {
        const auto now = Clock::now();
        if (!give_up && limits.deadline && now > *limits.deadline) {
          give_up = *limits.deadline + grace;
          why = "time limit reached; ";
          after = "after it";
        }
        if (!give_up && cancel.load()) {
          give_up = now + grace;
          why = "stopped; ";
          after = "after the race was stopped";
        }
        if (give_up && now >= *give_up) break;
        state.ended.wait_for(lock, std::chrono::milliseconds(20));
      }
    }
    state.closed->store(true);
    std::vector<Racer> finished;
    for (std::size_t i = 0; i < state.racers.size(); ++i) {
      auto& r = state.racers[i];
      Racer out{r.name, nullptr, {}, {}, {}, {}};
      if (state.done[i]) {
        out.report = std::move(r.report);
        out.stopped = std::move(r.stopped);
        out.error = r.error;
      } else {
        state.abandoned[i] = true;
        ++g_abandoned_racers;
        out.stopped = why + "the " + r.name + " engine had not stopped " +
                      seconds_text(*options_.abandon_after) + " " + after +
                      ", and the report does not wait for it";
      }
      finished.push_back(std::move(out));
    }
    return finished;
  }

  CheckReport merge(const logic::CheckTask& task, const Scoreboard& board,
                    const std::vector<Racer>& racers, const std::optional<CheckReport>& probe,
                    Clock::time_point start) const {
    const auto& bdd = racers[0].report;
    CheckReport out;
    out.engine = "auto";
    if (bdd && bdd->complete) {
      out.states = bdd->states;
      out.edges = bdd->edges;
      out.states_known = bdd->states_known;
      out.edges_known = bdd->edges_known;
      out.depth = bdd->depth;
      out.stopped_early = bdd->stopped_early;
    } else {
      out.states_known = false;
      out.edges_known = false;
      for (const auto& r : racers)
        if (r.report) out.depth = std::max(out.depth, r.report->depth);
    }
    bool unknown = false;
    const auto& questions = board.questions();
    for (std::size_t i = 0; i < questions.size(); ++i) {
      if (const auto& w = board.winner(i)) {
        out.results.push_back(*w);
        continue;
      }
      out.results.push_back(undecided_account(racers, probe, i, questions[i]));
      unknown = unknown || out.results.back().verdict == Verdict::Unknown;
    }
    if (unknown) {
      // The limit that left them unknown: the racers' first (a racer that was not cancelled,
      // since the race ends in a cancel only once every question is decided), else the probe's.
      for (const auto& r : racers)
        if (r.report && !r.report->complete && out.complete) {
          out.complete = false;
          out.limit = r.report->limit;
        }
      if (out.complete && probe && !probe->complete) {
        out.complete = false;
        out.limit = probe->limit;
      }
      if (out.complete && task.limits.expired()) {
        out.complete = false;
        out.limit = to_string(Limit::Time);
      }
    }
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return out;
  }

  /// Why `question` is undecided, in the words of the engines that handle it (unknown, and the
  /// limit that stopped each: "bdd: time limit reached in a BDD operation; ic3: 14 of 64
  /// undecided ..."), with the findings of the one that found most. The BDD engine and the
  /// explicit probe handle every question of the race, IC3 and BMC only some: their "not
  /// checked by the ic3 engine" is the account only when no engine handles the question.
  static PropertyResult undecided_account(const std::vector<Racer>& racers,
                                          const std::optional<CheckReport>& probe,
                                          std::size_t index, const PropertyResult& question) {
    const auto& bdd = racers[0];
    std::vector<std::pair<std::string, PropertyResult>> accounts;  // engine, its answer
    if (bdd.report) {
      if (const auto* r = find_result(*bdd.report, index, question))
        accounts.emplace_back(bdd.name, *r);
    } else if (!bdd.stopped.empty()) {
      PropertyResult r = question;
      r.verdict = Verdict::Unknown;
      r.message = bdd.stopped;
      accounts.emplace_back(bdd.name, std::move(r));
    }
    if (probe)
      if (const auto* r = find_result(*probe, index, question))
        accounts.emplace_back("explicit", *r);
    for (std::size_t k = 1; k < racers.size(); ++k)
      if (racers[k].report)
        if (const auto* r = find_result(*racers[k].report, index, question))
          accounts.emplace_back(racers[k].name, *r);
    if (accounts.empty()) return question;
    const PropertyResult first = accounts.front().second;
    std::erase_if(accounts, [](const auto& a) { return a.second.verdict == Verdict::NotChecked; });
    if (accounts.empty()) return first;  // nobody handles it: the first "not checked" says so
    if (accounts.size() == 1) return accounts.front().second;
    const auto most =
        std::max_element(accounts.begin(), accounts.end(), [](const auto& a, const auto& b) {
          return a.second.findings_total < b.second.findings_total;
        });
    PropertyResult out = most->second;
    out.message.clear();
    std::vector<std::string> said;
    for (const auto& [engine, r] : accounts) {
      if (r.message.empty() || std::find(said.begin(), said.end(), r.message) != said.end())
        continue;
      said.push_back(r.message);
      out.message += (out.message.empty() ? "" : "; ") + engine + ": " + r.message;
    }
    return out;
  }

  PortfolioOptions options_;
  /// BMC's bound in the race (`--depth`'s default): deep enough for the bugs that IC3 finds
  /// slowly (a counterexample of hundreds of cycles costs IC3 seconds, BMC a fraction), and a
  /// bound, so that BMC's thread ends on a chart without bugs instead of sharing the two cores
  /// with the engines that prove.
  static constexpr std::uint32_t kBmcDepth = 200;
  /// explicit_ runs alone when the symbolic engines cannot; probe_ is the same engine with the
  /// forecast that hands a hopeless exploration over early. The racers are shared with their
  /// threads, which may outlive this object when the race leaves them behind.
  ModelCheckerPtr explicit_, probe_;
  std::shared_ptr<const ModelChecker> bdd_, ic3_, bmc_;
};

}  // namespace

std::size_t abandoned_racers() {
  return g_abandoned_racers.load();
}

ModelCheckerPtr make_portfolio_model_checker(PortfolioOptions options) {
  return std::make_unique<PortfolioModelChecker>(std::move(options));
}

}  // namespace sfcv::engine
