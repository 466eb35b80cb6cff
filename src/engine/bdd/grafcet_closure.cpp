#include "engine/bdd/grafcet_closure.hpp"

#include <functional>
#include <map>

#include "engine/bdd/variable_order.hpp"

namespace sfcv::engine {

using semantics::Aig;
using semantics::AigLit;
using Bdd = bdd::Bdd;

GrafcetClosure::GrafcetClosure(const semantics::GrafcetCircuit& circuit, GrafcetVariables vars,
                               const std::function<Bdd(AigLit)>& state_bdd, int cluster_nodes,
                               double timeout_seconds)
    : circuit_(circuit), v_(std::move(vars)), num_state_(circuit.num_state_latches) {
  if (timeout_seconds > 0) {
    has_deadline_ = true;
    deadline_ = std::chrono::steady_clock::now() +
                std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                    std::chrono::duration<double>(timeout_seconds));
  }
  const Aig& aig = circuit_.aig;
  c_to_n_ = std::make_unique<bdd::VarMap>();
  n_to_c_ = std::make_unique<bdd::VarMap>();
  m_to_n_ = std::make_unique<bdd::VarMap>();
  n_to_m_ = std::make_unique<bdd::VarMap>();
  final_m_to_n_ = std::make_unique<bdd::VarMap>();
  for (std::size_t l = 0; l < num_state_; ++l) {
    c_to_n_->rename(v_.c[l], v_.n[l]);
    n_to_c_->rename(v_.n[l], v_.c[l]);
    m_to_n_->rename(v_.m[l], v_.n[l]);
    n_to_m_->rename(v_.n[l], v_.m[l]);
  }
  for (std::size_t p = 0; p < v_.q.size(); ++p) {
    m_to_n_->rename(v_.qp[p], v_.q[p]);
    n_to_m_->rename(v_.q[p], v_.qp[p]);
  }
  auto on_n = [&](AigLit lit) { return state_bdd(lit).replace(*c_to_n_); };

  std::vector<int> changed_n;
  for (std::size_t l = 0; l < num_state_; ++l) {
    start_.push_back(state_bdd(circuit_.start_next[l]));
    initial_.push_back(state_bdd(circuit_.initial_next[l]));
    final_.push_back(on_n(circuit_.final_next[l]));
    final_changes_.push_back(circuit_.final_next[l] != aig.latches()[l].current);
    if (final_changes_.back()) {
      changed_n.push_back(v_.n[l]);
      final_m_to_n_->rename(v_.m[l], v_.n[l]);
    }
  }
  for (auto f : circuit_.fired) cleared_.push_back(on_n(f));
  event_ = state_bdd(circuit_.event);
  initial_event_ = state_bdd(circuit_.initial_event);
  valid_ = state_bdd(circuit_.valid);
  stable_ = on_n(circuit_.stable);
  error_ = on_n(circuit_.range_error);
  continue_ = (!stable_) & (!error_);

  std::vector<int> cs(v_.c.begin(), v_.c.begin() + static_cast<std::ptrdiff_t>(num_state_));
  std::vector<int> ns(v_.n.begin(), v_.n.begin() + static_cast<std::ptrdiff_t>(num_state_));
  c_cube_ = Bdd::cube(cs);
  n_cube_ = Bdd::cube(ns);
  q_cube_ = Bdd::cube(v_.q);
  final_changed_n_cube_ = Bdd::cube(changed_n);
  std::vector<bool> kept(v_.in.size(), false);
  for (auto i : circuit_.kept_inputs) kept[i] = true;
  std::vector<int> dropped, keep;
  for (std::size_t i = 0; i < v_.in.size(); ++i) (kept[i] ? keep : dropped).push_back(v_.in[i]);
  dropped_inputs_cube_ = Bdd::cube(dropped);
  kept_inputs_cube_ = Bdd::cube(keep);
  all_inputs_cube_ = Bdd::cube(v_.in);

