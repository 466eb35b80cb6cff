#include "engine/bdd/bdd_manager.hpp"

#include <bdd.h>

#include <string>

// bdd.h maps these names to its C++ layer; the facade uses the C API with explicit reference
// counting.
#undef bdd_init
#undef bdd_ithvar

namespace sfcv::engine::bdd {

namespace {

void throw_on_error(int code) {
  throw BddError(std::string("BDD package error: ") + bdd_errstring(code));
}

void quiet_gbc(int, bddGbcStat*) {}

}  // namespace

void ensure_manager(int nodes, int cache) {
  if (bdd_isrunning()) return;
  bdd_error_hook(throw_on_error);
  if (bdd_init(nodes, cache) < 0) throw BddError("BDD package: initialisation failed");
  bdd_setcacheratio(64);
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
