#include "engine/sat/ic3.hpp"

#include <algorithm>
#include <memory>
#include <queue>
#include <stdexcept>

#include "engine/sat/unrolling.hpp"

namespace sfcv::engine::sat {

namespace {

using semantics::AigLit;
/// A conjunction of latch literals, sorted by latch: a set of states.
using Cube = std::vector<LatchLiteral>;

struct TimeUp {};

/// One solver with the transition relation: frame 0 is the current state, frame 1 (the
/// next-state functions of frame 0, by renaming) the successor.
struct FrameSolver {
  std::unique_ptr<Solver> solver;
  std::unique_ptr<Unrolling> frames;
  /// `cuts`: a simplifying encoding (unrolling.hpp) with these cuts; null: a plain one.
  FrameSolver(const semantics::Aig& aig, bool initial, Deadline d,
              const std::shared_ptr<CutMapping>& cuts)
      : solver(std::make_unique<Solver>(d, SolverProfile::ManySmallQueries)),
        frames(std::make_unique<Unrolling>(aig, *solver, initial, cuts != nullptr, cuts)) {}
  int current(const LatchLiteral& l) const {
    const int x = frames->latch(l.latch, 0);
    return l.value ? x : -x;
  }
  int next(const LatchLiteral& l) const {
    const int x = frames->latch(l.latch, 1);
    return l.value ? x : -x;
  }
  /// Adds the clause !cube over the current state.
  void block(const Cube& c) const {
    std::vector<int> clause;
    for (const auto& l : c) clause.push_back(-current(l));
    solver->add_clause(clause);
  }
  SatResult solve(const std::vector<int>& assumptions,
                  const std::vector<int>& constraint = {}) const {
    const auto r = solver->solve(assumptions, constraint);
    if (r == SatResult::Interrupted) throw TimeUp{};
    return r;
  }
};

/// `small`'s literals are a subset of `big`'s: the states of `big` lie inside `small`.
bool subsumes(const Cube& small, const Cube& big) {
  return std::includes(big.begin(), big.end(), small.begin(), small.end());
}

class Ic3 {
 public:
  Ic3(const ReachQuery& q, std::size_t target, const Ic3Options& o, Ic3Stats* stats)
      : aig_(*q.aig),
        step_ok_(q.step_ok),
        target_(q.targets[target]),
        options_(o),
        stats_(stats),
        cone_(cone_latches(aig_, {target_, step_ok_})),
        cuts_(!q.simplify ? nullptr
              : q.cuts    ? q.cuts
                          : std::make_shared<CutMapping>(aig_)),
        lift_(aig_, false, o.deadline, cuts_) {
    if (!o.known_invariant) return;
    // All of it, not only the clauses over the cone: a part of an inductive invariant need not
    // be inductive. Latches outside the cone stay free in the frames, where the invariant then
    // reads as its projection onto the cone, which is inductive there too.
    for (const auto& clause : *o.known_invariant) {
      if (clause.empty()) continue;
      Cube excluded;  // the states the clause rules out
      for (const auto& l : clause) excluded.push_back({l.latch, !l.value});
      std::sort(excluded.begin(), excluded.end());
      known_.push_back(std::move(excluded));
    }
  }

  ReachResult run() {
    ReachResult result;
    try {
      result = search();
    } catch (const TimeUp&) {
      result.kind = ReachResult::Kind::Unknown;
      result.why = "the time limit passed at frame " + std::to_string(frames_.size() - 1);
    }
    if (stats_) {
      stats_->frames = frames_.size();
      for (const auto& f : blocked_) stats_->cubes += f.size();
      for (const auto& f : frames_) stats_->sat_calls += f.solver->calls();
    }
    return result;
  }

 private:
  /// One link of a possible run to the target: the inputs under which every state of the
  /// obligation's cube steps into its parent's cube (or, at the root, meets the target).
  struct Link {
    std::vector<bool> inputs;
    std::size_t parent;  ///< index into links_; kNone at the root
  };
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct Obligation {
    std::size_t level;
    std::uint32_t depth;  ///< steps from these states to the target
    Cube cube;
    std::size_t link;                            ///< into links_
    bool operator<(const Obligation& o) const {  // lowest level first, then the deepest
      return level != o.level ? level > o.level : depth < o.depth;
    }
  };

