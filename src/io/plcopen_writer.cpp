#include "io/plcopen_writer.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <map>
#include <numeric>
#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/plcopen_xml_dom.hpp"
#include "io/st_names.hpp"
#include "model/errors.hpp"
#include "model/names.hpp"
#include "model/types.hpp"

namespace sfcv::io {

namespace {

using model::ExprKind;

constexpr const char* kNamespace = "http://www.plcopen.org/xml/tc6_0201";
constexpr const char* kXhtml = "http://www.w3.org/1999/xhtml";

[[noreturn]] void cannot_write(const std::string& what) {
  throw UnsupportedConstruct("cannot write as PLCopen XML: " + what);
}

void check_writable(const model::StmtList& body, const std::string& where) {
  if (auto why = st_text_obstacle(body, where); !why.empty()) cannot_write(why);
}

// Every graphical element needs a position (the schema requires one); sfcv lays nothing out.
void position(pugi::xml_node n, const char* name = "position") {
  auto p = n.append_child(name);
  p.append_attribute("x") = 0;
  p.append_attribute("y") = 0;
}

void connect(pugi::xml_node n, const std::vector<unsigned>& from) {
  auto cpi = n.append_child("connectionPointIn");
  for (unsigned id : from) cpi.append_child("connection").append_attribute("refLocalId") = id;
}

// A textual body (ST, IL) as formattedText: one xhtml paragraph holding CDATA.
void text_language(pugi::xml_node parent, const char* language, const std::string& text) {
  parent.append_child(language)
      .append_child("xhtml:p")
      .append_child(pugi::node_cdata)
      .set_value(text.c_str());
}

void type_element(pugi::xml_node type, const model::Type& t) {
  switch (t.kind) {
    case model::TypeKind::Bool:
      type.append_child("BOOL");
      return;
    case model::TypeKind::Time:
      type.append_child("TIME");
      return;
    case model::TypeKind::FunctionBlock:
      // A user function block keeps the name it was declared with.
      type.append_child("derived").append_attribute("name") =
          t.fb == model::StandardFb::None ? t.name.c_str()
                                          : std::string(model::to_string(t.fb)).c_str();
      return;
    case model::TypeKind::Int:
      break;
  }
  std::string base = model::to_upper(t.name.substr(0, t.name.find('(')));
  auto elementary = model::elementary_type(base);
  if (elementary && elementary->kind == model::TypeKind::Int && elementary->lo == t.lo &&
      elementary->hi == t.hi) {
    type.append_child(base.c_str());
    return;
  }
  if (!elementary || elementary->kind != model::TypeKind::Int || t.lo < elementary->lo ||
      t.hi > elementary->hi) {
    base = "LINT";
    elementary = model::elementary_type(base);
  }
  const bool is_unsigned = elementary && elementary->lo >= 0;
  auto sub = type.append_child(is_unsigned ? "subrangeUnsigned" : "subrangeSigned");
  auto range = sub.append_child("range");
  range.append_attribute("lower") = std::to_string(t.lo).c_str();
  range.append_attribute("upper") = std::to_string(t.hi).c_str();
  sub.append_child("baseType").append_child(base.c_str());
}

const char* section_name(model::VarDirection d) {
  switch (d) {
    case model::VarDirection::Input:
      return "inputVars";
    case model::VarDirection::Output:
      return "outputVars";
    case model::VarDirection::InOut:
      return "inOutVars";
    case model::VarDirection::Global:
      return "globalVars";
    case model::VarDirection::External:
      return "externalVars";
    case model::VarDirection::Local:
      break;
  }
  return "localVars";
}

const char* pou_type(model::PouKind k) {
  switch (k) {
    case model::PouKind::FunctionBlock:
      return "functionBlock";
    case model::PouKind::Function:
      return "function";
    case model::PouKind::Program:
      break;
  }
  return "program";
}

class PouWriter {
 public:
  explicit PouWriter(const model::Pou& pou)
      : pou_(pou),
        printed_(pou.associations.size(), false),
        chart_written_(pou.charts.size(), false) {}

