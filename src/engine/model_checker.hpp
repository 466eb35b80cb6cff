#pragma once
// The interface every model-checking engine implements (Storm's canHandle/check): the explicit
// engine (graph + labelling) now, a BDD engine later. Header only: each engine library
// provides its own factory.

#include <memory>
#include <string>
#include <string_view>

#include "logic/check_result.hpp"
#include "logic/check_task.hpp"

namespace sfcv::engine {

class ModelChecker {
 public:
  virtual ~ModelChecker() = default;
  virtual std::string_view name() const = 0;
  /// Whether this engine can answer every part of `task`; when not, `why` says what it lacks.
  virtual bool can_handle(const logic::CheckTask& task, std::string* why = nullptr) const = 0;
  /// Checks every property and standard check of `task`. Never answers Holds when a limit
  /// stopped exploration before the answer was certain.
  virtual logic::CheckReport check(const logic::CheckTask& task) const = 0;
};

using ModelCheckerPtr = std::unique_ptr<ModelChecker>;

}  // namespace sfcv::engine
