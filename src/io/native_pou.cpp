// Declarations of vendor project files as ST text (native_pou.hpp).

#include "io/native_pou.hpp"

#include "io/st_lexer.hpp"
#include "model/data_types.hpp"
#include "model/names.hpp"

namespace sfcv::io::native {

std::unique_ptr<st::Parser> declaration_parser(const plcopen::BodyText& text,
                                               plcopen::XmlContext& ctx,
                                               const model::Budget* budget) {
  model::SourceLocation start = text.start;
  start.element_path.clear();  // file:line:col inside the text says more
  st::Locator locator(start);
  model::Diagnostics lexical;
  auto tokens = st::tokenize(text.text, locator, lexical, budget);
  const bool broken = model::has_errors(lexical);
  for (auto& d : lexical) ctx.add(std::move(d));
  if (broken) return nullptr;
  for (std::size_t i = 1; i < tokens.size(); ++i)
    if (tokens[i].kind == st::TokenKind::Identifier && model::iequals(tokens[i].text, "END_TYPE") &&
        tokens[i - 1].kind != st::TokenKind::Semicolon) {
      st::Token semicolon = tokens[i];
      semicolon.kind = st::TokenKind::Semicolon;
      semicolon.text = ";";
      tokens.insert(tokens.begin() + static_cast<std::ptrdiff_t>(i), semicolon);
      ++i;
    }
  return std::make_unique<st::Parser>(std::move(tokens), locator, budget);
}

void pou_declaration(st::Parser& p, model::Pou& pou) {
  const bool program = p.at_word("PROGRAM");
  const bool function = p.at_word("FUNCTION");
  if (!program && !function && !p.at_word("FUNCTION_BLOCK"))
    p.fail_unexpected("PROGRAM, FUNCTION_BLOCK or FUNCTION");
  p.next();
  pou.kind = program    ? model::PouKind::Program
             : function ? model::PouKind::Function
                        : model::PouKind::FunctionBlock;
  // Access specifiers change nothing the model runs.
  while (p.at_word("PUBLIC") || p.at_word("INTERNAL") || p.at_word("FINAL")) p.next();
  if (p.at_word("ABSTRACT") || p.at_word("PRIVATE") || p.at_word("PROTECTED"))
    p.fail(p.peek(),
           "unsupported: " + model::to_upper(p.peek().text) + " (object-oriented function blocks)");
  const st::Token& name_token = p.peek();
  const std::string declared = p.identifier("the POU's name");
  if (!model::iequals(declared, pou.name))
    p.fail(name_token,
           "the declaration names '" + declared + "', the file's POU is '" + pou.name + "'");
  if (function) {
    p.expect(st::TokenKind::Colon, "':' and the function's result type");
    model::Variable result;
    result.name = pou.name;
    result.direction = model::VarDirection::Output;
    result.where = pou.where;
    result.type = p.var_type();
    pou.variables.push_back(std::move(result));
  }
  if (p.at_word("EXTENDS") || p.at_word("IMPLEMENTS"))
    p.fail(p.peek(),
           "unsupported: " + model::to_upper(p.peek().text) + " (object-oriented function blocks)");
  while (p.at_var_section()) p.var_section(pou.variables);
  if (!p.at(st::TokenKind::End)) p.fail_unexpected("a VAR section or the end of the declaration");
}

void gvl_declaration(st::Parser& p, model::Pou& pou) {
  while (p.at_var_section()) p.var_section(pou.variables);
  if (!p.at(st::TokenKind::End)) p.fail_unexpected("VAR_GLOBAL or the end of the list");
}

void refuse_non_globals(const model::Pou& pou, plcopen::XmlContext& ctx, pugi::xml_node where) {
  for (const auto& v : pou.variables)
    if (v.direction != model::VarDirection::Global)
      ctx.error(where, "global variable list '" + pou.name + "': '" + v.name +
                           "' is not in a VAR_GLOBAL section");
}

void dut_declaration(st::Parser& p, std::vector<model::DataType>& types) {
  if (!p.at_word("TYPE")) p.fail_unexpected("TYPE");
  p.type_declarations(types);
  if (!p.at(st::TokenKind::End)) p.fail_unexpected("the end of the type declaration");
}

LoadResult finish(model::Project project, model::Diagnostics diags) {
  if (project.pous.empty() && !model::has_errors(diags)) {
    model::SourceLocation where = project.where;
    diags.push_back({model::Severity::Error, where, "no POU or global variable list read"});
  }
  // A single file is named after its chart or program (a folder or .plcproj keeps its own).
  if (project.name.empty())
    for (const auto& pou : project.pous)
      if (project.name.empty() && (pou.has_sfc() || !pou.body.empty())) project.name = pou.name;
  if (project.name.empty() && !project.pous.empty()) project.name = project.pous.front().name;
  if (!model::has_errors(diags)) model::lower_data_types(project, diags);
  LoadResult r;
  if (!model::has_errors(diags)) r.project = std::move(project);
  r.diagnostics = std::move(diags);
  return r;
}

}  // namespace sfcv::io::native
