// The IEC compiler's implicit SFC flags (CODESYS, TwinCAT): a POU with an SFC body that declares
// a BOOL `SFCInit` or `SFCReset` has its charts reset to the initial situation while the flag is
// TRUE (docs/semantics.md, "Implicit SFC flags"). The flags are attached to the compiled Pou, so
// every compiled POU (an instance included) carries its own. The other vendor flags, which the
// runtime reads or writes behind the program's back, are refused rather than modelled as plain
// variables.

#include <array>
#include <string_view>

#include "model/names.hpp"
#include "semantics/detail/iec_compiler.hpp"

namespace sfcv::semantics::iec::detail {

namespace {
/// Upper-case names of the vendor flags sfcv does not model (CODESYS V2/V3, TwinCAT 2/3).
constexpr std::array<std::string_view, 15> kRefusedFlags = {"SFCPAUSE",
                                                            "SFCERROR",
                                                            "SFCTRANS",
                                                            "SFCERRORSTEP",
                                                            "SFCERRORPOU",
                                                            "SFCQUITERROR",
                                                            "SFCENABLELIMIT",
                                                            "SFCTIP",
                                                            "SFCTIPMODE",
                                                            "SFCCURRENTSTEP",
                                                            "SFCRESETTING",
                                                            "SFCMAXFLAGS",
                                                            "SFCERRORANALYZATION",
                                                            "SFCERRORANALYZATIONTABLE",
                                                            "SFCSETTINGS"};
}  // namespace

void Compiler::sfc_flags() {
  for (auto& sc : scopes) {
    const auto& pou = *sc.pou;
    if (!pou.has_sfc()) continue;
    auto& cp = p.pous[sc.index];
    for (const auto& v : pou.variables) {
      const auto up = model::to_upper(v.name);
      for (auto refused : kRefusedFlags)
        if (up == refused)
          error(v.where, "'" + v.name + "' in " + pou.name +
                             " is a CODESYS/TwinCAT implicit SFC flag that sfcv does not "
                             "model (only SFCInit and SFCReset are); rename the variable or "
                             "remove it");
      if (up != "SFCINIT" && up != "SFCRESET") continue;
      auto it = sc.names.find(up);
      if (v.type.kind != TypeKind::Bool || it == sc.names.end() || it->second.kind == Ref::FbInst) {
        error(v.where, "'" + v.name + "' in " + pou.name +
                           " names a CODESYS/TwinCAT SFC flag and must be a BOOL variable");
        continue;
      }
      reading(sc, v.where);
      Node n;
      n.op = it->second.kind == Ref::Field ? Op::Field : Op::Input;
      n.a = it->second.index;
      (up == "SFCINIT" ? cp.sfc_init : cp.sfc_reset) = static_cast<std::int32_t>(node(n));
    }
    if (cp.sfc_init == kNone && cp.sfc_reset == kNone) continue;
    // What the flags restore: the charts' steps and .T, the actions' activity, stored flags,
    // Boolean variables, and their qualifiers' timers and latches.
    for (auto c : cp.charts)
      for (auto s : p.charts[c].steps) {
        cp.chart_fields.push_back(p.steps[s].ready);
        if (p.steps[s].t_field != kNone)
          cp.chart_fields.push_back(static_cast<std::uint32_t>(p.steps[s].t_field));
      }
    for (const auto& a : p.actions) {
      if (a.pou != sc.index) continue;
      cp.chart_fields.push_back(a.active);
      if (a.stored != kNone) cp.chart_fields.push_back(static_cast<std::uint32_t>(a.stored));
      if (a.final_call != kNone)
        cp.chart_fields.push_back(static_cast<std::uint32_t>(a.final_call));
      if (a.variable != kNone) cp.chart_fields.push_back(static_cast<std::uint32_t>(a.variable));
      for (auto x : a.assocs) {
        const auto& as = p.assocs[x];
        if (as.timer != kNone)
          cp.chart_fields.push_back(p.timers[static_cast<std::size_t>(as.timer)].field);
        if (as.latch != kNone) cp.chart_fields.push_back(static_cast<std::uint32_t>(as.latch));
      }
    }
  }
}

}  // namespace sfcv::semantics::iec::detail
