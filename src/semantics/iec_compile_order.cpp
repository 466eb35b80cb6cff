// The IEC 61131-3 compiler: the order of actions within a cycle (seed 000's partial order ⊏,
// docs/semantics.md §1.2a). A total order (declaration, alphabetical) is one exec_order. Under a
// partial order, the actions of a POU that write a common variable form groups; the order
// between the members of a group is every linearisation of ⊏ restricted to it, chosen each
// cycle by a pseudo-input, while every other action keeps its place in the base order (the
// declaration order refined by ⊏).

#include <algorithm>
#include <functional>
#include <set>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

namespace {

/// More orders than this in one group are not enumerated (each is one value of the choice
/// input and one successor of the explicit engine): 6 unordered actions on one variable.
constexpr std::size_t kMaxOrders = 720;

/// What a block may write: fields, and for calls of instances and units a marker per callee
/// (`marker_base + pou`), since two calls of one instance in either order differ.
class WriteSets {
 public:
  WriteSets(const Program& p, const std::vector<PouScope>& scopes)
      : p_(p),
        scopes_(scopes),
        marker_base_(static_cast<std::uint32_t>(p.layout.fields().size())) {}

  std::set<std::uint32_t> of(Block b) {
    std::set<std::uint32_t> out;
    std::set<std::uint32_t> seen;
    block(b, out, seen);
    return out;
  }
  bool is_field(std::uint32_t w) const { return w < marker_base_; }

 private:
  void node(std::uint32_t n, std::set<std::uint32_t>& out) {
    const auto& x = p_.nodes[n];
    if (x.op == Op::Call && x.k > 0)
      for (const auto& [from, to] : p_.call_output_copies[static_cast<std::size_t>(x.k - 1)])
        out.insert(to);
    for (std::uint32_t i = 0; i < x.count; ++i) node(p_.kids[x.first + i], out);
  }
  void block(Block b, std::set<std::uint32_t>& out, std::set<std::uint32_t>& seen) {
    for (std::uint32_t i = 0; i < b.count; ++i)
      stmt(p_.stmts[p_.block_items[b.first + i]], out, seen);
  }
  void fb(const Fb& f, std::set<std::uint32_t>& out) {
    for (auto x : {f.q, f.mem, f.cv, f.et})
      if (x != kNone) out.insert(static_cast<std::uint32_t>(x));
    if (f.timer != kNone) out.insert(p_.timers[static_cast<std::size_t>(f.timer)].field);
  }
  void stmt(const Stmt& s, std::set<std::uint32_t>& out, std::set<std::uint32_t>& seen) {
    switch (s.op) {
      case SOp::Assign:
        out.insert(s.target);
        node(s.expr, out);
        return;
      case SOp::Eval:
        node(s.expr, out);
        return;
      case SOp::If:
        for (std::uint32_t i = 0; i < s.arm_count; ++i) {
          node(p_.if_arms[s.arm_first + i].cond, out);
          block(p_.if_arms[s.arm_first + i].body, out, seen);
        }
        block(s.else_body, out, seen);
        return;
      case SOp::Case:
        node(s.expr, out);
        for (std::uint32_t i = 0; i < s.arm_count; ++i)
          block(p_.case_arms[s.arm_first + i].body, out, seen);
        block(s.else_body, out, seen);
        return;
      case SOp::FbCall:
        fb(p_.fbs[s.target], out);
        for (auto a : {s.arg1, s.arg2, s.arg3})
          if (a != kNone) node(static_cast<std::uint32_t>(a), out);
        return;
      case SOp::Loop:
        node(s.expr, out);
        block(s.init, out, seen);
        block(s.body, out, seen);
        block(s.step, out, seen);
        return;
      case SOp::Call: {
        out.insert(marker_base_ + s.target);
        if (!seen.insert(s.target).second) return;
        block(p_.pous[s.target].body, out, seen);
        for (const auto& [up, id] : scopes_[s.target].actions)
          block(p_.actions[id].body, out, seen);
        return;
      }
      case SOp::Exit:
      case SOp::Continue:
      case SOp::Return:
        return;
    }
  }