  // Partitioned micro-step relation: M_l <-> g_l(N, Q, I) per state latch, Q'_p <-> N_src per
  // prev latch, clustered greedily; N and Q variables are quantified after the last cluster
  // that reads them (forward), M and Q' after the cluster that defines them (backward).
  struct Part {
    Bdd bdd;
    std::vector<int> reads;    // N and Q variables read
    std::vector<int> defines;  // M and Q' variables defined
  };
  std::vector<Part> parts;
  std::vector<bool> seen(aig.nodes().size());
  Part cur{Bdd::constant(true), {}, {}};
  auto flush = [&] {
    if (!cur.defines.empty()) parts.push_back(cur);
    cur = Part{Bdd::constant(true), {}, {}};
  };
  const std::size_t num_latches = aig.latches().size();
  for (std::size_t l = 0; l < num_latches; ++l) {
    Bdd conjunct;
    std::vector<int> reads;
    int defined;
    if (l < num_state_) {
      conjunct = Bdd::variable(v_.m[l]).iff(on_n(aig.latches()[l].next));
      std::fill(seen.begin(), seen.end(), false);
      std::vector<std::uint32_t> ins, lats;
      aig_support(aig, aig.latches()[l].next, seen, ins, lats);
      for (auto x : lats) reads.push_back(x < num_state_ ? v_.n[x] : v_.q[x - num_state_]);
      defined = v_.m[l];
    } else {
      const auto p = l - num_state_;
      conjunct = Bdd::variable(v_.qp[p]).iff(Bdd::variable(v_.n[circuit_.prev_of[p]]));
      reads.push_back(v_.n[circuit_.prev_of[p]]);
      defined = v_.qp[p];
    }
    check_time();
    const Bdd merged = cur.bdd & conjunct;
    if (!cur.defines.empty() && merged.node_count() > cluster_nodes) {
      flush();
      cur.bdd = conjunct;
    } else {
      cur.bdd = merged;
    }
    cur.reads.insert(cur.reads.end(), reads.begin(), reads.end());
    cur.defines.push_back(defined);
  }
  flush();
  std::vector<int> all_nq = ns;
  all_nq.insert(all_nq.end(), v_.q.begin(), v_.q.end());
  std::map<int, int> last;
  for (std::size_t k = 0; k < parts.size(); ++k)
    for (int x : parts[k].reads) last[x] = static_cast<int>(k);
  std::vector<std::vector<int>> after(parts.size());
  std::vector<int> first;
  for (int x : all_nq) {
    auto it = last.find(x);
    if (it == last.end())
      first.push_back(x);
    else
      after[static_cast<std::size_t>(it->second)].push_back(x);
  }
  quantify_first_ = Bdd::cube(first);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    clusters_.push_back(parts[k].bdd);
    quantify_after_.push_back(Bdd::cube(after[k]));
    pre_quantify_after_.push_back(Bdd::cube(parts[k].defines));
  }
  fires_.resize(cleared_.size());
  fires_set_.assign(cleared_.size(), false);
}

void GrafcetClosure::check_time() const {
  if (has_deadline_ && std::chrono::steady_clock::now() > deadline_)
    throw LimitReached(Limit::Time,
                       "time limit reached while closing the Grafcet transient evolutions");
}

Bdd GrafcetClosure::micro_image(const Bdd& configs) const {
  check_time();
  Bdd acc = configs.exist(quantify_first_);
  for (std::size_t k = 0; k < clusters_.size(); ++k)
    acc = acc.and_exist(clusters_[k], quantify_after_[k]);
  return acc.replace(*m_to_n_);
}

Bdd GrafcetClosure::micro_preimage(const Bdd& configs) const {
  check_time();
  Bdd acc = configs.replace(*n_to_m_);
  for (std::size_t k = 0; k < clusters_.size(); ++k)
    acc = acc.and_exist(clusters_[k], pre_quantify_after_[k]);
  return acc;
}

Bdd GrafcetClosure::forward(const Bdd& start) const {
  Bdd reach = start, frontier = start;
  for (;;) {
    const Bdd next = micro_image(frontier & continue_) & !reach;
    if (next.is_false()) return reach;
    reach = reach | next;
    frontier = next;
  }
}

Bdd GrafcetClosure::backward(const Bdd& targets, const Bdd& within) const {
  const Bdd through = within & continue_;
  Bdd z = targets;
  for (;;) {
    const Bdd next = targets | (through & micro_preimage(z));
    if (next == z) return z;
    z = next;
  }
}

