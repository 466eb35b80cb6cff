// CODESYS native exports (`.export`: `<ExportFile><StructuredView>`), the objects of a CODESYS
// project tree as the IDE's "Export..." (and its scripting `export_native`) writes them.
//
// The file is one serialised archive in CODESYS's verbose XML spelling (`<Single Name Type>`,
// `<List2>`, `<Dictionary2>`): an `EntryList` of entries, each a `MetaObject` (Guid, ParentGuid,
// Name, TypeGuid) and its `Object`. Objects are typed by class GUID only: POUs, their actions
// and transitions (child objects whose ParentGuid is the POU's Guid), global variable lists and
// data types. Declarations and ST bodies are text documents (`TextLines`, one element per line,
// or one `TextBlobForSerialisation`), read with the ST parser at their place in the file. An SFC
// body is the same SFCImplementationObject archive TwinCAT writes, read by io/sfc_archive. What
// the model cannot say is refused with the file, the element path and the object's name.

#include <map>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "io/native_pou.hpp"
#include "io/plcopen_pou.hpp"
#include "io/plcopen_st.hpp"
#include "io/plcopen_xml_dom.hpp"
#include "io/sfc_archive.hpp"
#include "model/names.hpp"

namespace sfcv::io {

namespace {

using plcopen::BodyText;
using plcopen::child;
using plcopen::children;
using plcopen::element_children;
using plcopen::local_name;
using plcopen::trim;
using plcopen::XmlContext;

// Class GUIDs of the project objects and implementations read (the object types CODESYS's
// scripting API reports for them).
constexpr std::string_view kPou = "6f9dac99-8de1-4efc-8465-68ac443b7d08";
constexpr std::string_view kAction = "8ac092e5-3128-4e26-9e7e-11016c6684f2";
constexpr std::string_view kTransition = "a10c6218-cb94-436f-91c6-e1652575253d";
constexpr std::string_view kGvl = "ffbfa93a-b94d-45fc-a329-229860183b1d";
constexpr std::string_view kPersistentGvl = "261bd6e6-249c-4232-bb6f-84c2fbeef430";
constexpr std::string_view kDut = "2db5746d-d284-4425-9f7f-2663a34b0ebc";
constexpr std::string_view kFolder = "738bea1e-99bb-4f04-90bb-a7a567e74e3a";
constexpr std::string_view kStImplementation = "3b83b776-fb25-43b8-99f2-3c507c9143fc";
constexpr std::string_view kSfcImplementation = "74f81948-1328-492c-b6c1-a9ea72048b28";
constexpr std::string_view kNetworkImplementation = "25e509de-33d4-4447-93f8-c9e4ea381c8b";

// Objects that hold no program logic the model runs: left out with a warning.
const std::map<std::string_view, std::string_view>& unread_objects() {
  static const std::map<std::string_view, std::string_view> m = {
      {"adb5cb65-8e1d-4a00-b70a-375ea27582f3", "library manager"},
      {"ae1de277-a207-4a28-9efb-456c06bd52f3", "task configuration"},
      {"98a2708a-9b18-4f31-82ed-a1465b24fa2d", "task"},
      {"085afe48-c5d8-4ea5-ab0d-b35701fa6009", "project information"},
      {"8753fe6f-4a22-4320-8103-e553c4fc8e04", "project settings"},
      {"2bef0454-1bd3-412a-ac2c-af0f31dbc40f", "text list"},
      {"63784cbb-9ba0-45e6-9d69-babf3f040511", "global text list"},
      {"bb0b9044-714e-4614-ad3e-33cbdf34d16b", "image pool"},
      {"f18bec89-9fef-401d-9953-2f11739a6808", "visualisation"},
      {"4d3fdb8f-ab50-4c35-9d3a-d4bb9bb9a628", "visualisation manager"},
  };
  return m;
}

// Objects of POUs that object-oriented function blocks use: refused by name.
const std::map<std::string_view, std::string_view>& refused_objects() {
  static const std::map<std::string_view, std::string_view> m = {
      {"f8a58466-d7f6-439f-bbb8-d4600e41d099", "METHOD"},
      {"f89f7675-27f1-46b3-8abb-b7da8e774ffd", "METHOD"},
      {"5a3b8626-d3e9-4f37-98b5-66420063d91e", "PROPERTY"},
      {"792f2eb6-721e-4e64-ba20-bc98351056db", "PROPERTY"},
      {"6654496c-404d-479a-aad2-8551054e5f1e", "INTERFACE"},
  };
  return m;
}

using sfc_archive::guid_key;

// One entry of the export: an object of the project tree.
struct Entry {
  pugi::xml_node node, object;
  std::string guid, parent, name, type, path;
};

class ExportReader {
 public:
  ExportReader(XmlContext& ctx, model::Project& project, const model::Budget* budget)
      : ctx_(ctx), project_(project), budget_(budget) {}

