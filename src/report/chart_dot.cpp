#include "report/chart_dot.hpp"

#include <map>
#include <string>

#include "logic/standard_checks.hpp"
#include "model/expr.hpp"
#include "model/names.hpp"
#include "report/markup.hpp"

namespace sfcv::report {

namespace {

std::string qualifier_text(const model::ActionAssociation& a) {
  std::string q(model::to_string(a.qualifier));
  if (a.duration_ms) q += ", T#" + std::to_string(*a.duration_ms) + "ms";
  if (!a.duration_variable.empty()) q += ", " + a.duration_variable;
  return q;
}

class ChartPrinter {
 public:
  ChartPrinter(std::ostream& out, bool grafcet) : out_(out), grafcet_(grafcet) {}

  void pou(std::size_t pou_index, const model::Pou& pou) {
    for (std::size_t c = 0; c < pou.charts.size(); ++c) {
      const auto& chart = pou.charts[c];
      const std::string prefix = "p" + std::to_string(pou_index) + "c" + std::to_string(c);
      // A Grafcet partial grafcet is named after itself (G1, G2), not after the project.
      const std::string title =
          grafcet_ && !chart.name.empty()
              ? chart.name
              : pou.name + (chart.parent_action.empty() ? std::string()
                                                        : " / action " + chart.parent_action);
      out_ << "  subgraph cluster_" << prefix << " {\n    label=\"" << dot_escape(title)
           << "\";\n    style=rounded;\n";
      for (std::size_t s = 0; s < chart.steps.size(); ++s) step(pou, chart, prefix, s);
      for (std::size_t t = 0; t < chart.transitions.size(); ++t) transition(chart, prefix, t);
      out_ << "  }\n";
    }
    // Nested charts hang off the action that holds them.
    for (std::size_t c = 0; c < pou.charts.size(); ++c) {
      const auto& chart = pou.charts[c];
      if (chart.parent_action.empty() || chart.steps.empty()) continue;
      for (const auto& [node, action] : action_nodes_)
        if (action == pou.name + "/" + chart.parent_action)
          out_ << "  " << node << " -> p" << pou_index << "c" << c
               << "s0 [style=dashed, arrowhead=odot, lhead=cluster_p" << pou_index << "c" << c
               << "];\n";
    }
  }

 private:
  void step(const model::Pou& pou, const model::Chart& chart, const std::string& prefix,
            std::size_t s) {
    const auto& st = chart.steps[s];
    const std::string id = prefix + "s" + std::to_string(s);
    // id= survives into the SVG (<g id="p0c0s3" class="node step">): the HTML report's player
    // highlights steps through it.
    out_ << "    " << id << " [id=\"" << id << "\", class=\"step\", shape=box, label=\""
         << dot_escape(st.name) << "\"" << (st.initial ? ", peripheries=2" : "")
         << (st.kind == model::StepKind::MacroStep ? ", style=\"dashed\"" : "")
         << (st.kind == model::StepKind::Enclosing ? ", style=\"rounded\"" : "") << "];\n";
    // Action blocks: one table of (qualifier | action) rows beside the step.
    std::string rows;
    for (const auto& a : pou.associations)
      if (a.step == st.name && (a.chart.empty() || a.chart == chart.name))
        rows += "<tr><td>" + html_escape(qualifier_text(a)) + "</td><td>" + html_escape(a.action) +
                (a.condition ? " if " + html_escape(model::to_st(a.condition)) : "") + "</td></tr>";
    for (const auto& sa : pou.stored_actions)
      if (sa.step == st.name && (sa.chart.empty() || sa.chart == chart.name)) {
        const char* when = sa.when == model::StoredWhen::Activation     ? "&#8593;"
                           : sa.when == model::StoredWhen::Deactivation ? "&#8595;"
                                                                        : "event";
        rows += "<tr><td>" + std::string(when) + "</td><td>" + html_escape(sa.variable) +
                " := " + html_escape(model::to_st(sa.value)) + "</td></tr>";
      }
    for (const auto& f : pou.forcing_orders)
      if (f.step == st.name && (f.chart.empty() || f.chart == chart.name)) {
        std::string what = f.kind == model::ForcingKind::Current   ? "*"
                           : f.kind == model::ForcingKind::Initial ? "INIT"
                                                                   : "";
        for (std::size_t i = 0; i < f.situation.size(); ++i)
          what += (i ? "," : "") + f.situation[i];
        rows +=
            "<tr><td>F</td><td>G" + html_escape(f.target) + "{" + html_escape(what) + "}</td></tr>";
      }
    if (!rows.empty()) {
      const std::string actions = id + "a";
      out_ << "    " << actions
           << " [shape=plaintext, label=<<table border=\"0\" cellborder=\"1\" "
              "cellspacing=\"0\">"
           << rows << "</table>>];\n    { rank=same; " << id << "; " << actions << "; }\n    " << id
           << " -> " << actions << " [arrowhead=none];\n";
      for (const auto& a : pou.associations)
        if (a.step == st.name && (a.chart.empty() || a.chart == chart.name))
          action_nodes_.emplace_back(actions, pou.name + "/" + a.action);
    }
  }

