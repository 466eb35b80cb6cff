#include "engine/sat/loop_pumping.hpp"

#include <algorithm>

#include "engine/sat/unrolling.hpp"

namespace sfcv::engine::sat {

namespace {

using semantics::Aig;
using semantics::AigLit;

/// The circuit as a flat program over one byte per node: the pumped runs are tens of
/// thousands of cycles, and Aig::evaluate (bit vectors, checked access, one allocation per
/// cycle) made them several times slower (too slow for the sanitizer build's budget).
class Simulator {
 public:
  explicit Simulator(const Aig& aig) : aig_(aig), value_(aig.nodes().size(), 0) {
    for (std::uint32_t i = 1; i < aig.nodes().size(); ++i)
      if (aig.nodes()[i].kind == Aig::NodeKind::And)
        ands_.push_back({i, aig.nodes()[i].left, aig.nodes()[i].right});
  }
  /// One cycle from `latches` under `inputs`; read the nodes with value().
  void evaluate(const std::vector<bool>& inputs, const std::vector<std::uint8_t>& latches) {
    for (std::size_t i = 0; i < aig_.inputs().size(); ++i)
      value_[Aig::node_of(aig_.inputs()[i].literal)] = inputs[i];
    for (std::size_t l = 0; l < aig_.latches().size(); ++l)
      value_[Aig::node_of(aig_.latches()[l].current)] = latches[l];
    for (const auto& g : ands_) value_[g.node] = value(g.left) & value(g.right);
  }
  std::uint8_t value(AigLit l) const {
    return static_cast<std::uint8_t>(value_[Aig::node_of(l)] ^ (Aig::is_negated(l) ? 1 : 0));
  }

 private:
  struct And {
    std::uint32_t node;
    AigLit left, right;
  };
  const Aig& aig_;
  std::vector<And> ands_;  ///< in node order: operands come first
  std::vector<std::uint8_t> value_;
};

/// Simulates `prefix` and then `loop` over and over from the initial state; every wanted
/// target met on the way gets its run. Stops when every wanted target is met, a step is not
/// allowed (the run ends there), a turn leaves the loop or the run turns periodic, after
/// `max_frames` frames, or at the deadline.
class Pump {
 public:
  Pump(const ReachQuery& q, const std::vector<bool>& is_counter, const std::vector<bool>& wanted,
       std::vector<ReachResult>& out)
      : q_(q),
        aig_(*q.aig),
        simulator_(aig_),
        is_counter_(is_counter),
        wanted_(wanted),
        out_(out) {}

  /// Wanted targets not met yet.
  std::size_t left() const {
    std::size_t n = 0;
    for (std::size_t t = 0; t < out_.size(); ++t)
      n += wanted_[t] && out_[t].kind != ReachResult::Kind::Reached;
    return n;
  }

  void run(const std::vector<std::vector<bool>>& prefix, const std::vector<std::vector<bool>>& loop,
           const PumpOptions& o) {
    std::vector<std::uint8_t> latches, next(aig_.latches().size());
    for (const auto& l : aig_.latches()) latches.push_back(l.initial ? 1 : 0);
    // The state at the first turn's start, and Brent's cycle detection over the turns' starts:
    // `saved` is the start of turn 2^i - 1, compared with each later start up to turn 2^(i+1).
    std::vector<std::uint8_t> first_start, saved;
    std::uint64_t turns = 0, power = 1;
    for (std::uint64_t f = 0; f < o.max_frames; ++f) {
      if ((f & 1023) == 0 && o.deadline.passed()) return;
      const bool in_loop = f >= prefix.size();
      const std::uint64_t at = in_loop ? (f - prefix.size()) % loop.size() : f;
      if (in_loop && at == 0) {
        // Each turn must bring the latches outside the counters back (else the loop's inputs
        // no longer drive the same steps), and the counters must not repeat (else the run is
        // periodic from here on and meets nothing new).
        if (first_start.empty()) first_start = latches;
        if (!same_outside_counters(latches, first_start) || latches == saved) return;
        if (++turns == power) {
          saved = latches;
          power *= 2;
        }
      }
      simulator_.evaluate(in_loop ? loop[at] : prefix[at], latches);
      for (std::size_t t = 0; t < out_.size(); ++t)
        if (wanted_[t] && out_[t].kind != ReachResult::Kind::Reached &&
            simulator_.value(q_.targets[t]))
          reached(t, f, prefix, loop);
      if (left() == 0 || !simulator_.value(q_.step_ok)) return;
      for (std::size_t l = 0; l < next.size(); ++l)
        next[l] = simulator_.value(aig_.latches()[l].next);
      latches.swap(next);
    }
  }

