// Rockwell Studio 5000 `.L5X` exports (RSLogix5000Content): programs with an SFC or RLL main
// routine.
//
// A program is a POU; its tags are its variables (controller tags: a global list, as TwinCAT's
// GVLs). An SFC routine (`<Routine Type="SFC"><SFCContent>`) is not a sequence in document
// order but a graph: Step, Transition and Branch elements (a Branch is Selection or
// Simultaneous, Diverge or Converge, with Legs) joined by `DirectedLink FromID ToID`. Each
// transition's sources and targets are read through the branches around it. Conditions and
// action bodies are ST, one `<Line>` per line, read with the ST parser at their place in the
// file; `[:=]` assigns (its tag starting at 0) and a step's `.DN` leaving it is `.T >= PRE`
// (docs/semantics.md 1.15). What the model cannot say (qualifiers other than NonStored, Boolean
// actions, the other step timer and status bits, JSR in ST, Stop elements, user priorities, SFC
// execution options other than the modelled ones) is refused with the element path. An RLL main
// routine is read with the RLL routines it calls by JSR (io/l5x_ladder.hpp): a TIMER tag that TON
// runs is an IEC TON instance, an integer tag the rungs use only bit by bit
// (`X.3`) is one BOOL per bit used (`X_3`), and S:FS is S_FS, TRUE in the first scan only; of
// tags of a user type and arrays, each part the rungs use is a variable (io/l5x_tags.hpp).
// ST/FBD main routines load as not modelled (refused when run).

#include <algorithm>
#include <bit>
#include <cctype>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <vector>

