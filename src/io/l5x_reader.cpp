// Rockwell Studio 5000 `.L5X` exports (RSLogix5000Content): programs with an SFC main routine.
//
// A program is a POU; its tags are its variables (controller tags: a global list, as TwinCAT's
// GVLs). An SFC routine (`<Routine Type="SFC"><SFCContent>`) is not a sequence in document
// order but a graph: Step, Transition and Branch elements (a Branch is Selection or
// Simultaneous, Diverge or Converge, with Legs) joined by `DirectedLink FromID ToID`. Each
// transition's sources and targets are read through the branches around it. Conditions and
// action bodies are ST, one `<Line>` per line, read with the ST parser at their place in the
// file. What the model cannot say (qualifiers other than NonStored, Boolean actions, step timer
// and status bits other than `.X`, non-retentive assignments `[:=]`, JSR, Stop elements, user
// priorities, SFC execution options other than the modelled ones) is refused with the element
// path; RLL/FBD main routines load as not modelled (refused when run).

#include <algorithm>
#include <cctype>
#include <map>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <vector>

#include "io/load.hpp"
#include "io/plcopen_st.hpp"
#include "io/plcopen_xml_dom.hpp"
#include "model/data_types.hpp"
#include "model/names.hpp"
#include "model/types.hpp"

namespace sfcv::io {

namespace {

using plcopen::BodyText;
using plcopen::child;
using plcopen::children;
using plcopen::element_children;
using plcopen::local_name;
using plcopen::trim;
using plcopen::XmlContext;

bool is_true(pugi::xml_node n, const char* attribute) {
  return model::iequals(trim(n.attribute(attribute).value()), "true");
}

// The ST text of an `<STContent>`: its `<Line>` CDATA, at their place in the file.
BodyText st_content(pugi::xml_node st, const XmlContext& ctx) {
  return plcopen::lines_text(st, children(st, "Line"), ctx);
}

// What an SFC element is, for reading the links around it.
struct Node {
  enum class Kind { Step, Transition, Branch, Leg } kind = Kind::Step;
  pugi::xml_node node;
  std::string branch;                          ///< Leg: its branch's ID
  bool simultaneous = false, diverge = false;  ///< Branch and Leg: the branch's
  std::size_t doc = 0;                         ///< document position
};

std::string describe_kind(const Node& n) {
  switch (n.kind) {
    case Node::Kind::Step:
      return "step";
    case Node::Kind::Transition:
      return "transition";
    case Node::Kind::Branch:
    case Node::Kind::Leg:
      break;
  }
  std::string s = std::string(n.simultaneous ? "simultaneous" : "selection") +
                  (n.diverge ? " divergence" : " convergence");
  return n.kind == Node::Kind::Leg ? "a leg of a " + s : s;
}

class SfcRoutineReader {
 public:
  SfcRoutineReader(XmlContext& ctx, model::Pou& pou, model::Chart& chart)
      : ctx_(ctx), pou_(pou), chart_(chart) {}

  void read(pugi::xml_node content) {
    std::size_t doc = 0;
    for (auto e : element_children(content)) {
      ctx_.poll();
      const auto k = local_name(e);
      if (k == "Step") {
        add(e, {Node::Kind::Step, e, {}, false, false, doc++});
      } else if (k == "Transition") {
        add(e, {Node::Kind::Transition, e, {}, false, false, doc++});
      } else if (k == "Branch") {
        branch(e, doc++);
      } else if (k == "DirectedLink") {
        links_.push_back(e);
      } else if (k == "TextBox" || k == "Attachment") {
        // Comments drawn on the chart: no meaning.
      } else if (k == "Stop") {
        ctx_.error(e, "unsupported: SFC Stop element '" +
                          std::string(e.attribute("Operand").value()) +
                          "' (a path that stops the chart is not modelled)");
      } else {
        ctx_.error(e, "unsupported: SFC element <" + std::string(k) + ">");
      }
    }
    if (model::has_errors(ctx_.diagnostics())) return;
    read_links();
    for (const auto& id : ids_)
      if (const auto& n = nodes_.at(id); n.kind == Node::Kind::Step) step(n.node);
    if (model::has_errors(ctx_.diagnostics())) return;
    read_transitions();
    if (chart_.steps.empty()) ctx_.error(content, "SFC routine without a step");
    std::size_t initial = 0;
    for (const auto& s : chart_.steps) initial += s.initial;
    if (!chart_.steps.empty() && initial != 1)
      ctx_.error(content, "SFC routine with " + std::to_string(initial) +
                              " initial steps (Studio 5000 charts have one)");
  }

