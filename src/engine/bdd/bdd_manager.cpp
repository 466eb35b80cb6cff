#include "engine/bdd/bdd_manager.hpp"

#include <bdd.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "model/errors.hpp"

// bdd.h maps these names to its C++ layer; the facade uses the C API with explicit reference
// counting.
#undef bdd_init
#undef bdd_ithvar
#undef bdd_makeset

namespace sfcv::engine::bdd {

namespace {

// After an error BuDDy's tables are in doubt (the error may come from the middle of a resize
// or a reordering): reference counts are no longer touched, and the next start_manager()
// replaces the manager.
bool g_failed = false;
bool g_reordering_used = false;  ///< the variable order may differ from the identity
long g_live = 0;

void throw_on_error(int code) {
  g_failed = true;
  if (code == BDD_NODENUM || code == BDD_MEMORY)
    throw LimitReached(Limit::Memory, std::string("the BDD node table is full (--memory): ") +
                                          bdd_errstring(code));
  throw BddError(std::string("BDD package error: ") + bdd_errstring(code));
}

bool g_has_deadline = false;
std::chrono::steady_clock::time_point g_deadline;
const std::atomic<bool>* g_cancel = nullptr;

// BuDDy's reordering allocates its own tables and frees them only if it returns: a limit is
// not thrown from a hook while it runs (LeakSanitizer saw the leaks under --engine auto).
bool g_in_reorder = false;

using Clock = std::chrono::steady_clock;

bool past_deadline(Clock::time_point now) {
  return g_has_deadline && !g_in_reorder &&
         ((g_cancel && g_cancel->load(std::memory_order_relaxed)) || now > g_deadline);
}
bool past_deadline() {
  return g_has_deadline && past_deadline(Clock::now());
}

// A sifting pass cannot be interrupted (see g_in_reorder) and moves every variable through
// every level: on a system of 1,800 variables (corpus 11, 860 latches) one pass ran 20 s past
// --timeout 20. With a deadline (or the portfolio's cancel flag) set, systems above this many
// variables are not reordered, so that the limit holds; without one, reordering is only slow.
constexpr int kMaxSiftedVariables = 1200;
// Below that, a pass still costs about variables x live nodes: on corpus 09 (641 variables)
// passes from 0.43 M, 0.64 M and 0.78 M nodes took 2.4 s, 24.5 s and 30.7 s, up to 6.1e-8 s
// per variable and node, and ran 31 s past --timeout 40. Before a deadline, a pass starts only
// if this many seconds per variable and node (the worst measured, with a margin for slower
// machines and a trigger that fires above the current count) fit in the time left.
constexpr double kSiftSecondsPerVariableNode = 1e-7;
bool sifting_too_long(Clock::time_point now) {
  if (!g_has_deadline) return false;
  if (bdd_varnum() > kMaxSiftedVariables) return true;
  if (g_deadline == Clock::time_point::max()) return false;  // cancel only
  const double left = std::chrono::duration<double>(g_deadline - now).count();
  return kSiftSecondsPerVariableNode * bdd_varnum() * std::max(bdd_getnodenum(), 1) > left;
}
bool sifting_too_long() {
  return g_has_deadline && sifting_too_long(Clock::now());
}

// Automatic reordering waits until a collection leaves this many live nodes
// (set_automatic_reordering): BuDDy's own trigger is the initial table.
int g_armed_passes = 0;
int g_first_pass_nodes = 0;

void quiet_gbc(int pre, bddGbcStat*) {
  if (!pre && g_armed_passes > 0 && bdd_getnodenum() >= g_first_pass_nodes && !sifting_too_long()) {
    // BuDDy checks its trigger right after this collection: the pass runs at once.
    bdd_autoreorder_times(BDD_REORDER_SIFT, g_armed_passes);
    g_armed_passes = 0;
  }
  // Before the collection starts (the node table is still consistent). The manager is replaced
  // at the next start all the same, as after any error.
  if (pre && past_deadline()) {
    g_has_deadline = false;
    g_failed = true;
    throw LimitReached(Limit::Time, "time limit reached in the BDD package");
  }
}

// A table that grows by doubling is rarely collected: one operation can run for seconds
// between collections, so each resize polls the deadline too (after it, the tables are
// consistent; the manager is replaced all the same).
void deadline_on_resize(int, int) {
  if (past_deadline()) {
    g_has_deadline = false;
    g_failed = true;
    throw LimitReached(Limit::Time, "time limit reached in the BDD package");
  }
}

// Between operations the tables are consistent: past the deadline the next operation throws
// without failing the manager. Fixpoint loops are made of many operations, so this bounds them
// to about one operation past the deadline (every operation reads the clock: one operation on
// a large model can take a second, and sampling every 16th overshot a 20 s limit by 22 s); the
// garbage-collection and resize hooks above stop a single operation that blows up.
void check_deadline() {
  if (!g_has_deadline) return;
  const auto now = Clock::now();  // read once: this runs before every operation
  if (past_deadline(now)) throw LimitReached(Limit::Time, "time limit reached in a BDD operation");
  // An automatic pass may start inside the next operation: none that would outlast the time.
  if (bdd_getreorder_method() != BDD_REORDER_NONE && sifting_too_long(now)) {
    bdd_autoreorder(BDD_REORDER_NONE);
    g_armed_passes = 0;
  }
}

int g_reorderings = 0;
// Automatic passes stop after one that gained less than this (percent of the live nodes): the
// order is as good as sifting makes it, and passes over ever larger BDDs (a deep counter's
// rings) would only cost (measured: counter 16 went from 0.6 s to 3 to 6 s without it).
int g_min_gain = 0;
void count_reorder(int before) {
  g_in_reorder = before != 0;
  if (before) return;
  ++g_reorderings;
  if (bdd_reorder_gain() < g_min_gain) bdd_autoreorder(BDD_REORDER_NONE);
}

// Sizing chosen by configure_manager() before the manager starts; 0 = the defaults.
int g_nodes = 0, g_cache = 0, g_ratio = 0;

void init_manager(int nodes, int cache, int ratio, int max_nodes) {
  if (bdd_init(nodes, cache) < 0) throw BddError("BDD package: initialisation failed");
  // bdd_init installs BuDDy's own handler, which exits the process: replace it after.
  bdd_error_hook(throw_on_error);
  g_failed = false;
  g_reordering_used = false;
  bdd_setcacheratio(ratio > 0 ? ratio : 64);
  // Grow by doubling (BuDDy's default adds at most 50 000 nodes per resize: a table started
  // small would be collected and resized thousands of times on a large model).
  bdd_setmaxincrease(1 << 26);
  bdd_gbc_hook(quiet_gbc);
  bdd_resize_hook(deadline_on_resize);
  bdd_reorder_hook(count_reorder);
  bdd_reorder_verbose(0);
  bdd_autoreorder(BDD_REORDER_NONE);
  g_armed_passes = 0;
  // BuDDy rounds the table up to a prime and refuses a limit not above it.
  bdd_setmaxnodenum(max_nodes > 0 ? std::max(max_nodes, bdd_getallocnum() + 1) : 0);
  bdd_setvarnum(1);
}

}  // namespace

void configure_manager(int nodes, int cache, int cache_ratio) {
  if (bdd_isrunning()) return;
  g_nodes = nodes;
  g_cache = cache;
  g_ratio = cache_ratio;
}

void set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline,
                  const std::atomic<bool>* cancel) {
  // A cancel flag alone is a deadline at the end of time.
  g_has_deadline = deadline.has_value() || cancel;
  g_deadline = deadline ? *deadline : std::chrono::steady_clock::time_point::max();
  g_cancel = cancel;
  if (bdd_isrunning() && sifting_too_long()) {
    bdd_autoreorder(BDD_REORDER_NONE);
    g_armed_passes = 0;
  }
}

