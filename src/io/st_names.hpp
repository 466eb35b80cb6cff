#pragma once
// The one check of the writers that print names into IEC 61131-3
// ST text (iec_text_writer, plcopen_writer). ST has no quoted identifiers, so a name that is
// not an identifier would be read back as something else (`a b`, `x(*`, a keyword): such a
// name is refused with a clear error, never written.

#include <string>
#include <string_view>

#include "model/expr.hpp"
#include "model/statement.hpp"

namespace sfcv::io {

/// The characters of an IEC 61131-3 identifier: the first (a letter or '_') and the others
/// (letters, digits, '_'), for the readers that find names in ST text.
bool is_st_identifier_start(char c);
bool is_st_identifier_char(char c);

/// An IEC 61131-3 identifier (letter or '_', then letters, digits, '_'), not an ST keyword.
bool is_st_identifier(std::string_view s);

/// Identifiers joined by dots (`inst.Q`, `S1.X`).
bool is_st_dotted_name(std::string_view s);

/// The first name printed by model::to_st for `e` / `body` that is not one (a variable, a
/// member, a called function, an assignment target, an FB call's parameters), or "" when
/// there is none.
std::string first_non_st_name(const model::ExprPtr& e);
std::string first_non_st_name(const model::StmtList& body);

/// Why ST text cannot carry `e` / `body`, in words ("rising edge in <where>", "name 'a b' in
/// <where> is not an IEC identifier"), or "" when it can. Edges and Grafcet delays have no ST
/// form; the writers turn a non-empty answer into UnsupportedConstruct.
std::string st_text_obstacle(const model::ExprPtr& e, std::string_view where);
std::string st_text_obstacle(const model::StmtList& body, std::string_view where);

}  // namespace sfcv::io