 private:
  void add(pugi::xml_node e, Node n) {
    const std::string id = trim(e.attribute("ID").value());
    if (id.empty()) {
      ctx_.error(e, "SFC element without an ID");
      return;
    }
    if (!nodes_.emplace(id, std::move(n)).second)
      ctx_.error(e, "duplicate SFC ID '" + id + "'");
    else
      ids_.push_back(id);
  }

  void branch(pugi::xml_node e, std::size_t doc) {
    const std::string type = e.attribute("BranchType").value();
    const std::string flow = e.attribute("BranchFlow").value();
    if ((type != "Selection" && type != "Simultaneous") ||
        (flow != "Diverge" && flow != "Converge")) {
      ctx_.error(
          e, "unsupported: Branch with BranchType '" + type + "' and BranchFlow '" + flow + "'");
      return;
    }
    const std::string priority = e.attribute("Priority").value();
    if (!priority.empty() && priority != "Default")
      ctx_.error(e, "unsupported: selection branch with Priority '" + priority +
                        "' (only the default left-to-right order is read)");
    Node b{Node::Kind::Branch, e, {}, type == "Simultaneous", flow == "Diverge", doc};
    const std::string id = trim(e.attribute("ID").value());
    const auto legs = children(e, "Leg");
    if (legs.size() < 2) ctx_.error(e, "Branch with fewer than two legs");
    for (auto leg : legs) {
      Node l = b;
      l.kind = Node::Kind::Leg;
      l.node = leg;
      l.branch = id;
      add(leg, l);
      legs_[id].push_back(trim(leg.attribute("ID").value()));
    }
    add(e, b);
  }

  // Each link is one of the shapes a Studio 5000 chart is drawn with; any other is refused.
  void read_links() {
    for (auto l : links_) {
      const std::string from = trim(l.attribute("FromID").value());
      const std::string to = trim(l.attribute("ToID").value());
      const auto f = nodes_.find(from), t = nodes_.find(to);
      if (f == nodes_.end() || t == nodes_.end()) {
        ctx_.error(
            l, "DirectedLink to or from an unknown ID '" + (f == nodes_.end() ? from : to) + "'");
        continue;
      }
      const Node &a = f->second, &b = t->second;
      using K = Node::Kind;
      const bool ok =
          (a.kind == K::Step &&
           (b.kind == K::Transition || (b.kind == K::Branch && !b.simultaneous && b.diverge) ||
            (b.kind == K::Leg && b.simultaneous && !b.diverge))) ||
          (a.kind == K::Transition &&
           (b.kind == K::Step || (b.kind == K::Leg && !b.simultaneous && !b.diverge) ||
            (b.kind == K::Branch && b.simultaneous && b.diverge))) ||
          (a.kind == K::Leg && a.diverge &&
           (a.simultaneous ? b.kind == K::Step : b.kind == K::Transition)) ||
          (a.kind == K::Branch && !a.diverge &&
           (a.simultaneous ? b.kind == K::Transition : b.kind == K::Step));
      if (!ok) {
        ctx_.error(l, "unsupported: a link from " + describe_kind(a) + " " + from + " to " +
                          describe_kind(b) + " " + to);
        continue;
      }
      out_[from].push_back(to);
      in_[to].push_back(from);
    }
  }

  // The one element linked from (`out`) or to `id`, or an error.
  const Node* only(const std::string& id, bool out, const char* what) {
    const auto& m = out ? out_ : in_;
    const auto it = m.find(id);
    const std::size_t count = it == m.end() ? 0 : it->second.size();
    if (count != 1) {
      const Node& n = nodes_.at(id);
      ctx_.error(n.node, describe_kind(n) + " " + id + " has " + std::to_string(count) + " " +
                             what + " links (one expected)");
      return nullptr;
    }
    return &nodes_.at(it->second[0]);
  }

