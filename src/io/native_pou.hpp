#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// What the readers of vendor project files (TwinCAT 3, CODESYS native export) share: POU, global
// list and data type declarations written as ST text, read at their place in the file.

#include <memory>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "io/plcopen_xml_dom.hpp"
#include "io/st_parser.hpp"
#include "model/chart.hpp"

namespace sfcv::io::native {

/// The declaration text through the ST lexer, located in the file; nullptr after lexical
/// errors (reported to `ctx`). TwinCAT and CODESYS write `END_STRUCT` (or an enumeration's
/// `)`) right before END_TYPE without IEC 61131-3's `;`: it is supplied.
std::unique_ptr<st::Parser> declaration_parser(const plcopen::BodyText& text,
                                               plcopen::XmlContext& ctx,
                                               const model::Budget* budget);

/// Runs `f`, reporting an st::ParseError to `ctx`; false then.
template <typename F>
bool parse(plcopen::XmlContext& ctx, F&& f) {
  try {
    f();
    return true;
  } catch (const st::ParseError& e) {
    ctx.add({model::Severity::Error, e.where, e.what()});
    return false;
  }
}

/// `PROGRAM P` / `FUNCTION_BLOCK [INTERNAL|PUBLIC|FINAL] FB` / `FUNCTION F : T`, then VAR
/// sections: `pou`'s kind and variables (its name must be `pou.name`). Throws st::ParseError;
/// object-oriented function blocks (EXTENDS, IMPLEMENTS, ABSTRACT...) are refused.
void pou_declaration(st::Parser& p, model::Pou& pou);

/// A global variable list: its VAR sections into `pou.variables`. Throws st::ParseError.
void gvl_declaration(st::Parser& p, model::Pou& pou);
/// A variable of a global list `pou` outside VAR_GLOBAL is an error at `where`.
void refuse_non_globals(const model::Pou& pou, plcopen::XmlContext& ctx, pugi::xml_node where);

/// `TYPE ... END_TYPE` into `types`. Throws st::ParseError.
void dut_declaration(st::Parser& p, std::vector<model::DataType>& types);

/// The load result of a vendor project: an error when nothing was read; named after its first
/// chart or program when it has no name yet; data types lowered; no project after errors.
LoadResult finish(model::Project project, model::Diagnostics diags);

}  // namespace sfcv::io::native
