#include "io/plcopen_st.hpp"

namespace sfcv::io::plcopen {

// TEMPORARY until the ST parser (branch iec-text) is merged: conditions kept as raw text.
model::ExprPtr parse_expression_text(const BodyText& text, model::Diagnostics&) {
  return model::make_name(trim(text.text), text.start);
}

std::optional<model::StmtList> parse_statements_text(const BodyText&, model::Diagnostics&) {
  return model::StmtList{};
}

}  // namespace sfcv::io::plcopen