  const Program& p_;
  const std::vector<PouScope>& scopes_;
  std::uint32_t marker_base_;
};

/// Every order of `members` (indices 0..k-1 in base order) in which i comes before j when
/// before[i][j]; lexicographic, so the base order comes first. False past kMaxOrders.
bool linearisations(std::size_t k, const std::vector<std::vector<bool>>& before,
                    std::vector<std::vector<std::uint32_t>>& out) {
  std::vector<std::uint32_t> cur;
  std::vector<bool> used(k, false);
  std::function<bool()> go = [&]() {
    if (cur.size() == k) {
      out.push_back(cur);
      return out.size() <= kMaxOrders;
    }
    for (std::uint32_t i = 0; i < k; ++i) {
      if (used[i]) continue;
      bool ready = true;
      for (std::uint32_t j = 0; j < k && ready; ++j)
        if (!used[j] && before[j][i]) ready = false;
      if (!ready) continue;
      used[i] = true;
      cur.push_back(i);
      if (!go()) return false;
      cur.pop_back();
      used[i] = false;
    }
    return true;
  };
  return go();
}

std::string short_name(const std::string& full, const std::string& scope) {
  return full.size() > scope.size() + 1 && full.compare(0, scope.size() + 1, scope + ".") == 0
             ? full.substr(scope.size() + 1)
             : full;
}

}  // namespace