  std::string step_name(const Node* n) { return trim(n->node.attribute("Operand").value()); }

  void step(pugi::xml_node e) {
    model::Step s;
    s.name = trim(e.attribute("Operand").value());
    s.initial = is_true(e, "InitialStep");
    s.where = ctx_.where(e);
    if (s.name.empty()) {
      ctx_.error(e, "step without an Operand (its SFC_STEP tag)");
      return;
    }
    if (chart_.find_step(s.name)) {
      ctx_.error(e, "duplicate step '" + s.name + "'");
      return;
    }
    step_names_.insert(model::to_upper(s.name));
    const auto it = out_.find(trim(e.attribute("ID").value()));
    if (it != out_.end() && it->second.size() > 1)
      ctx_.error(e, "step '" + s.name + "' has " + std::to_string(it->second.size()) +
                        " outgoing links (alternatives are drawn with a selection branch)");
    for (auto c : element_children(e)) {
      const auto k = local_name(c);
      if (k == "Action") {
        action(c, s.name);
      } else if (k != "Description" && k != "Preset" && k != "LimitHigh" && k != "LimitLow") {
        // The preset and alarm limits only set the step's timer bits, which are refused where
        // they are read (.DN, .AL...).
        ctx_.error(c, "unsupported: <" + std::string(k) + "> in step '" + s.name + "'");
      }
    }
    chart_.steps.push_back(std::move(s));
  }

  void action(pugi::xml_node e, const std::string& step) {
    model::Action a;
    a.name = trim(e.attribute("Operand").value());
    a.where = ctx_.where(e);
    if (a.name.empty() || pou_.find_action(a.name)) {
      ctx_.error(e, a.name.empty() ? "action without an Operand (its SFC_ACTION tag)"
                                   : "duplicate action '" + a.name + "'");
      return;
    }
    action_names_.insert(model::to_upper(a.name));
    const std::string q = e.attribute("Qualifier").value();
    // Rockwell spells the qualifiers out; only N's meaning is the same as the model's without a
    // dialect (issue 46): the others (Stored, pulses, timed) are refused by name.
    if (q != "NonStored") {
      ctx_.error(e, "unsupported: action qualifier '" + q + "' of action '" + a.name +
                        "' (only NonStored is read)");
      return;
    }
    if (is_true(e, "IsBoolean")) {
      ctx_.error(e, "unsupported: Boolean action '" + a.name + "' (an action without a body)");
      return;
    }
    const auto st = child(child(e, "Body"), "STContent");
    if (!st) {
      ctx_.error(e, "unsupported: action '" + a.name + "' without an ST body");
      return;
    }
    const auto text = st_content(st, ctx_);
    if (!rockwell_text_ok(st, text.text)) return;
    auto body = plcopen::parse_statements_text(text, ctx_.diagnostics());
    if (!body) return;
    a.body = std::move(*body);
    model::ActionAssociation as;
    as.chart = chart_.name;
    as.step = step;
    as.action = a.name;
    as.qualifier = model::Qualifier::N;
    as.where = a.where;
    pou_.associations.push_back(std::move(as));
    pou_.actions.push_back(std::move(a));
  }