  void write(pugi::xml_node pous) {
    if (!pou_.stored_actions.empty())
      cannot_write("Grafcet stored actions (POU '" + pou_.name + "')");
    if (!pou_.forcing_orders.empty())
      cannot_write("Grafcet forcing orders (POU '" + pou_.name + "')");
    auto node = pous.append_child("pou");
    node.append_attribute("name") = pou_.name.c_str();
    node.append_attribute("pouType") = pou_type(pou_.kind);
    variables(node.append_child("interface"));

    // Charts: action bodies go inside their action, macro-step expansions inside their
    // macro-step, the rest are SFC bodies of the POU.
    std::set<std::size_t> expansions;
    for (const auto& c : pou_.charts)
      for (const auto& s : c.steps)
        if (s.kind == model::StepKind::MacroStep) {
          const int i = pou_.chart_index(s.expansion);
          if (i < 0)
            cannot_write("macro-step '" + s.name + "' without its expansion '" + s.expansion + "'");
          // The importer names an expansion after its macro-step.
          if (!model::iequals(s.expansion, s.name))
            cannot_write("macro-step '" + s.name + "' expanded by a chart of another name ('" +
                         s.expansion + "')");
          expansions.insert(static_cast<std::size_t>(i));
        }
    std::vector<std::size_t> bodies;
    for (std::size_t i = 0; i < pou_.charts.size(); ++i) {
      const auto& c = pou_.charts[i];
      if (!c.macro_entry.empty() || !c.macro_exit.empty())
        cannot_write("Grafcet macro-step expansion '" + c.name + "' with entry/exit steps");
      if (c.parent_action.empty() && !expansions.count(i)) bodies.push_back(i);
    }
    // With several top-level charts, charts are told apart by name; the importer names SFC
    // bodies P, P_2, P_3 ...
    if (bodies.size() + expansions.size() > 1)
      for (std::size_t k = 0; k < bodies.size(); ++k) {
        const std::string expected = k == 0 ? pou_.name : pou_.name + "_" + std::to_string(k + 1);
        if (!model::iequals(pou_.charts[bodies[k]].name, expected))
          cannot_write("SFC body '" + pou_.charts[bodies[k]].name + "' of POU '" + pou_.name +
                       "' would be read back as '" + expected + "'");
      }

    if (!pou_.actions.empty()) {
      auto actions = node.append_child("actions");
      for (const auto& a : pou_.actions) action(actions, a);
    }
    for (std::size_t i : bodies) chart(node.append_child("body").append_child("SFC"), i);
    if (pou_.body_unsupported) {
      // Given back as read: the text of an ST/IL body, the element of a graphical one.
      auto b = node.append_child("body");
      if (pou_.unsupported_language == "ST" || pou_.unsupported_language == "IL") {
        std::string text = pou_.unsupported_text;
        while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
        text_language(b, pou_.unsupported_language.c_str(), text);
      } else {
        pugi::xml_document fragment;
        if (!fragment.load_string(pou_.unsupported_text.c_str()) || !fragment.document_element())
          cannot_write("the " + pou_.unsupported_language + " body of POU '" + pou_.name +
                       "', which sfcv does not model");
        b.append_copy(fragment.document_element());
      }
    } else if (!pou_.body.empty()) {
      check_writable(pou_.body, "the body of '" + pou_.name + "'");
      text_language(node.append_child("body"), "ST", model::to_st(pou_.body));
    }
    for (std::size_t i = 0; i < pou_.charts.size(); ++i)
      if (!chart_written_[i])
        cannot_write("chart '" + pou_.charts[i].name + "' is the body of no action (parent '" +
                     pou_.charts[i].parent_action + "')");
    for (std::size_t i = 0; i < printed_.size(); ++i)
      if (!printed_[i]) {
        const auto& a = pou_.associations[i];
        cannot_write("association of action '" + a.action + "' to step '" + a.step +
                     "' of chart '" + a.chart + "', which does not exist");
      }
  }

  /// A global variable list (only VAR_GLOBALs, nothing to run): a `configuration` holding them,
  /// which the importer reads back as a list of this name that every POU sees.
  void write_global_list(pugi::xml_node configurations) {
    auto configuration = configurations.append_child("configuration");
    configuration.append_attribute("name") = pou_.name.c_str();
    variables(configuration);
    for (auto list : configuration.children("globalVars"))
      list.prepend_attribute("name") = pou_.name.c_str();
  }

