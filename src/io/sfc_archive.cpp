// The SFC object archive CODESYS writes, in TwinCAT's compact and CODESYS's verbose XML
// spellings (sfc_archive.hpp). The walk reads the sequence as the editor draws it
// (docs/formats.md, "The SFC archive").

#include "io/sfc_archive.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <vector>

#include "io/plcopen_st.hpp"
#include "io/plcopen_xml_dom.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"

namespace sfcv::io::sfc_archive {

namespace {

using plcopen::BodyText;
using plcopen::child;
using plcopen::element_children;
using plcopen::trim;
using plcopen::XmlContext;

// Compact archive string values are quoted: `"N000"`.
std::string unquote(std::string_view s) {
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"')
    return std::string(s.substr(1, s.size() - 2));
  return std::string(s);
}

// The class GUIDs of the SFC objects, as a TwinCAT archive's own `<TypeList>` names them (a
// CODESYS export writes the GUID alone). SFCActionAssociation is this reader's name for the
// class of the IEC action associations a step holds (no TypeList names it).
const std::map<std::string, std::string>& sfc_classes() {
  static const std::map<std::string, std::string> m = {
      {"74f81948-1328-492c-b6c1-a9ea72048b28", "SFCImplementationObject"},
      {"f1db7f6f-4774-46a6-ad9b-a94414f875fc", "SFCSegment"},
      {"587d6556-cfe6-4e76-9cc9-fc0daf0c8c29", "SFCElementList"},
      {"86ee92a2-d863-4136-be27-82b36d84211c", "SFCStep"},
      {"4ecb29e8-a90a-4646-84ac-2ff54215ab29", "SFCTransition"},
      {"7e39ac27-154f-419a-a255-6a6cf37d5ed0", "SFCJump"},
      {"e221b778-bb8f-44ba-8a6a-f796287d4e62", "SFCBranch"},
      {"a94bb75d-5fb3-40ad-9d01-41d5b980784d", "SFCActionAssociation"},
      {"21f3f16e-04fa-4637-b6b7-d84e4192e99f", "SFCAttribute"},
  };
  return m;
}

}  // namespace

// The archive writes GUIDs with braces in records and without them as dictionary keys.
std::string guid_key(std::string_view s) {
  std::string r;
  for (char c : s)
    if (c != '{' && c != '}' && c != ' ' && c != '\n' && c != '\r' && c != '\t')
      r += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

// ------------------------------------------------------------------------------------ Format

pugi::xml_node Format::member(pugi::xml_node obj, std::string_view compact_tag,
                              std::string_view name) const {
  const bool compact = encoding_ == Encoding::Compact;
  const char* key = compact ? "n" : "Name";
  for (auto c = obj.first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_element || std::string_view(c.attribute(key).value()) != name)
      continue;
    const std::string_view tag = c.name();
    if (compact                                      ? tag == compact_tag
        : (compact_tag == "o" || compact_tag == "v") ? tag == "Single"
        : compact_tag == "l2" ? (tag == "List2" || tag == "List" || tag == "Array")
                              : (tag == "Dictionary2" || tag == "Dictionary"))
      return c;
  }
  return {};
}

pugi::xml_node Format::object(pugi::xml_node obj, std::string_view name) const {
  return member(obj, "o", name);
}
pugi::xml_node Format::value_node(pugi::xml_node obj, std::string_view name) const {
  return member(obj, "v", name);
}
std::string Format::text(pugi::xml_node value) const {
  const std::string t = value.text().get();
  return encoding_ == Encoding::Compact ? unquote(t) : t;
}
std::string Format::value(pugi::xml_node obj, std::string_view name) const {
  return text(value_node(obj, name));
}
pugi::xml_node Format::list(pugi::xml_node obj, std::string_view name) const {
  return member(obj, "l2", name);
}
pugi::xml_node Format::dictionary(pugi::xml_node obj, std::string_view name) const {
  return member(obj, "d2", name);
}

std::vector<std::pair<pugi::xml_node, pugi::xml_node>> Format::entries(pugi::xml_node dict) const {
  std::vector<std::pair<pugi::xml_node, pugi::xml_node>> r;
  if (encoding_ == Encoding::Verbose) {
    for (auto e : plcopen::children(dict, "Entry"))
      r.emplace_back(child(child(e, "Key"), "Single"), child(child(e, "Value"), "Single"));
    return r;
  }
  pugi::xml_node key;
  for (auto c : element_children(dict)) {
    if (std::string_view(c.name()) == "v") {
      key = c;
    } else if (key) {
      r.emplace_back(key, c);
      key = {};
    }
  }
  return r;
}

std::vector<pugi::xml_node> Format::inner_list(pugi::xml_node obj) const {
  return element_children(list(object(obj, "ElementList"), "InnerList"));
}

std::string Format::type(pugi::xml_node obj) const {
  if (encoding_ == Encoding::Compact) {
    if (const auto t = obj.attribute("t")) return t.value();
    return obj.parent().attribute("cet").value();
  }
  const std::string guid = guid_key(obj.attribute("Type").value());
  const auto it = sfc_classes().find(guid);
  return it == sfc_classes().end() ? "{" + guid + "}" : it->second;
}

std::string Format::id(pugi::xml_node obj) const {
  std::string id = trim(value(obj, "Id"));
  if (!id.empty() && (id.back() == 'L' || id.back() == 'l')) id.pop_back();
  return id;
}

namespace {

// The archive's own description of the element attributes: GUID -> Identifier.
class AttributeTable {
 public:
  void read(const Format& f, pugi::xml_node implementation) {
    for (const auto& [key, value] : f.entries(f.dictionary(implementation, "Attributes")))
      names_[guid_key(key.text().get())] = trim(f.value(value, "Identifier"));
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
  SfcArchiveReader(plcopen::PouContext& pc, const Format& format, const Options& options,
                   model::Chart& chart)
      : pc_(pc), ctx_(pc.ctx), f_(format), options_(options), chart_(chart) {}

  void read(pugi::xml_node impl) {
    table_.read(f_, impl);
    if (table_.empty()) {
      ctx_.error(impl, "SFC archive without its attribute table (SFCAttributeDescription)");
      return;
    }
    const auto root = f_.object(impl, "Root");
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
  std::string describe(pugi::xml_node obj) const {
    return f_.type(obj) + " (archive object " + f_.id(obj) + ")";
  }
  void fail(pugi::xml_node n, const std::string& message) {
    ctx_.error(n, message);
    failed_ = true;
  }

  ElementAttributes attributes(pugi::xml_node obj) {
    ElementAttributes r;
    for (auto rec : element_children(f_.list(obj, "Attributes"))) {
      const std::string guid = guid_key(f_.value(rec, "AttributeId"));
      const std::string* id = table_.identifier(guid);
      if (!id) {
        fail(rec,
             describe(obj) + ": attribute {" + guid + "} is not in the archive's attribute table");
        continue;
      }
      const auto value = f_.value_node(f_.object(rec, "Value"), "Value");
      r.values[*id] = {f_.text(value), value};
    }
    return r;
  }

  // Embedded action/transition objects are a CODESYS option whose archive is not read.
  void refuse_embedded(pugi::xml_node obj, std::initializer_list<const char*> names) {
    for (const char* n : names)
      if (f_.object(obj, n))
        fail(f_.object(obj, n), "unsupported: " + std::string(n) + " of " + describe(obj) +
                                    " (embedded implementations are not read)");
  }

  Flow sequence(pugi::xml_node segment, Flow in) {
    Flow f = std::move(in);
    for (auto e : f_.inner_list(segment)) {
      ctx_.poll();
      if (failed_) return f;
      const std::string type = f_.type(e);
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
    if (!options_.step_associations && !f_.inner_list(e).empty())
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
    for (auto rec : element_children(f_.list(e, "Attributes"))) {
      const std::string* id = table_.identifier(guid_key(f_.value(rec, "AttributeId")));
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
      as.step_action = true;
      as.where = ctx_.where(a.node(*id));
      pc_.pou.associations.push_back(std::move(as));
    }
    if (options_.step_associations) read_associations(e, s.name);
    chart_.steps.push_back(std::move(s));
    Flow out;
    out.kind = Flow::Kind::Steps;
    out.step_sets.push_back({chart_.steps.back().name});
    return out;
  }

  // The IEC action associations a step holds (CODESYS): an action or Boolean variable and its
  // qualifier. P is read, its vendor meaning coming from the final call (--dialect codesys,
  // docs/semantics.md 1.4a); the timed qualifiers are refused, their duration not being read
  // from the archive.
  void read_associations(pugi::xml_node step, const std::string& step_name) {
    for (auto x : f_.inner_list(step)) {
      const std::string where = " in step '" + step_name + "'";
      if (f_.type(x) != "SFCActionAssociation") {
        fail(x, "unsupported: " + describe(x) + where);
        continue;
      }
      const auto a = attributes(x);
      const std::string action = trim(a.text("Name"));
      const std::string text = trim(a.text("Qualifier"));
      const auto at = a.node("Qualifier") ? a.node("Qualifier") : x;
      if (action.empty()) {
        fail(x, describe(x) + where + " names no action");
        continue;
      }
      if (a.flag("Exclude")) {
        fail(x, "unsupported: the association of action '" + action + "'" + where +
                    " is excluded from build");
        continue;
      }
      const auto q = model::parse_qualifier(text);
      if (!q) {
        fail(at, "action '" + action + "'" + where + " has an unknown qualifier '" + text + "'");
        continue;
      }
      if (model::is_timed(*q)) {
        fail(at, "unsupported: qualifier " + text + " of action '" + action + "'" + where +
                     " (its duration is not read from the archive)");
        continue;
      }
      model::ActionAssociation as;
      as.chart = chart_.name;
      as.step = step_name;
      as.action = action;
      as.qualifier = *q;
      as.where = ctx_.where(x);
      pc_.pou.associations.push_back(std::move(as));
    }
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
    if (auto guard = named_condition(text)) {
      name = text;
      return *guard;
    }
    BodyText body;
    body.text = text;
    body.start = ctx_.where(node);
    body.start.line = 0;  // the value's own line/column are not those of the condition text
    body.start.column = 0;
    return plcopen::parse_expression_text(body, ctx_.diagnostics());
  }

  // The condition of the POU's transition object `name`, read once per chart.
  std::optional<model::ExprPtr> named_condition(const std::string& name) {
    const auto key = model::to_upper(name);
    if (const auto it = guards_.find(key); it != guards_.end()) return it->second;
    if (!options_.named_condition) return std::nullopt;
    auto guard = options_.named_condition(name);
    if (guard) guards_[key] = *guard;
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
    const auto legs = f_.inner_list(e);
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
  const Format& f_;
  const Options& options_;
  model::Chart& chart_;
  AttributeTable table_;
  std::map<std::string, model::ExprPtr> guards_;
  std::string first_step_;
  int depth_ = 0;
  bool failed_ = false;
};

}  // namespace

model::ExprPtr transition_body_condition(plcopen::BodyText body, const std::string& name,
                                         plcopen::XmlContext& ctx, pugi::xml_node where) {
  std::string s = trim(body.text);
  // `expr`, `NAME := expr;` or `:= expr;`
  if (s.rfind(":=", 0) == 0) {
    s = s.substr(2);
  } else if (const auto pos = s.find(":=");
             pos != std::string::npos && model::iequals(trim(s.substr(0, pos)), name)) {
    s = s.substr(pos + 2);
  }
  s = trim(s);
  while (!s.empty() && (s.back() == ';' || s.back() == ' ' || s.back() == '\n' || s.back() == '\r'))
    s.pop_back();
  body.text = s;
  if (s.empty()) {
    ctx.error(where, "transition '" + name + "' has an empty condition");
    return nullptr;
  }
  return plcopen::parse_expression_text(body, ctx.diagnostics());
}

void read_chart(plcopen::PouContext& pc, const Format& format, pugi::xml_node impl,
                const Options& options, model::Chart& chart) {
  SfcArchiveReader(pc, format, options, chart).read(impl);
}

}  // namespace sfcv::io::sfc_archive