  // Rockwell ST the model has no meaning for, refused by name before parsing: the
  // non-retentive assignment `[:=]` (cleared on the step's last scan, which depends on the
  // controller's SFC options), JSR, and members of the chart's SFC_STEP / SFC_ACTION tags other
  // than a step's `.X` (its activity, as IEC 61131-3's S.X).
  bool rockwell_text_ok(pugi::xml_node where, const std::string& text) {
    bool ok = true;
    if (text.find("[:=]") != std::string::npos) {
      ctx_.error(where,
                 "unsupported: non-retentive assignment '[:=]' (Rockwell: cleared on the "
                 "step's last scan, not modelled)");
      ok = false;
    }
    for (std::size_t i = 0; i < text.size();) {
      if (!is_st_identifier_char(text[i]) || (i > 0 && is_st_identifier_char(text[i - 1]))) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < text.size() && is_st_identifier_char(text[j])) ++j;
      const std::string word = model::to_upper(text.substr(i, j - i));
      if (word == "JSR") {
        ctx_.error(where, "unsupported: JSR (subroutine calls are not read)");
        ok = false;
      }
      if (j + 1 < text.size() && text[j] == '.' && is_st_identifier_char(text[j + 1])) {
        std::size_t m = j + 1;
        while (m < text.size() && is_st_identifier_char(text[m])) ++m;
        const std::string member = model::to_upper(text.substr(j + 1, m - j - 1));
        const bool step = step_operands_.count(word) > 0;
        if ((step && member != "X") || action_operands_.count(word)) {
          ctx_.error(where, "unsupported: '" + text.substr(i, m - i) + "': member " + member +
                                " of the " + (step ? "SFC_STEP" : "SFC_ACTION") +
                                " tag (Rockwell step timers and status bits are not modelled; "
                                "a step's .X is)");
          ok = false;
        }
        j = m;
      }
      i = j;
    }
    return ok;
  }

  void read_transitions() {
    struct Read {
      model::Transition t;
      std::size_t anchor = 0;  ///< the selection branch it leaves, or itself
      long x = 0;
      pugi::xml_node node;
    };
    std::vector<Read> read;
    for (const auto& id : ids_) {
      const Node& n = nodes_.at(id);
      if (n.kind != Node::Kind::Transition) continue;
      ctx_.poll();
      Read r;
      r.t.name = trim(n.node.attribute("Operand").value());
      r.t.where = ctx_.where(n.node);
      r.anchor = n.doc;
      r.x = n.node.attribute("X").as_int();
      r.node = n.node;
      const Node* before = only(id, false, "incoming");
      const Node* after = only(id, true, "outgoing");
      if (!before || !after) continue;
      if (!sources(*before, r.t.sources, r.anchor) || !targets(*after, r.t.targets)) continue;
      r.t.guard = condition(n.node, r.t.name);
      if (!r.t.guard) continue;
      read.push_back(std::move(r));
    }
    // Studio 5000 tries the transitions of a selection branch left to right by default.
    std::sort(read.begin(), read.end(), [](const Read& a, const Read& b) {
      return a.anchor != b.anchor ? a.anchor < b.anchor : a.x < b.x;
    });
    for (std::size_t i = 0; i + 1 < read.size(); ++i)
      if (read[i].anchor == read[i + 1].anchor && read[i].x == read[i + 1].x)
        ctx_.error(read[i + 1].node, "transitions '" + read[i].t.name + "' and '" +
                                         read[i + 1].t.name +
                                         "' of one selection branch are drawn at the same X: "
                                         "their left-to-right order is unknown");
    for (auto& r : read) {
      r.t.order = static_cast<int>(chart_.transitions.size());
      chart_.transitions.push_back(std::move(r.t));
    }
  }

  bool sources(const Node& n, std::vector<std::string>& out, std::size_t& anchor) {
    using K = Node::Kind;
    if (n.kind == K::Step) {
      out.push_back(step_name(&n));
    } else if (n.kind == K::Leg) {  // a selection divergence: the step before it
      const Node* s = only(n.branch, false, "incoming");
      if (!s) return false;
      if (s->kind != K::Step) {
        ctx_.error(s->node, "unsupported: a selection divergence after " + describe_kind(*s));
        return false;
      }
      anchor = nodes_.at(n.branch).doc;
      out.push_back(step_name(s));
    } else {  // a simultaneous convergence: the last step of every leg
      for (const auto& leg : legs_[trim(n.node.attribute("ID").value())]) {
        const Node* s = only(leg, false, "incoming");
        if (!s) return false;
        out.push_back(step_name(s));
      }
    }
    return true;
  }