EarlierDeadlineScope::EarlierDeadlineScope(std::chrono::steady_clock::time_point earlier)
    : had_deadline_(g_has_deadline), deadline_(g_deadline) {
  if (!g_has_deadline || earlier < g_deadline) {
    g_has_deadline = true;
    g_deadline = earlier;
  }
}

EarlierDeadlineScope::~EarlierDeadlineScope() {
  g_has_deadline = had_deadline_;
  g_deadline = deadline_;
}

bool deadline_passed() {
  return past_deadline();
}

void poll_deadline() {
  if (past_deadline()) throw LimitReached(Limit::Time, "time limit reached in a simulation");
}

int allocated_nodes() {
  return bdd_isrunning() ? bdd_getnodenum() : 0;
}

void reset_operation_caches() {
  if (bdd_isrunning()) bdd_gbc();  // a garbage collection also empties the caches
}

void ensure_manager(int nodes, int cache) {
  if (bdd_isrunning()) return;
  if (g_nodes > 0) {
    nodes = g_nodes;
    cache = g_cache;
  }
  init_manager(nodes, cache, g_ratio, 0);
}

void start_manager(const ManagerOptions& o) {
  const int nodes = o.max_nodes > 0 ? std::min(o.nodes, o.max_nodes) : o.nodes;
  const int cache = std::max(1, std::min(o.cache, nodes / std::max(1, o.cache_ratio)));
  if (bdd_isrunning()) {
    const bool unfit =
        g_failed || g_reordering_used || (o.max_nodes > 0 && bdd_getallocnum() > o.max_nodes);
    if (!unfit) {
      bdd_setmaxnodenum(o.max_nodes > 0 ? std::max(o.max_nodes, bdd_getallocnum() + 1) : 0);
      bdd_clrvarblocks();
      bdd_autoreorder(BDD_REORDER_NONE);
      g_armed_passes = 0;
      return;
    }
    if (g_live > 0) {
      if (g_failed) throw BddError("BDD package: a failed manager is still in use");
      // Cannot replace it: keep the order it has and bound its growth from here on.
      if (o.max_nodes == 0 || o.max_nodes > bdd_getallocnum()) bdd_setmaxnodenum(o.max_nodes);
      bdd_clrvarblocks();
      g_armed_passes = 0;
      return;
    }
    bdd_done();
  }
  init_manager(nodes, cache, o.cache_ratio, o.max_nodes);
}