  static bool is_global_list(const model::Pou& pou) {
    return pou.kind == model::PouKind::Program && pou.charts.empty() && pou.body.empty() &&
           pou.actions.empty() && !pou.body_unsupported &&
           std::all_of(pou.variables.begin(), pou.variables.end(), [](const model::Variable& v) {
             return v.direction == model::VarDirection::Global;
           });
  }

 private:
  void variables(pugi::xml_node interface) {
    // A function's result (the variable named like it) is its returnType.
    auto result = [&](const model::Variable& v) {
      return pou_.kind == model::PouKind::Function && model::iequals(v.name, pou_.name);
    };
    std::vector<const model::Variable*> vars;
    for (const auto& v : pou_.variables) {
      if (result(v))
        type_element(interface.append_child("returnType"), v.type);
      else
        vars.push_back(&v);
    }
    std::size_t i = 0;
    while (i < vars.size()) {
      const auto dir = vars[i]->direction;
      const bool constant = vars[i]->constant;
      auto section = interface.append_child(section_name(dir));
      if (constant) section.append_attribute("constant") = true;
      for (; i < vars.size() && vars[i]->direction == dir && vars[i]->constant == constant; ++i) {
        const auto& v = *vars[i];
        auto var = section.append_child("variable");
        var.append_attribute("name") = v.name.c_str();
        if (!v.address.empty()) var.append_attribute("address") = v.address.c_str();
        type_element(var.append_child("type"), v.type);
        if (!v.initial) continue;
        std::string text;
        switch (v.type.kind) {
          case model::TypeKind::Bool:
            text = *v.initial ? "TRUE" : "FALSE";
            break;
          case model::TypeKind::Time:
            text = model::to_st(model::make_time(*v.initial));
            break;
          case model::TypeKind::Int:
            text = std::to_string(*v.initial);
            break;
          case model::TypeKind::FunctionBlock:
            cannot_write("initial value of FB instance '" + v.name + "'");
        }
        var.append_child("initialValue").append_child("simpleValue").append_attribute("value") =
            text.c_str();
      }
    }
  }

  void action(pugi::xml_node actions, const model::Action& a) {
    switch (a.kind) {
      case model::ActionBodyKind::Variable: {
        // Re-created on loading from an association naming the Boolean variable.
        const auto* v = pou_.find_variable(a.variable);
        const bool named =
            std::any_of(pou_.associations.begin(), pou_.associations.end(),
                        [&](const auto& x) { return model::iequals(x.action, a.name); });
        if (!model::iequals(a.name, a.variable) || !v || v->type.kind != model::TypeKind::Bool ||
            !named)
          cannot_write("action '" + a.name + "' standing for variable '" + a.variable + "'");
        return;
      }
      case model::ActionBodyKind::Statements: {
        auto body = actions.append_child("action");
        body.append_attribute("name") = a.name.c_str();
        auto b = body.append_child("body");
        if (a.body_unsupported) {
          if (a.unsupported_language != "ST" && a.unsupported_language != "IL")
            cannot_write("action '" + a.name + "', whose graphical body sfcv does not model");
          // The importer ends a paragraph with a line break: drop it, or every round trip adds one.
          std::string text = a.unsupported_text;
          while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
          text_language(b, a.unsupported_language.c_str(), text);
          return;
        }
        check_writable(a.body, "action '" + a.name + "'");
        text_language(b, "ST", model::to_st(a.body));
        return;
      }
      case model::ActionBodyKind::Chart: {
        if (a.chart < 0 || static_cast<std::size_t>(a.chart) >= pou_.charts.size())
          cannot_write("action '" + a.name + "' without its chart");
        const auto index = static_cast<std::size_t>(a.chart);
        if (!model::iequals(pou_.charts[index].parent_action, a.name))
          cannot_write("chart '" + pou_.charts[index].name + "' of action '" + a.name +
                       "' names another parent ('" + pou_.charts[index].parent_action + "')");
        auto body = actions.append_child("action");
        body.append_attribute("name") = a.name.c_str();
        chart(body.append_child("body").append_child("SFC"), index);
        return;
      }
    }
  }

