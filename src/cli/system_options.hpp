#pragma once
// Internal header of sfcv_cli (only src/cli includes it; cmake/CheckInternalHeaders.cmake).
// The options that choose and parametrise the semantics (--semantics, --pou, --priority, --time,
// --cycle, --unwritten, --multi-input-change), registered and turned into a transition system in
// one place, so that check, query, rsg, simulate and export build the same system from the same
// flags.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "model/budget.hpp"
#include "model/chart.hpp"
#include "model/expr.hpp"
#include "semantics/options.hpp"
#include "semantics/transition_system.hpp"

namespace sfcv::cli {

struct SystemOptions {
  std::string semantics;  ///< empty or "auto": from the model's dialect
  std::vector<std::string> pous;
  std::string priority = "standard";
  std::string time = "abstract";
  std::string cycle = "10ms";
  std::string unwritten = "free";  ///< variables no POU of the run writes: free or keep
  bool multi_input_change = false;
  /// declaration, alphabetical, unordered or a FILE of pairs (cli/action_order.hpp); empty:
  /// the subcommand's default
  std::string action_order;
  /// iec, codesys, twincat, siemens or rockwell; empty: the vendor that wrote the file
  std::string dialect;
};

/// Which semantics a subcommand offers: the circuit exports run IEC 61131-3 only.
enum class SemanticsChoice { Both, IecOnly };

void add_system_options(CLI::App& sub, SystemOptions& options,
                        SemanticsChoice choice = SemanticsChoice::Both);

/// "grafcet" or "iec61131": --semantics, else the model's dialect. Bad values throw InputError.
std::string chosen_semantics(const model::Project& project, const SystemOptions& options);

/// The value of a --dialect option: nullopt when empty or "auto"; a bad value throws UsageError.
std::optional<semantics::VendorDialect> given_dialect(const std::string& text);

/// --dialect, else the vendor that wrote the file (semantics::file_dialect). Bad values throw
/// UsageError.
semantics::VendorDialect chosen_dialect(const model::Project& project,
                                        const SystemOptions& options);

/// The file's dialect of IEC 61131-3 and the other options' defaults, for subcommands that have
/// no --dialect (lint, info): the system `check` builds by default.
semantics::Iec61131Options default_iec_options(const model::Project& project);
struct BuiltSystem {
  semantics::TransitionSystemPtr system;
  std::string semantics;  ///< "grafcet" or "iec61131"
};

/// Builds the system the options describe. Diagnostics go to standard error; a model the
/// semantics cannot express (or bad option values) throws InputError naming `command`.
BuiltSystem build_system(const model::Project& project, const SystemOptions& options,
                         const std::vector<model::ExprPtr>& assumptions, const std::string& command,
                         semantics::ActionOrder action_order = semantics::ActionOrder::Declaration,
                         const model::Budget* budget = nullptr);

}  // namespace sfcv::cli