void add_variable_block(int first, int last) {
  ensure_variables(last + 1);
  bdd_intaddvarblock(first, last, BDD_REORDER_FIXED);
}

void set_automatic_reordering(int max_passes, int min_gain_percent, int first_pass_nodes) {
  ensure_manager();
  g_min_gain = min_gain_percent;
  g_armed_passes = 0;
  bdd_autoreorder(BDD_REORDER_NONE);
  if (max_passes > 0) {
    g_reordering_used = true;
    if (sifting_too_long()) {
      // no pass: see kMaxSiftedVariables
    } else if (first_pass_nodes <= bdd_getallocnum()) {
      bdd_autoreorder_times(BDD_REORDER_SIFT, max_passes);
    } else {
      g_armed_passes = max_passes;
      g_first_pass_nodes = first_pass_nodes;
    }
  }
}

void delay_automatic_reordering(int first_pass_nodes) {
  if (g_armed_passes > 0) g_first_pass_nodes = std::max(g_first_pass_nodes, first_pass_nodes);
}

bool automatic_reordering_waits() {
  return g_armed_passes > 0;
}

void start_automatic_reordering() {
  if (g_armed_passes == 0 || sifting_too_long()) return;
  // BuDDy's trigger (the initial table) is below the live nodes: the next collection sifts.
  bdd_autoreorder_times(BDD_REORDER_SIFT, g_armed_passes);
  g_armed_passes = 0;
}

