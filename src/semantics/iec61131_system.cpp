// The IEC 61131-3 TransitionSystem: successor enumeration over the leaves of the lazy input
// decisions, merged by target (docs/semantics.md, "Successors").

#include "semantics/iec61131_system.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

#include "model/names.hpp"
#include "semantics/detail/iec_program.hpp"
#include "semantics/detail/iec_system_impl.hpp"

namespace sfcv::semantics {

namespace iec {

Iec61131System::Iec61131System(std::unique_ptr<Program> p)
    : p_(std::move(p)), machine_(*p_), scratch_(p_->layout.words()) {}

std::vector<PouInstance> Iec61131System::pou_instances() const {
  std::vector<PouInstance> out;
  std::vector<std::size_t> at(p_->pous.size(), 0);  // Pou -> its entry in `out`
  for (std::size_t i = 0; i < p_->pous.size(); ++i)
    if (!p_->pous[i].unit) {
      at[i] = out.size();
      out.push_back({p_->pous[i].name, p_->pous[i].type, {}});
    }
  for (const auto& pou : p_->pous)
    if (pou.unit) out[at[pou.owner]].units.push_back(pou.name);
  return out;
}

void Iec61131System::initial_states(SuccessorSink& sink) const {
  const std::lock_guard<std::recursive_mutex> lock(scratch_lock_);
  std::vector<StateWord> s(p_->layout.words());
  machine_.initial(s);
  static const InputCondition kAlways = InputCondition::always();
  sink.successor(Successor{s, kAlways, {}});
}

Iec61131System::Entry& Iec61131System::entry_for(std::span<const std::uint32_t> fired) const {
  const auto words = p_->layout.words();
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (std::size_t i = 0; i < words; ++i) h = (h ^ scratch_[i]) * 0x100000001b3ULL + (h >> 29);
  for (auto f : fired) h = (h ^ f) * 0x100000001b3ULL + (h >> 29);
  if (table_.size() < 2 * (used_ + 1)) {
    // Grow and rehash the entries of this call.
    table_.assign(std::max<std::size_t>(16, table_.size() * 2), 0);
    for (std::size_t i = 0; i < used_; ++i) {
      auto slot = entries_[i].hash & (table_.size() - 1);
      while (table_[slot]) slot = (slot + 1) & (table_.size() - 1);
      table_[slot] = static_cast<std::uint32_t>(i + 1);
      entries_[i].slot = slot;
    }
  }
  auto slot = h & (table_.size() - 1);
  while (const auto t = table_[slot]) {
    auto& e = entries_[t - 1];
    if (e.hash == h &&
        std::equal(e.target.begin(), e.target.end(), scratch_.begin(), scratch_.begin() + words) &&
        std::equal(e.fired.begin(), e.fired.end(), fired.begin(), fired.end()))
      return e;
    slot = (slot + 1) & (table_.size() - 1);
  }
  if (used_ == entries_.size()) entries_.emplace_back();
  table_[slot] = static_cast<std::uint32_t>(used_ + 1);
  auto& e = entries_[used_++];
  e.hash = h;
  e.slot = slot;
  e.target.assign(scratch_.begin(), scratch_.begin() + words);
  e.fired.assign(fired.begin(), fired.end());
  e.cubes = 0;
  return e;
}

void Iec61131System::add_cube(InputCondition& cond, std::size_t& n) const {
  if (n == cond.cubes.size()) {
    if (spare_cubes_.empty()) {
      cond.cubes.emplace_back();
    } else {
      cond.cubes.push_back(std::move(spare_cubes_.back()));
      spare_cubes_.pop_back();
    }
  }
  machine_.cube(cond.cubes[n]);
  ++n;
}

void Iec61131System::trim(InputCondition& cond, std::size_t n) const {
  // Surplus cubes go to the spare pool rather than being freed: steady state allocates nothing.
  while (cond.cubes.size() > n) {
    spare_cubes_.push_back(std::move(cond.cubes.back()));
    cond.cubes.pop_back();
  }
}

void Iec61131System::successors(StateView state, SuccessorSink& sink) const {
  const std::lock_guard<std::recursive_mutex> lock(scratch_lock_);
  for (std::size_t i = 0; i < used_; ++i) {
    trim(entries_[i].condition, 0);
    table_[entries_[i].slot] = 0;
  }
  for (std::size_t i = 0; i < anomalies_used_; ++i) trim(anomalies_[i].condition, 0);
  // The pool keeps the cubes of the widest state so far: after a state with millions of
  // valuations, give most of them back rather than hold them for the rest of the run.
  constexpr std::size_t kSpareCubesKept = 1U << 16;
  if (spare_cubes_.size() > kSpareCubesKept) {
    spare_cubes_.resize(kSpareCubesKept);
    spare_cubes_.shrink_to_fit();
  }
  used_ = 0;
  anomalies_used_ = 0;
  machine_.load(state);
  machine_.reset_trail();
  std::uint64_t leaves = 0;
  std::size_t widest_cube = 0;  // literals: the bytes held are about leaves times a cube
  do {
    // A cycle that reads many inputs has exponentially many leaves: one state alone may
    // outlast the run's deadline, so the clock is read here too, not only between states.
    if ((++leaves & 4095U) == 0) {
      if (p_->options.deadline && std::chrono::steady_clock::now() > *p_->options.deadline)
        throw LimitReached(Limit::Time,
                           "time limit reached while computing the successors of "
                           "one state (" +
                               std::to_string(leaves) + " input valuations so far)");
      const std::uint64_t cube_bytes = sizeof(InputCube) + widest_cube * sizeof(InputLiteral);
      // The engine's own limits (--engine auto's probe, --memory).
      sink.valuations(leaves, (leaves + spare_cubes_.size()) * cube_bytes);
    }
    try {
      if (!machine_.run()) continue;  // excluded by an assumption
    } catch (const RangeAbort& e) {
      std::string msg =
          std::string(e.what) + (e.where && !e.where->empty() ? " at " + *e.where : "");
      AnomalyEntry* a = nullptr;
      for (std::size_t i = 0; i < anomalies_used_; ++i)
        if (anomalies_[i].message == msg) a = &anomalies_[i];
      if (!a) {
        if (anomalies_used_ == anomalies_.size()) anomalies_.emplace_back();
        a = &anomalies_[anomalies_used_++];
        a->message = msg;
        a->cubes = 0;
      }
      add_cube(a->condition, a->cubes);
      continue;
    }
    machine_.pack(scratch_);
    auto& e = entry_for(machine_.fired());
    add_cube(e.condition, e.cubes);
    widest_cube = std::max(widest_cube, e.condition.cubes[e.cubes - 1].literals.capacity());
  } while (machine_.next_leaf());
  for (std::size_t i = 0; i < used_; ++i) {
    auto& e = entries_[i];
    trim(e.condition, e.cubes);
    sink.successor(Successor{e.target, e.condition, e.fired});
  }
  for (std::size_t i = 0; i < anomalies_used_; ++i) {
    auto& a = anomalies_[i];
    trim(a.condition, a.cubes);
    Anomaly an;
    an.kind = Anomaly::Kind::RangeError;
    an.message = a.message;
    an.condition = a.condition;
    sink.anomaly(an);
  }
}

std::int64_t Iec61131System::observe(StateView state, std::uint32_t index) const {
  const auto& r = p_->observable_refs[index];
  const auto& L = p_->layout;
  switch (r.kind) {
    case ObservableKind::Step: {
      const auto& s = p_->steps[r.a];
      if (!L.get(state, s.ready)) return 0;
      const auto pa = p_->charts[s.chart].parent_action;
      return pa == kNone ? 1 : L.get(state, p_->actions[static_cast<std::size_t>(pa)].active);
    }
    case ObservableKind::Action:
      return L.get(state, p_->actions[r.a].active);
    case ObservableKind::Variable:
      return L.get(state, r.a);
  }
  return 0;
}

std::optional<std::vector<std::uint32_t>> Iec61131System::observed_fields(
    std::uint32_t index) const {
  // The fields observe() reads, case by case.
  const auto& r = p_->observable_refs[index];
  switch (r.kind) {
    case ObservableKind::Step: {
      const auto& s = p_->steps[r.a];
      const auto pa = p_->charts[s.chart].parent_action;
      if (pa == kNone) return std::vector<std::uint32_t>{s.ready};
      return std::vector<std::uint32_t>{s.ready, p_->actions[static_cast<std::size_t>(pa)].active};
    }
    case ObservableKind::Action:
      return std::vector<std::uint32_t>{p_->actions[r.a].active};
    case ObservableKind::Variable:
      return std::vector<std::uint32_t>{r.a};
  }
  return std::nullopt;
}

bool Iec61131System::step_once(StateView state, const std::vector<std::int64_t>& valuation,
                               std::vector<StateWord>& out, std::vector<std::uint32_t>* fired,
                               std::string* error) const {
  const std::lock_guard<std::recursive_mutex> lock(scratch_lock_);
  machine_.load(state);
  try {
    if (!machine_.run_fixed(valuation)) {
      if (error) *error = "the inputs violate an assumption";
      return false;
    }
  } catch (const RangeAbort& e) {
    if (error)
      *error = std::string(e.what) + (e.where && !e.where->empty() ? " at " + *e.where : "");
    return false;
  }
  out.assign(p_->layout.words(), 0);
  machine_.pack(out);
  if (fired) *fired = machine_.fired();
  return true;
}

}  // namespace iec

VendorDialect file_dialect(const model::Project& project) {
  return parse_vendor_dialect(model::vendor_of(project)).value_or(VendorDialect::Iec);
}

std::string_view to_string(VendorDialect dialect) {
  switch (dialect) {
    case VendorDialect::Iec:
      return "iec";
    case VendorDialect::Codesys:
      return "codesys";
    case VendorDialect::Twincat:
      return "twincat";
    case VendorDialect::Siemens:
      return "siemens";
    case VendorDialect::Rockwell:
      return "rockwell";
  }
  return "iec";
}

std::optional<VendorDialect> parse_vendor_dialect(std::string_view text) {
  const auto up = model::to_upper(text);
  for (auto d : {VendorDialect::Iec, VendorDialect::Codesys, VendorDialect::Twincat,
                 VendorDialect::Siemens, VendorDialect::Rockwell})
    if (model::to_upper(to_string(d)) == up) return d;
  return std::nullopt;
}

void set_dialect(Iec61131Options& options, VendorDialect dialect) {
  options.dialect = dialect;
  const bool vendor = dialect == VendorDialect::Codesys || dialect == VendorDialect::Twincat;
  if (vendor && options.action_order == ActionOrder::Declaration)
    options.action_order = ActionOrder::Vendor;
  else if (!vendor && options.action_order == ActionOrder::Vendor)
    options.action_order = ActionOrder::Declaration;
}

TransitionSystemPtr make_iec61131_system(const model::Project& project,
                                         const Iec61131Options& options,
                                         model::Diagnostics& diagnostics) {
  auto p = std::make_unique<iec::Program>();
  if (!iec::compile(project, options, *p, diagnostics)) return nullptr;
  return std::make_unique<iec::Iec61131System>(std::move(p));
}

namespace {

std::string read_place(const UnwrittenVariable& u) {
  std::string s = "read in " + u.read_in;
  if (u.read_at.line > 0) s += ", line " + std::to_string(u.read_at.line);
  return s;
}

}  // namespace

std::string unwritten_note(const std::vector<UnwrittenVariable>& list, std::size_t shown) {
  if (list.empty()) return {};
  const bool free = list.front().free;
  const auto n = list.size();
  std::string s =
      std::to_string(n) + (n == 1 ? " variable" : " variables") +
      " that no POU of the run writes " + (n == 1 ? "is" : "are") +
      (free ? " read as " + std::string(n == 1 ? "an input" : "inputs") + " (free each cycle): "
            : std::string(n == 1 ? " held at its initial value" : " held at their initial values") +
                  " (--unwritten keep): ");
  for (std::size_t i = 0; i < n && i < shown; ++i)
    s += (i ? ", " : "") + list[i].name + " (" + read_place(list[i]) + ")";
  if (n > shown) s += " and " + std::to_string(n - shown) + " more (sfcv info lists them)";
  s += free ? std::string("; --unwritten keep holds ") +
                  (n == 1 ? "it at its initial value" : "them at their initial values")
            : std::string("; by default (--unwritten free) ") + (n == 1 ? "it is" : "they are") +
                  " free each cycle";
  return s;
}

std::vector<UnwrittenVariable> unwritten_variables(const TransitionSystem& system) {
  const auto* iec = dynamic_cast<const iec::Iec61131System*>(&system);
  return iec ? iec->program().unwritten : std::vector<UnwrittenVariable>{};
}

}  // namespace sfcv::semantics
