#include "engine/bdd/bdd_manager.hpp"

#include <bdd.h>

#include <algorithm>
#include <chrono>
#include <string>

// bdd.h maps these names to its C++ layer; the facade uses the C API with explicit reference
// counting.
#undef bdd_init
#undef bdd_ithvar
#undef bdd_makeset

namespace sfcv::engine::bdd {

namespace {

void throw_on_error(int code) {
  throw BddError(std::string("BDD package error: ") + bdd_errstring(code));
}

bool g_has_deadline = false;
std::chrono::steady_clock::time_point g_deadline;

void quiet_gbc(int pre, bddGbcStat*) {
  // Before the collection starts (the node table is still consistent).
  if (pre && g_has_deadline && std::chrono::steady_clock::now() > g_deadline) {
    g_has_deadline = false;
    throw BddError("time limit reached in the BDD package");
  }
}

// Sizing chosen by configure_manager() before the manager starts; 0 = the defaults.
int g_nodes = 0, g_cache = 0, g_ratio = 0;

}  // namespace

void configure_manager(int nodes, int cache, int cache_ratio) {
  if (bdd_isrunning()) return;
  g_nodes = nodes;
  g_cache = cache;
  g_ratio = cache_ratio;
}

void set_time_limit(double seconds) {
  g_has_deadline = seconds > 0;
  if (g_has_deadline)
    g_deadline = std::chrono::steady_clock::now() +
                 std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                     std::chrono::duration<double>(seconds));
}

int allocated_nodes() { return bdd_isrunning() ? bdd_getnodenum() : 0; }

void reset_operation_caches() {
  if (bdd_isrunning()) bdd_gbc();  // a garbage collection also empties the caches
}

void ensure_manager(int nodes, int cache) {
  if (bdd_isrunning()) return;
  if (g_nodes > 0) {
    nodes = g_nodes;
    cache = g_cache;
  }
  bdd_error_hook(throw_on_error);
  if (bdd_init(nodes, cache) < 0) throw BddError("BDD package: initialisation failed");
  bdd_setcacheratio(g_ratio > 0 ? g_ratio : 64);
  bdd_gbc_hook(quiet_gbc);
  bdd_setvarnum(1);
}

void ensure_variables(int count) {
  ensure_manager();
  const int have = bdd_varnum();
  if (count > have) bdd_extvarnum(count - have);
}

Bdd::Bdd() : root_(0) { ensure_manager(); }
Bdd::Bdd(int root) : root_(root) { bdd_addref(root_); }
Bdd::Bdd(const Bdd& other) : root_(other.root_) { bdd_addref(root_); }
Bdd::Bdd(Bdd&& other) noexcept : root_(other.root_) { other.root_ = 0; }
Bdd& Bdd::operator=(const Bdd& other) {
  if (this != &other) {
    bdd_addref(other.root_);
    bdd_delref(root_);
    root_ = other.root_;
  }
  return *this;
}
Bdd& Bdd::operator=(Bdd&& other) noexcept {
  if (this != &other) {
    bdd_delref(root_);
    root_ = other.root_;
    other.root_ = 0;
  }
  return *this;
}
Bdd::~Bdd() { bdd_delref(root_); }

Bdd Bdd::constant(bool value) {
  ensure_manager();
  return Bdd(value ? 1 : 0);  // BuDDy's bddtrue and bddfalse
}

Bdd Bdd::variable(int index) {
  ensure_variables(index + 1);
  return Bdd(bdd_ithvar(index));
}

Bdd Bdd::operator&(const Bdd& o) const { return Bdd(bdd_and(root_, o.root_)); }
Bdd Bdd::operator|(const Bdd& o) const { return Bdd(bdd_or(root_, o.root_)); }
Bdd Bdd::operator!() const { return Bdd(bdd_not(root_)); }

Bdd Bdd::operator^(const Bdd& o) const { return Bdd(bdd_apply(root_, o.root_, bddop_xor)); }
Bdd Bdd::iff(const Bdd& o) const { return Bdd(bdd_apply(root_, o.root_, bddop_biimp)); }
Bdd Bdd::ite(const Bdd& t, const Bdd& e) const { return Bdd(bdd_ite(root_, t.root_, e.root_)); }

Bdd Bdd::cube(const std::vector<int>& vars) {
  ensure_manager();
  int max_var = -1;
  for (int v : vars) max_var = std::max(max_var, v);
  ensure_variables(max_var + 1);
  std::vector<int> copy(vars);
  return Bdd(bdd_makeset(copy.data(), static_cast<int>(copy.size())));
}

Bdd Bdd::exist(const Bdd& vars) const { return Bdd(bdd_exist(root_, vars.root_)); }
Bdd Bdd::and_exist(const Bdd& o, const Bdd& vars) const {
  return Bdd(bdd_appex(root_, o.root_, bddop_and, vars.root_));
}
Bdd Bdd::replace(const VarMap& map) const {
  return Bdd(bdd_replace(root_, static_cast<bddPair*>(map.pair_)));
}
Bdd Bdd::compose(const VarMap& map) const {
  return Bdd(bdd_veccompose(root_, static_cast<bddPair*>(map.pair_)));
}
Bdd Bdd::sat_one(const Bdd& vars) const { return Bdd(bdd_satoneset(root_, vars.root_, 0)); }
int Bdd::value_in_cube(int var) const {
  int r = root_;
  while (r > 1) {
    const int v = bdd_var(r);
    if (v == var) return bdd_low(r) == 0 ? 1 : 0;
    r = bdd_low(r) == 0 ? bdd_high(r) : bdd_low(r);
  }
  return -1;
}
double Bdd::sat_count_log2(const Bdd& vars) const { return bdd_satcountlnset(root_, vars.root_); }
int Bdd::node_count() const { return bdd_nodecount(root_); }

VarMap::VarMap() : pair_(nullptr) {
  ensure_manager();
  pair_ = bdd_newpair();
}
VarMap::~VarMap() { bdd_freepair(static_cast<bddPair*>(pair_)); }
void VarMap::rename(int from, int to) {
  ensure_variables(std::max(from, to) + 1);
  bdd_setpair(static_cast<bddPair*>(pair_), from, to);
}
void VarMap::substitute(int var, const Bdd& f) {
  ensure_variables(var + 1);
  bdd_setbddpair(static_cast<bddPair*>(pair_), var, f.root_);
}

bool Bdd::is_true() const { return root_ == 1; }
bool Bdd::is_false() const { return root_ == 0; }
int Bdd::top() const { return bdd_var(root_); }
Bdd Bdd::low() const { return Bdd(bdd_low(root_)); }
Bdd Bdd::high() const { return Bdd(bdd_high(root_)); }

Bdd Bdd::cofactor(int var, bool value) const {
  if (root_ <= 1 || bdd_var(root_) != var) return *this;
  return value ? high() : low();
}

}  // namespace sfcv::engine::bdd