  bool targets(const Node& n, std::vector<std::string>& out) {
    using K = Node::Kind;
    if (n.kind == K::Step) {
      out.push_back(step_name(&n));
    } else if (n.kind == K::Leg) {  // a selection convergence: the step after it
      const Node* s = only(n.branch, true, "outgoing");
      if (!s) return false;
      out.push_back(step_name(s));
    } else {  // a simultaneous divergence: the first step of every leg
      for (const auto& leg : legs_[trim(n.node.attribute("ID").value())]) {
        const Node* s = only(leg, true, "outgoing");
        if (!s) return false;
        out.push_back(step_name(s));
      }
    }
    return true;
  }

  model::ExprPtr condition(pugi::xml_node e, const std::string& name) {
    const auto st = child(child(e, "Condition"), "STContent");
    if (!st) {
      ctx_.error(e, "unsupported: transition '" + name + "' without an ST condition");
      return nullptr;
    }
    auto text = st_content(st, ctx_);
    if (!rockwell_text_ok(st, text.text)) return nullptr;
    // A condition may end with `;`.
    auto end = text.text.find_last_not_of(" \t\r\n");
    if (end != std::string::npos && text.text[end] == ';') text.text[end] = ' ';
    if (trim(text.text).empty()) {
      ctx_.error(st, "transition '" + name + "' has an empty condition");
      return nullptr;
    }
    return plcopen::parse_expression_text(text, ctx_.diagnostics());
  }

 public:
  /// The chart's SFC_STEP and SFC_ACTION operands (upper case), known before any text is read.
  void operands(pugi::xml_node content) {
    for (auto s : children(content, "Step")) {
      step_operands_.insert(model::to_upper(trim(s.attribute("Operand").value())));
      for (auto a : children(s, "Action"))
        action_operands_.insert(model::to_upper(trim(a.attribute("Operand").value())));
    }
  }

 private:
  XmlContext& ctx_;
  model::Pou& pou_;
  model::Chart& chart_;
  std::map<std::string, Node> nodes_;
  std::vector<std::string> ids_;  ///< document order
  std::map<std::string, std::vector<std::string>> legs_, out_, in_;
  std::vector<pugi::xml_node> links_;
  std::set<std::string> step_names_, action_names_, step_operands_, action_operands_;
};

class L5xReader {
 public:
  L5xReader(XmlContext& ctx, model::Project& project) : ctx_(ctx), project_(project) {}

  void read(pugi::xml_node root) {
    if (local_name(root) != "RSLogix5000Content") {
      ctx_.error(root, "not a Studio 5000 export: the root element is <" +
                           std::string(root.name()) + ">, not <RSLogix5000Content>");
      return;
    }
    if (const std::string v = trim(root.attribute("SoftwareRevision").value()); !v.empty())
      project_.source_format += " " + v;
    project_.name = trim(root.attribute("TargetName").value());
    const auto controller = child(root, "Controller");
    if (!controller) {
      ctx_.error(root, "no <Controller>");
      return;
    }
    execution_options(controller);
    if (const auto tags = child(controller, "Tags"); !element_children(tags).empty()) {
      model::Pou globals;
      globals.name = trim(controller.attribute("Name").value());
      globals.where = ctx_.where(controller);
      read_tags(tags, globals, true);
      project_.pous.push_back(std::move(globals));
    }
    for (auto p : children(child(controller, "Programs"), "Program")) {
      ctx_.poll();
      read_program(p);
    }
  }

 private:
  // The controller's SFC options decide how a chart runs. The model runs one evolution per
  // scan and gives an action no last scan after its step is left: Studio 5000's
  // "CurrentActive" and "DontScan".
  void execution_options(pugi::xml_node c) {
    const std::string exec = c.attribute("SFCExecutionControl").value();
    const std::string last = c.attribute("SFCLastScan").value();
    if (!exec.empty() && exec != "CurrentActive")
      ctx_.error(c, "unsupported: SFCExecutionControl '" + exec +
                        "' (only CurrentActive, one evolution per scan, is modelled)");
    if (!last.empty() && last != "DontScan")
      ctx_.error(c, "unsupported: SFCLastScan '" + last +
                        "' (only DontScan is modelled: no last scan of a step's actions)");
    if (exec.empty() || last.empty())
      ctx_.warning(c,
                   "the controller's SFC options are not in the file: read as "
                   "SFCExecutionControl CurrentActive and SFCLastScan DontScan "
                   "(Studio 5000's defaults)");
  }