  void read(pugi::xml_node root) {
    for (auto view : children(root, "StructuredView")) {
      const auto archive = child(view, "Single");
      if (const std::string profile = trim(f_.value(archive, "ProfileName"));
          !profile.empty() && project_.source_format == "codesys-export")
        project_.source_format += " " + profile;  // `sfcv info` shows what wrote the file
      for (auto e : element_children(f_.list(archive, "EntryList"))) entry(e);
    }
    if (entries_.empty()) {
      ctx_.error(root, "CODESYS export without objects (no StructuredView EntryList entry)");
      return;
    }
    std::set<std::string> pous;
    for (const auto& e : entries_)
      if (e.type == kPou) pous.insert(e.guid);
    // Lists and types first: POU declarations name them.
    for (const auto& e : entries_) {
      ctx_.poll();
      if (e.type == kGvl || e.type == kPersistentGvl)
        read_gvl(e);
      else if (e.type == kDut)
        read_dut(e);
    }
    for (const auto& e : entries_) {
      ctx_.poll();
      if (e.type == kPou) {
        read_pou(e);
      } else if (e.type == kAction || e.type == kTransition) {
        if (!pous.count(e.parent))
          ctx_.error(e.node, std::string(e.type == kAction ? "action" : "transition") + " '" +
                                 e.name + "' (" + e.path +
                                 ") belongs to a POU that is not in the export");
      } else if (const auto r = refused_objects().find(e.type); r != refused_objects().end()) {
        ctx_.error(e.node, "unsupported: " + std::string(r->second) + " '" + e.name + "' (" +
                               e.path + "): object-oriented function blocks are not modelled");
      } else if (const auto u = unread_objects().find(e.type); u != unread_objects().end()) {
        ctx_.warning(e.node,
                     "not read: " + std::string(u->second) + " '" + e.name + "' (" + e.path + ")");
      } else if (e.type != kGvl && e.type != kPersistentGvl && e.type != kDut &&
                 e.type != kFolder) {
        ctx_.error(e.node, "unsupported: object '" + e.name + "' (" + e.path + ") of type {" +
                               e.type + "}");
      }
    }
  }

 private:
  void entry(pugi::xml_node n) {
    const auto meta = f_.object(n, "MetaObject");
    Entry e;
    e.node = n;
    e.object = f_.object(n, "Object");
    e.guid = guid_key(f_.value(meta, "Guid"));
    e.parent = guid_key(f_.value(meta, "ParentGuid"));
    e.name = trim(f_.value(meta, "Name"));
    e.type = guid_key(f_.value(meta, "TypeGuid"));
    for (auto p : element_children(f_.list(n, "Path"))) e.path += trim(p.text().get()) + "/";
    e.path += e.name;
    if (!meta || !e.object || e.name.empty()) {
      ctx_.error(n, "export entry without a MetaObject, an Object or a Name");
      return;
    }
    entries_.push_back(std::move(e));
  }