  ReachResult search() {
    ReachResult r;
    add_frame();  // F_0: the initial state
    if (frames_[0].solve({frames_[0].frames->literal(target_, 0)}) == SatResult::Sat) {
      r.kind = ReachResult::Kind::Reached;
      return r;
    }
    add_frame();  // F_1
    for (std::size_t k = 1;; ++k) {
      if (k >= options_.max_frames) {
        r.why = "no answer within " + std::to_string(options_.max_frames) + " frames";
        return r;
      }
      // Blocking: every state of F_k that meets the target is blocked at k, recursively.
      for (;;) {
        const auto& top = frames_[k];
        if (top.solve({top.frames->literal(target_, 0)}) == SatResult::Unsat) break;
        std::vector<bool> inputs;
        Cube bad = lift(top, state_of(top), nullptr, &inputs);
        links_.push_back({std::move(inputs), kNone});
        if (!block(std::move(bad), k, links_.size() - 1)) {
          r.kind = ReachResult::Kind::Reached;
          r.depth = cex_depth_;
          r.inputs = replayed_run();
          return r;
        }
      }
      // Propagation: clauses that hold one step further move up; an empty delta means
      // F_i = F_{i+1}, an inductive invariant.
      add_frame();
      for (std::size_t i = 1; i <= k; ++i) {
        const auto cubes = blocked_[i];
        for (const auto& c : cubes) {
          if (std::find(blocked_[i].begin(), blocked_[i].end(), c) == blocked_[i].end()) continue;
          std::vector<int> assume{frames_[i].frames->literal(step_ok_, 0)};
          for (const auto& l : c) assume.push_back(frames_[i].next(l));
          if (frames_[i].solve(assume) == SatResult::Unsat) add_blocked(c, i + 1);
        }
        if (blocked_[i].empty()) {
          r.kind = ReachResult::Kind::Unreachable;
          r.depth = static_cast<std::uint32_t>(k);  // the frames it took
          r.certificate.kind = Certificate::Kind::Invariant;
          if (options_.known_invariant)  // assumed in every frame: part of the invariant
            for (const auto& clause : *options_.known_invariant)
              if (!clause.empty()) r.certificate.clauses.push_back(clause);
          for (std::size_t j = i + 1; j < blocked_.size(); ++j)
            for (const auto& c : blocked_[j]) {
              LatchClause clause;
              for (const auto& l : c) clause.push_back({l.latch, !l.value});
              r.certificate.clauses.push_back(std::move(clause));
            }
          return r;
        }
      }
    }
  }

  void add_frame() {
    frames_.emplace_back(aig_, frames_.empty(), options_.deadline, cuts_);
    blocked_.emplace_back();
    if (frames_.size() > 1)
      for (const auto& c : known_) frames_.back().block(c);
    if (options_.on_frame) options_.on_frame(static_cast<std::uint32_t>(frames_.size() - 1));
  }

  bool intersects_initial(const Cube& c) const {
    return std::all_of(c.begin(), c.end(), [&](const LatchLiteral& l) {
      return aig_.latches()[l.latch].initial == l.value;
    });
  }

  /// The current state of a model, over the cone latches the query encoded (the others do
  /// not matter to it).
  Cube state_of(const FrameSolver& f) const {
    Cube s;
    for (auto l : cone_)
      if (const int x = f.frames->literal_if_encoded(aig_.latches()[l].current, 0))
        s.push_back({l, f.solver->value(x)});
    return s;
  }

