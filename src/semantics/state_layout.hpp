#pragma once
// Bit-level layout of a packed state: an explicit engine stores a state in a few 64-bit words,
// a BDD engine allocates one variable per bit.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sfcv::semantics {

using StateWord = std::uint64_t;
using StateView = std::span<const StateWord>;
using MutableStateView = std::span<StateWord>;

enum class FieldKind {
  StepReady,        ///< IEC: the step is ready (active, or history of a suspended nested chart)
  StepActive,       ///< Grafcet: the step is active (IEC step activity is derived, never stored)
  ActionActive,     ///< IEC: the action is active
  ActionStored,     ///< IEC: the action is stored (S without R yet)
  ActionFinalCall,  ///< IEC, CODESYS/TwinCAT dialect: the action stopped; its final call is due
  Variable,         ///< a Boolean or bounded-integer program variable (outputs, locals)
  InputMemory,      ///< the previous value of an input, kept for edges / the single-change rule
  Timer,            ///< a timer's phase or cycle counter
  FbState,          ///< other standard-FB memory (R_TRIG memory, counters, SR/RS latch)
};

struct StateField {
  std::string name;  ///< human name: "MAIN.FILL_A", "V1", "TON1.ET"
  FieldKind kind = FieldKind::Variable;
  std::uint32_t offset = 0;  ///< first bit
  std::uint32_t width = 1;   ///< number of bits
  std::int64_t lo = 0;       ///< the encoded value v is stored as (v - lo)
};

class StateLayout {
 public:
  /// Appends a field wide enough for [lo, hi]; returns its index.
  std::uint32_t add_field(std::string name, FieldKind kind, std::int64_t lo = 0,
                          std::int64_t hi = 1);

  /// The next field starts in a fresh word (so that a prefix of the words is a whole state of
  /// a system this layout extends).
  void align_to_word() { bits_ = words() * 64; }

  const std::vector<StateField>& fields() const { return fields_; }
  std::uint32_t bits() const { return bits_; }
  std::uint32_t words() const { return (bits_ + 63) / 64; }

  std::int64_t get(StateView state, std::uint32_t field) const;
  void set(MutableStateView state, std::uint32_t field, std::int64_t value) const;
  bool get_bit(StateView state, std::uint32_t bit) const {
    return (state[bit / 64] >> (bit % 64)) & 1U;
  }

 private:
  std::vector<StateField> fields_;
  std::uint32_t bits_ = 0;
};

}  // namespace sfcv::semantics