  // The SFC graph. A step with several outgoing transitions feeds them through a selection
  // divergence; a transition with several sources starts at a simultaneous convergence, one
  // with several targets ends in a simultaneous divergence; a step with several incoming
  // wires gathers them in a selection convergence. A transition back to a step at or before
  // its first source ends in a jump. Transitions are written in document order.
  void chart(pugi::xml_node sfc, std::size_t index) {
    if (chart_written_[index]) cannot_write("chart '" + pou_.charts[index].name + "' used twice");
    chart_written_[index] = true;
    const model::Chart& c = pou_.charts[index];
    const std::size_t n = c.steps.size();
    std::map<std::string, std::size_t> by_name;
    for (std::size_t i = 0; i < n; ++i) by_name.emplace(model::to_upper(c.steps[i].name), i);
    auto step_of = [&](const std::string& name, const model::Transition& t) {
      const auto it = by_name.find(model::to_upper(name));
      if (it == by_name.end())
        cannot_write("transition " + (t.name.empty() ? std::string() : "'" + t.name + "' ") +
                     "of chart '" + c.name + "' names step '" + name +
                     "', which the chart does not declare");
      return it->second;
    };

    std::vector<std::size_t> order(c.transitions.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return c.transitions[x].order < c.transitions[y].order;
    });
    struct Plan {
      std::vector<std::size_t> sources, targets;
      unsigned id = 0, convergence = 0, divergence = 0;
    };
    std::vector<Plan> plans(c.transitions.size());
    std::vector<unsigned> step_id(n);
    for (auto& id : step_id) id = next_id_++;
    std::vector<int> consumers(n, 0);
    for (std::size_t k : order) {
      const auto& t = c.transitions[k];
      if (t.sources.empty() || t.targets.empty())
        cannot_write("transition without source or target steps in chart '" + c.name + "'");
      if (t.priority && *t.priority < 0) cannot_write("negative transition priority");
      if (!t.guard) cannot_write("transition without a condition in chart '" + c.name + "'");
      if (auto why = st_text_obstacle(t.guard, "a transition condition"); !why.empty())
        cannot_write(why);
      auto& p = plans[k];
      for (const auto& s : t.sources) {
        const auto i = step_of(s, t);
        if (std::find(p.sources.begin(), p.sources.end(), i) == p.sources.end())
          p.sources.push_back(i);
      }
      for (const auto& s : t.targets) {
        const auto i = step_of(s, t);
        if (std::find(p.targets.begin(), p.targets.end(), i) == p.targets.end())
          p.targets.push_back(i);
      }
      for (auto i : p.sources) ++consumers[i];
    }
    std::vector<unsigned> out_port(step_id);
    std::vector<std::size_t> diverging;
    for (std::size_t i = 0; i < n; ++i)
      if (consumers[i] > 1) {
        out_port[i] = next_id_++;
        diverging.push_back(i);
      }
    std::vector<std::vector<unsigned>> incoming(n);
    struct Jump {
      unsigned id, from;
      std::size_t step;
    };
    std::vector<Jump> jumps;
    for (std::size_t k : order) {
      auto& p = plans[k];
      if (p.sources.size() > 1) p.convergence = next_id_++;
      p.id = next_id_++;
      if (p.targets.size() > 1) p.divergence = next_id_++;
      const unsigned producer = p.divergence ? p.divergence : p.id;
      for (auto x : p.targets) {
        if (x <= p.sources.front())
          jumps.push_back({next_id_++, producer, x});
        else
          incoming[x].push_back(producer);
      }
    }
    std::vector<unsigned> in_port(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (incoming[i].size() == 1)
        in_port[i] = incoming[i][0];
      else if (incoming[i].size() > 1)
        in_port[i] = next_id_++;
    }