void reorder_now() {
  if (sifting_too_long()) return;
  g_reordering_used = true;
  bdd_reorder(BDD_REORDER_SIFT);
  ++g_reorderings;  // BuDDy calls the hook for automatic reorderings only
}

int reorderings() {
  return g_reorderings;
}

int level_of(int var) {
  return bdd_var2level(var);
}

long live_bdds() {
  return g_live;
}  // references to non-constant nodes

void ensure_variables(int count) {
  ensure_manager();
  const int have = bdd_varnum();
  if (count > have) bdd_extvarnum(count - have);
  if (sifting_too_long()) {
    bdd_autoreorder(BDD_REORDER_NONE);
    g_armed_passes = 0;
  }
}

// g_live counts references to non-constant nodes: constants need no manager, so a Bdd holding
// one survives a replaced manager.
namespace {
void add_ref(int root) {
  if (root <= 1) return;
  ++g_live;
  if (!g_failed) bdd_addref(root);
}
void del_ref(int root) noexcept {
  if (root <= 1) return;
  --g_live;
  if (!g_failed) bdd_delref(root);
}
}  // namespace

Bdd::Bdd() : root_(0) {}
Bdd::Bdd(int root) : root_(root) {
  add_ref(root_);
}
Bdd::Bdd(const Bdd& other) : root_(other.root_) {
  add_ref(root_);
}
Bdd::Bdd(Bdd&& other) noexcept : root_(other.root_) {
  other.root_ = 0;
}
Bdd& Bdd::operator=(const Bdd& other) {
  if (this != &other) {
    add_ref(other.root_);
    del_ref(root_);
    root_ = other.root_;
  }
  return *this;
}
Bdd& Bdd::operator=(Bdd&& other) noexcept {
  if (this != &other) {
    del_ref(root_);
    root_ = other.root_;
    other.root_ = 0;
  }
  return *this;
}
Bdd::~Bdd() {
  del_ref(root_);
}

Bdd Bdd::constant(bool value) {
  ensure_manager();
  return Bdd(value ? 1 : 0);  // BuDDy's bddtrue and bddfalse
}

Bdd Bdd::variable(int index) {
  ensure_variables(index + 1);
  return Bdd(bdd_ithvar(index));
}

Bdd Bdd::operator&(const Bdd& o) const {
  check_deadline();
  return Bdd(bdd_and(root_, o.root_));
}
Bdd Bdd::operator|(const Bdd& o) const {
  check_deadline();
  return Bdd(bdd_or(root_, o.root_));
}
// BuDDy 2.4's bdd_not (not_rec) stores its results in the apply cache writing only the
// entry's fields a, c and res; apply_rec then compares field b of such an entry when its
// operand equals a, reading memory never written since the cache was allocated (valgrind:
// "conditional jump depends on uninitialised value", allocated in BddCache_resize). The answer
// is right all the same (field c, bddop_not, never matches an apply operator), but the report
// hides real memory errors. x XOR true is the same function through apply_rec, which writes
// every field.
Bdd Bdd::operator!() const {
  check_deadline();
  return Bdd(bdd_apply(root_, 1, bddop_xor));
}

Bdd Bdd::operator^(const Bdd& o) const {
  check_deadline();
  return Bdd(bdd_apply(root_, o.root_, bddop_xor));
}
Bdd Bdd::iff(const Bdd& o) const {
  check_deadline();
  return Bdd(bdd_apply(root_, o.root_, bddop_biimp));
}
Bdd Bdd::ite(const Bdd& t, const Bdd& e) const {
  check_deadline();
  // bdd_ite negates through not_rec (operator! above) when it meets then = false and
  // else = true; a variable above both branches (successor_simulator's use) never recurses
  // into such a pair, any other case is written with apply.
  if (t.root_ == 0 && e.root_ == 1) return !*this;
  const int top_level = root_ > 1 ? bdd_var2level(bdd_var(root_)) : -1;
  auto below = [&](int r) { return r <= 1 || bdd_var2level(bdd_var(r)) > top_level; };
  const bool variable = root_ > 1 && bdd_low(root_) == 0 && bdd_high(root_) == 1;
  if (root_ <= 1 || (variable && below(t.root_) && below(e.root_)))
    return Bdd(bdd_ite(root_, t.root_, e.root_));
  return (*this & t) | ((!*this) & e);
}