Bdd GrafcetClosure::starts(const Bdd& sources, bool keep_all_inputs) const {
  Bdd acc = sources & valid_ & event_;
  for (std::size_t l = 0; l < num_state_; ++l) {
    check_time();
    acc = acc & Bdd::variable(v_.n[l]).iff(start_[l]);
  }
  for (std::size_t p = 0; p < v_.q.size(); ++p)
    acc = acc & Bdd::variable(v_.q[p]).iff(Bdd::variable(v_.c[circuit_.prev_of[p]]));
  return keep_all_inputs ? acc : acc.exist(dropped_inputs_cube_);
}

Bdd GrafcetClosure::initial_starts(bool keep_all_inputs) const {
  Bdd acc = initial_event_;
  for (std::size_t l = 0; l < num_state_; ++l) acc = acc & Bdd::variable(v_.n[l]).iff(initial_[l]);
  for (std::size_t p = 0; p < v_.q.size(); ++p)
    acc = acc & Bdd::variable(v_.q[p]).iff(Bdd::variable(v_.n[circuit_.prev_of[p]]));
  return keep_all_inputs ? acc : acc.exist(dropped_inputs_cube_);
}

Bdd GrafcetClosure::emitted(const Bdd& ends) const {
  Bdd acc = ends;
  for (std::size_t l = 0; l < num_state_; ++l)
    if (final_changes_[l]) acc = acc & Bdd::variable(v_.m[l]).iff(final_[l]);
  acc = acc.exist(final_changed_n_cube_).exist(q_cube_).exist(all_inputs_cube_);
  return acc.replace(*final_m_to_n_);
}

void GrafcetClosure::set_sources(const Bdd& sources) {
  if (have_sources_ && sources == sources_) return;
  sources_ = sources;
  have_sources_ = true;
  have_relation_ = false;
  fires_set_.assign(fires_set_.size(), false);
}

void GrafcetClosure::compute_relation() {
  if (have_relation_) return;
  if (!have_sources_) {
    // The reachable stable situations, by images from the initial ones.
    Bdd reached = initial(), frontier = reached;
    while (!frontier.is_false()) {
      frontier = image(frontier) & !reached;
      reached = reached | frontier;
    }
    sources_ = reached;
    have_sources_ = true;
  }
  const Bdd st = starts(sources_, false);
  reach_ = forward(st);
  const Bdd ends = reach_ & stable_ & !error_;
  Bdd same = Bdd::constant(true);  // the emitted situation is the source itself
  for (std::size_t l = 0; l < num_state_; ++l) same = same & Bdd::variable(v_.c[l]).iff(final_[l]);
  ends_ = ends;
  ends_ne_ = ends & !same;
  relation_ = emitted(ends_ne_);
  has_successor_ = relation_.exist(n_cube_);
  // Anomalies: starts from which no end is reachable.
  good_ = backward(ends, reach_);
  const Bdd errors = backward(reach_ & error_, reach_);
  auto sources = [&](const Bdd& configs) {
    return configs.exist(n_cube_).exist(q_cube_).exist(kept_inputs_cube_);
  };
  unstable_ = sources(st & !good_ & !errors);
  range_ = sources(st & errors);
  have_relation_ = true;
}

void GrafcetClosure::compute_initial() {
  if (have_initial_) return;
  const Bdd st = initial_starts(false);
  const Bdd reach = forward(st);
  const Bdd ends = reach & stable_ & !error_;
  initial_set_ = emitted(ends).replace(*n_to_c_);
  const Bdd good = backward(ends, reach);
  const Bdd errors = backward(reach & error_, reach);
  initial_anomaly_ = !(st & !good).is_false();
  initial_range_ = !(st & errors).is_false();
  initial_good_ = good;
  have_initial_ = true;
}

Bdd GrafcetClosure::initial() {
  compute_initial();
  return initial_set_;
}

bool GrafcetClosure::fires_initially(std::uint32_t transition) {
  compute_initial();
  // Cleared on a run that stabilises (as the explicit engine's initial edges record it).
  return !(initial_good_ & cleared_[transition]).is_false();
}

bool GrafcetClosure::initial_anomaly() {
  compute_initial();
  return initial_anomaly_;
}

