#pragma once
// A thin facade over BuDDy: one global manager, initialised on first use, and an RAII value
// class. No other file includes bdd.h, so BuDDy's global state and its error handling (which
// would exit the process) stay behind this interface: errors become BddError exceptions.

#include <cstdint>
#include <stdexcept>

namespace sfcv::engine::bdd {

class BddError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Initialises BuDDy once (later calls do nothing): node table, cache, hooks.
void ensure_manager(int nodes = 1 << 18, int cache = 1 << 15);
/// Makes sure variables 0..count-1 exist.
void ensure_variables(int count);

/// A BDD node held with a reference count (copyable value; comparison is canonical equality).
class Bdd {
 public:
  Bdd();  ///< false
  Bdd(const Bdd& other);
  Bdd(Bdd&& other) noexcept;
  Bdd& operator=(const Bdd& other);
  Bdd& operator=(Bdd&& other) noexcept;
  ~Bdd();

  static Bdd constant(bool value);
  static Bdd variable(int index);  ///< ensures the variable exists

  Bdd operator&(const Bdd& o) const;
  Bdd operator|(const Bdd& o) const;
  Bdd operator!() const;
  bool operator==(const Bdd& o) const { return root_ == o.root_; }
  bool operator!=(const Bdd& o) const { return root_ != o.root_; }

  bool is_true() const;
  bool is_false() const;
  /// Top variable (precondition: not constant); low/high cofactors of the top node.
  int top() const;
  Bdd low() const;
  Bdd high() const;
  /// Cofactor with respect to `var` when it is the top variable, else *this (the caller walks
  /// variables in order, so a non-top variable does not occur above the root).
  Bdd cofactor(int var, bool value) const;

 private:
  explicit Bdd(int root);
  int root_;
};

}  // namespace sfcv::engine::bdd