Bdd Bdd::cube(const std::vector<int>& vars) {
  ensure_manager();
  int max_var = -1;
  for (int v : vars) max_var = std::max(max_var, v);
  ensure_variables(max_var + 1);
  std::vector<int> copy(vars);
  return Bdd(bdd_makeset(copy.data(), static_cast<int>(copy.size())));
}

Bdd Bdd::exist(const Bdd& vars) const {
  check_deadline();
  return Bdd(bdd_exist(root_, vars.root_));
}
Bdd Bdd::and_exist(const Bdd& o, const Bdd& vars) const {
  check_deadline();
  return Bdd(bdd_appex(root_, o.root_, bddop_and, vars.root_));
}
Bdd Bdd::replace(const VarMap& map) const {
  check_deadline();
  return Bdd(bdd_replace(root_, static_cast<bddPair*>(map.pair_)));
}
Bdd Bdd::compose(const VarMap& map) const {
  check_deadline();
  return Bdd(bdd_veccompose(root_, static_cast<bddPair*>(map.pair_)));
}
Bdd Bdd::sat_one(const Bdd& vars) const {
  return Bdd(bdd_satoneset(root_, vars.root_, 0));
}
int Bdd::value_in_cube(int var) const {
  int r = root_;
  while (r > 1) {
    const int v = bdd_var(r);
    if (v == var) return bdd_low(r) == 0 ? 1 : 0;
    r = bdd_low(r) == 0 ? bdd_high(r) : bdd_low(r);
  }
  return -1;
}
double Bdd::sat_count_log2(const Bdd& vars) const {
  return bdd_satcountlnset(root_, vars.root_);
}

namespace {

/// A value per internal node (index >= 2) of one BDD: open addressing, at most half full. A
/// walk's memo is most of a count's cost, and std::unordered_map's node per entry tripled it.
template <typename T>
class NodeMemo {
 public:
  bool contains(int n) const { return keys_[slot(n)] == n; }
  T& operator[](int n) {
    std::size_t i = slot(n);
    if (keys_[i] != n) {
      if (2 * (size_ + 1) > keys_.size()) {
        grow();
        i = slot(n);
      }
      keys_[i] = n;
      ++size_;
    }
    return values_[i];
  }
  const T& at(int n) const { return values_[slot(n)]; }
  std::size_t size() const { return size_; }

 private:
  std::size_t slot(int n) const {
    const std::size_t mask = keys_.size() - 1;
    std::size_t i = (static_cast<std::size_t>(n) * 0x9e3779b97f4a7c15ULL) >> 20 & mask;
    while (keys_[i] != 0 && keys_[i] != n) i = (i + 1) & mask;
    return i;
  }
  void grow() {
    std::vector<int> keys(keys_.size() * 2, 0);
    std::vector<T> values(keys.size());
    keys.swap(keys_);
    values.swap(values_);
    for (std::size_t k = 0; k < keys.size(); ++k)
      if (keys[k] != 0) {
        const std::size_t i = slot(keys[k]);
        keys_[i] = keys[k];
        values_[i] = std::move(values[k]);
      }
  }
  std::vector<int> keys_ = std::vector<int>(64, 0);  // 0: empty (never an internal node)
  std::vector<T> values_ = std::vector<T>(64);
  std::size_t size_ = 0;
};

/// Calls `combine(n, low, high)` once for every internal node below `root`, children first,
/// with an explicit stack (a BDD may be deeper than the call stack); `combine` stores n's value
/// in `memo` and returns false to stop the walk.
template <typename T, typename Combine>
void fold_post_order(int root, NodeMemo<T>& memo, Combine&& combine) {
  std::vector<int> stack{root};
  while (!stack.empty()) {
    const int n = stack.back();
    if (n <= 1 || memo.contains(n)) {
      stack.pop_back();
      continue;
    }
    const int lo = bdd_low(n), hi = bdd_high(n);
    const bool lo_done = lo <= 1 || memo.contains(lo), hi_done = hi <= 1 || memo.contains(hi);
    if (!lo_done || !hi_done) {
      if (!lo_done) stack.push_back(lo);
      if (!hi_done) stack.push_back(hi);
      continue;
    }
    if (!combine(n, lo, hi)) return;
    stack.pop_back();
  }
}

}  // namespace