    // Steps (with their action blocks planned), in the chart's order.
    std::vector<std::pair<std::size_t, std::vector<std::size_t>>> blocks;
    for (std::size_t i = 0; i < n; ++i) {
      const auto& s = c.steps[i];
      if (s.kind == model::StepKind::Enclosing)
        cannot_write("Grafcet enclosing step '" + s.name + "'");
      auto e = sfc.append_child(s.kind == model::StepKind::MacroStep ? "macroStep" : "step");
      e.append_attribute("localId") = step_id[i];
      e.append_attribute("name") = s.name.c_str();
      if (s.initial) e.append_attribute("initialStep") = "true";
      position(e);
      if (in_port[i]) connect(e, {in_port[i]});
      e.append_child("connectionPointOut");
      // Associations name a step, not one of several steps of that name: the first takes them.
      std::vector<std::size_t> mine, step_actions;
      if (by_name.at(model::to_upper(s.name)) == i)
        for (std::size_t k = 0; k < pou_.associations.size(); ++k) {
          const auto& a = pou_.associations[k];
          if (!model::iequals(a.chart, c.name) || !model::iequals(a.step, s.name)) continue;
          (a.step_action ? step_actions : mine).push_back(k);
          printed_[k] = true;
        }
      if (s.kind == model::StepKind::MacroStep) {
        chart(e.append_child("body").append_child("SFC"),
              static_cast<std::size_t>(pou_.chart_index(s.expansion)));
      } else if (!mine.empty()) {
        e.append_child("connectionPointOutAction").append_attribute("formalParameter") = "";
      }
      if (!mine.empty()) blocks.emplace_back(i, std::move(mine));
      if (!step_actions.empty()) codesys_step_actions(e, s.name, step_actions);
    }
    for (std::size_t i : diverging) {
      auto e = sfc.append_child("selectionDivergence");
      e.append_attribute("localId") = out_port[i];
      position(e);
      connect(e, {step_id[i]});
      for (int k = 0; k < consumers[i]; ++k)
        e.append_child("connectionPointOut").append_attribute("formalParameter") = "";
    }
    for (std::size_t k : order) {
      const auto& t = c.transitions[k];
      const auto& p = plans[k];
      if (p.convergence) {
        auto e = sfc.append_child("simultaneousConvergence");
        e.append_attribute("localId") = p.convergence;
        position(e);
        // One input per branch, as for the selection convergence.
        for (auto i : p.sources) connect(e, {out_port[i]});
        e.append_child("connectionPointOut");
      }
      auto e = sfc.append_child("transition");
      e.append_attribute("localId") = p.id;
      if (t.priority) e.append_attribute("priority") = *t.priority;
      position(e);
      connect(e, {p.convergence ? p.convergence : out_port[p.sources.front()]});
      e.append_child("connectionPointOut");
      auto inl = e.append_child("condition").append_child("inline");
      inl.append_attribute("name") = t.name.c_str();
      text_language(inl, "ST", model::to_st(t.guard));
      if (p.divergence) {
        auto d = sfc.append_child("simultaneousDivergence");
        d.append_attribute("localId") = p.divergence;
        position(d);
        connect(d, {p.id});
        for (std::size_t x = 0; x < p.targets.size(); ++x)
          d.append_child("connectionPointOut").append_attribute("formalParameter") = "";
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (incoming[i].size() < 2) continue;
      auto e = sfc.append_child("selectionConvergence");
      e.append_attribute("localId") = in_port[i];
      position(e);
      for (unsigned from : incoming[i]) connect(e, {from});
      e.append_child("connectionPointOut");
    }
    for (const auto& j : jumps) {
      auto e = sfc.append_child("jumpStep");
      e.append_attribute("localId") = j.id;
      e.append_attribute("targetName") = c.steps[j.step].name.c_str();
      position(e);
      connect(e, {j.from});
    }
    for (const auto& [step, associations] : blocks) {
      auto e = sfc.append_child("actionBlock");
      e.append_attribute("localId") = next_id_++;
      position(e);
      connect(e, {step_id[step]});
      for (std::size_t k : associations) association(e, pou_.associations[k]);
    }
  }

