#include "engine/sat/loop_pumping.hpp"

#include <algorithm>

#include "engine/sat/unrolling.hpp"

namespace sfcv::engine::sat {

namespace {

using semantics::Aig;

/// Simulates `prefix` and then `loop` over and over from the initial state; every wanted
/// target met on the way gets its run. Stops when every wanted target is met, a step is not
/// allowed (the run ends there), the state at a loop's start repeats the previous one (no
/// progress: the run is periodic), after `max_frames` frames, or at the deadline.
class Pump {
 public:
  Pump(const ReachQuery& q, const std::vector<bool>& is_counter, const std::vector<bool>& wanted,
       std::vector<ReachResult>& out)
      : q_(q), aig_(*q.aig), is_counter_(is_counter), wanted_(wanted), out_(out) {}

  /// Wanted targets not met yet.
  std::size_t left() const {
    std::size_t n = 0;
    for (std::size_t t = 0; t < out_.size(); ++t)
      n += wanted_[t] && out_[t].kind != ReachResult::Kind::Reached;
    return n;
  }

  void run(const std::vector<std::vector<bool>>& prefix, const std::vector<std::vector<bool>>& loop,
           const PumpOptions& o) {
    std::vector<bool> latches;
    for (const auto& l : aig_.latches()) latches.push_back(l.initial);
    // The state at the first turn's start, and Brent's cycle detection over the turns' starts:
    // `saved` is the start of turn 2^i - 1, compared with each later start up to turn 2^(i+1).
    std::vector<bool> first_start, saved;
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
      const auto nodes = aig_.evaluate(in_loop ? loop[at] : prefix[at], latches);
      for (std::size_t t = 0; t < out_.size(); ++t)
        if (wanted_[t] && out_[t].kind != ReachResult::Kind::Reached &&
            Aig::value_of(nodes, q_.targets[t]))
          reached(t, f, prefix, loop);
      if (left() == 0 || !Aig::value_of(nodes, q_.step_ok)) return;
      for (std::size_t l = 0; l < latches.size(); ++l)
        latches[l] = Aig::value_of(nodes, aig_.latches()[l].next);
    }
  }

 private:
  bool same_outside_counters(const std::vector<bool>& a, const std::vector<bool>& b) const {
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