std::optional<std::uint64_t> Bdd::sat_count_u64(const std::vector<int>& vars, int* nodes) const {
  // below[l]: how many counted variables lie above level l. count(n) counts the assignments of
  // the counted variables at or below n's level; a skipped counted variable doubles it.
  __extension__ typedef unsigned __int128 Wide;
  const int levels = bdd_varnum();
  std::vector<int> below(static_cast<std::size_t>(levels) + 1, 0);
  std::vector<char> counted(static_cast<std::size_t>(levels), 0);
  for (int v : vars) counted[static_cast<std::size_t>(bdd_var2level(v))] = 1;
  for (int l = 0; l < levels; ++l) below[l + 1] = below[l] + counted[l];
  const Wide limit = ~std::uint64_t{0};
  bool overflow = false;
  auto level = [&](int n) { return n <= 1 ? levels : bdd_var2level(bdd_var(n)); };
  auto scale = [&](Wide c, int from_level, int to_level) -> Wide {
    const int skipped = below[to_level] - below[from_level];
    if (c == 0) return 0;
    if (skipped >= 64 || (c << skipped) >> skipped != c || (c << skipped) > limit) {
      overflow = true;
      return limit;
    }
    return c << skipped;
  };
  NodeMemo<Wide> memo;
  auto value = [&](int c) -> Wide { return c <= 1 ? Wide(c) : memo.at(c); };
  fold_post_order(root_, memo, [&](int n, int lo, int hi) {
    const int l = level(n);
    const Wide sum = scale(value(lo), l + 1, level(lo)) + scale(value(hi), l + 1, level(hi));
    if (sum > limit) overflow = true;
    memo[n] = sum;
    return !overflow;
  });
  if (nodes) *nodes = overflow ? node_count() : static_cast<int>(memo.size());
  if (overflow) return std::nullopt;
  const Wide top = root_ <= 1 ? Wide(root_) : memo.at(root_);
  const Wide total = scale(top, 0, level(root_));
  if (overflow || total > limit) return std::nullopt;
  return static_cast<std::uint64_t>(total);
}
logic::BigCount Bdd::sat_count_exact(const std::vector<int>& vars) const {
  if (const auto small = sat_count_u64(vars)) return *small;
  // As sat_count_u64, with big integers: counted[l] marks the levels of `vars`, above[l] how
  // many of them lie above level l.
  const int levels = bdd_varnum();
  std::vector<int> above(static_cast<std::size_t>(levels) + 1, 0);
  std::vector<char> counted(static_cast<std::size_t>(levels), 0);
  for (int v : vars) counted[static_cast<std::size_t>(bdd_var2level(v))] = 1;
  for (int l = 0; l < levels; ++l) above[l + 1] = above[l] + counted[l];
  auto level = [&](int n) { return n <= 1 ? levels : bdd_var2level(bdd_var(n)); };
  auto scale = [&](const logic::BigCount& c, int from_level, int to_level) {
    return c.shifted_left(static_cast<unsigned>(above[to_level] - above[from_level]));
  };
  NodeMemo<logic::BigCount> memo;
  auto value = [&](int c) {
    return c <= 1 ? logic::BigCount(static_cast<std::uint64_t>(c)) : memo.at(c);
  };
  fold_post_order(root_, memo, [&](int n, int lo, int hi) {
    const int l = level(n);
    auto sum = scale(value(lo), l + 1, level(lo));
    sum += scale(value(hi), l + 1, level(hi));
    memo[n] = std::move(sum);
    return true;
  });
  return scale(value(root_), 0, level(root_));
}