  void transition(const model::Chart& chart, const std::string& prefix, std::size_t t) {
    const auto& tr = chart.transitions[t];
    const std::string id = prefix + "t" + std::to_string(t);
    std::string label = model::to_st(tr.guard);
    if (tr.priority) label = "(" + std::to_string(*tr.priority) + ") " + label;
    if (!tr.name.empty()) label = tr.name + ": " + label;
    // The bar and its guard in one node (an HTML table: the bar cell is the port the edges
    // meet): the layout then reserves room for the guard, so that guards never overlap, which
    // external labels (xlabel) placed after the layout did.
    out_ << "    " << id << " [id=\"" << id
         << "\", class=\"transition\", shape=plain, label=<<table border=\"0\" cellborder=\"0\" "
            "cellspacing=\"0\" cellpadding=\"0\"><tr><td port=\"bar\" width=\"36\" height=\"4\" "
            "fixedsize=\"true\" bgcolor=\"black\"></td><td align=\"left\"> "
         << html_escape(label) << "</td></tr></table>>];\n";
    // Simultaneous convergence / divergence: a double bar between the steps and the transition.
    std::string from = id + ":bar", to = id + ":bar";
    if (tr.sources.size() > 1) {
      from = id + "join";
      out_ << "    " << from
           << " [shape=box, style=filled, fillcolor=white, peripheries=2, height=0.02, "
              "width=1.0, label=\"\"];\n    "
           << from << " -> " << id << ":bar [arrowhead=none];\n";
    }
    if (tr.targets.size() > 1) {
      to = id + "fork";
      out_ << "    " << to
           << " [shape=box, style=filled, fillcolor=white, peripheries=2, height=0.02, "
              "width=1.0, label=\"\"];\n    "
           << id << ":bar -> " << to << " [arrowhead=none];\n";
    }
    for (const auto& s : tr.sources) {
      const int i = chart.step_index(s);
      if (i >= 0) out_ << "    " << prefix << "s" << i << " -> " << from << " [arrowhead=none];\n";
    }
    for (const auto& s : tr.targets) {
      const int i = chart.step_index(s);
      if (i >= 0) out_ << "    " << to << " -> " << prefix << "s" << i << ";\n";
    }
  }

  std::ostream& out_;
  bool grafcet_;
  std::vector<std::pair<std::string, std::string>> action_nodes_;
};

}  // namespace

ChartNodeIds chart_node_ids(const model::Project& project, const semantics::TransitionSystem& ts) {
  ChartNodeIds ids;
  auto node = [](std::size_t p, std::size_t c, char kind, std::size_t i) {
    return "p" + std::to_string(p) + "c" + std::to_string(c) + kind + std::to_string(i);
  };
  auto find_chart = [&](const std::string& pou, const std::string& chart) -> std::pair<int, int> {
    for (std::size_t p = 0; p < project.pous.size(); ++p) {
      if (!model::iequals(project.pous[p].name, pou)) continue;
      for (std::size_t c = 0; c < project.pous[p].charts.size(); ++c)
        if (model::iequals(project.pous[p].charts[c].name, chart))
          return {static_cast<int>(p), static_cast<int>(c)};
    }
    return {-1, -1};
  };
  for (const auto& ref : logic::step_refs(ts, &project)) {
    const auto [p, c] = find_chart(ref.pou, ref.chart);
    if (p < 0) continue;
    const int s = project.pous[p].charts[c].step_index(ref.step);
    if (s >= 0) ids.steps[ts.observables()[ref.observable].name] = node(p, c, 's', s);
  }
  // A compiled transition is the chart's transition written at the same place; without a
  // location, the n-th one compiled from a chart is its n-th transition.
  std::map<std::pair<int, int>, std::size_t> seen;
  for (const auto& info : ts.transitions()) {
    const auto [p, c] = find_chart(info.pou, info.chart);
    if (p < 0) continue;
    const auto& chart = project.pous[p].charts[c];
    const auto ordinal = seen[{p, c}]++;
    std::size_t found = ordinal;
    for (std::size_t t = 0; t < chart.transitions.size(); ++t) {
      const auto& w = chart.transitions[t].where;
      if (info.where.known() && w.file == info.where.file && w.line == info.where.line &&
          w.column == info.where.column && w.element_path == info.where.element_path)
        found = t;
    }
    if (found < chart.transitions.size()) ids.transitions[info.name] = node(p, c, 't', found);
  }
  return ids;
}

void print_chart_dot(std::ostream& out, const model::Project& project) {
  out << "digraph \"" << dot_escape(project.name.empty() ? "chart" : project.name)
      << "\" {\n  compound=true;\n  rankdir=TB;\n  node [fontname=\"Helvetica\", "
         "fontsize=11];\n  edge [fontname=\"Helvetica\", fontsize=10];\n";
  ChartPrinter printer(out, project.dialect == model::Dialect::Grafcet);
  for (std::size_t p = 0; p < project.pous.size(); ++p)
    if (project.pous[p].has_sfc()) printer.pou(p, project.pous[p]);
  out << "}\n";
}

}  // namespace sfcv::report
