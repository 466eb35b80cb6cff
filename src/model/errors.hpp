#pragma once
// The errors the library throws, one small hierarchy (like Storm's src/storm/exceptions): the
// CLI maps each kind to an exit code in one place (src/main.cpp), so no caller matches messages.
//   InputError, UnsupportedConstruct, UsageError -> 2   LimitReached -> 3   InternalError -> 4

#include <stdexcept>
#include <string>

#include "model/source_location.hpp"

namespace sfcv {

/// The base of every sfcv error; what() is the message as printed after "sfcv: error: ".
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The input (a model file, a property, a spec or query) is wrong; `where` when known.
class InputError : public Error {
 public:
  explicit InputError(const std::string& message, model::SourceLocation where = {})
      : Error(where.known() ? where.str() + ": " + message : message), where_(std::move(where)) {}
  const model::SourceLocation& where() const { return where_; }

 private:
  model::SourceLocation where_;
};

/// The input uses a construct sfcv does not model: an error, never a silent gap.
class UnsupportedConstruct : public InputError {
 public:
  using InputError::InputError;
};

/// The command line asks for something invalid (an option value, a missing tool).
class UsageError : public Error {
 public:
  using Error::Error;
};

/// Which resource ran out. Enumeration: an integer input whose values the explicit engine
/// would have to list one by one (semantics::kMaxEnumeratedValues). Valuations: one state's
/// successors need more input valuations than model::Budget::max_valuations allows (the probe of
/// --engine auto, engine/auto_policy.hpp).
enum class Limit { States, Time, Memory, Enumeration, Valuations };

/// "states", "time", "memory": the word reports use (CheckReport::limit, JSON "limit").
inline const char* to_string(Limit limit) {
  switch (limit) {
    case Limit::States:
      return "states";
    case Limit::Time:
      return "time";
    case Limit::Memory:
      return "memory";
    case Limit::Enumeration:
      return "enumeration";
    case Limit::Valuations:
      return "valuations";
  }
  return "?";
}

/// A resource limit (--max-states, --timeout, --memory, or a representation's own bound) was
/// reached before an answer was certain: the verdict is unknown.
class LimitReached : public Error {
 public:
  LimitReached(Limit which, const std::string& message) : Error(message), which_(which) {}
  Limit which() const { return which_; }

 private:
  Limit which_;
};

/// A bug in sfcv: a broken invariant. Reported with a request for a bug report.
class InternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace sfcv