void Compiler::action_order(PouScope& sc, std::vector<std::uint32_t>& pair_used) {
  auto& cp = p.pous[sc.index];
  const auto& acts = cp.exec_order;  // declaration order
  const std::size_t n = acts.size();
  auto index_of = [&](const std::string& name) -> std::int32_t {
    const auto up = model::to_upper(name);
    for (std::size_t i = 0; i < n; ++i) {
      const auto full = model::to_upper(p.actions[acts[i]].name);
      if (full == up || model::to_upper(short_name(p.actions[acts[i]].name, sc.name)) == up)
        return static_cast<std::int32_t>(i);
    }
    return kNone;
  };
  // ⊏ on this POU's actions, transitively closed; a pair closing a cycle is an error.
  std::vector<std::vector<bool>> before(n, std::vector<bool>(n, false));
  std::vector<const ActionPair*> cause(n * n, nullptr);
  const auto& pairs = p.options.action_pairs;
  if (p.options.action_order == ActionOrder::Partial)
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const auto u = index_of(pairs[k].before), v = index_of(pairs[k].after);
      if (u == kNone && v == kNone) continue;
      if (u == kNone || v == kNone) {
        pair_used[k] |= 2;  // names one action of this POU only
        continue;
      }
      pair_used[k] |= 1;
      const auto a = static_cast<std::size_t>(u), b = static_cast<std::size_t>(v);
      if (a == b || before[b][a]) {
        error(pairs[k].where, "the action order '" + pairs[k].before + " < " + pairs[k].after +
                                  "' closes a cycle: " + pairs[k].after + " already runs before " +
                                  pairs[k].before + " in " + sc.name);
        continue;
      }
      for (std::size_t x = 0; x < n; ++x)
        for (std::size_t y = 0; y < n; ++y)
          if ((x == a || before[x][a]) && (y == b || before[b][y]) && !before[x][y]) {
            before[x][y] = true;
            cause[x * n + y] = &pairs[k];
          }
    }
  // Base order: declaration order refined by ⊏ (the first ready action in declaration order).
  std::vector<std::uint32_t> base;
  std::vector<bool> placed(n, false);
  while (base.size() < n) {
    for (std::size_t i = 0; i < n; ++i) {
      if (placed[i]) continue;
      bool ready = true;
      for (std::size_t j = 0; j < n && ready; ++j)
        if (!placed[j] && before[j][i]) ready = false;
      if (!ready) continue;
      placed[i] = true;
      base.push_back(static_cast<std::uint32_t>(i));
      break;
    }
  }
  // Groups: connected by writing a common variable (statement bodies only: a Boolean action's
  // variable follows its activity in phase 4, whatever the order).
  WriteSets ws(p, scopes);
  std::vector<std::set<std::uint32_t>> writes(n);
  for (std::size_t i = 0; i < n; ++i)
    if (p.actions[acts[i]].kind == model::ActionBodyKind::Statements)
      writes[i] = ws.of(p.actions[acts[i]].body);
  std::vector<std::size_t> root(n);
  for (std::size_t i = 0; i < n; ++i) root[i] = i;
  std::function<std::size_t(std::size_t)> find = [&](std::size_t i) {
    return root[i] == i ? i : root[i] = find(root[i]);
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      bool common = false;
      for (auto w : writes[i])
        if (writes[j].count(w)) {
          common = true;
          break;
        }
      if (common) root[find(i)] = find(j);
    }
  std::vector<std::uint32_t> order;  // actions
  for (auto i : base) order.push_back(acts[i]);
  cp.exec_order = order;
  cp.exec_group.assign(n, kNone);
  cp.exec_slot.assign(n, kNone);
  std::vector<std::int64_t> lo_pos(n), hi_pos(n);  // where each action may run
  for (std::size_t pos = 0; pos < n; ++pos)
    lo_pos[base[pos]] = hi_pos[base[pos]] = static_cast<std::int64_t>(pos);
  std::vector<bool> done(n, false);
  for (std::size_t pos = 0; pos < n; ++pos) {
    const auto r = find(base[pos]);
    if (done[r]) continue;
    done[r] = true;
    std::vector<std::uint32_t> mem_idx, slots;  // indices into acts, in base order
    for (std::size_t q = 0; q < n; ++q)
      if (find(base[q]) == r) {
        mem_idx.push_back(base[q]);
        slots.push_back(static_cast<std::uint32_t>(q));
      }
    if (mem_idx.size() < 2) continue;
    std::vector<std::vector<bool>> sub(mem_idx.size(), std::vector<bool>(mem_idx.size()));
    for (std::size_t x = 0; x < mem_idx.size(); ++x)
      for (std::size_t y = 0; y < mem_idx.size(); ++y) sub[x][y] = before[mem_idx[x]][mem_idx[y]];
    std::vector<std::vector<std::uint32_t>> lins;
    if (!linearisations(mem_idx.size(), sub, lins)) {
      error(sc.pou->where, std::to_string(mem_idx.size()) + " actions of " + sc.name +
                               " write a common variable and the action order leaves more than " +
                               std::to_string(kMaxOrders) +
                               " orders between them; give a partial order (--action-order FILE)");
      continue;
    }
    if (lins.size() < 2) continue;  // ⊏ is total on the group: the base order
    OrderGroup g;
    for (auto m : mem_idx) g.members.push_back(acts[m]);
    g.slots = slots;
    model::Type t = model::Type::integer("ORDER", 0, static_cast<std::int64_t>(lins.size()) - 1);
    for (std::size_t l = 0; l < lins.size(); ++l) {
      std::vector<std::uint32_t> o;
      std::string label;
      for (auto x : lins[l]) {
        o.push_back(acts[mem_idx[x]]);
        label += (label.empty() ? "" : "<") + short_name(p.actions[acts[mem_idx[x]]].name, sc.name);
        const auto at = static_cast<std::int64_t>(slots[o.size() - 1]);
        lo_pos[mem_idx[x]] = std::min(lo_pos[mem_idx[x]], at);
        hi_pos[mem_idx[x]] = std::max(hi_pos[mem_idx[x]], at);
      }
      t.enumerators.emplace_back(label, static_cast<std::int64_t>(l));
      g.orders.push_back(std::move(o));
    }
    // The input is named after the first variable the group writes in common.
    std::string what;
    for (std::size_t x = 0; x < mem_idx.size() && what.empty(); ++x)
      for (std::size_t y = x + 1; y < mem_idx.size() && what.empty(); ++y)
        for (auto w : writes[mem_idx[x]])
          if (ws.is_field(w) && writes[mem_idx[y]].count(w)) {
            what = p.layout.fields()[w].name;
            break;
          }
    if (what.empty()) what = p.actions[g.members[0]].name;
    g.choice_input = add_input("order:" + what, std::move(t), true);
    const auto gi = static_cast<std::int32_t>(cp.order_groups.size());
    for (std::size_t s = 0; s < slots.size(); ++s) {
      cp.exec_group[slots[s]] = gi;
      cp.exec_slot[slots[s]] = static_cast<std::int32_t>(s);
    }
    cp.order_groups.push_back(std::move(g));
  }
  // A pair between actions of different groups holds in the base order; a reordering that
  // would break it is not modelled (the slots are those of the base order).
  for (std::size_t x = 0; x < n; ++x)
    for (std::size_t y = 0; y < n; ++y)
      if (before[x][y] && find(x) != find(y) && hi_pos[x] >= lo_pos[y]) {
        const auto* c = cause[x * n + y];
        error(c ? c->where : sc.pou->where,
              "the action order puts " + p.actions[acts[x]].name + " before " +
                  p.actions[acts[y]].name +
                  ", which write no common variable, while the order within their groups is "
                  "left open; sfcv cannot honour both: order the groups' actions too");
      }
}

}  // namespace sfcv::semantics::iec::detail
