// TwinCAT 3 native project files: `.TcPOU` (a POU with its actions and transitions), `.TcGVL`
// (a global variable list), `.TcDUT` (a data type), and a `.plcproj` or a folder of them.
//
// Declarations and ST bodies are ST text in CDATA, read with the ST parser at their place in
// the file. An SFC body is not PLCopen: `<Implementation><SFC><XmlArchive>` is a serialised
// object tree (SFCImplementationObject -> Root SFCSegment -> ElementList of SFCStep,
// SFCTransition, SFCJump and SFCBranch in document order; a branch holds legs, each an
// SFCSegment). Element attributes are records keyed by GUIDs which the archive describes in
// its own table (`d2 n="Attributes" cvt="SFCAttributeDescription"`: GUID -> Identifier); they
// are read through that table, so a GUID is never hard-coded here. What the model cannot say
// (time monitoring, embedded actions, IEC action associations inside a step, LD/FBD network
// archives as conditions, object-oriented POUs) is refused with the file and element path.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <memory>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "io/plcopen_pou.hpp"
#include "io/plcopen_st.hpp"
#include "io/plcopen_xml_dom.hpp"
#include "io/st_lexer.hpp"
#include "io/st_parser.hpp"
#include "model/data_types.hpp"
#include "model/input_file.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"