  void read_program(pugi::xml_node p) {
    model::Pou pou;
    pou.name = trim(p.attribute("Name").value());
    pou.kind = model::PouKind::Program;
    pou.where = ctx_.where(p);
    if (pou.name.empty() || project_.find_pou(pou.name)) {
      ctx_.error(
          p, pou.name.empty() ? "program without a Name" : "duplicate program '" + pou.name + "'");
      return;
    }
    if (is_true(p, "Disabled"))
      ctx_.warning(p,
                   "program '" + pou.name + "' is disabled in the controller; read as if it ran");
    read_tags(child(p, "Tags"), pou, false);
    const std::string main = trim(p.attribute("MainRoutineName").value());
    bool main_seen = false;
    for (auto r : children(child(p, "Routines"), "Routine")) {
      const std::string name = trim(r.attribute("Name").value());
      const std::string type = r.attribute("Type").value();
      const bool is_main = name == main;
      main_seen = main_seen || is_main;
      if (type == "SFC") {
        sfc_routine(r, pou, name);
        if (!is_main)
          ctx_.error(r, "unsupported: SFC routine '" + name +
                            "' is not the program's main routine (routines called by JSR are "
                            "not read)");
      } else if (is_main) {
        // RLL, ST or FBD main routine: loads as not modelled, refused when run.
        pou.body_unsupported = true;
        pou.unsupported_language = type == "RLL" ? "LD" : type;
        pou.unsupported_reason = ctx_.where(r).str() + ": main routine '" + name + "' is " + type +
                                 ", which is not read (SFC main routines are)";
        ctx_.warning(r, "program '" + pou.name + "': its main routine '" + name + "' (" + type +
                            ") is not modelled; running it is refused");
      } else {
        ctx_.note(r, "routine '" + name + "' (" + type + ") is not the main routine: not read");
      }
    }
    if (!main.empty() && !main_seen)
      ctx_.error(p,
                 "program '" + pou.name + "': its main routine '" + main + "' is not in the file");
    project_.pous.push_back(std::move(pou));
  }

  void sfc_routine(pugi::xml_node r, model::Pou& pou, const std::string& name) {
    const auto content = child(r, "SFCContent");
    if (!content) {
      ctx_.error(r, "SFC routine '" + name + "' without <SFCContent>");
      return;
    }
    // Studio 5000 runs the actions of the active steps, then evaluates their transitions on
    // what the actions left, in one scan: the model's cycle (docs/semantics.md 1.2).
    model::Chart c;
    c.name = name;
    c.where = ctx_.where(r);
    SfcRoutineReader reader(ctx_, pou, c);
    reader.operands(content);
    reader.read(content);
    pou.charts.push_back(std::move(c));
  }

  // Tags: BOOL and integer base tags are variables; I/O aliases of one bit (`Local:1:I.Data.4`)
  // are Boolean inputs/outputs; the chart's own SFC_STEP/SFC_ACTION tags are its steps and
  // actions. Tags of other types are left out with a note: a use of one is an error.
  void read_tags(pugi::xml_node tags, model::Pou& pou, bool global) {
    for (auto t : children(tags, "Tag")) {
      ctx_.poll();
      model::Variable v;
      v.name = trim(t.attribute("Name").value());
      v.where = ctx_.where(t);
      v.direction = global ? model::VarDirection::Global : model::VarDirection::Local;
      v.constant = is_true(t, "Constant");
      const std::string kind =
          t.attribute("TagType").empty() ? "Base" : t.attribute("TagType").value();
      const std::string type = trim(t.attribute("DataType").value());
      if (kind == "Alias") {
        if (!io_alias(t, v, global)) continue;
      } else if (kind != "Base") {
        ctx_.note(t,
                  "tag '" + v.name + "' (" + kind + ") is not modelled: a use of it is an error");
        continue;
      } else if (type == "SFC_STEP" || type == "SFC_ACTION" || type == "SFC_STOP") {
        continue;  // the chart's own: its steps and actions
      } else {
        const auto et = model::elementary_type(type);
        if (!et || et->kind == model::TypeKind::FunctionBlock ||
            et->kind == model::TypeKind::Time || !trim(t.attribute("Dimensions").value()).empty()) {
          ctx_.note(t, "tag '" + v.name + "' of type " + type +
                           (t.attribute("Dimensions").empty()
                                ? ""
                                : "[" + std::string(t.attribute("Dimensions").value()) + "]") +
                           " is not modelled: a use of it is an error");
          continue;
        }
        v.type = *et;
        if (!global) {
          const std::string usage = t.attribute("Usage").value();
          if (usage == "Input")
            v.direction = model::VarDirection::Input;
          else if (usage == "Output")
            v.direction = model::VarDirection::Output;
          else if (!usage.empty() && usage != "Local" && usage != "Public") {
            ctx_.error(
                t, "unsupported: program parameter '" + v.name + "' with Usage '" + usage + "'");
            continue;
          }
        }
        initial_value(t, v);
      }
      if (pou.find_variable(v.name)) {
        ctx_.error(t, "duplicate tag '" + v.name + "'");
        continue;
      }
      pou.variables.push_back(std::move(v));
    }
  }

