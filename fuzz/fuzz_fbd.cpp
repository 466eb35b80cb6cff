// libFuzzer harness: FBD/LD networks. The input is the inside of an `<FBD>` body of a program
// with Boolean and integer variables (the seeds are networks: shared wires, blocks, contacts,
// coils, connectors); the harness loads it, validates it and compiles the program, so that a
// network that unfolds (docs/semantics.md, "Shared wires") or wires itself into a loop meets
// every consumer, not only the reader.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>

#include "io/load.hpp"
#include "model/validate.hpp"
#include "semantics/iec61131_system.hpp"

namespace {

constexpr std::string_view kHead =
    "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"><fileHeader companyName=\"f\" "
    "productName=\"CODESYS\" productVersion=\"3.5\" creationDateTime=\"2024-01-01T00:00:00\"/>"
    "<contentHeader name=\"f\"/><types><dataTypes/><pous><pou name=\"Main\" pouType=\"program\">"
    "<interface><inputVars><variable name=\"a\"><type><BOOL/></type></variable>"
    "<variable name=\"b\"><type><BOOL/></type></variable><variable name=\"n\"><type><INT/></type>"
    "</variable></inputVars><outputVars><variable name=\"q\"><type><BOOL/></type></variable>"
    "<variable name=\"r\"><type><INT/></type></variable></outputVars><localVars>"
    "<variable name=\"t\"><type><derived name=\"TON\"/></type></variable></localVars></interface>"
    "<body>";
constexpr std::string_view kTail =
    "</body></pou></pous></types><instances><configurations/></instances></project>\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The body element is the input's (FBD or LD), so the fuzzer reaches both readers.
  std::string text(kHead);
  text.append(reinterpret_cast<const char*>(data), size);
  text.append(kTail);
  try {
    auto r = sfcv::io::load_plcopen_xml(text, "fuzz.xml", nullptr);
    if (!r.ok()) return 0;
    if (sfcv::model::has_errors(sfcv::model::validate(*r.project))) return 0;
    sfcv::model::Diagnostics d;
    sfcv::semantics::Iec61131Options o;
    o.pous = {"Main"};
    sfcv::semantics::make_iec61131_system(*r.project, o, d);
  } catch (const std::exception&) {
  }
  return 0;
}