  /// Lifting: the literals of `state` that suffice, under the same inputs, for a step into
  /// `successor` (or, with none, for the target), from the failed assumptions of a query that
  /// asks for the opposite.
  Cube lift(const FrameSolver& f, const Cube& state, const Cube* successor,
            std::vector<bool>* inputs) {
    std::vector<int> assume;
    inputs->assign(aig_.inputs().size(), false);
    for (std::uint32_t i = 0; i < aig_.inputs().size(); ++i)
      if (const int x = f.frames->input_if_encoded(i, 0)) {
        const int y = lift_.frames->literal(aig_.inputs()[i].literal, 0);
        (*inputs)[i] = f.solver->value(x);
        assume.push_back((*inputs)[i] ? y : -y);
      }
    std::vector<int> state_lits;
    for (const auto& l : state) state_lits.push_back(lift_.current(l));
    std::vector<int> goal;  // the opposite of the step, for this call only
    if (successor) {
      goal.push_back(-lift_.frames->literal(step_ok_, 0));
      for (const auto& l : *successor) goal.push_back(-lift_.next(l));
    } else {
      goal.push_back(-lift_.frames->literal(target_, 0));
    }
    assume.insert(assume.end(), state_lits.begin(), state_lits.end());
    Cube lifted = state;
    if (lift_.solve(assume, goal) == SatResult::Unsat) {
      lifted.clear();
      for (std::size_t k = 0; k < state.size(); ++k)
        if (lift_.solver->failed(state_lits[k])) lifted.push_back(state[k]);
    }
    return lifted;
  }

  /// Is `c` inductive relative to F_{level-1}: F_{level-1} & !c & T & c' unsatisfiable? If so
  /// `core` gets the literals of c that the proof used (still excluding the initial state);
  /// if not, `pred` gets a lifted predecessor.
  bool relatively_inductive(std::size_t level, const Cube& c, Cube* core, Cube* pred,
                            std::vector<bool>* pred_inputs = nullptr) {
    // An empty cube (every state) contains the initial state and is never blocked; the
    // constraint below would read as none.
    if (c.empty()) throw std::logic_error("ic3: relative induction of the empty cube");
    const auto& f = frames_[level - 1];
    std::vector<int> not_c;  // !c, for this call only
    for (const auto& l : c) not_c.push_back(-f.current(l));
    std::vector<int> assume{f.frames->literal(step_ok_, 0)};
    for (const auto& l : c) assume.push_back(f.next(l));
    const bool unsat = f.solve(assume, not_c) == SatResult::Unsat;
    if (unsat && core) {
      core->clear();
      for (std::size_t k = 0; k < c.size(); ++k)
        if (f.solver->failed(assume[k + 1])) core->push_back(c[k]);
      if (intersects_initial(*core))  // put back a literal that excludes the initial state
        for (const auto& l : c)
          if (aig_.latches()[l.latch].initial != l.value) {
            core->push_back(l);
            std::sort(core->begin(), core->end());
            break;
          }
    }
    if (!unsat && pred) *pred = lift(f, state_of(f), &c, pred_inputs);
    return unsat;
  }

  /// MIC-style generalisation: drop each literal in turn while the rest stays relatively
  /// inductive (and excludes the initial state), shrinking further by the cores.
  Cube generalize(std::size_t level, Cube c) {
    for (std::size_t k = 0; k < c.size() && c.size() > 1;) {
      Cube smaller = c;
      smaller.erase(smaller.begin() + static_cast<std::ptrdiff_t>(k));
      Cube core;
      if (!intersects_initial(smaller) && relatively_inductive(level, smaller, &core, nullptr))
        c = std::move(core);  // k now points at the next untried literal, or past the end
      else
        ++k;
    }
    return c;
  }

  /// F_level already excludes c syntactically (a blocked cube at level >= `level` covers it).
  bool covered(std::size_t level, const Cube& c) const {
    for (std::size_t j = level; j < blocked_.size(); ++j)
      for (const auto& d : blocked_[j])
        if (subsumes(d, c)) return true;
    return false;
  }

  void add_blocked(const Cube& c, std::size_t level) {
    // Cubes at lower levels that c covers are implied from now on.
    for (std::size_t j = 1; j <= level; ++j) {
      auto& row = blocked_[j];
      row.erase(
          std::remove_if(row.begin(), row.end(), [&](const Cube& d) { return subsumes(c, d); }),
          row.end());
    }
    blocked_[level].push_back(c);
    for (std::size_t j = 1; j <= level; ++j) frames_[j].block(c);
  }