  // `Local:1:I.Data.4`: bit 4 of an input module's data, a Boolean input; `:O.` an output.
  bool io_alias(pugi::xml_node t, model::Variable& v, bool global) {
    const std::string alias = trim(t.attribute("AliasFor").value());
    const bool in = alias.find(":I.") != std::string::npos;
    const bool out = alias.find(":O.") != std::string::npos;
    const auto dot = alias.rfind('.');
    const bool bit =
        dot != std::string::npos && dot + 1 < alias.size() &&
        std::all_of(alias.begin() + static_cast<std::ptrdiff_t>(dot + 1), alias.end(),
                    [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    if ((in == out) || !bit || global) {
      ctx_.error(
          t, "unsupported: alias tag '" + v.name + "' for '" + alias +
                 (global ? "' in the controller's tags" : "'") +
                 " (program tags aliasing one bit of a module's input or output data are read)");
      return false;
    }
    v.type = model::Type::boolean();
    v.direction = in ? model::VarDirection::Input : model::VarDirection::Output;
    return true;
  }

  void initial_value(pugi::xml_node t, model::Variable& v) {
    for (auto d : children(t, "Data")) {
      if (std::string_view(d.attribute("Format").value()) != "Decorated") continue;
      const auto dv = child(d, "DataValue");
      if (!dv) continue;
      const std::string text = trim(dv.attribute("Value").value());
      const auto value = plcopen::parse_int_literal(text);
      if (!value.value) {
        ctx_.error(dv, "tag '" + v.name + "': initial value '" + text + "' not read");
        return;
      }
      if (*value.value < v.type.lo || *value.value > v.type.hi) {
        ctx_.error(dv, "tag '" + v.name + "': initial value " + text + " out of the range of " +
                           v.type.name);
        return;
      }
      v.initial = *value.value;
    }
  }

  XmlContext& ctx_;
  model::Project& project_;
};

}  // namespace

LoadResult load_l5x(std::string_view text, const std::string& file, const model::Budget* budget) {
  model::Project project;
  project.source_format = "rockwell-l5x";
  project.dialect = model::Dialect::Iec61131;
  project.where.file = file;
  model::Diagnostics diags;
  {
    XmlContext ctx(file, text, diags, budget);
    pugi::xml_document doc;
    if (plcopen::load_document(doc, text, ctx))
      L5xReader(ctx, project).read(doc.document_element());
  }
  bool program = false;
  for (const auto& pou : project.pous) program = program || pou.has_sfc() || pou.body_unsupported;
  if (!program && !model::has_errors(diags))
    diags.push_back({model::Severity::Error, project.where, "no program with a routine read"});
  if (project.name.empty() && !project.pous.empty()) project.name = project.pous.back().name;
  if (!model::has_errors(diags)) model::lower_data_types(project, diags);
  LoadResult r;
  if (!model::has_errors(diags)) r.project = std::move(project);
  r.diagnostics = std::move(diags);
  return r;
}

}  // namespace sfcv::io
