// PLCopen TC6 XML (v1.0 tc6.xsd, v2.0 tc6_0200, v2.01 tc6_0201) -> chart IR.
//
// Element names are matched without their namespace prefix, so the three versions and the
// vendor dialects (Beremiz, CODESYS, TwinCAT) go through the same code. POUs are read from
// types/pous and from the addData sections where CODESYS/TwinCAT keep them.

#include <algorithm>
#include <cctype>
#include <functional>
#include <limits>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "io/plcopen_pou.hpp"
#include "io/plcopen_st.hpp"
#include "io/plcopen_xml_dom.hpp"
#include "io/st_parser.hpp"
#include "model/data_types.hpp"
#include "model/literal.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"
#include "model/types.hpp"
#include "model/validate.hpp"

namespace sfcv::io {

namespace {
using namespace plcopen;

constexpr const char* kNamespaces[] = {
    "http://www.plcopen.org/xml/tc6.xsd",
    "http://www.plcopen.org/xml/tc6_0200",
    "http://www.plcopen.org/xml/tc6_0201",
};

// ------------------------------------------------------------------------------------ variables

struct TypeRead {
  std::optional<model::Type> type;
  std::string written;                            ///< for messages: "REAL", "derived Motor"
  std::vector<model::ArrayDimension> dimensions;  ///< <array>: its bounds, `type` its elements
};

/// Whether the word ENO (any case) occurs in a text or attribute under `node`: a body that
/// never names it cannot clear it.
bool names_eno(pugi::xml_node node) {
  auto has_word = [](std::string_view text) {
    const auto up = model::to_upper(std::string(text));
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (auto at = up.find("ENO"); at != std::string::npos; at = up.find("ENO", at + 1))
      if ((at == 0 || !word(up[at - 1])) && (at + 3 == up.size() || !word(up[at + 3]))) return true;
    return false;
  };
  for (auto a : node.attributes())
    if (has_word(a.value())) return true;
  for (auto c : node.children()) {
    if ((c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) && has_word(c.value()))
      return true;
    if (c.type() == pugi::node_element && names_eno(c)) return true;
  }
  return false;
}

/// `user_types`: the upper-case names of the project's function blocks and data types; a
/// derived type of such a name is read as a placeholder that lowering (data types) or the
/// semantics (function blocks) resolves.
TypeRead read_type(pugi::xml_node t, const std::set<std::string>& user_types) {
  TypeRead r;
  if (!t) {
    r.written = "(none)";
    return r;
  }
  const std::string k(local_name(t));
  if (k == "derived") {
    r.written = t.attribute("name").value();
    r.type = model::elementary_type(r.written);
    if (!r.type && user_types.count(model::to_upper(r.written))) {
      model::Type placeholder;
      placeholder.kind = model::TypeKind::FunctionBlock;
      placeholder.fb = model::StandardFb::None;
      placeholder.name = r.written;
      r.type = placeholder;
    }
    return r;
  }
  const auto base_of = [&](pugi::xml_node n) {
    const auto b = element_children(child(n, "baseType"));
    return read_type(b.empty() ? pugi::xml_node{} : b.front(), user_types);
  };
  if (k == "array") {
    std::vector<model::ArrayDimension> dims;
    for (auto d : children(t, "dimension")) {
      const auto lo = parse_int_literal(d.attribute("lower").value());
      const auto hi = parse_int_literal(d.attribute("upper").value());
      if (!lo || !hi || *lo > *hi) {
        r.written = "array with bounds '" + std::string(d.attribute("lower").value()) + ".." +
                    d.attribute("upper").value() + "'";
        return r;
      }
      dims.push_back({*lo, *hi});
    }
    r = base_of(t);
    if (dims.empty()) r.type.reset();
    dims.insert(dims.end(), r.dimensions.begin(), r.dimensions.end());
    r.dimensions = std::move(dims);
    r.written = "ARRAY OF " + r.written;
    return r;
  }
  if (k == "subrangeSigned" || k == "subrangeUnsigned") {
    const auto range = child(t, "range");
    const auto base = base_of(t);
    const auto lo = parse_int_literal(range.attribute("lower").value());
    const auto hi = parse_int_literal(range.attribute("upper").value());
    r.written = base.written + "(" + range.attribute("lower").value() + ".." +
                range.attribute("upper").value() + ")";
    if (base.type && base.type->kind == model::TypeKind::Int && lo && hi && *lo <= *hi &&
        *lo >= base.type->lo && *hi <= base.type->hi)
      r.type = model::Type::integer(r.written, *lo, *hi);
    return r;
  }
  r.written = k;
  r.type = k == "string" ? model::Type::string() : model::elementary_type(k);
  return r;
}

/// An <initialValue>'s content as the ST parser gives initial values: an expression, an array
/// (Call "[", repetitions expanded) or a structure (formal Call "(").
model::ExprPtr read_initial_value(XmlContext& ctx, pugi::xml_node value, int depth = 0) {
  const std::string k(local_name(value));
  if (depth > model::kMaxNesting) {
    ctx.error(value,
              "initial value nested deeper than " + std::to_string(model::kMaxNesting) + " levels");
    return nullptr;
  }
  if (k == "simpleValue") {
    model::Diagnostics problems;
    auto e =
        parse_st_expression(trim(value.attribute("value").value()), ctx.where(value), problems);
    for (auto& d : problems) ctx.diagnostics().push_back(d);
    return e;
  }
  // The <value> children of an array or structure, empty ones skipped: `take(v, element)`
  // for each; false when one cannot be read or `take` refuses it.
  const auto each_value = [&](const auto& take) {
    for (auto v : children(value, "value")) {
      const auto inner = element_children(v);
      if (inner.empty()) continue;
      auto e = read_initial_value(ctx, inner.front(), depth + 1);
      if (!e || !take(v, std::move(e))) return false;
    }
    return true;
  };
  if (k == "arrayValue") {
    std::vector<model::ExprPtr> elements;
    const bool read = each_value([&](pugi::xml_node v, model::ExprPtr e) {
      const std::string written = trim(v.attribute("repetitionValue").value());
      const auto repeat = parse_int_literal(written);
      if (!written.empty() && !repeat) {
        ctx.error(v, "repetition count: " + repeat.error);
        return false;
      }
      const std::int64_t n = repeat ? *repeat : 1;
      if (n < 0 || n > 100000 - static_cast<std::int64_t>(elements.size())) {
        ctx.error(v, "repetition count out of range (at most 100000 elements)");
        return false;
      }
      for (std::int64_t i = 0; i < n; ++i) elements.push_back(e);
      return true;
    });
    return read ? model::make_call("[", std::move(elements), ctx.where(value)) : nullptr;
  }
  if (k == "structValue") {
    std::vector<std::string> names;
    std::vector<model::ExprPtr> values;
    const bool read = each_value([&](pugi::xml_node v, model::ExprPtr e) {
      names.push_back(trim(v.attribute("member").value()));
      values.push_back(std::move(e));
      return true;
    });
    return read
               ? model::make_formal_call("(", std::move(names), std::move(values), ctx.where(value))
               : nullptr;
  }
  ctx.error(value, "unsupported initial value <" + k + ">");
  return nullptr;
}

std::optional<model::VarDirection> section_direction(std::string_view k) {
  using D = model::VarDirection;
  if (k == "inputVars") return D::Input;
  if (k == "outputVars") return D::Output;
  if (k == "inOutVars") return D::InOut;
  if (k == "localVars" || k == "tempVars") return D::Local;
  if (k == "externalVars") return D::External;
  if (k == "globalVars") return D::Global;
  return std::nullopt;
}

/// The base type of a local variable of a Beremiz HMI type (`HMI_BOOL`, `HMI_INT`: HMI_ and an
/// elementary type the project does not redefine), or nothing.
std::optional<model::Type> hmi_type(const TypeRead& t, const model::Variable& var,
                                    const std::set<std::string>& user_types) {
  if (t.type || var.direction != model::VarDirection::Local || !t.dimensions.empty())
    return std::nullopt;
  const auto up = model::to_upper(t.written);
  if (up.rfind("HMI_", 0) != 0 || user_types.count(up)) return std::nullopt;
  return model::elementary_type(up.substr(4));
}

/// `user_fbs`: the upper-case names of the project's function block POUs and data types; a
/// variable of such a derived type is an instance of that function block (its own copy of the
/// FB's variables and charts, compiled by the semantics) or lowered by its data type.
void read_section(XmlContext& ctx, pugi::xml_node section, model::VarDirection direction,
                  model::Pou& pou, const std::set<std::string>& user_fbs) {
  const std::optional<model::VarDirection> dir = direction;
  {
    for (auto v : children(section, "variable")) {
      model::Variable var;
      var.name = trim(v.attribute("name").value());
      var.direction = *dir;
      var.address = trim(v.attribute("address").value());
      var.constant = section.attribute("constant").as_bool(false);
      var.where = ctx.where(v);
      if (var.name.empty()) {
        ctx.error(v, "variable without a name");
        continue;
      }
      const auto type_el = element_children(child(v, "type"));
      auto t = read_type(type_el.empty() ? pugi::xml_node{} : type_el.front(), user_fbs);
      if (const auto hmi = hmi_type(t, var, user_fbs)) {
        // Beremiz's HMI types (HMI_BOOL, HMI_INT, ...): the operator sets them through the HMI
        // between any two cycles, so a program's own such variable is an input of the plant of
        // the base type, which the program's writes overwrite until the next cycle reads it.
        t.type = hmi;
        var.address = "%I*";
        ctx.note(v, "HMI variable '" + var.name + "' (" + t.written +
                        "): the operator may set it at any cycle, modelled as an input (%I) of "
                        "type " +
                        hmi->name);
      }
      if (!t.type) {
        ctx.warning(v, "unsupported type " + t.written + " of variable '" + var.name +
                           "': variable ignored");
        ctx.unmodelled_variables[model::to_upper(pou.name)][model::to_upper(var.name)] = t.written;
        continue;
      }
      var.type = *t.type;
      var.dimensions = t.dimensions;
      const bool user_type =
          var.type.kind == model::TypeKind::FunctionBlock && var.type.fb == model::StandardFb::None;
      const auto init = child(v, "initialValue");
      if (init && (user_type || !var.dimensions.empty() || var.type.is_string())) {
        // Checked when the types are lowered (model::lower_data_types).
        const auto inner = element_children(init);
        if (!inner.empty()) var.declared_initial = read_initial_value(ctx, inner.front());
      } else if (init) {
        const auto simple = child(init, "simpleValue");
        const std::string text = trim(simple.attribute("value").value());
        if (!simple || var.type.kind == model::TypeKind::FunctionBlock) {
          ctx.error(init, "unsupported: structured initial value of variable '" + var.name + "'");
        } else {
          model::Converted<std::int64_t> value;
          switch (var.type.kind) {
            case model::TypeKind::Bool:
              if (const auto b = parse_bool_literal(text)) value.value = *b ? 1 : 0;
              break;
            case model::TypeKind::Int:
              value = parse_int_literal(text);
              break;
            case model::TypeKind::Time:
              value = parse_time_literal(text);
              break;
            case model::TypeKind::FunctionBlock:
              break;
          }
          const std::string range =
              value
                  ? model::range_error(*value, var.type,
                                       "initial value " + text + " of variable '" + var.name + "'")
                  : "";
          if (!value)
            ctx.error(init, "cannot read the initial value '" + text + "' of variable '" +
                                var.name + "' (" + var.type.name + ")" +
                                (value.error.empty() ? "" : ": " + value.error));
          else if (!range.empty())
            ctx.error(init, range);
          else
            var.initial = value.value;
        }
      }
      pou.variables.push_back(std::move(var));
    }
  }
}

void read_variables(XmlContext& ctx, pugi::xml_node interface, model::Pou& pou,
                    const std::set<std::string>& user_fbs) {
  for (auto section : element_children(interface)) {
    const auto dir = section_direction(local_name(section));
    if (!dir) continue;  // returnType, accessVars, documentation, addData
    read_section(ctx, section, *dir, pou, user_fbs);
  }
}

/// A <dataType>: an enumeration, a structure, or an alias of another type (an array, a
/// subrange, a derived type).
void read_data_type(XmlContext& ctx, pugi::xml_node node, model::Project& project,
                    const std::set<std::string>& user_types) {
  model::DataType t;
  t.name = trim(node.attribute("name").value());
  t.where = ctx.where(node);
  const auto base = element_children(child(node, "baseType"));
  if (t.name.empty() || base.empty()) {
    ctx.error(node, "data type without a name or a base type");
    return;
  }
  const std::string k(local_name(base.front()));
  if (k == "enum") {
    t.kind = model::DataTypeKind::Enumeration;
    std::int64_t value = 0;
    bool past_lint = false;  // the previous enumerator was LINT's largest value
    for (auto v : children(child(base.front(), "values"), "value")) {
      const std::string written = trim(v.attribute("value").value());
      if (!written.empty()) {
        const auto given = parse_int_literal(written);
        if (!given) {
          ctx.error(
              v, "value of enumerator '" + trim(v.attribute("name").value()) + "': " + given.error);
          return;
        }
        value = *given;
      } else if (past_lint) {
        ctx.error(v, "enumerator '" + trim(v.attribute("name").value()) +
                         "' would be past the range of LINT");
        return;
      }
      t.enumerators.emplace_back(trim(v.attribute("name").value()), value);
      past_lint = value == std::numeric_limits<std::int64_t>::max();
      if (!past_lint) ++value;
    }
    if (t.enumerators.empty()) {
      ctx.error(node, "enumeration '" + t.name + "' has no value");
      return;
    }
  } else if (k == "struct") {
    t.kind = model::DataTypeKind::Structure;
    model::Pou fields;
    read_section(ctx, base.front(), model::VarDirection::Local, fields, user_types);
    t.fields = std::move(fields.variables);
    if (t.fields.empty()) {
      ctx.error(node, "structure '" + t.name + "' has no field sfcv models");
      return;
    }
  } else {
    t.kind = model::DataTypeKind::Alias;
    const auto r = read_type(base.front(), user_types);
    if (!r.type) {
      ctx.error(node, "unsupported type " + r.written + " of data type '" + t.name + "'");
      return;
    }
    model::Variable v;
    v.type = *r.type;
    v.dimensions = r.dimensions;
    v.where = t.where;
    if (const auto init = element_children(child(node, "initialValue")); !init.empty())
      v.declared_initial = read_initial_value(ctx, init.front());
    t.fields.push_back(std::move(v));
  }
  project.data_types.push_back(std::move(t));
}

/// Global variable lists: PLCopen `instances/configurations/configuration` and its `resource`s,
/// and the `resource` CODESYS/TwinCAT keep under addData (GVLs: `globalVars name="GVL"`). Each
/// list becomes a POU of its own name holding only VAR_GLOBALs (no body, no chart): the
/// semantics gives each of its variables one field, shared by every POU that names it
/// (unqualified, `GVL.x`, or through VAR_EXTERNAL).
void read_global_lists(XmlContext& ctx, pugi::xml_node container, model::Project& project,
                       const std::set<std::string>& user_fbs) {
  for (auto gv : children(container, "globalVars")) {
    model::Pou pou;
    pou.name = trim(gv.attribute("name").value());
    if (pou.name.empty()) pou.name = trim(container.attribute("name").value());
    if (pou.name.empty()) pou.name = "GLOBALS";
    pou.kind = model::PouKind::Program;
    pou.where = ctx.where(gv);
    read_section(ctx, gv, model::VarDirection::Global, pou, user_fbs);
    project.pous.push_back(std::move(pou));
  }
  for (auto r : children(container, "resource")) read_global_lists(ctx, r, project, user_fbs);
}

// ----------------------------------------------------------------------------------------- POUs

void find_addData_pous(pugi::xml_node node, std::vector<pugi::xml_node>& out) {
  for (auto c : element_children(node)) {
    if (local_name(c) == "pou")
      out.push_back(c);
    else
      find_addData_pous(c, out);
  }
}

std::string problems_message(const model::Diagnostics& problems, const std::string& fallback) {
  for (const auto& d : problems)
    if (d.severity == model::Severity::Error) return d.message;
  return fallback;
}

std::string list_instances(const model::StmtList& calls) {
  std::string s;
  for (const auto& c : calls) s += (s.empty() ? "" : ", ") + c->target;
  return s;
}

void read_pou(XmlContext& ctx, pugi::xml_node node, model::Project& project,
              const std::set<std::string>& user_fbs) {
  model::Pou pou;
  pou.name = trim(node.attribute("name").value());
  pou.where = ctx.where(node);
  const std::string type = node.attribute("pouType").value();
  if (type == "functionBlock")
    pou.kind = model::PouKind::FunctionBlock;
  else if (type == "function")
    pou.kind = model::PouKind::Function;
  else if (type == "program")
    pou.kind = model::PouKind::Program;
  else
    ctx.warning(node, "unknown pouType '" + type + "': read as a program");
  read_variables(ctx, child(node, "interface"), pou, user_fbs);
  // A function's result: the variable named like it (model::PouKind). Without a modelled type
  // the function loads, and a call of it is refused with this reason.
  std::string unmodelled_function;
  if (pou.kind == model::PouKind::Function) {
    const auto type_el = element_children(child(child(node, "interface"), "returnType"));
    const auto t = read_type(type_el.empty() ? pugi::xml_node{} : type_el.front(), {});
    if (t.type && t.type->kind != model::TypeKind::FunctionBlock && t.dimensions.empty()) {
      model::Variable result;
      result.name = pou.name;
      result.direction = model::VarDirection::Output;
      result.type = *t.type;
      result.where = pou.where;
      pou.variables.push_back(std::move(result));
    } else {
      unmodelled_function = "its result type " + t.written + " is not modelled";
    }
  }

  PouContext pc{ctx, node, pou, {}, {}, {}, 0};
  for (auto t : children(child(node, "transitions"), "transition"))
    pc.named_transitions.emplace(model::to_upper(trim(t.attribute("name").value())), t);

  // Declared actions first, so that references and inline names see them; SFC action bodies
  // are read after the POU body so that the body is chart 0.
  std::vector<std::pair<std::size_t, pugi::xml_node>> sfc_actions;
  for (auto a : children(child(node, "actions"), "action")) {
    model::Action act;
    act.name = trim(a.attribute("name").value());
    act.where = ctx.where(a);
    if (act.name.empty()) {
      ctx.error(a, "action without a name");
      continue;
    }
    if (pou.find_action(act.name)) {
      ctx.error(a, "duplicate action '" + act.name + "'");
      continue;
    }
    const auto lang = body_language(child(a, "body"));
    if (!lang) {
      ctx.error(a, "action '" + act.name + "' has no body");
      continue;
    }
    if (local_name(lang) == "SFC") {
      act.kind = model::ActionBodyKind::Chart;
      sfc_actions.emplace_back(pou.actions.size(), lang);
    } else {
      read_action_body(pc, act, lang);
    }
    pou.actions.push_back(std::move(act));
  }

  int sfc_bodies = 0;
  std::vector<pugi::xml_node> other_bodies;
  for (auto body : children(node, "body")) {
    const auto lang = body_language(body);
    if (!lang) continue;
    if (local_name(lang) == "SFC") {
      build_sfc_chart(pc, lang,
                      sfc_bodies == 0 ? pou.name : pou.name + "_" + std::to_string(sfc_bodies + 1),
                      "");
      ++sfc_bodies;
    } else {
      other_bodies.push_back(lang);
    }
  }
  // Every other body (ST, FBD, LD) runs every cycle before the POU's charts; a POU without an
  // SFC body is a program whose body is its whole scan cycle.
  for (std::size_t bi = 0; bi < other_bodies.size(); ++bi) {
    const auto lang = other_bodies[bi];
    const std::string k(local_name(lang));
    model::Diagnostics problems;
    if (!unmodelled_function.empty())
      problems.push_back({model::Severity::Error, ctx.where(lang),
                          "function '" + pou.name + "': " + unmodelled_function});
    auto stmts = problems.empty()
                     ? read_statement_body(
                           pc, lang, bi == 0 ? "BODY" : "BODY" + std::to_string(bi + 1), problems)
                     : std::nullopt;
    if (stmts && !stmts->empty()) {
      // Vendor bodies call instances of user function blocks (whose variables were dropped
      // above) and read global lists: a body that does not validate against the POU's own
      // declarations is not modelled, and the file still loads.
      model::Project alone;
      model::Pou scope;
      scope.name = pou.name;
      scope.kind = pou.kind;
      scope.variables = pou.variables;
      for (const auto& a : pou.actions) {  // their names only: SFC bodies are not read yet
        model::Action named;
        named.name = a.name;
        scope.actions.push_back(std::move(named));
      }
      scope.body = *stmts;
      scope.where = pou.where;
      alone.pous.push_back(std::move(scope));
      for (const auto& g : ctx.global_lists) alone.pous.push_back(g);
      // The file's user functions by name, so that a call of one as a statement
      // (`F(x := a, q => z);`) is not taken for an undeclared instance; the compiler checks
      // the call against the function itself.
      for (const auto& f : ctx.user_functions)
        if (f != model::to_upper(pou.name)) {
          model::Pou declared;
          declared.name = f;
          declared.kind = model::PouKind::Function;
          alone.pous.push_back(std::move(declared));
        }
      // Validated as the project will be: with its data types lowered (the body itself is
      // lowered with the whole project, once every POU is read).
      alone.data_types = project.data_types;
      model::lower_data_types(alone, problems);
      if (!model::has_errors(problems))
        for (auto& d : model::validate(alone))
          if (d.severity == model::Severity::Error) problems.push_back(std::move(d));
      if (model::has_errors(problems)) stmts.reset();
    }
    name_unmodelled_types(pc, problems);
    if (stmts && !pou.body_unsupported) {
      for (auto& st : *stmts) pou.body.push_back(std::move(st));
      for (auto& d : problems) ctx.add(std::move(d));
      continue;
    }
    // The POU still loads (other POUs may be checked), but running it is refused.
    std::string reason = "bodies in " + k + " are not modelled";
    for (const auto& d : problems)
      if (d.severity == model::Severity::Error) {
        reason = d.where.str() + ": " + d.message;
        break;
      }
    if (!pou.body_unsupported) {
      pou.body_unsupported = true;
      pou.unsupported_language = k;
      if (k == "ST" || k == "IL") {
        pou.unsupported_text = body_text(lang, ctx).text;
      } else {
        std::ostringstream xml;
        lang.print(xml, "", pugi::format_raw);
        pou.unsupported_text = xml.str();
      }
      pou.unsupported_reason = reason;
    }
    pou.body.clear();
    ctx.warning(lang, "POU '" + pou.name + "': its " + k + " body is not modelled (" +
                          problems_message(problems, reason) + "); running it is refused");
    for (auto& d : problems) {
      d.severity = model::Severity::Note;
      ctx.add(std::move(d));
    }
  }
  for (const auto& [index, sfc] : sfc_actions) {
    const std::string name = pou.actions[index].name;
    if (pou.find_chart(name)) {
      ctx.error(sfc, "action '" + name + "': a chart of that name already exists");
      continue;
    }
    const int chart = build_sfc_chart(pc, sfc, name, name);
    pou.actions[index].chart = chart;
  }

  if (!pc.condition_calls.empty()) {
    ctx.warning(node, "POU '" + pou.name + "': function blocks of condition networks (" +
                          list_instances(pc.condition_calls) +
                          ") are modelled as calls in the POU body, executed every cycle");
    for (auto& c : pc.condition_calls) pou.body.push_back(std::move(c));
  }

  // An action named after a Boolean variable is that variable (IEC 61131-3 "Boolean action").
  model::add_boolean_variable_actions(pou);

  project.pous.push_back(std::move(pou));
}

// What wrote the file, for `sfcv info`: the fileHeader's companyName, productName and
// productVersion as written (" from CODESYS V3.5 SP14 Patch 1", " from Beckhoff Automation GmbH
// TwinCAT PLC Control 3.5.8.40"); a version that repeats the product name stands for both.
// Beremiz writes its project's own properties there ("Beremiz Unnamed 1"): shown as they are.
std::string written_by(pugi::xml_node header) {
  const std::string company = trim(header.attribute("companyName").value());
  std::string product = trim(header.attribute("productName").value());
  const std::string version = trim(header.attribute("productVersion").value());
  if (!product.empty() && version.rfind(product, 0) == 0) product.clear();
  std::string out;
  for (const std::string& part : {company, product, version})
    if (!part.empty()) out += (out.empty() ? "" : " ") + part;
  return out.empty() ? out : " from " + out;
}

}  // namespace

LoadResult load_plcopen_xml(std::string_view text, const std::string& file,
                            const model::Budget* budget) {
  LoadResult r;
  XmlContext ctx(file, text, r.diagnostics, budget);
  pugi::xml_document doc;
  const auto parsed =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_auto);
  if (!parsed) {
    r.diagnostics.push_back({model::Severity::Error, ctx.where_offset(parsed.offset),
                             std::string("XML parse error: ") + parsed.description()});
    return r;
  }
  const auto root = doc.document_element();
  if (local_name(root) != "project") {
    ctx.error(root, "not a PLCopen TC6 document: the root element is <" + std::string(root.name()) +
                        ">, not <project>");
    return r;
  }
  {
    std::string_view name = root.name();
    const auto colon = name.find(':');
    const std::string xmlns =
        colon == std::string_view::npos ? "xmlns" : "xmlns:" + std::string(name.substr(0, colon));
    const std::string ns = root.attribute(xmlns.c_str()).value();
    bool known = false;
    for (const char* k : kNamespaces) known = known || ns == k;
    if (!known)
      ctx.warning(root, ns.empty() ? std::string("no PLCopen namespace: read as TC6")
                                   : "unknown namespace '" + ns + "': read as PLCopen TC6");
  }