  // A `TextDocument` (declaration or ST body) as text at its place in the file.
  std::optional<BodyText> text(pugi::xml_node holder) {
    const auto doc = f_.object(holder, "TextDocument");
    if (!doc) return std::nullopt;
    if (const auto lines = f_.list(doc, "TextLines")) {
      std::vector<pugi::xml_node> text_nodes;
      for (auto l : element_children(lines)) text_nodes.push_back(f_.value_node(l, "Text"));
      return plcopen::lines_text(lines, text_nodes, ctx_);
    }
    if (const auto blob = f_.value_node(doc, "TextBlobForSerialisation"))
      return plcopen::body_text(blob, ctx_);
    return std::nullopt;
  }

  std::unique_ptr<st::Parser> declaration_parser(const Entry& e) {
    const auto decl = text(f_.object(e.object, "Interface"));
    if (!decl) {
      ctx_.error(e.object, "'" + e.name + "' (" + e.path + ") has no textual declaration");
      return nullptr;
    }
    return native::declaration_parser(*decl, ctx_, budget_);
  }

  void add_pou(const Entry& e, model::Pou pou) {
    if (project_.find_pou(pou.name)) {
      ctx_.error(e.node, "duplicate POU or global list '" + pou.name + "'");
      return;
    }
    project_.pous.push_back(std::move(pou));
  }

  void read_gvl(const Entry& e) {
    model::Pou pou;
    pou.name = e.name;
    pou.kind = model::PouKind::Program;
    pou.where = ctx_.where(e.node);
    auto p = declaration_parser(e);
    if (!p) return;
    native::parse(ctx_, [&] { native::gvl_declaration(*p, pou); });
    native::refuse_non_globals(pou, ctx_, e.node);
    add_pou(e, std::move(pou));
  }

  void read_dut(const Entry& e) {
    auto p = declaration_parser(e);
    if (!p) return;
    native::parse(ctx_, [&] { native::dut_declaration(*p, project_.data_types); });
  }

  // The implementation of a POU or action: its class and node.
  pugi::xml_node implementation(const Entry& e) { return f_.object(e.object, "Implementation"); }

  static std::string kind_of(pugi::xml_node impl, const sfc_archive::Format& f) {
    const std::string type = guid_key(impl.attribute("Type").value());
    if (type == kStImplementation) return "ST";
    if (type == kSfcImplementation) return "SFC";
    if (type == kNetworkImplementation) {
      const std::string mode = model::to_upper(trim(f.value(impl, "DefaultViewMode")));
      return mode == "LD" ? "LD" : mode == "IL" ? "IL" : "FBD";
    }
    return "an implementation of type {" + type + "}";
  }

  // ST statements of a body, or nullopt with the reasons in `problems`.
  std::optional<model::StmtList> statements(plcopen::PouContext& pc, const BodyText& body,
                                            model::Diagnostics& problems) {
    auto stmts = plcopen::parse_statements_text(body, problems);
    if (!stmts || model::has_errors(problems)) return std::nullopt;
    plcopen::leave_out_unmodelled_writes(pc, *stmts, problems);
    return stmts;
  }

  // A body that cannot be modelled still loads; running it is refused (as PLCopen bodies).
  struct Unmodelled {
    std::string language, text, reason;
  };
  Unmodelled unmodelled(const std::string& kind, const std::optional<BodyText>& body,
                        model::Diagnostics& problems) {
    Unmodelled u;
    u.language = kind == "ST" || kind == "IL" || kind == "LD" || kind == "FBD" ? kind : "";
    if (body && kind == "ST") u.text = body->text;
    u.reason = kind == "ST" ? "" : "bodies in " + kind + " are not read from CODESYS exports";
    for (const auto& d : problems)
      if (u.reason.empty() && d.severity == model::Severity::Error)
        u.reason = d.where.str() + ": " + d.message;
    if (u.reason.empty()) u.reason = "its text could not be read";
    for (auto& d : problems) {
      d.severity = model::Severity::Note;
      ctx_.add(std::move(d));
    }
    problems.clear();
    return u;
  }