namespace sfcv::io {

namespace {

using plcopen::BodyText;
using plcopen::child;
using plcopen::children;
using plcopen::element_children;
using plcopen::local_name;
using plcopen::trim;
using plcopen::XmlContext;

// The archive writes GUIDs with braces in records and without them as dictionary keys.
std::string guid_key(std::string_view s) {
  std::string r;
  for (char c : s)
    if (c != '{' && c != '}' && c != ' ' && c != '\n' && c != '\r' && c != '\t')
      r += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

// Archive string values are quoted: `"N000"`.
std::string unquote(std::string_view s) {
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"')
    return std::string(s.substr(1, s.size() - 2));
  return std::string(s);
}

// A child `<tag n="name">` of an archive object.
pugi::xml_node member(pugi::xml_node obj, std::string_view tag, std::string_view name) {
  for (auto c = obj.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element && std::string_view(c.name()) == tag &&
        std::string_view(c.attribute("n").value()) == name)
      return c;
  return {};
}

// `<o n="ElementList"><l2 n="InnerList"><o .../>...` : the elements of a list, in order.
std::vector<pugi::xml_node> inner_list(pugi::xml_node obj) {
  return element_children(member(member(obj, "o", "ElementList"), "l2", "InnerList"));
}

// The type of an archive object: its `t`, or the element type of the list holding it.
std::string object_type(pugi::xml_node obj) {
  if (const auto t = obj.attribute("t")) return t.value();
  return obj.parent().attribute("cet").value();
}

// The archive's own description of the element attributes: GUID -> Identifier.
class AttributeTable {
 public:
  void read(pugi::xml_node implementation) {
    for (auto d : children(implementation, "d2")) {
      if (std::string_view(d.attribute("n").value()) != "Attributes") continue;
      std::string key;
      for (auto c : element_children(d)) {
        if (std::string_view(c.name()) == "v") {
          key = guid_key(c.text().get());
        } else if (!key.empty()) {
          names_[key] = unquote(trim(member(c, "v", "Identifier").text().get()));
          key.clear();
        }
      }
    }
  }
  bool empty() const { return names_.empty(); }
  const std::string* identifier(const std::string& guid) const {
    const auto it = names_.find(guid);
    return it == names_.end() ? nullptr : &it->second;
  }

 private:
  std::map<std::string, std::string> names_;
};

// The attributes of one SFC element, by identifier: the value text and its node.
struct ElementAttributes {
  std::map<std::string, std::pair<std::string, pugi::xml_node>> values;
  const std::string& text(const std::string& id) const {
    static const std::string none;
    const auto it = values.find(id);
    return it == values.end() ? none : it->second.first;
  }
  pugi::xml_node node(const std::string& id) const {
    const auto it = values.find(id);
    return it == values.end() ? pugi::xml_node{} : it->second.second;
  }
  bool flag(const std::string& id) const { return model::iequals(trim(text(id)), "TRUE"); }
};

// The state a sequence leaves for the element after it.
struct Flow {
  enum class Kind { Start, Steps, Transitions, Closed } kind = Kind::Start;
  std::vector<std::vector<std::string>> step_sets;  ///< Steps: alternative source sets
  std::vector<std::size_t> transitions;             ///< Transitions: waiting for targets
};

class SfcArchiveReader {
 public:
  SfcArchiveReader(plcopen::PouContext& pc, const std::map<std::string, pugi::xml_node>& named,
                   model::Chart& chart)
      : pc_(pc), ctx_(pc.ctx), named_transitions_(named), chart_(chart) {}

  void read(pugi::xml_node sfc) {
    const auto data = child(child(sfc, "XmlArchive"), "Data");
    pugi::xml_node impl;
    for (auto o : children(data, "o"))
      if (object_type(o) == "SFCImplementationObject") impl = o;
    if (!impl) {
      ctx_.error(sfc, "SFC body without an SFCImplementationObject in its XmlArchive");
      return;
    }
    table_.read(impl);
    if (table_.empty()) {
      ctx_.error(impl, "SFC archive without its attribute table (SFCAttributeDescription)");
      return;
    }
    const auto root = member(impl, "o", "Root");
    if (!root) {
      ctx_.error(impl, "SFC archive without a Root segment");
      return;
    }
    Flow start;
    const Flow end = sequence(root, start);
    if (failed_) return;
    if (first_step_.empty()) {
      ctx_.error(root, "SFC chart without a step");
      return;
    }
    if (end.kind == Flow::Kind::Transitions) {
      // The chart is closed: a main sequence ending with a transition goes back to its top.
      for (auto t : end.transitions) chart_.transitions[t].targets.push_back(first_step_);
    } else if (end.kind == Flow::Kind::Steps) {
      ctx_.error(root, "the chart's main sequence ends with a step, not a transition or jump");
    }
  }

 private:
  std::string id_of(pugi::xml_node obj) const {
    std::string id = trim(member(obj, "v", "Id").text().get());
    if (!id.empty() && (id.back() == 'L' || id.back() == 'l')) id.pop_back();
    return id;
  }
  std::string describe(pugi::xml_node obj) const {
    return object_type(obj) + " (archive object " + id_of(obj) + ")";
  }
  void fail(pugi::xml_node n, const std::string& message) {
    ctx_.error(n, message);
    failed_ = true;
  }

  ElementAttributes attributes(pugi::xml_node obj) {
    ElementAttributes r;
    for (auto rec : element_children(member(obj, "l2", "Attributes"))) {
      const std::string guid = guid_key(member(rec, "v", "AttributeId").text().get());
      const std::string* id = table_.identifier(guid);
      if (!id) {
        fail(rec,
             describe(obj) + ": attribute {" + guid + "} is not in the archive's attribute table");
        continue;
      }
      const auto value = member(member(rec, "o", "Value"), "v", "Value");
      r.values[*id] = {unquote(value.text().get()), value};
    }
    return r;
  }

  // Embedded action/transition objects are a CODESYS option whose archive is not read.
  void refuse_embedded(pugi::xml_node obj, std::initializer_list<const char*> names) {
    for (const char* n : names)
      if (member(obj, "o", n))
        fail(member(obj, "o", n), "unsupported: " + std::string(n) + " of " + describe(obj) +
                                      " (embedded implementations are not read)");
  }

  Flow sequence(pugi::xml_node segment, Flow in) {
    Flow f = std::move(in);
    for (auto e : inner_list(segment)) {
      ctx_.poll();
      if (failed_) return f;
      const std::string type = object_type(e);
      if (f.kind == Flow::Kind::Closed) {
        fail(e, describe(e) + " follows a jump: it can never be reached");
        return f;
      }
      if (type == "SFCStep") {
        f = step(e, f);
      } else if (type == "SFCTransition") {
        f = transition(e, f);
      } else if (type == "SFCJump") {
        f = jump(e, f);
      } else if (type == "SFCBranch") {
        f = branch(e, f);
      } else {
        fail(e, "unsupported: SFC element " + describe(e));
      }
    }
    return f;
  }

  Flow step(pugi::xml_node e, const Flow& in) {
    const auto a = attributes(e);
    refuse_embedded(e, {"EmbeddedMainAction", "EmbeddedEntryAction", "EmbeddedExitAction"});
    model::Step s;
    s.name = trim(a.text("Name"));
    s.initial = a.flag("InitStep");
    s.where = ctx_.where(e);
    if (s.name.empty()) fail(e, describe(e) + " without a name");
    if (a.flag("Exclude")) fail(e, "unsupported: step '" + s.name + "' is excluded from build");
    for (const char* t : {"MinTime", "MaxTime"})
      if (!trim(a.text(t)).empty())
        fail(a.node(t),
             "unsupported: " + std::string(t) + " on step '" + s.name + "' (step time monitoring)");
    if (!inner_list(e).empty())
      fail(e, "unsupported: action associations inside step '" + s.name + "' (" + describe(e) +
                  "); only the step's entry, main and exit actions are read");
    if (in.kind == Flow::Kind::Steps) {
      fail(e, "step '" + s.name + "' follows a step without a transition between them");
      return in;
    }
    for (auto t : in.transitions) chart_.transitions[t].targets.push_back(s.name);
    if (first_step_.empty()) first_step_ = s.name;
    // CODESYS/TwinCAT step actions: entry once on activation (P1), main while active (N), exit
    // once on deactivation (P0) -- the reading docs/plcopen-xml.md gives the same actions when
    // they come in a PLCopen export's addData.
    for (auto rec : element_children(member(e, "l2", "Attributes"))) {
      const std::string* id =
          table_.identifier(guid_key(member(rec, "v", "AttributeId").text().get()));
      if (!id) continue;
      model::Qualifier q;
      if (*id == "EntryAction")
        q = model::Qualifier::P1;
      else if (*id == "MainAction")
        q = model::Qualifier::N;
      else if (*id == "ExitAction")
        q = model::Qualifier::P0;
      else
        continue;
      const std::string action = trim(a.text(*id));
      if (action.empty()) continue;
      model::ActionAssociation as;
      as.chart = chart_.name;
      as.step = s.name;
      as.action = action;
      as.qualifier = q;
      as.where = ctx_.where(a.node(*id));
      pc_.pou.associations.push_back(std::move(as));
    }
    chart_.steps.push_back(std::move(s));
    Flow out;
    out.kind = Flow::Kind::Steps;
    out.step_sets.push_back({chart_.steps.back().name});
    return out;
  }

  Flow transition(pugi::xml_node e, const Flow& in) {
    const auto a = attributes(e);
    refuse_embedded(e, {"EmbeddedTransition"});
    if (in.kind != Flow::Kind::Steps) {
      fail(e, describe(e) + " does not follow a step");
      return in;
    }
    if (a.flag("Exclude")) fail(e, "unsupported: " + describe(e) + " is excluded from build");
    model::Transition t;
    t.where = ctx_.where(e);
    t.guard = condition(e, a, t.name);
    if (!t.guard) failed_ = true;
    Flow out;
    out.kind = Flow::Kind::Transitions;
    for (std::size_t i = 0; i < in.step_sets.size(); ++i) {
      model::Transition copy = t;
      copy.sources = in.step_sets[i];
      copy.order = static_cast<int>(chart_.transitions.size());
      if (in.step_sets.size() > 1 && !t.name.empty())
        copy.name = t.name + "_" + std::to_string(i + 1);
      out.transitions.push_back(chart_.transitions.size());
      chart_.transitions.push_back(std::move(copy));
    }
    return out;
  }

  // The Name attribute of a transition is its condition: an ST expression, or the name of a
  // `<Transition Name=...>` object of the POU whose ST body gives it.
  model::ExprPtr condition(pugi::xml_node e, const ElementAttributes& a, std::string& name) {
    const std::string text = trim(a.text("Name"));
    const auto node = a.node("Name");
    if (text.empty()) {
      ctx_.error(node ? node : e, describe(e) + " without a condition");
      return nullptr;
    }
    if (const auto it = named_transitions_.find(model::to_upper(text));
        it != named_transitions_.end()) {
      name = text;
      return named_condition(it->second, text);
    }
    BodyText body;
    body.text = text;
    body.start = ctx_.where(node);
    body.start.line = 0;  // the value's own line/column are not those of the condition text
    body.start.column = 0;
    return plcopen::parse_expression_text(body, ctx_.diagnostics());
  }

  model::ExprPtr named_condition(pugi::xml_node decl, const std::string& name) {
    const auto key = model::to_upper(name);
    if (const auto it = guards_.find(key); it != guards_.end()) return it->second;
    const auto st = child(child(decl, "Implementation"), "ST");
    model::ExprPtr guard;
    if (!st) {
      const auto impl = element_children(child(decl, "Implementation"));
      ctx_.error(decl,
                 "unsupported: transition '" + name + "' written in " +
                     (impl.empty() ? std::string("nothing") : std::string(local_name(impl[0]))) +
                     " (ST conditions are read)");
    } else {
      auto body = plcopen::body_text(st, ctx_);
      std::string s = trim(body.text);
      // `expr`, `NAME := expr;` or `:= expr;`
      if (s.rfind(":=", 0) == 0) {
        s = s.substr(2);
      } else if (const auto pos = s.find(":=");
                 pos != std::string::npos && model::iequals(trim(s.substr(0, pos)), name)) {
        s = s.substr(pos + 2);
      }
      s = trim(s);
      while (!s.empty() &&
             (s.back() == ';' || s.back() == ' ' || s.back() == '\n' || s.back() == '\r'))
        s.pop_back();
      body.text = s;
      if (s.empty())
        ctx_.error(st, "transition '" + name + "' has an empty condition");
      else
        guard = plcopen::parse_expression_text(body, ctx_.diagnostics());
    }
    guards_[key] = guard;
    return guard;
  }

  Flow jump(pugi::xml_node e, const Flow& in) {
    const auto a = attributes(e);
    const std::string target = trim(a.text("Name"));
    if (target.empty()) fail(e, describe(e) + " without a target step");
    if (in.kind != Flow::Kind::Transitions) {
      fail(e, "jump to '" + target + "' does not follow a transition");
      return in;
    }
    for (auto t : in.transitions) chart_.transitions[t].targets.push_back(target);
    Flow out;
    out.kind = Flow::Kind::Closed;
    return out;
  }

  Flow branch(pugi::xml_node e, const Flow& in) {
    // Legs are read recursively: bound the nesting so that a hostile file is an error, not a
    // stack overflow.
    if (depth_ >= model::kMaxNesting) {
      fail(e, describe(e) + ": branches nested deeper than " + std::to_string(model::kMaxNesting));
      return in;
    }
    ++depth_;
    Flow out = branch_legs(e, in);
    --depth_;
    return out;
  }

  Flow branch_legs(pugi::xml_node e, const Flow& in) {
    const auto a = attributes(e);
    const bool parallel = a.flag("Parallel");
    const auto legs = inner_list(e);
    if (legs.size() < 2) {
      fail(e, describe(e) + " with fewer than two legs");
      return in;
    }
    Flow out;
    if (parallel) {
      // Simultaneous divergence after a transition: every leg starts from it; the legs'
      // last steps join into one source set of the next transition.
      if (in.kind != Flow::Kind::Transitions) {
        fail(e, "parallel " + describe(e) + " does not follow a transition");
        return in;
      }
      out.kind = Flow::Kind::Steps;
      out.step_sets.push_back({});
      for (auto leg : legs) {
        const Flow f = sequence(leg, in);
        if (failed_) return out;
        if (f.kind != Flow::Kind::Steps) {
          fail(leg, "unsupported: a leg of parallel " + describe(e) +
                        " does not end with a step (a jump or transition out of a parallel leg)");
          return out;
        }
        std::vector<std::vector<std::string>> joined;
        for (const auto& x : out.step_sets)
          for (const auto& y : f.step_sets) {
            auto z = x;
            z.insert(z.end(), y.begin(), y.end());
            joined.push_back(std::move(z));
          }
        out.step_sets = std::move(joined);
      }
      return out;
    }
    // Alternative divergence after a step: every leg starts from the same steps; the legs'
    // ends meet at the next element (a leg ending with a jump leaves nothing to meet).
    if (in.kind != Flow::Kind::Steps) {
      fail(e, "alternative " + describe(e) + " does not follow a step");
      return in;
    }
    out.kind = Flow::Kind::Closed;
    for (auto leg : legs) {
      const Flow f = sequence(leg, in);
      if (failed_) return out;
      if (f.kind == Flow::Kind::Closed) continue;
      if (out.kind != Flow::Kind::Closed && out.kind != f.kind) {
        fail(leg, "the legs of alternative " + describe(e) +
                      " end differently (one with a step, another with a transition)");
        return out;
      }
      out.kind = f.kind;
      out.step_sets.insert(out.step_sets.end(), f.step_sets.begin(), f.step_sets.end());
      out.transitions.insert(out.transitions.end(), f.transitions.begin(), f.transitions.end());
    }
    return out;
  }

  plcopen::PouContext& pc_;
  XmlContext& ctx_;
  const std::map<std::string, pugi::xml_node>& named_transitions_;
  model::Chart& chart_;
  AttributeTable table_;
  std::map<std::string, model::ExprPtr> guards_;
  std::string first_step_;
  int depth_ = 0;
  bool failed_ = false;
};

// One file's XML, read into a shared project.
class NativeFileReader {
 public:
  NativeFileReader(XmlContext& ctx, model::Project& project, const model::Budget* budget)
      : ctx_(ctx), project_(project), budget_(budget) {}

  void read(pugi::xml_node root) {
    for (auto n : element_children(root)) {
      ctx_.poll();
      const auto k = local_name(n);
      if (k == "POU")
        read_pou(n);
      else if (k == "GVL")
        read_gvl(n);
      else if (k == "DUT")
        read_dut(n);
      else
        ctx_.error(n, "unsupported: TwinCAT object <" + std::string(k) + ">");
    }
  }

 private:
  // The declaration's CDATA through the ST parser, located at its line in the file.
  std::unique_ptr<st::Parser> declaration_parser(pugi::xml_node object) {
    const auto decl = child(object, "Declaration");
    if (!decl) {
      ctx_.error(object, "no <Declaration>");
      return nullptr;
    }
    const auto text = plcopen::body_text(decl, ctx_);
    model::SourceLocation start = text.start;
    start.element_path.clear();  // file:line:col inside the CDATA says more
    st::Locator locator(start);
    model::Diagnostics lexical;
    auto tokens = st::tokenize(text.text, locator, lexical, budget_);
    const bool broken = model::has_errors(lexical);
    for (auto& d : lexical) ctx_.add(std::move(d));
    if (broken) return nullptr;
    // TwinCAT writes `END_STRUCT` (or an enumeration's `)`) right before END_TYPE without the
    // `;` IEC 61131-3 puts there: supply it.
    for (std::size_t i = 1; i < tokens.size(); ++i)
      if (tokens[i].kind == st::TokenKind::Identifier &&
          model::iequals(tokens[i].text, "END_TYPE") &&
          tokens[i - 1].kind != st::TokenKind::Semicolon) {
        st::Token semicolon = tokens[i];
        semicolon.kind = st::TokenKind::Semicolon;
        semicolon.text = ";";
        tokens.insert(tokens.begin() + static_cast<std::ptrdiff_t>(i), semicolon);
        ++i;
      }
    return std::make_unique<st::Parser>(std::move(tokens), locator, budget_);
  }

  template <typename F>
  void parse(F&& f) {
    try {
      f();
    } catch (const st::ParseError& e) {
      ctx_.add({model::Severity::Error, e.where, e.what()});
    }
  }

  void read_gvl(pugi::xml_node n) {
    model::Pou pou;
    pou.name = trim(n.attribute("Name").value());
    pou.kind = model::PouKind::Program;
    pou.where = ctx_.where(n);
    auto p = declaration_parser(n);
    if (!p) return;
    parse([&] {
      while (p->at_var_section()) p->var_section(pou.variables);
      if (!p->at(st::TokenKind::End)) p->fail_unexpected("VAR_GLOBAL or the end of the list");
    });
    for (auto& v : pou.variables)
      if (v.direction != model::VarDirection::Global)
        ctx_.error(n, "global variable list '" + pou.name + "': '" + v.name +
                          "' is not in a VAR_GLOBAL section");
    add_pou(n, std::move(pou));
  }

  void read_dut(pugi::xml_node n) {
    auto p = declaration_parser(n);
    if (!p) return;
    parse([&] {
      if (!p->at_word("TYPE")) p->fail_unexpected("TYPE");
      p->type_declarations(project_.data_types);
      if (!p->at(st::TokenKind::End)) p->fail_unexpected("the end of the type declaration");
    });
  }

  void add_pou(pugi::xml_node n, model::Pou pou) {
    if (pou.name.empty()) {
      ctx_.error(n, "object without a Name");
      return;
    }
    if (project_.find_pou(pou.name)) {
      ctx_.error(n, "duplicate POU or global list '" + pou.name + "'");
      return;
    }
    project_.pous.push_back(std::move(pou));
  }

  void read_pou(pugi::xml_node n) {
    model::Pou pou;
    pou.name = trim(n.attribute("Name").value());
    pou.where = ctx_.where(n);
    auto p = declaration_parser(n);
    if (!p) return;
    bool ok = true;
    parse([&] {
      ok = false;
      declaration(*p, pou);
      ok = true;
    });
    if (!ok) return;
    plcopen::PouContext pc{ctx_, n, pou, {}, {}, {}, 0};
    std::map<std::string, pugi::xml_node> named;
    for (auto c : element_children(n)) {
      const auto k = local_name(c);
      if (k == "Transition") {
        named[model::to_upper(trim(c.attribute("Name").value()))] = c;
      } else if (k == "Method" || k == "Property" || k == "Interface") {
        ctx_.error(c, "unsupported: " + model::to_upper(k) + " '" + c.attribute("Name").value() +
                          "' of POU '" + pou.name + "' (object-oriented function blocks)");
      } else if (k != "Declaration" && k != "Implementation" && k != "Action" && k != "LineIds" &&
                 k != "ObjectProperties" && k != "Folder") {
        ctx_.error(c, "unsupported: <" + std::string(k) + "> in POU '" + pou.name + "'");
      }
    }
    // Actions first: a chart's associations are resolved against them.
    std::vector<std::pair<std::size_t, pugi::xml_node>> sfc_actions;
    for (auto a : children(n, "Action")) {
      model::Action act;
      act.name = trim(a.attribute("Name").value());
      act.where = ctx_.where(a);
      if (act.name.empty() || pou.find_action(act.name)) {
        ctx_.error(
            a, act.name.empty() ? "action without a Name" : "duplicate action '" + act.name + "'");
        continue;
      }
      const auto impl = element_children(child(a, "Implementation"));
      if (impl.empty()) {
        ctx_.error(a, "action '" + act.name + "' has no implementation");
        continue;
      }
      if (local_name(impl[0]) == "SFC") {
        act.kind = model::ActionBodyKind::Chart;
        sfc_actions.emplace_back(pou.actions.size(), impl[0]);
      } else {
        // ST is read; <NWL> (LD/FBD) and others load as not modelled, refused when run.
        plcopen::read_action_body(pc, act, impl[0]);
      }
      pou.actions.push_back(std::move(act));
    }
    const auto impl = element_children(child(n, "Implementation"));
    if (impl.empty()) {
      ctx_.error(n, "POU '" + pou.name + "' has no implementation");
      return;
    }
    const auto body = impl[0];
    if (local_name(body) == "SFC") {
      chart(pc, named, body, pou.name, "");
    } else {
      read_body(pc, body);
    }
    for (const auto& [index, sfc] : sfc_actions) {
      const std::string name = pou.actions[index].name;
      pou.actions[index].chart = chart(pc, named, sfc, name, name);
    }
    // An action named after a Boolean variable is that variable (IEC 61131-3 Boolean action).
    for (const auto& as : pou.associations) {
      if (pou.find_action(as.action)) continue;
      const auto* var = pou.find_variable(as.action);
      if (!var || var->type.kind != model::TypeKind::Bool) continue;
      model::Action act;
      act.name = var->name;
      act.kind = model::ActionBodyKind::Variable;
      act.variable = var->name;
      act.where = var->where;
      pou.actions.push_back(std::move(act));
    }
    add_pou(n, std::move(pou));
  }

  int chart(plcopen::PouContext& pc, const std::map<std::string, pugi::xml_node>& named,
            pugi::xml_node sfc, const std::string& name, const std::string& parent) {
    model::Chart c;
    c.name = name;
    c.parent_action = parent;
    c.where = ctx_.where(sfc);
    SfcArchiveReader(pc, named, c).read(sfc);
    pc.pou.charts.push_back(std::move(c));
    return static_cast<int>(pc.pou.charts.size()) - 1;
  }

  // The POU's own body: ST is read; another language loads as not modelled (refused when run).
  void read_body(plcopen::PouContext& pc, pugi::xml_node body) {
    model::Diagnostics problems;
    const std::string k(local_name(body));
    auto stmts = plcopen::read_statement_body(pc, body, "BODY", problems);
    if (stmts) {
      pc.pou.body = std::move(*stmts);
      for (auto& d : problems) ctx_.add(std::move(d));
      return;
    }
    std::string reason = k == "NWL" ? "LD/FBD network archives (<NWL>) are not read"
                                    : "bodies in " + k + " are not modelled";
    if (k != "NWL")
      for (const auto& d : problems)
        if (d.severity == model::Severity::Error) {
          reason = d.where.str() + ": " + d.message;
          break;
        }
    pc.pou.body_unsupported = true;
    pc.pou.unsupported_language = k == "NWL" ? "LD" : k;
    if (k == "ST") pc.pou.unsupported_text = plcopen::body_text(body, ctx_).text;
    pc.pou.unsupported_reason = reason;
    ctx_.warning(body, "POU '" + pc.pou.name + "': its body is not modelled (" + reason +
                           "); running it is refused");
    for (auto& d : problems) {
      d.severity = model::Severity::Note;
      ctx_.add(std::move(d));
    }
  }

  // `PROGRAM P` / `FUNCTION_BLOCK [INTERNAL|PUBLIC|FINAL] FB` / `FUNCTION F : T`, then VAR
  // sections.
  void declaration(st::Parser& p, model::Pou& pou) {
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
      p.fail(p.peek(), "unsupported: " + model::to_upper(p.peek().text) +
                           " (object-oriented function blocks)");
    const Token& name_token = p.peek();
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
      p.fail(p.peek(), "unsupported: " + model::to_upper(p.peek().text) +
                           " (object-oriented function blocks)");
    while (p.at_var_section()) p.var_section(pou.variables);
    if (!p.at(st::TokenKind::End)) p.fail_unexpected("a VAR section or the end of the declaration");
  }

  using Token = st::Token;

  XmlContext& ctx_;
  model::Project& project_;
  const model::Budget* budget_;
};

void new_project(model::Project& project, const std::string& file) {
  project.source_format = "twincat";
  project.dialect = model::Dialect::Iec61131;
  project.where.file = file;
}

// Reads one native file's text into `project`; false when the XML itself is broken.
void read_native_text(std::string_view text, const std::string& file, model::Project& project,
                      model::Diagnostics& diags, const model::Budget* budget) {
  XmlContext ctx(file, text, diags, budget);
  pugi::xml_document doc;
  const auto parsed =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_auto);
  if (!parsed) {
    diags.push_back({model::Severity::Error, ctx.where_offset(parsed.offset),
                     std::string("XML parse error: ") + parsed.description()});
    return;
  }
  const auto root = doc.document_element();
  if (local_name(root) != "TcPlcObject") {
    ctx.error(root, "not a TwinCAT 3 object file: the root element is <" +
                        std::string(root.name()) + ">, not <TcPlcObject>");
    return;
  }
  // `sfcv info` shows the version that wrote the files (the first that says).
  if (const std::string v = trim(root.attribute("ProductVersion").value());
      !v.empty() && project.source_format == "twincat")
    project.source_format += " " + v;
  NativeFileReader(ctx, project, budget).read(root);
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

// A folder given by mistake (a home directory) should not be read file by file for minutes.
constexpr std::size_t kMaxProjectFiles = 20000;

bool has_suffix(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() &&
         model::iequals(std::string_view(s).substr(s.size() - suffix.size()), suffix);
}

bool is_object_file(const std::string& s) {
  return has_suffix(s, ".tcpou") || has_suffix(s, ".tcgvl") || has_suffix(s, ".tcdut");
}

// The object files a .plcproj compiles (`<Compile Include="POUs\MAIN.TcPOU">`), relative to it.
std::vector<std::string> plcproj_files(const std::string& path, std::string_view text,
                                       model::Diagnostics& diags, const model::Budget* budget) {
  std::vector<std::string> files;
  XmlContext ctx(path, text, diags, budget);
  pugi::xml_document doc;
  const auto parsed =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_auto);
  if (!parsed) {
    diags.push_back({model::Severity::Error, ctx.where_offset(parsed.offset),
                     std::string("XML parse error: ") + parsed.description()});
    return files;
  }
  const auto dir = std::filesystem::path(path).parent_path();
  for (auto group : children(doc.document_element(), "ItemGroup"))
    for (auto c : children(group, "Compile")) {
      std::string inc = c.attribute("Include").value();
      std::replace(inc.begin(), inc.end(), '\\', '/');
      if (is_object_file(inc)) files.push_back((dir / inc).string());
      // Task objects (.TcTTO) and others describe no program: skipped.
    }
  return files;
}

}  // namespace

LoadResult load_twincat(std::string_view text, const std::string& file,
                        const model::Budget* budget) {
  model::Project project;
  new_project(project, file);
  model::Diagnostics diags;
  read_native_text(text, file, project, diags, budget);
  return finish(std::move(project), std::move(diags));
}

LoadResult load_twincat_project(const std::string& path, const model::Budget* budget) {
  model::Project project;
  new_project(project, path);
  model::Diagnostics diags;
  std::vector<std::string> files;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    for (auto it = std::filesystem::recursive_directory_iterator(path, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
      if (it->is_regular_file() && is_object_file(it->path().string())) {
        if (files.size() == kMaxProjectFiles) {
          diags.push_back({model::Severity::Error, project.where,
                           "more than " + std::to_string(kMaxProjectFiles) +
                               " TwinCAT object files under the folder"});
          return LoadResult{std::nullopt, std::move(diags)};
        }
        files.push_back(it->path().string());
      }
    std::sort(files.begin(), files.end());  // directory order is not stable across systems
    project.name = std::filesystem::path(path).filename().string();
  } else {
    std::string text;
    if (auto reason = model::try_read_input_file(path, "the project", text)) {
      diags.push_back({model::Severity::Error, project.where, *reason});
      return LoadResult{std::nullopt, std::move(diags)};
    }
    files = plcproj_files(path, text, diags, budget);
    project.name = std::filesystem::path(path).stem().string();
  }
  if (files.empty() && !model::has_errors(diags))
    diags.push_back({model::Severity::Error, project.where,
                     "no .TcPOU, .TcGVL or .TcDUT file in the TwinCAT project"});
  for (const auto& f : files) {
    std::string text;
    if (auto reason = model::try_read_input_file(f, "a TwinCAT object", text)) {
      model::SourceLocation where;
      where.file = f;
      diags.push_back({model::Severity::Error, where, *reason});
      continue;
    }
    read_native_text(text, f, project, diags, budget);
  }
  return finish(std::move(project), std::move(diags));
}

}  // namespace sfcv::io
