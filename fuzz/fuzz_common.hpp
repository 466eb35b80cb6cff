#pragma once
// Shared body of the importer harnesses: load, validate, and build the system the semantics
// would check (each recursive pass of the pipeline up to exploration). Library errors are
// located diagnostics or exceptions; the fuzzer looks for crashes, hangs and sanitizer reports.

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>

#include "io/load.hpp"
#include "model/validate.hpp"
#ifndef SFCV_FUZZ_NO_SEMANTICS  // a lighter build: parse and validate only
#include "semantics/grafcet_system.hpp"
#include "semantics/iec61131_system.hpp"
#endif

namespace sfcv::fuzz {

inline void load_validate_build(io::LoadResult (*load)(std::string_view, const std::string&,
                                                       const model::Budget*),
                                const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    auto r = load(text, "fuzz", nullptr);  // no budget: libFuzzer's -timeout bounds an input
    if (!r.ok()) return;
    const auto diags = model::validate(*r.project);
    if (model::has_errors(diags)) return;
#ifndef SFCV_FUZZ_NO_SEMANTICS
    model::Diagnostics d;
    if (r.project->dialect == model::Dialect::Grafcet) {
      semantics::make_grafcet_system(*r.project, semantics::GrafcetOptions{}, d);
    } else {
      for (const auto& pou : r.project->pous) {
        // Charts, and programs without one (ladder, ST): what `sfcv check` builds.
        if (!pou.has_sfc() && (pou.kind != model::PouKind::Program || pou.body.empty())) continue;
        semantics::Iec61131Options o;
        o.pous = {pou.name};
        semantics::make_iec61131_system(*r.project, o, d);
      }
    }
#endif
  } catch (const std::exception&) {
    // A reported error, not a crash.
  }
}

}  // namespace sfcv::fuzz