 private:
  bool same_outside_counters(const std::vector<std::uint8_t>& a,
                             const std::vector<std::uint8_t>& b) const {
    for (std::size_t l = 0; l < a.size(); ++l)
      if (!is_counter_[l] && a[l] != b[l]) return false;
    return true;
  }

  void reached(std::size_t t, std::uint64_t last, const std::vector<std::vector<bool>>& prefix,
               const std::vector<std::vector<bool>>& loop) {
    auto& r = out_[t];
    r.kind = ReachResult::Kind::Reached;
    r.depth = static_cast<std::uint32_t>(last);
    r.inputs.clear();
    for (std::uint64_t f = 0; f <= last; ++f)
      r.inputs.push_back(f < prefix.size() ? prefix[f] : loop[(f - prefix.size()) % loop.size()]);
  }

  const ReachQuery& q_;
  const Aig& aig_;
  Simulator simulator_;
  const std::vector<bool>& is_counter_;
  const std::vector<bool>& wanted_;
  std::vector<ReachResult>& out_;
};

}  // namespace

std::vector<ReachResult> pump_loops(const ReachQuery& query,
                                    const std::vector<std::uint32_t>& counters,
                                    const std::vector<bool>& wanted, const PumpOptions& options) {
  std::vector<ReachResult> out(query.targets.size());
  const Aig& aig = *query.aig;
  std::vector<bool> is_counter(aig.latches().size(), false);
  for (auto l : counters) is_counter[l] = true;
  Pump pump(query, is_counter, wanted, out);
  if (counters.empty() || pump.left() == 0) return out;

  Solver solver(options.deadline);
  Unrolling frames(aig, solver, true);
  std::uint32_t lassos = 0;
  for (std::uint32_t k = 1; k <= options.max_lasso; ++k) {
    solver.add_clause({frames.literal(query.step_ok, k - 1)});  // steps 0..k-1 are allowed
    for (std::uint32_t j = k; j-- > 0;) {  // the shortest loop ending at k first
      if (lassos == options.max_lassos || pump.left() == 0) return out;
      // Under `loop`: frame k repeats frame j outside the counters, and some counter differs.
      const int loop = solver.new_var();
      std::vector<int> some_counter_differs{-loop};
      for (std::uint32_t l = 0; l < aig.latches().size(); ++l) {
        const int a = frames.latch(l, j), b = frames.latch(l, k);
        if (!is_counter[l]) {
          solver.add_clause({-loop, -a, b});
          solver.add_clause({-loop, a, -b});
        } else {
          const int differs = solver.new_var();
          solver.add_clause({-differs, a, b});
          solver.add_clause({-differs, -a, -b});
          some_counter_differs.push_back(differs);
        }
      }
      solver.add_clause(some_counter_differs);
      const auto r = solver.solve({loop});
      if (r == SatResult::Interrupted) return out;
      std::vector<std::vector<bool>> prefix, body;
      if (r == SatResult::Sat)
        for (std::uint32_t f = 0; f < k; ++f)
          (f < j ? prefix : body).push_back(frames.input_values(f));
      solver.add_clause({-loop});  // retired (this ends the model read above)
      if (r == SatResult::Unsat) continue;
      ++lassos;
      pump.run(prefix, body, options);
    }
  }
  return out;
}

}  // namespace sfcv::engine::sat
