#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// Rockwell ladder logic (RLL routines of Studio 5000 `.L5X` files) as ST statements. A rung is
// written in Studio 5000's neutral text: instructions left to right, `[ , ]` for parallel
// branches, `;` at the end (`XIC(start)[XIO(X.1) ,XIC(S:FS) ]OTE(X.0);`).
//
// The rung condition flows as in Logix 5000 Controllers General Instructions (1756-RM003): an
// examine instruction (XIC, XIO, comparisons) ANDs into it, each leg of a branch starts from the
// condition before the branch and the branch's result is the OR of its legs, and an output
// instruction (OTE, OTL, OTU, MOV, CLR, ADD, SUB, MUL, ONS, TON, CTU, CTD, RES, JSR) acts on
// the condition reaching it.
// Instructions run in the order they are written, so a value written by one is what the next
// reads. Where a condition already formed reads a tag that a later instruction writes, its
// value is kept in a hidden BOOL temporary first (reset at the end of the body, so it holds no
// state), so that the statements compute what the rung computes.

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "model/expr.hpp"
#include "model/source_location.hpp"
#include "model/statement.hpp"

namespace sfcv::io::l5x {

/// One instruction (`mnemonic(operands)`) or one branch (`legs`) of a rung, as written.
struct RungElement {
  std::string mnemonic;               ///< upper case; empty for a branch
  std::vector<std::string> operands;  ///< trimmed, as written
  std::vector<std::vector<RungElement>> legs;
};
using RungSequence = std::vector<RungElement>;

/// A rung's neutral text; nullopt with `error` set when it is not well formed.
std::optional<RungSequence> parse_rung(std::string_view text, std::string& error);

/// Every instruction of `rung`, branches included, in the order they run.
void each_instruction(const RungSequence& rung,
                      const std::function<void(const RungElement&)>& visit);

/// The operands (tags and their parts) a CPT expression reads, in order.
std::vector<std::string> compute_operands(std::string_view expression);

/// What the operands of a program's rungs are (the L5X reader knows its tags). Each returns
/// null / "" / nullopt after setting `error`.
class RungOperands {
 public:
  virtual ~RungOperands() = default;
  /// The Boolean an examine instruction reads (`start`, `X.3`, `T2.DN`, `S:FS`).
  virtual model::ExprPtr bit(const std::string& operand, std::string& error) = 0;
  /// The Boolean variable an output instruction writes.
  virtual std::string bit_target(const std::string& operand, std::string& error) = 0;
  /// An integer operand (a tag or a literal) and an integer variable written.
  virtual model::ExprPtr value(const std::string& operand, std::string& error) = 0;
  virtual std::string value_target(const std::string& operand, std::string& error) = 0;
  /// An element chosen by a tag as a write target (`Step[i].X`): the index, read, and each
  /// element's target (a BOOL's when `bit`). nullopt with `error` empty when `operand` is not
  /// one; `error` set when it is not read.
  struct Chosen {
    model::ExprPtr index;
    std::vector<std::string> targets;
  };
  virtual std::optional<Chosen> chosen_target(const std::string& operand, bool bit,
                                              std::string& error) = 0;
  /// The TON instance a TIMER tag is, and its preset in milliseconds.
  virtual std::optional<std::pair<std::string, std::int64_t>> timer(const std::string& operand,
                                                                    std::string& error) = 0;
  /// The variables a COUNTER tag is, and its preset.
  struct Counter {
    std::string accumulated, up, down, done;  ///< .ACC (DINT), .CU, .CD, .DN (BOOL)
    std::int64_t preset = 0;
  };
  virtual std::optional<Counter> counter(const std::string& operand, std::string& error) = 0;
  /// What `RES(operand)` does: for a TIMER, the TON call that clears its bits and time; for a
  /// COUNTER, .ACC, .CU, .CD and .DN cleared.
  virtual std::optional<model::StmtList> reset(const std::string& operand, std::string& error) = 0;
  /// The statements of the routine `JSR(routine, 0)` runs.
  virtual std::optional<model::StmtList> subroutine(const std::string& routine,
                                                    std::string& error) = 0;
};

/// Turns the rungs of one body into statements; the hidden temporaries are shared by the rungs.
class RungTranslator {
 public:
  /// `temporary_prefix` names the hidden temporaries (`<prefix>1`, `<prefix>2`, ...).
  RungTranslator(RungOperands& operands, std::string temporary_prefix);

  /// Appends what `rung` does in one scan to `out`, the statements located at `where`; false
  /// with the reasons in `errors` when it is not read.
  bool translate(const RungSequence& rung, const model::SourceLocation& where, model::StmtList& out,
                 std::vector<std::string>& errors);

  /// The hidden BOOL temporaries made so far: the caller declares them and resets them to
  /// FALSE at the end of the body.
  const std::vector<std::string>& temporaries() const { return temporaries_; }

 private:
  /// The rung condition reaching an instruction.
  struct Power {
    model::ExprPtr expr;          ///< null: TRUE (straight from the left rail)
    std::set<std::string> reads;  ///< upper-case names `expr` reads
    std::string unknown_after;    ///< the instruction (TON, JSR) after which it is not read
  };

  /// `result_needed`: the caller reads the condition `seq` ends with.
  Power run(const RungSequence& seq, Power in, bool result_needed);
  void instruction(const RungElement& e, Power& p);
  bool known(const Power& p, const RungElement& e);
  /// Keeps every live condition that reads `name` in a temporary before `name` is written.
  void before_write(const std::string& name);
  void and_into(Power& p, model::ExprPtr e);
  /// Appends `make(target)` for the target `operand` names (a BOOL's when `bit`), after
  /// before_write; for an element a tag chooses, a CASE over the elements.
  void write(const std::string& operand, bool bit,
             const std::function<model::StmtPtr(const std::string&)>& make);
  model::StmtPtr make_if(model::ExprPtr condition, model::StmtList body) const;
  void fail(std::string message);

  RungOperands& operands_;
  std::string prefix_;
  std::vector<std::string> temporaries_;
  // Per rung:
  model::SourceLocation where_;
  model::StmtList* out_ = nullptr;
  std::vector<std::string>* errors_ = nullptr;
  std::vector<Power*> live_;  ///< conditions read after the instruction at hand
};

}  // namespace sfcv::io::l5x
