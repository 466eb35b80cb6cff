// TwinCAT 3 native project files: `.TcPOU` (a POU with its actions and transitions), `.TcGVL`
// (a global variable list), `.TcDUT` (a data type), and a `.plcproj` or a folder of them.
//
// Declarations and ST bodies are ST text in CDATA, read with the ST parser at their place in
// the file. An SFC body is not PLCopen: `<Implementation><SFC><XmlArchive>` is a serialised
// object tree, read by io/sfc_archive (shared with the CODESYS export reader). What the model
// cannot say (time monitoring, embedded actions, IEC action associations inside a step, LD/FBD
// network archives as conditions, object-oriented POUs) is refused with the file and element path.

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "io/native_pou.hpp"
#include "io/plcopen_pou.hpp"
#include "io/plcopen_xml_dom.hpp"
#include "io/sfc_archive.hpp"
#include "io/st_parser.hpp"
#include "model/input_file.hpp"
#include "model/names.hpp"

namespace sfcv::io {

namespace {

using plcopen::child;
using plcopen::children;
using plcopen::element_children;
using plcopen::local_name;
using plcopen::trim;
using plcopen::XmlContext;

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
    return native::declaration_parser(plcopen::body_text(decl, ctx_), ctx_, budget_);
  }

  template <typename F>
  void parse(F&& f) {
    native::parse(ctx_, std::forward<F>(f));
  }

  void read_gvl(pugi::xml_node n) {
    model::Pou pou;
    pou.name = trim(n.attribute("Name").value());
    pou.kind = model::PouKind::Program;
    pou.where = ctx_.where(n);
    auto p = declaration_parser(n);
    if (!p) return;
    parse([&] { native::gvl_declaration(*p, pou); });
    native::refuse_non_globals(pou, ctx_, n);
    add_pou(n, std::move(pou));
  }

  void read_dut(pugi::xml_node n) {
    auto p = declaration_parser(n);
    if (!p) return;
    parse([&] { native::dut_declaration(*p, project_.data_types); });
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
    model::add_boolean_variable_actions(pou);
    add_pou(n, std::move(pou));
  }

  int chart(plcopen::PouContext& pc, const std::map<std::string, pugi::xml_node>& named,
            pugi::xml_node sfc, const std::string& name, const std::string& parent) {
    model::Chart c;
    c.name = name;
    c.parent_action = parent;
    c.where = ctx_.where(sfc);
    read_archive(pc, named, sfc, c);
    pc.pou.charts.push_back(std::move(c));
    return static_cast<int>(pc.pou.charts.size()) - 1;
  }

  void read_archive(plcopen::PouContext& pc, const std::map<std::string, pugi::xml_node>& named,
                    pugi::xml_node sfc, model::Chart& c) {
    const sfc_archive::Format format(sfc_archive::Encoding::Compact);
    pugi::xml_node impl;
    for (auto o : children(child(child(sfc, "XmlArchive"), "Data"), "o"))
      if (format.type(o) == "SFCImplementationObject") impl = o;
    if (!impl) {
      ctx_.error(sfc, "SFC body without an SFCImplementationObject in its XmlArchive");
      return;
    }
    sfc_archive::Options options;
    options.named_condition = [&](const std::string& text) -> std::optional<model::ExprPtr> {
      const auto it = named.find(model::to_upper(text));
      if (it == named.end()) return std::nullopt;
      return transition_condition(it->second, text);
    };
    sfc_archive::read_chart(pc, format, impl, options, c);
  }

  // The condition a `<Transition Name=...>` object's ST body gives.
  model::ExprPtr transition_condition(pugi::xml_node decl, const std::string& name) {
    const auto st = child(child(decl, "Implementation"), "ST");
    if (!st) {
      const auto impl = element_children(child(decl, "Implementation"));
      ctx_.error(decl,
                 "unsupported: transition '" + name + "' written in " +
                     (impl.empty() ? std::string("nothing") : std::string(local_name(impl[0]))) +
                     " (ST conditions are read)");
      return nullptr;
    }
    return sfc_archive::transition_body_condition(plcopen::body_text(st, ctx_), name, ctx_, st);
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

  void declaration(st::Parser& p, model::Pou& pou) { native::pou_declaration(p, pou); }

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
  if (!plcopen::load_document(doc, text, ctx)) return;
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
  return native::finish(std::move(project), std::move(diags));
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
  if (!plcopen::load_document(doc, text, ctx)) return files;
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