  // CODESYS's entry, main and exit actions (read as P1, N, P0) in the step's addData, where
  // CODESYS writes them: an action block would make them IEC actions, which the vendor
  // dialects run otherwise (docs/semantics.md 1.4a).
  void codesys_step_actions(pugi::xml_node step, const std::string& name,
                            const std::vector<std::size_t>& associations) {
    auto attributes = step.append_child("addData").append_child("data");
    attributes.append_attribute("name") = "http://www.3s-software.com/plcopenxml/sfc/element";
    attributes.append_attribute("handleUnknown") = "implementation";
    attributes = attributes.append_child("attributes");
    std::set<model::Qualifier> roles;
    for (std::size_t k : associations) {
      const auto& a = pou_.associations[k];
      const char* guid = a.qualifier == model::Qualifier::P1   ? plcopen::kCodesysEntryGuid
                         : a.qualifier == model::Qualifier::N  ? plcopen::kCodesysActiveGuid
                         : a.qualifier == model::Qualifier::P0 ? plcopen::kCodesysExitGuid
                                                               : nullptr;
      if (!guid || !roles.insert(a.qualifier).second)
        cannot_write("step action '" + a.action + "' of step '" + name + "' (qualifier " +
                     std::string(model::to_string(a.qualifier)) +
                     "): a step has one entry (P1), one main (N) and one exit (P0) action");
      auto attr = attributes.append_child("attribute");
      attr.append_attribute("guid") = guid;
      attr.text() = a.action.c_str();
    }
  }

  void association(pugi::xml_node block, const model::ActionAssociation& a) {
    if (a.condition) cannot_write("assignment condition of action '" + a.action + "'");
    auto e = block.append_child("action");
    e.append_attribute("localId") = next_id_++;
    e.append_attribute("qualifier") = std::string(model::to_string(a.qualifier)).c_str();
    if (a.duration_ms)
      e.append_attribute("duration") = model::to_st(model::make_time(*a.duration_ms)).c_str();
    else if (!a.duration_variable.empty())
      e.append_attribute("duration") = a.duration_variable.c_str();
    else if (model::is_timed(a.qualifier))
      cannot_write("timed qualifier " + std::string(model::to_string(a.qualifier)) +
                   " of action '" + a.action + "' without a duration");
    if (!a.indicator.empty()) e.append_attribute("indicator") = a.indicator.c_str();
    position(e, "relPosition");
    e.append_child("reference").append_attribute("name") = a.action.c_str();
  }

  const model::Pou& pou_;
  std::vector<bool> printed_;
  std::vector<bool> chart_written_;
  unsigned next_id_ = 1;
};

std::string now_utc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return buf;
}

}  // namespace

std::string write_plcopen_xml(const model::Project& project) {
  if (project.dialect == model::Dialect::Grafcet)
    cannot_write("a Grafcet (IEC 60848) project; print it in the native Grafcet format");
  if (project.data_types_lowered)
    cannot_write(
        "a project with user data types (ARRAY, STRUCT, enumerations): sfcv models them "
        "element by element and does not print them back as declared");
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "utf-8";
  auto root = doc.append_child("project");
  root.append_attribute("xmlns") = kNamespace;
  root.append_attribute("xmlns:xhtml") = kXhtml;
  auto file = root.append_child("fileHeader");
  file.append_attribute("companyName") = "sfcv";
  file.append_attribute("productName") = "sfcv";
  file.append_attribute("productVersion") = "1";
  file.append_attribute("creationDateTime") = now_utc().c_str();
  auto content = root.append_child("contentHeader");
  content.append_attribute("name") = project.name.empty() ? "sfcv" : project.name.c_str();
  auto coordinates = content.append_child("coordinateInfo");
  for (const char* language : {"fbd", "ld", "sfc"}) {
    auto scaling = coordinates.append_child(language).append_child("scaling");
    scaling.append_attribute("x") = 1;
    scaling.append_attribute("y") = 1;
  }
  auto types = root.append_child("types");
  types.append_child("dataTypes");
  auto pous = types.append_child("pous");
  auto configurations = root.append_child("instances").append_child("configurations");
  for (const auto& pou : project.pous) {
    if (PouWriter::is_global_list(pou) && !pou.variables.empty())
      PouWriter(pou).write_global_list(configurations);
    else
      PouWriter(pou).write(pous);
  }
  // The vendor whose dialect the model is in (a CODESYS project's final calls): sfcv wrote the
  // file, so its fileHeader no longer says (docs/formats.md).
  if (const auto vendor = model::vendor_of(project); !vendor.empty()) {
    auto data = root.append_child("addData").append_child("data");
    data.append_attribute("name") = plcopen::kDialectData;
    data.append_attribute("handleUnknown") = "discard";
    data.append_child("dialect").append_attribute("vendor") = vendor.c_str();
  }
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

}  // namespace sfcv::io