bool GrafcetClosure::initial_range_error() {
  compute_initial();
  return initial_range_;
}

Bdd GrafcetClosure::image(const Bdd& states) {
  if (have_relation_) return (states & relation_).exist(c_cube_).replace(*n_to_c_);
  const Bdd reach = forward(starts(states, false));
  Bdd same = Bdd::constant(true);
  for (std::size_t l = 0; l < num_state_; ++l) same = same & Bdd::variable(v_.c[l]).iff(final_[l]);
  const Bdd ends = reach & stable_ & !error_ & !same;
  return emitted(ends).exist(c_cube_).replace(*n_to_c_);
}

Bdd GrafcetClosure::preimage(const Bdd& states) {
  compute_relation();
  return relation_.and_exist(states.replace(*c_to_n_), n_cube_);
}

Bdd GrafcetClosure::has_successor() {
  compute_relation();
  return has_successor_;
}

Bdd GrafcetClosure::fires(std::uint32_t t) {
  compute_relation();
  if (!fires_set_[t]) {
    fires_[t] = (good_ & cleared_[t]).exist(n_cube_).exist(q_cube_).exist(kept_inputs_cube_);
    fires_set_[t] = true;
  }
  return fires_[t];
}

Bdd GrafcetClosure::enters(const Bdd& step) {
  compute_relation();
  // A configuration carries its source C, and N is one situation of its run (the first, each
  // transient one, the stable end): the run stabilises from it iff it lies in good_.
  const Bdd during = (good_ & step.replace(*c_to_n_)).exist(n_cube_).exist(q_cube_);
  return during.exist(kept_inputs_cube_) & !step;
}

bool GrafcetClosure::enters_initially(const Bdd& step) {
  compute_initial();
  return !(initial_good_ & step.replace(*c_to_n_)).is_false();
}

Bdd GrafcetClosure::fires_on_one_edge(std::uint32_t i, std::uint32_t j) {
  compute_relation();
  // Runs are deterministic and carry their source C, so the configurations reached from one
  // that clears t are exactly those of runs clearing t (a run merging into such a
  // configuration shares its end, hence its edge); their ends, emitted, are the edges whose
  // fired set holds t, and the situations an event clearing t returns to (docs/semantics.md
  // 3.2: an event that ends where it began clears its transitions too).
  auto edges_clearing = [&](std::uint32_t t) -> const Bdd& {
    if (edges_clearing_.size() != cleared_.size()) {
      edges_clearing_.assign(cleared_.size(), Bdd::constant(false));
      edges_clearing_set_.assign(cleared_.size(), false);
    }
    if (!edges_clearing_set_[t]) {
      edges_clearing_[t] = emitted(forward(reach_ & cleared_[t]) & ends_);
      edges_clearing_set_[t] = true;
    }
    return edges_clearing_[t];
  };
  const Bdd with_i = edges_clearing(i);
  return (with_i & edges_clearing(j)).exist(n_cube_);
}

Bdd GrafcetClosure::unstable_states() {
  compute_relation();
  return unstable_;
}

Bdd GrafcetClosure::range_error_states() {
  compute_relation();
  return range_;
}

Bdd GrafcetClosure::inputs_ending_in(const Bdd& reach, const Bdd& to) const {
  Bdd acc = reach & stable_ & !error_;
  for (std::size_t l = 0; l < num_state_; ++l)
    if (final_changes_[l]) acc = acc & Bdd::variable(v_.m[l]).iff(final_[l]);
  acc = acc.exist(final_changed_n_cube_).replace(*final_m_to_n_);
  acc = acc & to.replace(*c_to_n_);
  return acc.exist(c_cube_).exist(n_cube_).exist(q_cube_);
}

Bdd GrafcetClosure::inputs_between(const Bdd& from, const Bdd& to) {
  return inputs_ending_in(forward(starts(from, true)), to);
}

Bdd GrafcetClosure::initial_inputs(const Bdd& to) {
  // Every input is kept: the trace's first row must be a valuation that stabilises in `to`,
  // not only one that the input memory agrees with (docs/semantics.md 2.15).
  return inputs_ending_in(forward(initial_starts(true)), to);
}

}  // namespace sfcv::engine