int Bdd::node_count() const {
  return bdd_nodecount(root_);
}

bool Bdd::for_each_assignment(const std::vector<int>& vars,
                              const std::function<bool(const std::vector<bool>&)>& visit) const {
  if (root_ == 0) return true;
  // The variables in level order; a path fixes the ones it meets and leaves the others free.
  const int levels = bdd_varnum();
  std::vector<int> position_at_level(static_cast<std::size_t>(levels), -1);
  for (std::size_t k = 0; k < vars.size(); ++k)
    position_at_level[static_cast<std::size_t>(bdd_var2level(vars[k]))] = static_cast<int>(k);
  std::vector<int> order;  // positions in vars, by level
  for (int l = 0; l < levels; ++l)
    if (position_at_level[static_cast<std::size_t>(l)] >= 0)
      order.push_back(position_at_level[static_cast<std::size_t>(l)]);
  std::vector<bool> values(vars.size(), false);
  // Depth-first over (depth in `order`, node); each frame tries value 0, then value 1.
  struct Frame {
    std::size_t depth;
    int node;
    int next_value;
  };
  std::vector<Frame> stack{{0, root_, 0}};
  while (!stack.empty()) {
    Frame& f = stack.back();
    if (f.node == 0 || f.next_value > 1) {
      stack.pop_back();
      continue;
    }
    if (f.depth == order.size()) {
      if (f.node != 1) return false;  // a variable outside `vars`
      stack.pop_back();
      if (!visit(values)) return false;
      continue;
    }
    const int pos = order[f.depth];
    const int var = vars[static_cast<std::size_t>(pos)];
    const bool tested = f.node > 1 && bdd_var(f.node) == var;
    if (f.node > 1 && !tested && bdd_var2level(bdd_var(f.node)) < bdd_var2level(var))
      return false;  // tests a variable outside `vars`
    const int value = f.next_value++;
    values[static_cast<std::size_t>(pos)] = value == 1;
    const int child = !tested ? f.node : value == 1 ? bdd_high(f.node) : bdd_low(f.node);
    stack.push_back({f.depth + 1, child, 0});
  }
  return true;
}

VarMap::VarMap() : pair_(nullptr) {
  ensure_manager();
  pair_ = bdd_newpair();
}
VarMap::~VarMap() {
  bdd_freepair(static_cast<bddPair*>(pair_));
}
void VarMap::rename(int from, int to) {
  ensure_variables(std::max(from, to) + 1);
  bdd_setpair(static_cast<bddPair*>(pair_), from, to);
}
void VarMap::substitute(int var, const Bdd& f) {
  ensure_variables(var + 1);
  bdd_setbddpair(static_cast<bddPair*>(pair_), var, f.root_);
}

bool Bdd::is_true() const {
  return root_ == 1;
}
bool Bdd::is_false() const {
  return root_ == 0;
}
int Bdd::top() const {
  return bdd_var(root_);
}
Bdd Bdd::low() const {
  return Bdd(bdd_low(root_));
}
Bdd Bdd::high() const {
  return Bdd(bdd_high(root_));
}

Bdd Bdd::cofactor(int var, bool value) const {
  if (root_ <= 1 || bdd_var(root_) != var) return *this;
  return value ? high() : low();
}

}  // namespace sfcv::engine::bdd