  void read_pou(const Entry& e) {
    model::Pou pou;
    pou.name = e.name;
    pou.where = ctx_.where(e.node);
    auto p = declaration_parser(e);
    if (!p) return;
    if (!native::parse(ctx_, [&] { native::pou_declaration(*p, pou); })) return;
    refuse_sfc_flags(e, pou);
    plcopen::PouContext pc{ctx_, e.node, pou, {}, {}, {}, 0};
    std::map<std::string, const Entry*> transitions;
    std::vector<const Entry*> actions;
    for (const auto& c : entries_)
      if (c.parent == e.guid) {
        if (c.type == kTransition)
          transitions[model::to_upper(c.name)] = &c;
        else if (c.type == kAction)
          actions.push_back(&c);
      }
    // Actions first: a chart's associations are resolved against them.
    std::vector<std::pair<std::size_t, pugi::xml_node>> sfc_actions;
    for (const Entry* a : actions) {
      model::Action act;
      act.name = a->name;
      act.where = ctx_.where(a->node);
      if (pou.find_action(act.name)) {
        ctx_.error(a->node, "duplicate action '" + act.name + "'");
        continue;
      }
      const auto impl = implementation(*a);
      if (!impl) {
        ctx_.error(a->node, "action '" + act.name + "' (" + a->path + ") has no implementation");
        continue;
      }
      const std::string kind = kind_of(impl, f_);
      if (kind == "SFC") {
        act.kind = model::ActionBodyKind::Chart;
        sfc_actions.emplace_back(pou.actions.size(), impl);
      } else {
        read_action(pc, act, impl, kind);
      }
      pou.actions.push_back(std::move(act));
    }
    const auto impl = implementation(e);
    if (!impl) {
      ctx_.error(e.object, "POU '" + pou.name + "' (" + e.path + ") has no implementation");
      return;
    }
    const std::string kind = kind_of(impl, f_);
    if (kind == "SFC") {
      chart(pc, transitions, impl, pou.name, "");
    } else {
      read_body(pc, impl, kind);
    }
    for (const auto& [index, sfc] : sfc_actions) {
      const std::string name = pou.actions[index].name;
      pou.actions[index].chart = chart(pc, transitions, sfc, name, name);
    }
    model::add_boolean_variable_actions(pou);
    add_pou(e, std::move(pou));
  }

  void read_action(plcopen::PouContext& pc, model::Action& act, pugi::xml_node impl,
                   const std::string& kind) {
    act.kind = model::ActionBodyKind::Statements;
    model::Diagnostics problems;
    const auto body = kind == "ST" ? text(impl) : std::nullopt;
    if (body)
      if (auto stmts = statements(pc, *body, problems)) {
        act.body = std::move(*stmts);
        for (auto& d : problems) ctx_.add(std::move(d));
        return;
      }
    const auto u = unmodelled(kind, body, problems);
    act.body_unsupported = true;
    act.unsupported_language = u.language;
    act.unsupported_text = u.text;
    act.unsupported_reason = u.reason;
    ctx_.warning(impl, "action '" + act.name + "': body not modelled (" + u.reason +
                           "); checks that need this action will be refused");
  }

  void read_body(plcopen::PouContext& pc, pugi::xml_node impl, const std::string& kind) {
    model::Diagnostics problems;
    const auto body = kind == "ST" ? text(impl) : std::nullopt;
    if (body)
      if (auto stmts = statements(pc, *body, problems)) {
        pc.pou.body = std::move(*stmts);
        for (auto& d : problems) ctx_.add(std::move(d));
        return;
      }
    const auto u = unmodelled(kind, body, problems);
    pc.pou.body_unsupported = true;
    pc.pou.unsupported_language = u.language;
    pc.pou.unsupported_text = u.text;
    pc.pou.unsupported_reason = u.reason;
    ctx_.warning(impl, "POU '" + pc.pou.name + "': its body is not modelled (" + u.reason +
                           "); running it is refused");
  }