#include "io/l5x_ladder.hpp"
#include "io/l5x_tags.hpp"
#include "io/load.hpp"
#include "io/plcopen_st.hpp"
#include "io/plcopen_xml_dom.hpp"
#include "io/st_names.hpp"
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
  /// `step_presets`: the PRE (ms) of the program's SFC_STEP tags, by upper-case name.
  SfcRoutineReader(XmlContext& ctx, model::Pou& pou, model::Chart& chart,
                   const std::map<std::string, std::int64_t>& step_presets)
      : ctx_(ctx), pou_(pou), chart_(chart), step_presets_(step_presets) {}

  /// The tags the actions assign with `[:=]`, as written.
  const std::set<std::string>& non_retentive_targets() const { return non_retentive_; }

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
    auto text = st_content(st, ctx_);
    if (!rockwell_text_ok(st, text.text, nullptr)) return;
    non_retentive_assignments(text.text);
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

  // Rockwell ST the model has no meaning for, refused by name before parsing: JSR, and members
  // of the chart's SFC_STEP / SFC_ACTION tags other than a step's `.X` (its activity, as IEC
  // 61131-3's S.X) and, in a condition of a transition leaving the step (`leaving`), its `.DN`.
  bool rockwell_text_ok(pugi::xml_node where, const std::string& text,
                        const std::vector<std::string>* leaving) {
    bool ok = true;
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
        const bool done_bit_read =
            step && member == "DN" && leaving &&
            std::any_of(leaving->begin(), leaving->end(),
                        [&](const std::string& s) { return model::iequals(s, word); }) &&
            step_presets_.count(word) > 0 && preset_expressions_.count(word) == 0;
        if (step && member == "DN" && !done_bit_read) {
          ctx_.error(where, "unsupported: '" + text.substr(i, m - i) +
                                "' (a step's DN is read in the conditions of the transitions "
                                "leaving it, with the PRE of its SFC_STEP tag: " +
                                (step_presets_.count(word) > 0 && !preset_expressions_.count(word)
                                     ? "this condition does not leave the step"
                                     : "the step has no constant PRE") +
                                ")");
          ok = false;
        } else if ((step && member != "X" && !done_bit_read) || action_operands_.count(word)) {
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
      r.t.guard = condition(n.node, r.t.name, r.t.sources);
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

  model::ExprPtr condition(pugi::xml_node e, const std::string& name,
                           const std::vector<std::string>& sources) {
    const auto st = child(child(e, "Condition"), "STContent");
    if (!st) {
      ctx_.error(e, "unsupported: transition '" + name + "' without an ST condition");
      return nullptr;
    }
    auto text = st_content(st, ctx_);
    if (!rockwell_text_ok(st, text.text, &sources)) return nullptr;
    // A condition may end with `;`.
    auto end = text.text.find_last_not_of(" \t\r\n");
    if (end != std::string::npos && text.text[end] == ';') text.text[end] = ' ';
    if (trim(text.text).empty()) {
      ctx_.error(st, "transition '" + name + "' has an empty condition");
      return nullptr;
    }
    return with_step_done_bits(plcopen::parse_expression_text(text, ctx_.diagnostics()));
  }

  // `S.DN` (SFC_STEP's done bit: on once the step has been active for its preset PRE, kept
  // after the step is left until it is entered again, 1756-PM006) in a condition of a
  // transition leaving S, where S is active: `S.T >= PRE`.
  model::ExprPtr with_step_done_bits(const model::ExprPtr& e) const {
    if (!e) return e;
    if (e->kind == model::ExprKind::Member && model::iequals(e->member, "DN")) {
      const auto pre = step_presets_.find(model::to_upper(e->name));
      if (pre != step_presets_.end())
        return model::make_binary(model::ExprKind::Ge, model::make_member(e->name, "T", e->where),
                                  model::make_time(pre->second, e->where), e->where);
    }
    bool changed = false;
    std::vector<model::ExprPtr> args;
    for (const auto& a : e->args) {
      args.push_back(with_step_done_bits(a));
      changed = changed || args.back() != a;
    }
    if (!changed) return e;
    auto copy = std::make_shared<model::Expr>(*e);
    copy->args = std::move(args);
    return copy;
  }

  // `tag [:=] value`: Studio 5000's non-retentive assignment. With SFCLastScan DontScan (the
  // only option read) it assigns as `:=`; the tag is reset to 0 when the controller enters Run
  // (the model's initial state), which the caller applies to the targets collected here.
  void non_retentive_assignments(std::string& text) {
    for (auto at = text.find("[:=]"); at != std::string::npos; at = text.find("[:=]", at)) {
      auto end = at;
      while (end > 0 && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
      auto begin = end;
      while (begin > 0 && (is_st_identifier_char(text[begin - 1]) || text[begin - 1] == '.'))
        --begin;
      if (begin < end) non_retentive_.insert(text.substr(begin, end - begin));
      text.replace(at, 4, "  :=");  // the same width: later columns stay right
    }
  }

 public:
  /// The chart's SFC_STEP and SFC_ACTION operands (upper case), known before any text is read.
  void operands(pugi::xml_node content) {
    for (auto s : children(content, "Step")) {
      step_operands_.insert(model::to_upper(trim(s.attribute("Operand").value())));
      if (is_true(s, "PresetUsesExpr"))  // the preset is an expression, not the tag's PRE
        preset_expressions_.insert(model::to_upper(trim(s.attribute("Operand").value())));
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
  const std::map<std::string, std::int64_t>& step_presets_;
  std::set<std::string> non_retentive_;
  std::set<std::string> preset_expressions_;  ///< steps whose preset is an expression
};

// A program whose main routine is RLL: the routines it calls by JSR, as ST statements
// (io/l5x_ladder.hpp), with the tags the rungs need in the form the model has.
class LadderProgram : public l5x::RungOperands {
 public:
  /// Where the parts of structured tags the rungs use are declared: the program's in its POU,
  /// the controller's in `globals`, each once for every program (`global_split`: whether a
  /// controller tag's integer part is read bit by bit, so that two programs read it alike).
  struct StructuredTags {
    const l5x::TagTypes* types = nullptr;
    const std::map<std::string, l5x::StructuredTag>* program = nullptr;
    const std::map<std::string, l5x::StructuredTag>* controller = nullptr;
    model::Pou* globals = nullptr;
    std::map<std::string, bool>* global_split = nullptr;
    const std::set<std::string>* consumed = nullptr;  ///< consumed tags that are not structured
  };

  LadderProgram(XmlContext& ctx, model::Pou& pou,
                const std::map<std::string, pugi::xml_node>& timer_tags, StructuredTags structured)
      : ctx_(ctx), pou_(pou), timer_tags_(timer_tags), structured_(structured) {}

  void read(pugi::xml_node program, pugi::xml_node main) {
    test_edits_ = is_true(program, "TestEdits");
    for (auto r : children(child(program, "Routines"), "Routine"))
      routines_.emplace(trim(r.attribute("Name").value()), r);
    const std::string main_name = trim(main.attribute("Name").value());
    parse(main_name, 0);
    for (const auto& [name, r] : routines_)
      if (!parsed_.count(name))
        ctx_.note(r, "routine '" + name + "' (" + r.attribute("Type").value() +
                         ") is not called from the main routine '" + main_name + "': not read");
    if (model::has_errors(ctx_.diagnostics())) return;
    declare_tags();
    if (model::has_errors(ctx_.diagnostics())) return;
    std::string error;
    auto body = subroutine(main_name, error);
    if (!body) {
      if (!error.empty() || !model::has_errors(ctx_.diagnostics()))
        ctx_.error(main, error.empty() ? "main routine '" + main_name + "' not read" : error);
      return;
    }
    // The temporaries hold nothing from one scan to the next (a state they kept would
    // multiply the states), and S:FS is TRUE in the first scan only.
    for (const auto& t : temporaries_) {
      declare_bool(t, false);
      body->push_back(model::make_assign(t, model::make_bool(false, pou_.where), pou_.where));
    }
    if (first_scan_)
      body->push_back(
          model::make_assign(kFirstScan, model::make_bool(false, pou_.where), pou_.where));
    pou_.body = std::move(*body);
  }

  model::ExprPtr bit(const std::string& operand, std::string& error) override {
    if (model::iequals(operand, "S:FS")) return model::make_name(kFirstScan, at_);
    bool structured = false;
    if (const auto ix = indexed_of(operand, error, structured); ix)
      return chosen(*ix, error, [&](const std::string& o) { return bit(o, error); });
    if (!error.empty()) return nullptr;
    if (const auto leaf = leaf_of(operand, error, structured); structured) {
      if (!leaf) return nullptr;
      if (leaf->kind == l5x::LeafKind::Timer) {
        const auto t = timers_.find(model::to_upper(leaf->path));
        if (t != timers_.end()) return timer_bit(t->second.first, leaf->rest, operand, error);
        error = "TIMER '" + leaf->path + "' is not run by a TON: its bits are not read";
        return nullptr;
      }
      const auto name = leaf_bit(*leaf, operand, error);
      return name.empty() ? nullptr : model::make_name(name, at_);
    }
    if (!plain_operand(operand, error)) return nullptr;
    const auto dot = operand.find('.');
    if (dot == std::string::npos) return model::make_name(operand, at_);
    const std::string base = operand.substr(0, dot), member = operand.substr(dot + 1);
    const auto key = model::to_upper(base);
    if (auto b = split_bit(key, member)) return model::make_name(*b, at_);
    if (timers_.count(key) > 0) return timer_bit(base, member, operand, error);
    return model::make_member(base, member, at_);
  }

  std::string bit_target(const std::string& operand, std::string& error) override {
    if (consumed_write(operand, error)) return {};
    bool structured = false;
    if (const auto leaf = leaf_of(operand, error, structured); structured)
      return leaf ? leaf_bit(*leaf, operand, error) : std::string();
    if (!plain_operand(operand, error)) return {};
    const auto dot = operand.find('.');
    if (dot == std::string::npos) return operand;
    if (auto b = split_bit(model::to_upper(operand.substr(0, dot)), operand.substr(dot + 1)))
      return *b;
    error = "unsupported: writing '" + operand +
            "' (a bit of an integer tag is written when the rungs use that tag only bit by bit)";
    return {};
  }

  model::ExprPtr value(const std::string& operand, std::string& error) override {
    if (const auto v = plcopen::parse_int_literal(operand); v.value)
      return model::make_int(*v.value, at_);
    bool structured = false;
    if (const auto ix = indexed_of(operand, error, structured); ix)
      return chosen(*ix, error, [&](const std::string& o) { return value(o, error); });
    if (!error.empty()) return nullptr;
    const auto leaf = leaf_of(operand, error, structured);
    // A preset reads as the constant it is: no rung writes one (value_target refuses that).
    if (structured && leaf && model::iequals(leaf->rest, "PRE")) {
      if (leaf->kind == l5x::LeafKind::Counter)
        return model::make_int(counters_.at(model::to_upper(leaf->path)).preset, at_);
      if (leaf->kind == l5x::LeafKind::Timer) {
        if (const auto t = timers_.find(model::to_upper(leaf->path)); t != timers_.end())
          return model::make_int(t->second.second, at_);
        error = "TIMER '" + leaf->path + "' is not run by a TON: its preset is not read";
        return nullptr;
      }
    }
    error.clear();
    const auto name = integer_name(operand, error);
    return name.empty() ? nullptr : model::make_name(name, at_);
  }

  std::string value_target(const std::string& operand, std::string& error) override {
    if (consumed_write(operand, error)) return {};
    return integer_name(operand, error);
  }

  // The integer variable an operand names, read or written.
  std::string integer_name(const std::string& operand, std::string& error) {
    bool structured = false;
    if (const auto leaf = leaf_of(operand, error, structured); structured) {
      if (!leaf) return {};
      if (leaf->kind == l5x::LeafKind::Int && leaf->rest.empty()) return leaf->variable;
      if (leaf->kind == l5x::LeafKind::Counter && model::iequals(leaf->rest, "ACC"))
        return counters_.at(model::to_upper(leaf->path)).accumulated;
      error = (leaf->kind == l5x::LeafKind::Timer || leaf->kind == l5x::LeafKind::Counter) &&
                      model::iequals(leaf->rest, "PRE")
                  ? "unsupported: writing '" + operand +
                        "' (a TIMER's or COUNTER's preset is read from its tag's data, not "
                        "written by rungs)"
                  : "unsupported: '" + operand + "' (" + leaf->type_name +
                        ") as an integer (integer tags, their integer members and elements, "
                        "and literals are)";
      return {};
    }
    if (!plain_operand(operand, error)) return {};
    if (operand.find('.') != std::string::npos || split_.count(model::to_upper(operand))) {
      error = "unsupported: '" + operand + "' as an integer (a tag or a literal is read)";
      return {};
    }
    return operand;
  }

  std::optional<std::pair<std::string, std::int64_t>> timer(const std::string& operand,
                                                            std::string& error) override {
    if (consumed_write(operand, error)) return std::nullopt;
    bool structured = false;
    std::string key = model::to_upper(operand);
    if (const auto leaf = leaf_of(operand, error, structured); structured) {
      if (!leaf) return std::nullopt;
      key = model::to_upper(leaf->path);
      if (leaf->kind != l5x::LeafKind::Timer || !leaf->rest.empty()) {
        error = "TON on '" + operand + "', which is not a TIMER (it is " + leaf->type_name + ")";
        return std::nullopt;
      }
    }
    const auto it = timers_.find(key);
    if (it == timers_.end()) {
      error = "TON on '" + operand + "', which is not a TIMER tag of the program";
      return std::nullopt;
    }
    return it->second;
  }

  // RES on a TIMER that TON runs: calling the TON with IN FALSE clears its DN, EN, TT and
  // time, as RES clears .DN, .EN, .TT and .ACC (1756-RM003, RES); the TON then times again
  // from 0 when its rung is TRUE.
  std::optional<model::StmtList> reset(const std::string& operand, std::string& error) override {
    bool structured = false;
    std::string leaf_error;  // reported by counter() or timer() below
    const auto leaf = leaf_of(operand, leaf_error, structured);
    if (structured && leaf && leaf->kind == l5x::LeafKind::Counter) {
      // RES clears the COUNTER's .ACC and status bits (1756-RM003, RES).
      const auto c = counter(operand, error);
      if (!c) return std::nullopt;
      model::StmtList out;
      out.push_back(model::make_assign(c->accumulated, model::make_int(0, at_), at_));
      for (const auto* bit : {&c->up, &c->down, &c->done})
        out.push_back(model::make_assign(*bit, model::make_bool(false, at_), at_));
      return out;
    }
    const auto t = timer(operand, error);
    if (!t) {
      const bool idle_timer = structured ? leaf && leaf->kind == l5x::LeafKind::Timer
                                         : timer_tags_.count(model::to_upper(operand)) > 0;
      error = "unsupported: RES on '" + operand +
              "' (RES of a COUNTER, or of a TIMER that a TON runs, is read" +
              (idle_timer           ? "; no TON runs this one)"
               : structured && leaf ? "; it is " + leaf->type_name + ")"
                                    : "): " + error);
      return std::nullopt;
    }
    return model::StmtList{model::make_fb_call(
        t->first, {{"IN", model::make_bool(false, at_)}, {"PT", model::make_time(t->second, at_)}},
        at_)};
  }

  std::optional<Chosen> chosen_target(const std::string& operand, bool bit,
                                      std::string& error) override {
    bool structured = false;
    const auto ix = indexed_of(operand, error, structured);
    if (!ix) return std::nullopt;
    Chosen out;
    out.index = value(ix->index, error);
    if (!out.index) return std::nullopt;
    for (const auto& element : ix->elements) {
      out.targets.push_back(bit ? bit_target(element, error) : value_target(element, error));
      if (out.targets.back().empty()) return std::nullopt;
    }
    return out;
  }

  std::optional<Counter> counter(const std::string& operand, std::string& error) override {
    if (consumed_write(operand, error)) return std::nullopt;
    bool structured = false;
    const auto leaf = leaf_of(operand, error, structured);
    if (!structured || !leaf || leaf->kind != l5x::LeafKind::Counter || !leaf->rest.empty()) {
      if (error.empty())
        error = "'" + operand + "' is not a COUNTER tag" +
                (structured && leaf ? " (it is " + leaf->type_name + ")" : std::string());
      return std::nullopt;
    }
    return counters_.at(model::to_upper(leaf->path));
  }

  std::optional<model::StmtList> subroutine(const std::string& routine,
                                            std::string& error) override {
    const auto it = parsed_.find(routine);
    if (it == parsed_.end()) {
      error = "JSR to '" + routine + "', which is not read";  // reported by parse()
      return std::nullopt;
    }
    if (std::find(calling_.begin(), calling_.end(), routine) != calling_.end()) {
      error = "recursive JSR: routine '" + routine + "' calls itself (through '" + calling_.back() +
              "')";
      return std::nullopt;
    }
    if (const auto done = translated_.find(routine); done != translated_.end()) {
      unfolded_ += done->second.second;
      if (unfolded_ > kMaxUnfoldedStatements) {
        error = "the JSR calls unfold into more than " + std::to_string(kMaxUnfoldedStatements) +
                " statements";
        return std::nullopt;
      }
      return done->second.first;
    }
    calling_.push_back(routine);
    const auto saved_at = at_;
    const auto unfolded_before = unfolded_;
    l5x::RungTranslator translator(*this, "SFCV_RLL_" + std::to_string(++translators_) + "_");
    model::StmtList body;
    bool ok = true;
    for (const auto& [rung, seq] : it->second) {
      ctx_.poll();
      at_ = ctx_.where(rung);
      std::vector<std::string> errors;
      if (!translator.translate(seq, at_, body, errors)) {
        ok = false;
        for (const auto& e : errors)
          ctx_.error(rung, "rung " + std::string(rung.attribute("Number").value()) +
                               " of routine '" + routine + "': " + e);
      }
    }
    for (const auto& t : translator.temporaries()) temporaries_.push_back(t);
    at_ = saved_at;
    calling_.pop_back();
    if (!ok) return std::nullopt;
    // A routine called from several places is translated once; its statements are shared.
    unfolded_ += body.size();
    translated_[routine] = {body, unfolded_ - unfolded_before};
    if (unfolded_ > kMaxUnfoldedStatements) {
      error = "the JSR calls unfold into more than " + std::to_string(kMaxUnfoldedStatements) +
              " statements";
      return std::nullopt;
    }
    return body;
  }

 private:
  static constexpr const char* kFirstScan = "S_FS";
  /// Statements the JSRs may unfold into (a routine called twice by each of 30 nested
  /// routines would otherwise be 2^30 copies).
  static constexpr std::size_t kMaxUnfoldedStatements = 200000;
  /// JSR nesting read (each level is a recursion of the reader).
  static constexpr int kMaxCallDepth = 64;

  // The part of a structured tag `operand` addresses; `structured` false when its tag is not one
  // (then the caller reads it as a plain tag).
  std::optional<l5x::TagLeaf> leaf_of(const std::string& operand, std::string& error,
                                      bool& structured) const {
    const auto* tag = structured_tag_of(operand);
    structured = tag != nullptr;
    if (!tag) return std::nullopt;
    return structured_.types->resolve(*tag, operand, error);
  }

  // The structured tag `operand` starts with, or null: a program tag hides a controller tag of
  // its name.
  const l5x::StructuredTag* structured_tag_of(const std::string& operand) const {
    if (!structured_.types) return nullptr;
    const auto head = model::to_upper(operand.substr(0, operand.find_first_of(".[")));
    if (const auto p = structured_.program->find(head); p != structured_.program->end())
      return &p->second;
    if (pou_.find_variable(head) || timer_tags_.count(head)) return nullptr;
    const auto c = structured_.controller->find(head);
    return c != structured_.controller->end() ? &c->second : nullptr;
  }

  // A consumed tag is written by the controller producing it, never by these rungs: it is an
  // input of the model (docs/semantics.md 1.14).
  bool consumed_write(const std::string& operand, std::string& error) const {
    const auto head = model::to_upper(operand.substr(0, operand.find_first_of(".[")));
    const auto* tag = structured_tag_of(operand);
    const bool consumed = tag ? tag->consumed
                              : structured_.consumed && structured_.consumed->count(head) &&
                                    !pou_.find_variable(head);
    if (!consumed) return false;
    error = "unsupported: writing '" + operand +
            "', a consumed tag (the controller producing it writes it; it is read as an input)";
    return true;
  }

  // `operand` with a tag for index (`Recipe.Step[Index].Heat`), in a structured tag.
  std::optional<l5x::TagTypes::Indexed> indexed_of(const std::string& operand, std::string& error,
                                                   bool& structured) const {
    const auto* tag = structured_tag_of(operand);
    structured = tag != nullptr;
    if (!tag) return std::nullopt;
    return structured_.types->indexed(*tag, operand, error);
  }

  // The element a tag chooses (`Recipe.Step[Index].Heat`), read: MUX(index, element 0, ...),
  // an index out of the array's bounds being a range error as the controller's major fault.
  // `read` reads one element.
  template <typename Read>
  model::ExprPtr chosen(const l5x::TagTypes::Indexed& ix, std::string& error, Read read) {
    std::vector<model::ExprPtr> args;
    args.push_back(value(ix.index, error));
    if (!args.back()) return nullptr;
    for (const auto& element : ix.elements) {
      args.push_back(read(element));
      if (!args.back()) return nullptr;
    }
    return model::make_call("MUX", std::move(args), at_);
  }

  // The BOOL a BOOL part, or a bit of an integer part read bit by bit, is.
  std::string leaf_bit(const l5x::TagLeaf& leaf, const std::string& operand,
                       std::string& error) const {
    if (leaf.kind == l5x::LeafKind::Bool && leaf.rest.empty()) return leaf.variable;
    if (leaf.kind == l5x::LeafKind::Counter) {
      const auto& c = counters_.at(model::to_upper(leaf.path));
      const auto m = model::to_upper(leaf.rest);
      if (m == "DN") return c.done;
      if (m == "CU") return c.up;
      if (m == "CD") return c.down;
      error =
          "unsupported: '" + operand + "' (of a COUNTER, .DN, .CU, .CD, .ACC and .PRE are read)";
      return {};
    }
    if (leaf.kind == l5x::LeafKind::Int && bit_number(leaf.rest)) {
      if (split_leaves_.count(model::to_upper(leaf.path))) return leaf.variable + "_" + leaf.rest;
      error = "unsupported: '" + operand + "' (a bit of '" + leaf.path +
              "' is read when the rungs use that element only bit by bit)";
      return {};
    }
    error = "unsupported: operand '" + operand + "' ('" + leaf.path + "' is " + leaf.type_name +
            (leaf.rest.empty() ? "" : ", '" + leaf.rest + "' of it") +
            "; BOOL parts, bits of integer parts and the .DN, .EN, .TT of TIMERs run by TON are "
            "read as Booleans)";
    return {};
  }

  model::ExprPtr timer_bit(const std::string& base, const std::string& member,
                           const std::string& operand, std::string& error) const {
    const auto m = model::to_upper(member);
    if (m == "DN") return model::make_member(base, "Q", at_);
    if (m == "EN") return model::make_member(base, "IN", at_);
    if (m == "TT")
      return model::make_nary(
          model::ExprKind::And,
          {model::make_member(base, "IN", at_),
           model::make_unary(model::ExprKind::Not, model::make_member(base, "Q", at_), at_)},
          at_);
    error = "unsupported: '" + operand + "' (of a TIMER, .DN, .EN and .TT are read)";
    return nullptr;
  }

  // An operand the model can name: no module data (`Local:1:I.Data`), no array element.
  bool plain_operand(const std::string& operand, std::string& error) const {
    if (operand.find_first_of(":[?") == std::string::npos && !operand.empty()) return true;
    error = "unsupported: operand '" + operand +
            "' (tags, their members and bits, S:FS and integer literals are read)";
    return false;
  }

  // Rung edit markers (Logix 5000 Import/Export manual, 1756-RM084): N normal; I inserted, IR
  // inserted to replace R, R replaced, D deleted, pending in the controller; lower case, pending
  // in the software only (e, er: new rungs; d, rN, rR, rI: the controller's rungs they edit).
  // The controller runs its original rungs (N, R, D) until the program's edits are tested
  // (TestEdits), then the edited ones (N, I, IR).
  bool runs(const std::string& type) const {
    if (type.empty() || type == "N" || type == "d" || type == "rN") return true;
    if (test_edits_) return type == "I" || type == "IR" || type == "rI";
    return type == "R" || type == "D" || type == "rR";
  }
  static bool pending_edit(const std::string& type) {
    for (const char* t : {"I", "IR", "R", "D", "rR", "rI", "e", "er"})
      if (type == t) return true;
    return false;
  }

  // `3` in `X.3`: the member a bit of an integer is (one or two digits).
  static bool bit_number(const std::string& member) {
    return !member.empty() && member.size() <= 2 &&
           member.find_first_not_of("0123456789") == std::string::npos;
  }

  // `X.3` of a tag read bit by bit: its BOOL.
  std::optional<std::string> split_bit(const std::string& key, const std::string& member) const {
    const auto it = split_.find(key);
    if (it == split_.end() || !bit_number(member)) return std::nullopt;
    return it->second + "_" + member;
  }

  // The routines main calls by JSR, at any depth; located errors for what is not read.
  void parse(const std::string& name, int depth) {
    const auto r = routines_.find(name)->second;
    auto& rungs = parsed_[name];
    for (auto rung : children(child(r, "RLLContent"), "Rung")) {
      ctx_.poll();
      const std::string number = rung.attribute("Number").value();
      const std::string type = rung.attribute("Type").value();
      if (!runs(type)) {
        if (!pending_edit(type))
          ctx_.error(rung, "unsupported: rung " + number + " of routine '" + name + "' of Type '" +
                               type + "'");
        else
          ctx_.note(rung, "rung " + number + " of routine '" + name + "' (Type '" + type +
                              "') is a pending edit the controller does not run with TestEdits " +
                              (test_edits_ ? "true" : "false") + ": not read");
        continue;
      }
      std::string error;
      auto seq = l5x::parse_rung(child(rung, "Text").text().get(), error);
      if (!seq) {
        ctx_.error(rung, "rung " + number + " of routine '" + name + "': " + error);
        continue;
      }
      rungs.emplace_back(rung, *seq);
      l5x::each_instruction(*seq, [&](const l5x::RungElement& e) {
        for (std::size_t i = 0; i < e.operands.size(); ++i) use(e, i);
        if (e.mnemonic != "JSR" || e.operands.empty()) return;
        const auto& callee = e.operands[0];
        const auto c = routines_.find(callee);
        if (c == routines_.end()) {
          ctx_.error(rung, "rung " + number + " of routine '" + name + "': JSR to '" + callee +
                               "', which is not in the program");
        } else if (std::string_view(c->second.attribute("Type").value()) != "RLL") {
          ctx_.error(rung, "unsupported: rung " + number + " of routine '" + name +
                               "': JSR to the " + c->second.attribute("Type").value() +
                               " routine '" + callee + "' (RLL routines are read as subroutines)");
        } else if (depth >= kMaxCallDepth) {
          ctx_.error(rung, "rung " + number + " of routine '" + name + "': JSR calls nested " +
                               "deeper than " + std::to_string(kMaxCallDepth));
        } else if (!parsed_.count(callee)) {
          parse(callee, depth + 1);
        }
      });
    }
  }

  // How the rungs use a tag: bit by bit, as a whole, or as a TON's timer.
  void use(const l5x::RungElement& e, std::size_t i) {
    const auto& operand = e.operands[i];
    if ((e.mnemonic == "JSR") || operand.empty()) return;
    if (e.mnemonic == "CPT" && i == 1) {
      for (const auto& o : l5x::compute_operands(operand)) use_operand("CPT", false, o);
      return;
    }
    use_operand(e.mnemonic, i == 0, operand);
  }

  void use_operand(const std::string& mnemonic, bool first, const std::string& operand) {
    bool structured = false;
    std::string error;  // reported where the instruction is translated
    if (const auto ix = indexed_of(operand, error, structured); structured && ix) {
      use_operand(mnemonic, false, ix->index);
      for (const auto& element : ix->elements) use_operand(mnemonic, false, element);
      return;
    }
    error.clear();
    if (const auto leaf = leaf_of(operand, error, structured); structured) {
      if (!leaf) return;
      const auto key = model::to_upper(leaf->path);
      leaves_.emplace(key, *leaf);
      if (mnemonic == "TON" && first)
        ++ton_calls_[key];
      else if (leaf->kind == l5x::LeafKind::Int && leaf->rest.empty())
        whole_.insert(key);
      else if (leaf->kind == l5x::LeafKind::Int && bit_number(leaf->rest))
        bits_[key].insert(std::stoi(leaf->rest));
      return;
    }
    if (mnemonic == "TON") {
      if (first) ++ton_calls_[model::to_upper(operand)];
      return;
    }
    const auto dot = operand.find('.');
    const auto key = model::to_upper(operand.substr(0, dot));
    if (dot != std::string::npos && bit_number(operand.substr(dot + 1)))
      bits_[key].insert(std::stoi(operand.substr(dot + 1)));
    else
      whole_.insert(key);
  }

  void declare_tags() {
    std::vector<model::Variable> vars;
    for (auto& v : pou_.variables) {
      const auto key = model::to_upper(v.name);
      const auto b = bits_.find(key);
      if (b == bits_.end() || whole_.count(key) || v.type.kind != model::TypeKind::Int) {
        vars.push_back(std::move(v));
        continue;
      }
      // Only bits of it are used: one BOOL each, as the model's engines see them best.
      const int width = static_cast<int>(std::bit_width(static_cast<std::uint64_t>(v.type.hi))) +
                        (v.type.lo < 0 ? 1 : 0);
      split_[key] = v.name;
      for (int n : b->second) {
        model::Variable bit = v;
        bit.name = v.name + "_" + std::to_string(n);
        bit.type = model::Type::boolean();
        bit.initial = v.initial ? (static_cast<std::uint64_t>(*v.initial) >> n) & 1U : 0;
        if (n >= width)
          error_at(v.where, "rungs use bit " + std::to_string(n) + " of tag '" + v.name +
                                "', which has " + std::to_string(width) + " bits");
        if (structured_.globals && structured_.globals->find_variable(bit.name))
          error_at(v.where, "the BOOL '" + bit.name +
                                "' that a bit of an integer tag is read as is already a tag of "
                                "the controller (one would hide the other)");
        vars.push_back(std::move(bit));
      }
    }
    pou_.variables = std::move(vars);
    for (const auto& [key, calls] : ton_calls_) {
      const auto t = timer_tags_.find(key);
      if (t == timer_tags_.end()) continue;  // reported where TON names it
      if (calls > 1) {
        ctx_.error(t->second, "unsupported: TON runs " + std::to_string(calls) +
                                  " times on TIMER tag '" + t->second.attribute("Name").value() +
                                  "' (one TON per TIMER is read)");
        continue;
      }
      model::Variable v;
      v.name = t->second.attribute("Name").value();
      v.where = ctx_.where(t->second);
      v.direction = model::VarDirection::Local;
      v.type = model::Type::function_block(model::StandardFb::TON);
      timers_[key] = {v.name, timer_preset(t->second)};
      pou_.variables.push_back(std::move(v));
    }
    for (const auto& [key, t] : timer_tags_)
      if (!ton_calls_.count(key))
        ctx_.note(t, "tag '" + std::string(t.attribute("Name").value()) +
                         "' of type TIMER is not run by a TON: a use of it is an error");
    declare_structured();
    first_scan_ = whole_.count("S:FS") > 0;
    std::set<std::string> names;
    for (const auto& v : pou_.variables)
      if (!names.insert(model::to_upper(v.name)).second)
        error_at(v.where, "the BOOL '" + v.name +
                              "' that a bit of an integer tag is read as is already a tag");
    if (first_scan_) {
      if (names.count(kFirstScan) > 0)
        error_at(pou_.where, std::string("S:FS is read as the BOOL ") + kFirstScan +
                                 ", which is already a tag");
      declare_bool(kFirstScan, true);
    }
  }

  // The parts of structured tags the rungs use, each a variable of the program or, for the
  // controller's tags, of the controller's list (declared once for all its programs).
  void declare_structured() {
    for (const auto& entry : leaves_) {
      // Plain names: clang 15 refuses a lambda capturing a structured binding.
      const auto& key = entry.first;
      const auto& leaf = entry.second;
      const bool global = leaf.tag->global;
      model::Pou& into = global ? *structured_.globals : pou_;
      model::Variable v;
      v.name = leaf.variable;
      v.where = ctx_.where(leaf.tag->node);
      v.direction = global ? model::VarDirection::Global : model::VarDirection::Local;
      // A part of the program's and a tag of the controller's of one name (or the other way
      // round) would hide one another: which one a rung reads would depend on the scope.
      auto hides = [&](const std::string& name) {
        const model::Pou* other = global ? &pou_ : structured_.globals;
        if (!other || !other->find_variable(name)) return false;
        error_at(v.where, "tag '" + leaf.tag->name + "': its part '" + leaf.path +
                              "' is read as '" + name + "', which is already a tag of the " +
                              (global ? "program '" + pou_.name + "'" : std::string("controller")) +
                              " (one would hide the other)");
        return true;
      };
      auto declare = [&](model::Variable var) {
        if (hides(var.name)) return;
        if (const auto* old = into.find_variable(var.name)) {
          // A controller tag's part another program declared already: the same variable.
          if (global && old->where.str() == var.where.str() && old->type.name == var.type.name)
            return;
          error_at(var.where, "tag '" + leaf.tag->name + "': its part '" + leaf.path +
                                  "' is read as '" + var.name + "', which is already a tag");
          return;
        }
        into.variables.push_back(std::move(var));
      };
      if (leaf.kind == l5x::LeafKind::Timer) {
        // The TON instance of the one program whose rungs run it, even for a controller TIMER
        // (the semantics calls instances a POU declares).
        const auto calls = ton_calls_.count(key) ? ton_calls_.at(key) : 0;
        if (global && !structured_.global_split->emplace(key, false).second) {
          error_at(v.where, "unsupported: the controller's TIMER '" + leaf.path +
                                "' is used by two programs (it is read as the TON of the one "
                                "program that runs it)");
          continue;
        }
        if (calls == 0) continue;  // a use of its bits is an error where it is read
        if (calls > 1) {
          error_at(v.where, "unsupported: TON runs " + std::to_string(calls) + " times on TIMER '" +
                                leaf.path + "' (one TON per TIMER is read)");
          continue;
        }
        const auto preset = l5x::leaf_member(leaf, "PRE");
        if (preset < 0) error_at(v.where, "TIMER '" + leaf.path + "' with a negative preset");
        v.type = model::Type::function_block(model::StandardFb::TON);
        v.direction = model::VarDirection::Local;
        timers_[key] = {v.name, preset};
        if (structured_.globals && structured_.globals->find_variable(v.name)) {
          error_at(v.where, "tag '" + leaf.tag->name + "': its part '" + leaf.path +
                                "' is read as '" + v.name +
                                "', which is already a tag of the controller (one would hide the "
                                "other)");
          continue;
        }
        if (const auto* old = pou_.find_variable(v.name)) {
          error_at(v.where, "tag '" + leaf.tag->name + "': its part '" + leaf.path +
                                "' is read as '" + v.name + "', which is already the tag at " +
                                old->where.str());
          continue;
        }
        pou_.variables.push_back(std::move(v));
        continue;
      }
      if (leaf.kind == l5x::LeafKind::Counter) {
        // .CU and .CD start set: the prescan sets them so that the first scan does not count
        // (1756-RM003, CTU and CTD).
        Counter c{v.name + "_ACC", v.name + "_CU", v.name + "_CD", v.name + "_DN",
                  l5x::leaf_member(leaf, "PRE")};
        model::Variable acc = v;
        acc.name = c.accumulated;
        acc.type = *model::elementary_type("DINT");
        acc.initial = l5x::leaf_member(leaf, "ACC");
        declare(std::move(acc));
        for (const auto* bit : {&c.up, &c.down, &c.done}) {
          model::Variable b = v;
          b.name = *bit;
          b.type = model::Type::boolean();
          b.initial = bit == &c.done ? (l5x::leaf_member(leaf, "DN") != 0 ? 1 : 0) : 1;
          declare(std::move(b));
        }
        counters_[key] = std::move(c);
        continue;
      }
      if (leaf.kind == l5x::LeafKind::Other) continue;  // refused where it is read
      const auto initial = l5x::leaf_initial(leaf);
      if (!initial) {
        error_at(v.where, "tag '" + leaf.tag->name + "': the initial value of '" + leaf.path +
                              "' is not read");
        continue;
      }
      v.type = *model::elementary_type(leaf.type_name);
      const bool split = leaf.kind == l5x::LeafKind::Int && bits_.count(key) && !whole_.count(key);
      if (global) {
        const auto [it, fresh] = structured_.global_split->emplace(key, split);
        if (!fresh && it->second != split) {
          error_at(v.where, "unsupported: '" + leaf.path +
                                "' is used bit by bit in one program and as a whole in another");
          continue;
        }
      }
      if (!split) {
        if (*initial < v.type.lo || *initial > v.type.hi)
          error_at(v.where, "tag '" + leaf.tag->name + "': initial value " +
                                std::to_string(*initial) + " of '" + leaf.path +
                                "' out of the range of " + v.type.name);
        v.initial = *initial;
        declare(std::move(v));
        continue;
      }
      split_leaves_.insert(key);
      const int width = static_cast<int>(std::bit_width(static_cast<std::uint64_t>(v.type.hi))) +
                        (v.type.lo < 0 ? 1 : 0);
      for (int n : bits_.at(key)) {
        if (n >= width) {
          error_at(v.where, "rungs use bit " + std::to_string(n) + " of '" + leaf.path +
                                "', which has " + std::to_string(width) + " bits");
          continue;
        }
        model::Variable bit = v;
        bit.name = v.name + "_" + std::to_string(n);
        bit.type = model::Type::boolean();
        bit.initial = (static_cast<std::uint64_t>(*initial) >> n) & 1U;
        declare(std::move(bit));
      }
    }
  }

  // A BOOL the reader adds to the program (a hidden temporary, S_FS), located at the program.
  void declare_bool(const std::string& name, bool initial) {
    model::Variable v;
    v.name = name;
    v.where = pou_.where;
    v.direction = model::VarDirection::Local;
    v.type = model::Type::boolean();
    v.initial = initial ? 1 : 0;
    pou_.variables.push_back(std::move(v));
  }

  // PRE of the TIMER's decorated data, in milliseconds (Logix timers count milliseconds).
  std::int64_t timer_preset(pugi::xml_node tag) {
    std::int64_t pre = 0;
    for (auto d : children(tag, "Data")) {
      if (std::string_view(d.attribute("Format").value()) != "Decorated") continue;
      for (auto m : children(child(d, "Structure"), "DataValueMember")) {
        const std::string name = m.attribute("Name").value();
        const auto v = plcopen::parse_int_literal(trim(m.attribute("Value").value()));
        if (name == "PRE" && v.value) pre = *v.value;
        if (name == "ACC" && v.value && *v.value != 0)
          ctx_.warning(m, "TIMER '" + std::string(tag.attribute("Name").value()) +
                              "': its accumulated value " + std::to_string(*v.value) +
                              " is read as 0 (an IEC TON starts from 0)");
      }
    }
    if (pre < 0) ctx_.error(tag, "TIMER with a negative preset");
    return pre;
  }

  void error_at(const model::SourceLocation& where, std::string message) {
    ctx_.diagnostics().push_back({model::Severity::Error, where, std::move(message)});
  }

  XmlContext& ctx_;
  model::Pou& pou_;
  const std::map<std::string, pugi::xml_node>& timer_tags_;
  StructuredTags structured_;
  /// Upper-case path -> the part of a structured tag the rungs use.
  std::map<std::string, l5x::TagLeaf> leaves_;
  std::set<std::string> split_leaves_;       ///< upper-case paths of integer parts read by bit
  std::map<std::string, Counter> counters_;  ///< upper-case path of a COUNTER -> its variables
  std::map<std::string, pugi::xml_node> routines_;
  std::map<std::string, std::vector<std::pair<pugi::xml_node, l5x::RungSequence>>> parsed_;
  std::map<std::string, std::set<int>> bits_;  ///< upper-case tag -> bits the rungs use
  std::set<std::string> whole_;                ///< upper-case tags used as a whole
  std::map<std::string, int> ton_calls_;       ///< upper-case TIMER tag -> TON instructions
  std::map<std::string, std::string> split_;   ///< upper-case tag -> its name, read by bit
  /// Upper-case TIMER tag that TON runs -> its name and preset (ms).
  std::map<std::string, std::pair<std::string, std::int64_t>> timers_;
  std::vector<std::string> calling_;  ///< the JSR chain being read
  /// Routine -> its statements and the statements they unfold into, JSRs included.
  std::map<std::string, std::pair<model::StmtList, std::size_t>> translated_;
  std::size_t unfolded_ = 0;
  std::vector<std::string> temporaries_;
  int translators_ = 0;
  bool first_scan_ = false;
  bool test_edits_ = false;  ///< the program's TestEdits: the controller runs its edited rungs
  model::SourceLocation at_;
};

class L5xReader {
 public:
  L5xReader(XmlContext& ctx, model::Project& project) : ctx_(ctx), project_(project) {}

  void read(pugi::xml_node root) {
    if (local_name(root) == "SFCContent") {
      ctx_.error(root,
                 "a bare <SFCContent> (one SFC routine's content, without its program, tags and "
                 "controller options) is not read: export the program from Studio 5000 "
                 "(Export Program) to an .L5X holding its tags and routines");
      return;
    }
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
    types_ = l5x::TagTypes(child(controller, "DataTypes"));
    if (const auto tags = child(controller, "Tags"); !element_children(tags).empty()) {
      model::Pou globals;
      globals.name = trim(controller.attribute("Name").value());
      globals.where = ctx_.where(controller);
      read_tags(tags, globals, true);
      project_.pous.push_back(std::move(globals));
      globals_index_ = project_.pous.size() - 1;
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
    timer_tags_.clear();
    step_presets_.clear();
    program_structured_.clear();
    read_tags(child(p, "Tags"), pou, false);
    const std::string main = trim(p.attribute("MainRoutineName").value());
    for (auto r : children(child(p, "Routines"), "Routine"))
      if (trim(r.attribute("Name").value()) == main &&
          std::string_view(r.attribute("Type").value()) == "RLL") {
        // The controller's structured tags come from its <Tags>, so its list exists.
        LadderProgram::StructuredTags structured{
            &types_,
            &program_structured_,
            &controller_structured_,
            globals_index_ ? &project_.pous[*globals_index_] : nullptr,
            &global_split_,
            &consumed_plain_};
        LadderProgram(ctx_, pou, timer_tags_, structured).read(p, r);
        project_.pous.push_back(std::move(pou));
        return;
      }
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
        // ST or FBD main routine: loads as not modelled, refused when run.
        pou.body_unsupported = true;
        pou.unsupported_language = type;
        pou.unsupported_reason = ctx_.where(r).str() + ": main routine '" + name + "' is " + type +
                                 ", which is not read (SFC and RLL main routines are)";
        ctx_.warning(r, "program '" + pou.name + "': its main routine '" + name + "' (" + type +
                            ") is not modelled; running it is refused");
      } else {
        ctx_.note(r, "routine '" + name + "' (" + type + ") is not the main routine: not read");
      }
    }
    for (const auto& [name, t] : timer_tags_)
      ctx_.note(t, "tag '" + std::string(t.attribute("Name").value()) +
                       "' of type TIMER is not modelled (a TIMER is read where an RLL rung runs "
                       "TON on it): a use of it is an error");
    for (const auto& [name, t] : program_structured_)
      ctx_.note(t.node, "tag '" + t.name + "' of type " + t.data_type +
                            (t.dimensions.empty() ? "" : " (an array)") +
                            " is read part by part in ladder routines only: a use of it here is "
                            "an error");
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
    SfcRoutineReader reader(ctx_, pou, c, step_presets_);
    reader.operands(content);
    reader.read(content);
    pou.charts.push_back(std::move(c));
    for (const auto& target : reader.non_retentive_targets()) {
      auto* v = tag_variable(pou, target);
      for (auto& other : project_.pous) {
        if (v) break;
        v = tag_variable(other, target);
        if (v && v->direction != model::VarDirection::Global) v = nullptr;
      }
      if (v && v->initial && *v->initial != 0) {
        ctx_.warning(r, "tag '" + v->name +
                            "' is assigned with [:=], which Studio 5000 resets to 0 when the "
                            "controller enters Run: its initial value " +
                            std::to_string(*v->initial) + " is read as 0");
        v->initial = 0;
      }
    }
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
      } else if (kind == "Consumed" && structured_tag(t, v.name, type, global)) {
        continue;  // read part by part, as inputs (another controller writes it)
      } else if (kind != "Base" && kind != "Produced" && kind != "Consumed") {
        ctx_.note(t,
                  "tag '" + v.name + "' (" + kind + ") is not modelled: a use of it is an error");
        continue;
      } else if (type == "SFC_STEP" || type == "SFC_ACTION" || type == "SFC_STOP") {
        if (type == "SFC_STEP") step_preset(t);
        continue;  // the chart's own: its steps and actions
      } else if (structured_tag(t, v.name, type, global)) {
        continue;  // its parts are read where rungs use them (io/l5x_tags.hpp)
      } else if (type == "TIMER" && !global && t.attribute("Dimensions").empty()) {
        // A TON instance if a rung runs TON on it (LadderProgram), else left out.
        timer_tags_[model::to_upper(v.name)] = t;
        continue;
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
        if (kind == "Consumed") consumed_plain_.insert(model::to_upper(v.name));
      }
      if (pou.find_variable(v.name)) {
        ctx_.error(t, "duplicate tag '" + v.name + "'");
        continue;
      }
      pou.variables.push_back(std::move(v));
    }
  }

  // A tag of a user type, an array of BOOL, integers, TIMERs or a user type, or a controller
  // TIMER: kept for the rungs to use by part (only a ladder program reads them).
  bool structured_tag(pugi::xml_node t, const std::string& name, const std::string& type,
                      bool global) {
    const auto dims = l5x::tag_dimensions(t.attribute("Dimensions").value());
    const auto et = model::elementary_type(type);
    const bool part_type = types_.is_user_type(type) || model::iequals(type, "TIMER") ||
                           model::iequals(type, "COUNTER") ||
                           (et && (et->kind == model::TypeKind::Bool ||
                                   (et->kind == model::TypeKind::Int && et->enumerators.empty())));
    if (!dims || !part_type) return false;
    if (dims->empty() && !types_.is_user_type(type) && !model::iequals(type, "COUNTER") &&
        !(global && model::iequals(type, "TIMER")))
      return false;
    auto& into = global ? controller_structured_ : program_structured_;
    if (into.count(model::to_upper(name))) return false;  // reported as a duplicate
    into[model::to_upper(name)] = l5x::StructuredTag{
        t,     name,   type,
        *dims, global, std::string_view(t.attribute("TagType").value()) == "Consumed"};
    return true;
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
      // A module's whole data, a structure member...: left out, as tags of other types.
      ctx_.note(t, "alias tag '" + v.name + "' for '" + alias +
                       (global ? "' in the controller's tags" : "'") +
                       " is not modelled (program tags aliasing one bit of a module's input or "
                       "output data are): a use of it is an error");
      return false;
    }
    v.type = model::Type::boolean();
    v.direction = in ? model::VarDirection::Input : model::VarDirection::Output;
    return true;
  }

  static model::Variable* tag_variable(model::Pou& pou, const std::string& name) {
    for (auto& v : pou.variables)
      if (model::iequals(v.name, name)) return &v;
    return nullptr;
  }

  // The PRE of an SFC_STEP tag's decorated data (its step's timer preset, ms).
  void step_preset(pugi::xml_node t) {
    for (auto d : children(t, "Data")) {
      if (std::string_view(d.attribute("Format").value()) != "Decorated") continue;
      for (auto m : children(child(d, "Structure"), "DataValueMember"))
        if (std::string_view(m.attribute("Name").value()) == "PRE")
          if (const auto v = plcopen::parse_int_literal(trim(m.attribute("Value").value()));
              v.value && *v.value >= 0)
            step_presets_[model::to_upper(trim(t.attribute("Name").value()))] = *v.value;
    }
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
  std::map<std::string, pugi::xml_node> timer_tags_;  ///< the program's, upper-case name
  std::map<std::string, std::int64_t> step_presets_;  ///< SFC_STEP tag (upper case) -> PRE, ms
  l5x::TagTypes types_;
  /// Structured tags (upper-case name): the program's at hand, and the controller's.
  std::map<std::string, l5x::StructuredTag> program_structured_, controller_structured_;
  std::optional<std::size_t> globals_index_;  ///< the controller's list in project_.pous
  std::map<std::string, bool> global_split_;  ///< see LadderProgram::StructuredTags
  std::set<std::string> consumed_plain_;      ///< upper-case consumed BOOL and integer tags
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
  for (const auto& pou : project.pous)
    program = program || pou.has_sfc() || pou.body_unsupported || !pou.body.empty();
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