  /// Blocks `bad` at frame k with its proof obligations; false when one of them contains the
  /// initial state (a real run to the target, `cex_depth_` cycles long).
  bool block(Cube bad, std::size_t k, std::size_t root) {
    std::priority_queue<Obligation> queue;
    queue.push({k, 0, std::move(bad), root});
    while (!queue.empty()) {
      if (options_.deadline.passed()) throw TimeUp{};
      Obligation ob = queue.top();
      if (stats_) ++stats_->obligations;
      // Lifting keeps every state of a cube on a run to the target: one initial state in it
      // is a counterexample.
      if (ob.level == 0 || intersects_initial(ob.cube)) {
        cex_depth_ = ob.depth;
        cex_link_ = ob.link;
        return false;
      }
      if (covered(ob.level, ob.cube)) {
        queue.pop();
        continue;
      }
      Cube core, pred;
      std::vector<bool> pred_inputs;
      if (relatively_inductive(ob.level, ob.cube, &core, &pred, &pred_inputs)) {
        queue.pop();
        Cube g = generalize(ob.level, std::move(core));
        std::size_t level = ob.level;
        while (level < k && relatively_inductive(level + 1, g, nullptr, nullptr)) ++level;
        add_blocked(g, level);
        // Re-enqueued one frame higher: it will be blocked there too or yield a deeper run.
        if (level < k) queue.push({level + 1, ob.depth, std::move(ob.cube), ob.link});
      } else {
        links_.push_back({std::move(pred_inputs), ob.link});
        queue.push({ob.level - 1, ob.depth + 1, std::move(pred), links_.size() - 1});
      }
    }
    return true;
  }

  /// The inputs of the run the obligation chain describes, frames 0..cex_depth_, replayed on
  /// the circuit from the initial state: every step allowed, the target met in the last frame.
  /// Empty when the replay fails (the caller then rebuilds a run by BMC).
  std::vector<std::vector<bool>> replayed_run() const {
    std::vector<std::vector<bool>> run;
    for (std::size_t l = cex_link_; l != kNone; l = links_[l].parent)
      run.push_back(links_[l].inputs);
    if (run.size() != cex_depth_ + 1) return {};
    std::vector<bool> latches;
    for (const auto& l : aig_.latches()) latches.push_back(l.initial);
    for (std::size_t j = 0; j < run.size(); ++j) {
      const auto nodes = aig_.evaluate(run[j], latches);
      if (j + 1 == run.size())
        return semantics::Aig::value_of(nodes, target_) ? run : decltype(run){};
      if (!semantics::Aig::value_of(nodes, step_ok_)) return {};
      for (std::size_t l = 0; l < latches.size(); ++l)
        latches[l] = semantics::Aig::value_of(nodes, aig_.latches()[l].next);
    }
    return {};
  }

  const semantics::Aig& aig_;
  AigLit step_ok_, target_;
  Ic3Options options_;
  Ic3Stats* stats_;
  std::vector<std::uint32_t> cone_;
  std::vector<Cube> known_;                 ///< Ic3Options::known_invariant, as blocked cubes
  std::vector<FrameSolver> frames_;         ///< frames_[i] holds F_i
  std::vector<std::vector<Cube>> blocked_;  ///< cubes blocked up to exactly frame i (delta)
  std::shared_ptr<CutMapping> cuts_;        ///< the frame solvers' gates (none: plain)
  FrameSolver lift_;
  std::uint32_t cex_depth_ = 0;
  std::size_t cex_link_ = kNone;
  std::vector<Link> links_;  ///< every obligation's link, kept until the run ends
};

}  // namespace

ReachResult ic3(const ReachQuery& query, std::size_t target, const Ic3Options& options,
                Ic3Stats* stats) {
  if (options.deadline.passed()) {
    // Building the engine encodes the circuit's cone (seconds on a large one): with many
    // targets, doing so for each after the deadline overran --timeout by 10 s (corpus 11).
    ReachResult late;
    late.why = "the time limit passed before the search";
    return late;
  }
  Ic3 engine(query, target, options, stats);
  return engine.run();
}

}  // namespace sfcv::engine::sat
