// AGRAFE's XMI (.grafcet) files: the IEC 60848 meta-model of Project-AGRAFE/GRAFCET-meta-model
// (packages grafcet and terms). Attributes left out of a file take the meta-model's defaults,
// as EMF does: variableDeclarationType input, initial/activationLink false, BooleanConstant
// false, IntegerConstant 0, storedActionType activation, forcingOrderType currentSituation.

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "io/g7_lexicon.hpp"
#include "io/load.hpp"
#include "model/literal.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"

namespace sfcv::io {

namespace {

using model::ExprKind;
using model::ExprPtr;
using model::SourceLocation;

/// IEC 61131-3 INT: the default range of AGRAFE's unbounded output and internal integers.
constexpr std::int64_t kIntLo = -32768;
constexpr std::int64_t kIntHi = 32767;

struct Failure {
  pugi::xml_node at;
  std::string message;
};

std::string_view local_name(std::string_view qualified) {
  const auto colon = qualified.find(':');
  return colon == std::string_view::npos ? qualified : qualified.substr(colon + 1);
}

/// The xsi:type of a node without its package prefix ("grafcet:Step" -> "Step").
std::string_view type_of(pugi::xml_node n) {
  return local_name(n.attribute("xsi:type").value());
}

struct StepInfo {
  int chart = -1;
  std::string name;
  int index = -1;  ///< in its chart's steps
};

class Reader {
 public:
  Reader(std::string_view text, std::string file, model::Diagnostics& diags,
         const model::Budget* budget)
      : text_(text), file_(std::move(file)), diags_(diags), poll_(budget, 1024) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < text_.size(); ++i)
      if (text_[i] == '\n') line_starts_.push_back(i + 1);
  }

  std::optional<model::Project> run() {
    const auto parsed = doc_.load_buffer(text_.data(), text_.size(),
                                         pugi::parse_default | pugi::parse_ws_pcdata_single);
    if (!parsed) {
      SourceLocation l =
          at_offset(static_cast<std::size_t>(std::max<std::ptrdiff_t>(parsed.offset, 0)));
      diags_.push_back(
          {model::Severity::Error, l, std::string("XML error: ") + parsed.description()});
      return std::nullopt;
    }
    root_ = doc_.document_element();
    if (local_name(root_.name()) != "Grafcet") {
      error(root_, "not an AGRAFE grafcet: the root element is <" + std::string(root_.name()) +
                       ">, expected <grafcet:Grafcet>");
      return std::nullopt;
    }
    model::Project project;
    project.dialect = model::Dialect::Grafcet;
    project.source_format = "agrafe-xmi";
    project.name = root_.attribute("name") ? root_.attribute("name").value()
                                           : std::filesystem::path(file_).stem().string();
    if (project.name.empty()) project.name = "grafcet";
    project.where = where(root_);
    pou_.name = project.name;
    pou_.kind = model::PouKind::Program;
    pou_.where = project.where;
    try {
      check_name(root_, project.name, "grafcet name");
      read_variables();
      read_charts();
    } catch (const Failure& f) {
      error(f.at, f.message);
    }
    if (model::has_errors(diags_)) return std::nullopt;
    project.pous.push_back(std::move(pou_));
    return project;
  }

 private:
  // ---- locations
  SourceLocation at_offset(std::size_t offset) const {
    SourceLocation l;
    l.file = file_;
    const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
    const auto line = static_cast<std::size_t>(it - line_starts_.begin());
    l.line = static_cast<int>(line);
    l.column = static_cast<int>(offset - line_starts_[line - 1] + 1);
    return l;
  }
  /// The XMI path of a node, as the file's own references write it: //@partialGrafcets.0/@steps.2
  std::string xmi_path(pugi::xml_node n) const {
    std::vector<std::string> segments;  // innermost first; joined once (linear in the depth)
    for (; n && n != root_ && n.type() == pugi::node_element; n = n.parent()) {
      const auto& pos = sibling_positions(n.parent());
      const int index = pos.index.at(n.internal_object());
      const int count = pos.count.at(n.name());
      // EMF numbers the elements of many-valued features even when there is one.
      static const std::set<std::string_view> kMany{
          "partialGrafcets",      "steps",  "transitions", "synchronizations",
          "macrosteps",           "arcs",   "actionTypes", "actionLinks",
          "variableDeclarations", "subterm"};
      std::string seg = "@" + std::string(n.name());
      if (count > 1 || kMany.count(n.name())) seg += "." + std::to_string(index);
      segments.push_back(std::move(seg));
    }
    std::string path = "/";
    for (auto it = segments.rbegin(); it != segments.rend(); ++it) path += "/" + *it;
    return path;
  }
  /// The children of one element: each one's index among its same-named siblings (from 0),
  /// and how many share each name; counted once per parent, since a partial grafcet has
  /// thousands of steps and each one's path needs its index.
  struct SiblingPositions {
    std::unordered_map<const void*, int> index;
    std::unordered_map<std::string, int> count;
    std::unordered_map<std::string, std::vector<pugi::xml_node>> by_name;  ///< for references
  };
  const SiblingPositions& sibling_positions(pugi::xml_node parent) const {
    auto [it, fresh] = siblings_.try_emplace(parent.internal_object());
    if (fresh)
      for (auto s = parent.first_child(); s; s = s.next_sibling())
        if (s.type() == pugi::node_element) {
          it->second.index[s.internal_object()] = it->second.count[s.name()]++;
          it->second.by_name[s.name()].push_back(s);
        }
    return it->second;
  }
  SourceLocation where(pugi::xml_node n) const {
    // pugixml gives the offset of the element's name; the element starts at its '<'.
    auto offset = static_cast<std::size_t>(std::max<std::ptrdiff_t>(n.offset_debug(), 0));
    if (offset > 0 && offset <= text_.size() && text_[offset - 1] == '<') --offset;
    SourceLocation l = at_offset(offset);
    l.element_path = n == root_ ? "/" : xmi_path(n);
    return l;
  }
  void error(pugi::xml_node n, std::string message) {
    diags_.push_back({model::Severity::Error, where(n), std::move(message)});
  }
  void warn(pugi::xml_node n, model::Severity s, std::string message) {
    diags_.push_back({s, where(n), std::move(message)});
  }