  model::Project project;
  project.source_format = "plcopen-xml" + written_by(child(root, "fileHeader"));
  project.dialect = model::Dialect::Iec61131;
  project.name = trim(child(root, "contentHeader").attribute("name").value());
  project.where = ctx.where(root);

  std::vector<pugi::xml_node> pous = children(child(child(root, "types"), "pous"), "pou");
  find_addData_pous(child(root, "addData"), pous);
  for (auto data : children(child(root, "addData"), "data"))
    if (std::string_view(data.attribute("name").value()) == plcopen::kDialectData)
      project.vendor = trim(child(data, "dialect").attribute("vendor").value());
  if (const auto loose = child(root, "pous"))
    // ESBMC's LD benchmarks (`.ld`) put <pous> straight under <project>; TC6 has them in
    // <types>. Read, they would be skipped and the file found empty.
    ctx.error(loose,
              "unsupported: <pous> directly under <project> (the layout of ESBMC's LD "
              "benchmarks; PLCopen TC6 puts POUs in <types><pous>): not read");
  std::set<std::string> user_fbs;
  for (auto p : pous) {
    const std::string_view kind = p.attribute("pouType").value();
    const auto upper = model::to_upper(trim(p.attribute("name").value()));
    if (kind == "functionBlock") {
      user_fbs.insert(upper);
      ctx.user_function_blocks.insert(upper);
    }
    if (kind == "function") ctx.user_functions.insert(upper);
    if ((kind == "functionBlock" || kind == "function") && names_eno(p))
      ctx.pous_naming_eno.insert(upper);
  }
  ctx.pure_functions = pure_functions(ctx, pous);
  for (auto dt : children(child(child(root, "types"), "dataTypes"), "dataType"))
    user_fbs.insert(model::to_upper(trim(dt.attribute("name").value())));
  for (auto dt : children(child(child(root, "types"), "dataTypes"), "dataType"))
    read_data_type(ctx, dt, project, user_fbs);
  // Global lists first, so that POU bodies are validated with them; they join the project
  // after the POUs, as before.
  model::Project lists;
  for (auto conf : children(child(child(root, "instances"), "configurations"), "configuration"))
    read_global_lists(ctx, conf, lists, user_fbs);
  for (auto data : children(child(root, "addData"), "data"))
    read_global_lists(ctx, data, lists, user_fbs);
  ctx.global_lists = lists.pous;
  std::set<std::string> seen;
  for (auto p : pous) {
    ctx.poll();
    const std::string name = trim(p.attribute("name").value());
    if (name.empty()) {
      ctx.error(p, "POU without a name");
      continue;
    }
    if (!seen.insert(model::to_upper(name)).second) {
      ctx.error(p, "duplicate POU '" + name + "'");
      continue;
    }
    read_pou(ctx, p, project, user_fbs);
  }
  // Task order: the programs a configuration's tasks name (`pouInstance typeName="Main"`, or
  // TwinCAT's `pouInstance name="MAIN"` in addData) run first, in that order; the semantics
  // runs the programs in the order of project.pous.
  std::vector<std::string> task_order;
  std::function<void(pugi::xml_node)> find_tasks = [&](pugi::xml_node n) {
    for (auto c : element_children(n)) {
      if (local_name(c) == "pouInstance") {
        std::string type = trim(c.attribute("typeName").value());
        if (type.empty()) type = trim(c.attribute("name").value());
        if (!type.empty()) task_order.push_back(model::to_upper(type));
      } else if (local_name(c) != "pou") {
        find_tasks(c);
      }
    }
  };
  find_tasks(child(root, "instances"));
  find_tasks(child(root, "addData"));
  if (!task_order.empty()) {
    auto rank = [&](const model::Pou& q) {
      const auto it = std::find(task_order.begin(), task_order.end(), model::to_upper(q.name));
      return q.kind == model::PouKind::Program && it != task_order.end()
                 ? it - task_order.begin()
                 : static_cast<std::ptrdiff_t>(task_order.size());
    };
    std::stable_sort(project.pous.begin(), project.pous.end(),
                     [&](const model::Pou& a, const model::Pou& b) { return rank(a) < rank(b); });
  }
  for (auto& list : lists.pous) {
    if (project.find_pou(list.name)) {
      r.diagnostics.push_back(
          {model::Severity::Error, list.where,
           "global variable list '" + list.name + "' has the name of another POU"});
      continue;
    }
    project.pous.push_back(std::move(list));
  }
  if (!model::has_errors(r.diagnostics)) model::lower_data_types(project, r.diagnostics);
  r.project = std::move(project);
  return r;
}

}  // namespace sfcv::io