  int chart(plcopen::PouContext& pc, const std::map<std::string, const Entry*>& transitions,
            pugi::xml_node impl, const std::string& name, const std::string& parent) {
    model::Chart c;
    c.name = name;
    c.parent_action = parent;
    c.where = ctx_.where(impl);
    sfc_archive::Options options;
    options.step_associations = true;
    options.named_condition = [&](const std::string& text) -> std::optional<model::ExprPtr> {
      const auto it = transitions.find(model::to_upper(text));
      if (it == transitions.end()) return std::nullopt;
      return transition_condition(*it->second);
    };
    sfc_archive::read_chart(pc, f_, impl, options, c);
    pc.pou.charts.push_back(std::move(c));
    return static_cast<int>(pc.pou.charts.size()) - 1;
  }

  model::ExprPtr transition_condition(const Entry& t) {
    const auto impl = implementation(t);
    const std::string kind = kind_of(impl, f_);
    const auto body = kind == "ST" ? text(impl) : std::nullopt;
    if (!body) {
      ctx_.error(impl ? impl : t.node, "unsupported: transition '" + t.name + "' (" + t.path +
                                           ") written in " + kind + " (ST conditions are read)");
      return nullptr;
    }
    return sfc_archive::transition_body_condition(*body, t.name, ctx_, impl);
  }

  // The SFC settings of a POU (MetaObject Properties) mark the implicit flag variables it uses
  // (SFCReset, SFCPause, ...). A used flag the POU declares is a variable of the model, read as
  // docs/semantics.md 1.3a says (SFCInit/SFCReset modelled, the others refused there); one CODESYS
  // declares implicitly is not, and the runtime acts on the chart through it: refused.
  void refuse_sfc_flags(const Entry& e, const model::Pou& pou) {
    std::vector<pugi::xml_node> flags;
    find_named(f_.object(e.node, "MetaObject"), "Flags", 0, flags);
    for (auto d : flags)
      for (const auto& [key, value] : f_.entries(d)) {
        if (!model::iequals(trim(f_.value(value, "Use")), "True")) continue;
        std::string flag = trim(key.text().get());
        if (model::to_upper(flag).rfind("SFC", 0) != 0) flag = "SFC" + flag;
        if (!pou.find_variable(flag))
          ctx_.error(value, "unsupported: SFC flag '" + flag + "' of POU '" + e.name +
                                "' is used but not declared in the POU (an implicit flag "
                                "variable is not modelled; docs/semantics.md 1.3a)");
      }
  }

  // The elements named `name` under `n` (the SFC settings sit a few levels down).
  static void find_named(pugi::xml_node n, std::string_view name, int depth,
                         std::vector<pugi::xml_node>& out) {
    if (depth > 8) return;
    for (auto c : element_children(n)) {
      if (std::string_view(c.attribute("Name").value()) == name) out.push_back(c);
      find_named(c, name, depth + 1, out);
    }
  }

  XmlContext& ctx_;
  model::Project& project_;
  const model::Budget* budget_;
  sfc_archive::Format f_{sfc_archive::Encoding::Verbose};
  std::vector<Entry> entries_;
};

}  // namespace

LoadResult load_codesys_export(std::string_view text, const std::string& file,
                               const model::Budget* budget) {
  model::Project project;
  project.source_format = "codesys-export";
  project.dialect = model::Dialect::Iec61131;
  project.where.file = file;
  model::Diagnostics diags;
  XmlContext ctx(file, text, diags, budget);
  pugi::xml_document doc;
  if (!plcopen::load_document(doc, text, ctx)) return LoadResult{std::nullopt, std::move(diags)};
  const auto root = doc.document_element();
  if (local_name(root) != "ExportFile") {
    ctx.error(root, "not a CODESYS export: the root element is <" + std::string(root.name()) +
                        ">, not <ExportFile>");
    return LoadResult{std::nullopt, std::move(diags)};
  }
  ExportReader(ctx, project, budget).read(root);
  return native::finish(std::move(project), std::move(diags));
}

}  // namespace sfcv::io