  /// Resolves one XMI reference ("//@a.0/@b.3/@c") from the root; fails when it leads nowhere.
  pugi::xml_node resolve(pugi::xml_node from, std::string_view ref) const {
    if (ref.substr(0, 2) != "//")
      throw Failure{from, "unsupported reference '" + std::string(ref) + "'"};
    pugi::xml_node n = root_;
    std::size_t i = 2;
    while (i < ref.size()) {
      std::size_t j = ref.find('/', i);
      if (j == std::string_view::npos) j = ref.size();
      std::string_view seg = ref.substr(i, j - i);
      if (seg.empty() || seg[0] != '@')
        throw Failure{from, "malformed reference '" + std::string(ref) + "'"};
      seg.remove_prefix(1);
      std::size_t index = 0;
      const auto dot = seg.find('.');
      std::string child(seg.substr(0, dot));
      if (dot != std::string_view::npos) {
        const std::string digits(seg.substr(dot + 1));
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos)
          throw Failure{from, "malformed reference '" + std::string(ref) + "'"};
        // std::stoul would throw out_of_range (an internal error) past 64 bits.
        if (digits.size() > 9)
          throw Failure{from, "reference '" + std::string(ref) + "' leads to no element"};
        index = std::stoul(digits);
      }
      const auto& named = sibling_positions(n).by_name;
      const auto found = named.find(child);
      const pugi::xml_node c = found != named.end() && index < found->second.size()
                                   ? found->second[index]
                                   : pugi::xml_node();
      if (!c) throw Failure{from, "reference '" + std::string(ref) + "' leads to no element"};
      n = c;
      i = j + 1;
    }
    return n;
  }
  std::vector<pugi::xml_node> resolve_list(pugi::xml_node from, const char* attr) const {
    std::vector<pugi::xml_node> out;
    const std::string v = from.attribute(attr).value();
    std::size_t i = 0;
    while (i < v.size()) {
      const std::size_t j = std::min(v.find(' ', i), v.size());
      if (j > i) out.push_back(resolve(from, std::string_view(v).substr(i, j - i)));
      i = j + 1;
    }
    return out;
  }

  /// Names go into located diagnostics and into .g7 text: no control characters.
  static void check_name(pugi::xml_node n, const std::string& name, const char* what) {
    for (char c : name)
      if (static_cast<unsigned char>(c) < 0x20 || c == '\x7F')
        throw Failure{n, std::string(what) + " contains a control character"};
  }

  // ---- variables
  struct Delay {
    std::int64_t t1;
    std::string step_var;
    std::int64_t t2;
  };

  /// "2s/X202", "500ms/X3/1s": a duration (unit s when left out), '/', X and a step name, and
  /// optionally '/' and a second duration. Spaces are allowed around the parts.
  /// A name of that shape whose duration cannot be read sets `why`.
  static std::optional<Delay> delay_name(std::string_view s, std::string* why = nullptr) {
    std::size_t i = 0;
    auto spaces = [&] {
      while (i < s.size() && s[i] == ' ') ++i;
    };
    // The one checked conversion (model/literal.hpp) reads each number; a delay's shape with a
    // duration past TIME's range is an error (`why`), not a plain variable.
    std::string bad;
    auto duration = [&]() -> std::optional<std::int64_t> {
      spaces();
      const std::size_t b = i;
      while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
      if (i == b) return std::nullopt;
      const std::string_view digits = s.substr(b, i - b);
      std::int64_t unit_ns = 1000000000;
      for (const auto& [unit, ns] : {std::pair<std::string_view, std::int64_t>{"ms", 1000000},
                                     {"min", 60000000000},
                                     {"s", 1000000000},
                                     {"h", 3600000000000}})
        if (s.substr(i, unit.size()) == unit) {
          unit_ns = ns;
          i += unit.size();
          break;
        }
      spaces();
      model::DurationLiteral d(digits);
      const auto ms = d.add(digits, "", unit_ns) ? d.milliseconds(false)
                                                 : model::Converted<std::int64_t>{{}, d.error()};
      if (!ms) bad = ms.error;  // reported once the whole name has a delay's shape
      return ms.value.value_or(0);
    };
    const auto t1 = duration();
    if (!t1 || i >= s.size() || s[i] != '/') return std::nullopt;
    ++i;
    spaces();
    if (i >= s.size() || s[i] != 'X') return std::nullopt;
    const std::size_t b = ++i;
    while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_')) ++i;
    if (i == b) return std::nullopt;
    Delay d{*t1, "X" + std::string(s.substr(b, i - b)), 0};
    spaces();
    if (i < s.size() && s[i] == '/') {
      ++i;
      const auto t2 = duration();
      if (!t2) return std::nullopt;
      d.t2 = *t2;
    }
    if (i != s.size()) return std::nullopt;
    if (!bad.empty()) {
      if (why) *why = bad;
      return std::nullopt;
    }
    return d;
  }

  void read_variables() {
    for (auto decl : root_.child("variableDeclarationContainer").children("variableDeclarations")) {
      const std::string name = decl.attribute("name").value();
      const std::string kind = decl.attribute("variableDeclarationType")
                                   ? decl.attribute("variableDeclarationType").value()
                                   : "input";
      const std::string_view sort = type_of(decl.child("sort"));
      if (name.empty()) throw Failure{decl, "variable declaration without a name"};
      check_name(decl, name, "variable name");
      if (kind == "step") {
        if (!decl.attribute("step"))
          throw Failure{decl, "step variable '" + name + "' names no step"};
        step_vars_[decl] = resolve(decl, decl.attribute("step").value());
        continue;
      }
      if (kind == "internal" && sort == "Bool") {
        std::string why;
        const auto d = delay_name(name, &why);
        if (!d && !why.empty())
          throw Failure{decl, "internal variable '" + name + "' names a delay: " + why};
        if (d) {
          // AGRAFE has no delay term; models write the delay t1/Xi/t2 as an internal variable
          // of that name, which nothing assigns. Its intended meaning is the IEC 60848 delay.
          warn(decl, model::Severity::Warning,
               "internal variable '" + name + "' is read as the delay " + g7::duration(d->t1) +
                   "/" + d->step_var + "/" + g7::duration(d->t2) + " (AGRAFE has no delay term)");
          delay_vars_[decl] = std::move(*d);
          continue;
        }
      }
      model::Variable v;
      v.name = name;
      v.where = where(decl);
      if (kind == "input")
        v.direction = model::VarDirection::Input;
      else if (kind == "output")
        v.direction = model::VarDirection::Output;
      else if (kind == "internal")
        v.direction = model::VarDirection::Local;
      else
        throw Failure{decl, "unknown variableDeclarationType '" + kind + "'"};
      if (sort == "Bool") {
        v.type = model::Type::boolean();
      } else if (sort == "Integer") {
        // AGRAFE gives no bounds. Outputs and internal variables take INT's range, the type
        // AGRAFE's own code generator declares them with, so that a situation overflows only
        // where the file's arithmetic does; inputs keep 0..255, since a computed-with integer
        // input is enumerated value by value (docs/semantics.md 2.9).
        const bool input = kind == "input";
        const std::int64_t lo = input ? g7::kDefaultIntLo : kIntLo;
        const std::int64_t hi = input ? g7::kDefaultIntHi : kIntHi;
        v.type = model::Type::integer(g7::range_type_name(lo, hi), lo, hi);
        warn(decl, model::Severity::Note,
             "integer variable '" + name + "' has no bounds in AGRAFE: range " +
                 std::to_string(lo) + ".." + std::to_string(hi) + " assumed" +
                 (input ? "" : " (INT, as AGRAFE's generated code declares it)"));
      } else {
        throw Failure{decl,
                      "variable '" + name + "' has unsupported sort '" + std::string(sort) + "'"};
      }
      if (pou_.find_variable(name))
        throw Failure{decl, "variable '" + name + "' is declared twice"};
      var_names_[decl] = name;
      if (!decl.attribute("variableDeclarationType")) implicit_inputs_.insert(name);
      pou_.variables.push_back(std::move(v));
    }
  }

  // ---- charts

  void read_charts() {
    // Pass 1: charts and their steps, so that references between charts resolve.
    std::vector<pugi::xml_node> charts;
    int index = 0;
    for (auto pg : root_.children("partialGrafcets")) {
      const std::string_view t = type_of(pg);
      if (t != "PartialGrafcet" && t != "MacrostepExpansion" && !t.empty())
        throw Failure{pg, "unsupported partial grafcet type '" + std::string(t) + "'"};
      model::Chart c;
      c.name = pg.attribute("name") ? pg.attribute("name").value() : "";
      if (c.name.empty()) c.name = "G" + std::to_string(index);
      check_name(pg, c.name, "partial grafcet name");
      if (pou_.find_chart(c.name)) {
        const std::string renamed = c.name + "_" + std::to_string(index);
        warn(pg, model::Severity::Warning,
             "partial grafcet name '" + c.name + "' is used twice: this one is named '" + renamed +
                 "'");
        c.name = renamed;
      }
      c.where = where(pg);
      chart_of_[pg] = static_cast<int>(pou_.charts.size());
      pou_.charts.push_back(std::move(c));
      charts.push_back(pg);
      ++index;
    }
    for (auto pg : charts) read_steps(pg);
    for (auto pg : charts) read_enclosures(pg);
    for (auto pg : charts) read_transitions(pg);
    for (auto pg : charts) read_actions(pg);
    for (const auto& c : pou_.charts)
      for (const auto& s : c.steps)
        if (s.kind == model::StepKind::Enclosing && s.enclosed.empty())
          diags_.push_back(
              {model::Severity::Warning, s.where,
               "enclosing step '" + s.name + "' of '" + c.name + "' encloses no partial grafcet"});
  }

  model::Chart& chart(pugi::xml_node pg) {
    return pou_.charts[static_cast<std::size_t>(chart_of_.at(pg))];
  }

  void add_step(pugi::xml_node pg, pugi::xml_node n, model::Step s) {
    s.name = n.attribute("id").value();
    if (s.name.empty()) throw Failure{n, "step without an id"};
    check_name(n, s.name, "step id");
    s.initial = n.attribute("initial").as_bool(false);
    s.activation_link = n.attribute("activationLink").as_bool(false);
    s.where = where(n);
    model::Chart& c = chart(pg);
    const std::string upper = model::to_upper(s.name);
    if (!step_names_.insert({chart_of_.at(pg), upper}).second)
      throw Failure{n,
                    "step id '" + s.name + "' is used twice in partial grafcet '" + c.name + "'"};
    ++charts_with_step_[upper];
    steps_[n] = {chart_of_.at(pg), s.name, static_cast<int>(c.steps.size())};
    c.steps.push_back(std::move(s));
  }

  void read_steps(pugi::xml_node pg) {
    for (auto n : pg.children("steps")) {
      poll_.tick_or_throw("reading the model");
      const std::string_view t = type_of(n);
      model::Step s;
      if (t == "EnclosingStep")
        s.kind = model::StepKind::Enclosing;
      else if (t != "Step" && !t.empty())
        throw Failure{n, "unsupported step type '" + std::string(t) + "'"};
      add_step(pg, n, std::move(s));
    }
    if (auto e = pg.child("entryStep")) {
      add_step(pg, e, {});
      chart(pg).macro_entry = chart(pg).steps.back().name;
    }
    if (auto e = pg.child("exitStep")) {
      add_step(pg, e, {});
      chart(pg).macro_exit = chart(pg).steps.back().name;
    }
    for (auto n : pg.children("macrosteps")) {
      model::Step s;
      s.kind = model::StepKind::MacroStep;
      if (!n.attribute("expansion")) throw Failure{n, "macro-step without an expansion"};
      const auto e = resolve(n, n.attribute("expansion").value());
      if (!chart_of_.count(e) || type_of(e) != "MacrostepExpansion")
        throw Failure{n, "the expansion of a macro-step must be a MacrostepExpansion"};
      s.expansion = chart(e).name;
      add_step(pg, n, std::move(s));
    }
  }

  void read_enclosures(pugi::xml_node pg) {
    auto enclose = [&](pugi::xml_node step_node, pugi::xml_node enclosed, pugi::xml_node at) {
      const auto it = steps_.find(step_node);
      if (it == steps_.end() || type_of(step_node) != "EnclosingStep")
        throw Failure{at, "the enclosing step reference does not lead to an EnclosingStep"};
      if (!chart_of_.count(enclosed))
        throw Failure{at, "an enclosing step must enclose partial grafcets"};
      auto& c = pou_.charts[static_cast<std::size_t>(it->second.chart)];
      auto& s = c.steps[static_cast<std::size_t>(it->second.index)];
      const std::string& name = chart(enclosed).name;
      if (std::find(s.enclosed.begin(), s.enclosed.end(), name) == s.enclosed.end())
        s.enclosed.push_back(name);
    };
    for (auto n : pg.children("steps"))
      if (type_of(n) == "EnclosingStep")
        for (auto enclosed : resolve_list(n, "partialGrafcets")) enclose(n, enclosed, n);
    if (pg.attribute("enclosingStep"))
      enclose(resolve(pg, pg.attribute("enclosingStep").value()), pg, pg);
  }

  void read_transitions(pugi::xml_node pg) {
    model::Chart& c = chart(pg);
    std::set<pugi::xml_node> syncs;
    for (auto s : pg.children("synchronizations")) syncs.insert(s);
    std::map<pugi::xml_node, int> transitions;
    std::unordered_set<std::string> transition_ids;
    for (const auto& other : c.transitions) transition_ids.insert(model::to_upper(other.name));
    for (auto t : pg.children("transitions")) {
      poll_.tick_or_throw("reading the model");
      model::Transition tr;
      if (!t.attribute("id")) throw Failure{t, "transition without an id"};
      tr.name = t.attribute("id").value();
      check_name(t, tr.name, "transition id");
      tr.where = where(t);
      tr.order = static_cast<int>(c.transitions.size());
      ExprPtr guard =
          t.child("term") ? condition(t.child("term")) : model::make_bool(true, tr.where);
      tr.guard = timed(t, guard, {});
      if (!transition_ids.insert(model::to_upper(tr.name)).second) {
        // AGRAFE's own test inputs (conflictingActions9) copy a transition with its id. Arcs
        // name transitions by position, so the two are distinct: the copy gets its own name.
        std::string renamed = tr.name + "_2";
        for (int k = 3; !transition_ids.insert(model::to_upper(renamed)).second; ++k)
          renamed = tr.name + "_" + std::to_string(k);
        warn(t, model::Severity::Warning,
             "transition id '" + tr.name + "' is used twice in partial grafcet '" + c.name +
                 "': this one is named '" + renamed + "'");
        tr.name = renamed;
      }
      transitions[t] = static_cast<int>(c.transitions.size());
      c.transitions.push_back(std::move(tr));
    }
    // Arcs: step -> transition, transition -> step, and through AND bars (synchronizations):
    // steps -> bar -> transition (convergence), transition -> bar -> steps (divergence).
    enum class Kind { Step, Transition, Sync };
    auto kind_of = [&](pugi::xml_node n, pugi::xml_node arc) {
      if (n.parent() != pg)
        throw Failure{arc, "the arc leaves its partial grafcet '" + c.name + "'"};
      if (steps_.count(n)) return Kind::Step;
      if (transitions.count(n)) return Kind::Transition;
      if (syncs.count(n)) return Kind::Sync;
      throw Failure{arc,
                    "an arc ends at an element that is no step, transition or synchronization"};
    };
    std::vector<std::vector<int>> up(c.transitions.size()), down(c.transitions.size());
    std::map<pugi::xml_node, std::vector<int>> sync_in_steps, sync_out_steps;
    std::map<pugi::xml_node, std::vector<int>> sync_in_trans, sync_out_trans;
    for (auto arc : pg.children("arcs")) {
      poll_.tick_or_throw("reading the model");
      if (!arc.attribute("source") || !arc.attribute("target"))
        throw Failure{arc, "arc without a source or a target"};
      const auto s = resolve(arc, arc.attribute("source").value());
      const auto t = resolve(arc, arc.attribute("target").value());
      const Kind ks = kind_of(s, arc), kt = kind_of(t, arc);
      auto step_index = [&](pugi::xml_node n) { return steps_.at(n).index; };
      if (ks == Kind::Step && kt == Kind::Transition)
        up[transitions.at(t)].push_back(step_index(s));
      else if (ks == Kind::Transition && kt == Kind::Step)
        down[transitions.at(s)].push_back(step_index(t));
      else if (ks == Kind::Step && kt == Kind::Sync)
        sync_in_steps[t].push_back(step_index(s));
      else if (ks == Kind::Sync && kt == Kind::Transition)
        sync_out_trans[s].push_back(transitions.at(t));
      else if (ks == Kind::Transition && kt == Kind::Sync)
        sync_in_trans[t].push_back(transitions.at(s));
      else if (ks == Kind::Sync && kt == Kind::Step)
        sync_out_steps[s].push_back(step_index(t));
      else
        throw Failure{
            arc, "an arc must join a step and a transition, possibly through a synchronization"};
    }
    for (const auto& [sync, trs] : sync_out_trans)
      for (int tr : trs)
        for (int st : sync_in_steps[sync]) up[static_cast<std::size_t>(tr)].push_back(st);
    for (const auto& [sync, trs] : sync_in_trans)
      for (int tr : trs)
        for (int st : sync_out_steps[sync]) down[static_cast<std::size_t>(tr)].push_back(st);
    int sync_index = 0;
    for (auto s : pg.children("synchronizations")) {
      const bool steps_in = !sync_in_steps[s].empty(), steps_out = !sync_out_steps[s].empty();
      const bool trans_in = !sync_in_trans[s].empty(), trans_out = !sync_out_trans[s].empty();
      ++sync_index;
      if (steps_in && steps_out && !trans_in && !trans_out) {
        // AGRAFE's own test inputs (stepReachability4) draw steps -> bar -> steps with no
        // transition: read as a transition whose receptivity is always true (IEC 60848 "=1"),
        // the only transition such a bar can stand for.
        model::Transition tr;
        tr.name = "sync" + std::to_string(sync_index);
        while (!transition_ids.insert(model::to_upper(tr.name)).second) tr.name += "_";
        tr.where = where(s);
        tr.order = static_cast<int>(c.transitions.size());
        tr.guard = model::make_bool(true, tr.where);
        warn(s, model::Severity::Warning,
             "a synchronization joins steps to steps with no transition: read as transition '" +
                 tr.name + "' with receptivity =1 (always true)");
        up.push_back(sync_in_steps[s]);
        down.push_back(sync_out_steps[s]);
        c.transitions.push_back(std::move(tr));
        continue;
      }
      if ((steps_in && steps_out) || (trans_in && trans_out) || (steps_in && trans_in))
        throw Failure{
            s, "a synchronization joins either steps to transitions or transitions to steps"};
    }
    for (std::size_t i = 0; i < c.transitions.size(); ++i) {
      auto names = [&](std::vector<int> idx) {
        std::sort(idx.begin(), idx.end());
        idx.erase(std::unique(idx.begin(), idx.end()), idx.end());
        std::vector<std::string> out;
        for (int k : idx) out.push_back(c.steps[static_cast<std::size_t>(k)].name);
        return out;
      };
      auto& tr = c.transitions[i];
      tr.sources = names(up[i]);
      tr.targets = names(down[i]);
      if (tr.sources.empty())
        diags_.push_back({model::Severity::Note, tr.where,
                          "transition " + tr.name + " of '" + c.name +
                              "' is a source transition (no upstream step)"});
      if (tr.targets.empty())
        diags_.push_back({model::Severity::Note, tr.where,
                          "transition " + tr.name + " of '" + c.name +
                              "' is a sink transition (no downstream step)"});
    }
  }

  // ---- actions
  void read_actions(pugi::xml_node pg) {
    model::Chart& c = chart(pg);
    for (auto link : pg.children("actionLinks")) {
      poll_.tick_or_throw("reading the model");
      if (!link.attribute("step")) throw Failure{link, "action link without a step"};
      if (!link.attribute("actionType")) {
        // AGRAFE's conflictingActions7/9/10: a link that names no action associates nothing.
        warn(link, model::Severity::Warning, "action link without an action: ignored");
        continue;
      }
      const auto step_node = resolve(link, link.attribute("step").value());
      const auto act = resolve(link, link.attribute("actionType").value());
      const auto it = steps_.find(step_node);
      if (it == steps_.end()) throw Failure{link, "the action link's step is not a step"};
      if (it->second.chart != chart_of_.at(pg))
        throw Failure{link, "the action link's step belongs to another partial grafcet"};
      const std::string& step = it->second.name;
      const std::string_view t = type_of(act);
      if (t == "ContinuousAction") {
        const std::string var = assigned_variable(act, false);
        model::ActionAssociation a;
        a.chart = c.name;
        a.step = step;
        a.action = var;
        a.qualifier = model::Qualifier::N;
        a.where = where(act);
        ExprPtr cond = act.child("term") ? condition(act.child("term")) : nullptr;
        a.condition = timed(act, cond, "X" + step);
        if (!pou_.find_action(var)) {
          model::Action action;
          action.name = var;
          action.kind = model::ActionBodyKind::Variable;
          action.variable = var;
          action.where = a.where;
          pou_.actions.push_back(std::move(action));
        }
        pou_.associations.push_back(std::move(a));
      } else if (t == "StoredAction") {
        model::StoredAction sa;
        sa.chart = c.name;
        sa.step = step;
        sa.where = where(act);
        sa.variable = assigned_variable(act, true);
        const std::string when = act.attribute("storedActionType")
                                     ? act.attribute("storedActionType").value()
                                     : "activation";
        if (when == "activation")
          sa.when = model::StoredWhen::Activation;
        else if (when == "deactivation")
          sa.when = model::StoredWhen::Deactivation;
        else if (when == "event")
          sa.when = model::StoredWhen::Event;
        else
          throw Failure{act, "unknown storedActionType '" + when + "'"};
        if (sa.when == model::StoredWhen::Event) {
          if (!act.child("term"))
            throw Failure{act, "a stored action on event needs its event term"};
          sa.event = condition(act.child("term"));
        }
        if (!act.child("value")) throw Failure{act, "stored action without a value"};
        sa.value = term(act.child("value"));
        if (pou_.find_variable(sa.variable)->type.kind == model::TypeKind::Bool)
          sa.value = as_condition(sa.value, act.child("value"));
        pou_.stored_actions.push_back(std::move(sa));
      } else if (t == "ForcingOrder") {
        model::ForcingOrder fo;
        fo.chart = c.name;
        fo.step = step;
        fo.where = where(act);
        if (!act.attribute("partialGrafcet"))
          throw Failure{act, "forcing order without a partial grafcet"};
        const auto target = resolve(act, act.attribute("partialGrafcet").value());
        if (!chart_of_.count(target))
          throw Failure{act, "the forced element is not a partial grafcet"};
        fo.target = chart(target).name;
        const std::string kind = act.attribute("forcingOrderType")
                                     ? act.attribute("forcingOrderType").value()
                                     : "currentSituation";
        const auto forced = resolve_list(act, "forcedSteps");
        if (kind == "currentSituation")
          fo.kind = model::ForcingKind::Current;
        else if (kind == "emptySituation")
          fo.kind = model::ForcingKind::Empty;
        else if (kind == "initialSituation")
          fo.kind = model::ForcingKind::Initial;
        else if (kind == "explicitSituation")
          fo.kind = model::ForcingKind::Situation;
        else
          throw Failure{act, "unknown forcingOrderType '" + kind + "'"};
        if (fo.kind == model::ForcingKind::Situation) {
          for (auto s : forced) {
            const auto st = steps_.find(s);
            if (st == steps_.end() || st->second.chart != chart_of_.at(target))
              throw Failure{act, "a forced step is not a step of '" + fo.target + "'"};
            fo.situation.push_back(st->second.name);
          }
        } else if (!forced.empty()) {
          warn(act, model::Severity::Warning,
               "forcing order on '" + fo.target +
                   "' lists forced steps but its forcingOrderType is " + kind +
                   (act.attribute("forcingOrderType") ? "" : " (the meta-model's default)") +
                   ": the steps are ignored, as AGRAFE does; read as " + fo.target +
                   (fo.kind == model::ForcingKind::Current ? "{*}"
                    : fo.kind == model::ForcingKind::Empty ? "{}"
                                                           : "{INIT}"));
        }
        pou_.forcing_orders.push_back(std::move(fo));
      } else {
        throw Failure{act, "unsupported action type '" + std::string(t) + "'"};
      }
    }
  }

  std::string assigned_variable(pugi::xml_node act, bool stored) {
    const auto v = act.child("variable");
    if (!v || !v.attribute("variableDeclaration")) throw Failure{act, "action without a variable"};
    const auto decl = resolve(v, v.attribute("variableDeclaration").value());
    const auto it = var_names_.find(decl);
    if (it == var_names_.end()) throw Failure{v, "an action assigns a step variable or a delay"};
    model::Variable* var = nullptr;
    for (auto& x : pou_.variables)
      if (x.name == it->second) var = &x;
    if (var->direction == model::VarDirection::Input && implicit_inputs_.count(var->name)) {
      // The declaration left its type out (input by default), yet actions assign it: the
      // designer meant an output (continuous action) or an internal variable (stored action).
      var->direction = stored ? model::VarDirection::Local : model::VarDirection::Output;
      implicit_inputs_.erase(var->name);
      warn(decl, model::Severity::Warning,
           "variable '" + var->name +
               "' has no variableDeclarationType (input by default) but an "
               "action assigns it: read as " +
               (stored ? "internal" : "output"));
    }
    if (var->direction == model::VarDirection::Input)
      throw Failure{v, "an action assigns the input '" + var->name + "'"};
    if (!stored && var->type.kind != model::TypeKind::Bool)
      throw Failure{v, "the continuous action '" + var->name + "' needs a Boolean variable"};
    return var->name;
  }

  /// A duration attribute (a whole number of `unit_ns`; 0 when absent, XMI's default) in ms,
  /// through the one checked conversion: past TIME's range is an error.
  static std::int64_t duration_attribute(pugi::xml_node n, const char* name, std::int64_t unit_ns) {
    const std::string written = n.attribute(name).value();
    if (written.empty()) return 0;
    model::DurationLiteral d(std::string(name) + " " + written);
    const auto ms = d.add(written, "", unit_ns) ? d.milliseconds(false)
                                                : model::Converted<std::int64_t>{{}, d.error()};
    if (!ms) throw Failure{n, ms.error};
    return *ms;
  }

  /// The TimeCondition of a transition or continuous action: time-delayed and time-dependent
  /// conditions become the delay t1/e/t2 of `e` (the term, else the step variable).
  ExprPtr timed(pugi::xml_node n, ExprPtr e, const std::string& step_var) {
    const std::string type = n.attribute("timeConditionType").value();
    if (type.empty() || type == "none") return e;
    if (type != "timeDelayed" && type != "timeDependent")
      throw Failure{n, "unsupported time condition '" + type + "' (time-limited actions)"};
    const std::string unit = n.attribute("unit") ? n.attribute("unit").value() : "s";
    std::int64_t unit_ns = 0;
    for (const auto& [names, ns] : {std::pair<std::set<std::string>, std::int64_t>{
                                        {"ms", "millisecond", "milliseconds"}, 1000000},
                                    {{"s", "second", "seconds"}, 1000000000},
                                    {{"min", "minute", "minutes"}, 60000000000},
                                    {{"h", "hour", "hours"}, 3600000000000}})
      if (names.count(unit)) unit_ns = ns;
    if (unit_ns == 0) throw Failure{n, "unknown time unit '" + unit + "'"};
    const std::int64_t t1 = duration_attribute(n, "delayTime", unit_ns);
    const std::int64_t t2 = duration_attribute(n, "resetTime", unit_ns);
    if (!e && step_var.empty()) throw Failure{n, "a time condition needs a term"};
    return model::make_delay(t1, e ? e : model::make_name(step_var, where(n)), t2, where(n));
  }

  // ---- terms
  ExprPtr condition(pugi::xml_node n) { return as_condition(term(n), n); }

  /// Integer constants 0 and 1 where a Boolean is expected.
  ExprPtr as_condition(const ExprPtr& e, pugi::xml_node n) {
    if (e->kind != ExprKind::IntConst) return e;
    if (e->value != 0 && e->value != 1) throw Failure{n, "an integer is used as a condition"};
    return model::make_bool(e->value == 1, e->where);
  }

  ExprPtr term(pugi::xml_node n) {
    const model::NestingLevel level(term_depth_);
    if (level.too_deep())
      throw Failure{n, "term nested deeper than " + std::to_string(model::kMaxNesting) + " levels"};
    poll_.tick_or_throw("reading the model");
    const std::string_view t = type_of(n);
    const SourceLocation at = where(n);
    std::vector<ExprPtr> args;
    for (auto s : n.children("subterm")) args.push_back(term(s));
    auto arity = [&](std::size_t k) {
      if (args.size() != k)
        throw Failure{n, std::string(t) + " takes " + std::to_string(k) + " subterm(s), found " +
                             std::to_string(args.size())};
    };
    if (t == "Variable") return variable(n);
    if (t == "BooleanConstant") return model::make_bool(n.attribute("value").as_bool(false), at);
    if (t == "IntegerConstant") {
      // Absent: XMI's default 0. Otherwise the one checked conversion (no wrap-around, no
      // text read as 0).
      const std::string written = n.attribute("value").value();
      if (written.empty()) return model::make_int(0, at);
      const auto v = model::integer_literal(written);
      if (!v) throw Failure{n, "IntegerConstant: " + v.error};
      return model::make_int(*v, at);
    }
    if (t == "And" || t == "Or") {
      if (args.size() < 2) throw Failure{n, std::string(t) + " takes at least 2 subterms"};
      for (std::size_t i = 0; i < args.size(); ++i) args[i] = as_condition(args[i], n);
      return model::make_nary(t == "And" ? ExprKind::And : ExprKind::Or, std::move(args), at);
    }
    if (t == "Not" || t == "RisingEdge" || t == "FallingEdge") {
      arity(1);
      const ExprKind k = t == "Not"          ? ExprKind::Not
                         : t == "RisingEdge" ? ExprKind::Rising
                                             : ExprKind::Falling;
      return model::make_unary(k, as_condition(args[0], n), at);
    }
    static const std::pair<std::string_view, ExprKind> kBinary[] = {
        {"Equality", ExprKind::Eq},
        {"LessThan", ExprKind::Lt},
        {"GreaterThan", ExprKind::Gt},
        {"Addition", ExprKind::Add},
        {"Substraction", ExprKind::Sub}};
    for (const auto& [name, kind] : kBinary) {
      if (t == name) {
        arity(2);
        return model::make_binary(kind, args[0], args[1], at);
      }
    }
    throw Failure{n, "unsupported term type '" + std::string(t) + "'"};
  }

  ExprPtr variable(pugi::xml_node n) {
    if (!n.attribute("variableDeclaration"))
      throw Failure{n, "variable term without a declaration"};
    const auto decl = resolve(n, n.attribute("variableDeclaration").value());
    const SourceLocation at = where(n);
    if (auto it = var_names_.find(decl); it != var_names_.end())
      return model::make_name(it->second, at);
    if (auto it = delay_vars_.find(decl); it != delay_vars_.end()) {
      check_step_variable(n, it->second.step_var.substr(1));
      return model::make_delay(it->second.t1, model::make_name(it->second.step_var, at),
                               it->second.t2, at);
    }
    if (auto it = step_vars_.find(decl); it != step_vars_.end()) {
      const auto st = steps_.find(it->second);
      if (st == steps_.end()) throw Failure{decl, "step variable refers to no step"};
      check_step_variable(n, st->second.name);
      return model::make_name("X" + st->second.name, at);
    }
    throw Failure{n, "the variable term refers to no variable declaration"};
  }

  /// Step variables are written X<step name> in the IR; the name must then be unambiguous.
  void check_step_variable(pugi::xml_node n, const std::string& step) {
    const auto it = charts_with_step_.find(model::to_upper(step));
    const int found = it == charts_with_step_.end() ? 0 : it->second;
    if (found == 0) throw Failure{n, "step variable X" + step + " refers to no step"};
    if (found > 1)
      throw Failure{n, "step variable X" + step +
                           " is ambiguous: several partial grafcets have a step " + step};
    if (pou_.find_variable("X" + step))
      throw Failure{n, "step variable X" + step + " clashes with a declared variable of that name"};
  }

  std::string_view text_;
  std::string file_;
  model::Diagnostics& diags_;
  std::vector<std::size_t> line_starts_;
  pugi::xml_document doc_;
  int term_depth_ = 0;      ///< nesting of term() (model::kMaxNesting)
  model::BudgetPoll poll_;  ///< the run's deadline, polled once per element read
  mutable std::unordered_map<const void*, SiblingPositions> siblings_;  ///< by parent
  pugi::xml_node root_;
  model::Pou pou_;
  std::map<pugi::xml_node, std::string> var_names_;
  std::set<std::string> implicit_inputs_;  ///< declared without variableDeclarationType
  std::map<pugi::xml_node, pugi::xml_node> step_vars_;
  std::map<pugi::xml_node, Delay> delay_vars_;
  std::map<pugi::xml_node, int> chart_of_;
  std::map<pugi::xml_node, StepInfo> steps_;
  /// (chart, upper-cased step name) of every step read, and per upper-cased step name the
  /// number of charts that have it: no linear search per step or step variable.
  std::set<std::pair<int, std::string>> step_names_;
  std::unordered_map<std::string, int> charts_with_step_;
};

}  // namespace

LoadResult load_agrafe_xmi(std::string_view text, const std::string& file,
                           const model::Budget* budget) {
  LoadResult r;
  r.project = Reader(text, file, r.diagnostics, budget).run();
  return r;
}

}  // namespace sfcv::io
