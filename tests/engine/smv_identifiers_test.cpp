// The NuSMV export parsed back by a small SMV reader: every identifier is declared exactly once
// (VAR, IVAR, DEFINE and property NAMEs together), every identifier an expression uses is
// declared, and every VAR gets exactly one init and one next. Charts with nested SFC actions
// once gave a nested step's ready latch and its activity output the same name (NuSMV 2.6:
// "multiple declaration of identifier"); the chemical plant and random charts with nested
// actions are checked. The Cadence SMV export shares the naming: its declarations are checked
// for uniqueness too.

#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "chart_families.hpp"
#include "engine/explicit/explicit_model_checker.hpp"
#include "engine/external/aiger_writer.hpp"
#include "engine/external/circuit_export.hpp"
#include "engine/external/export_model.hpp"
#include "engine/external/identifiers.hpp"
#include "engine/external/nusmv_runner.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "semantics/iec61131_system.hpp"
#include "support/boolean_action_chart.hpp"
#include "support/hostile_names.hpp"
#include "support/sfcv_test.hpp"

namespace sfcv::engine {
namespace {

// Identifiers and single-character punctuation (":=" as one token), comments dropped.
std::vector<std::string> smv_tokens(const std::string& text) {
  std::vector<std::string> tokens;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '-' && i + 1 < text.size() && text[i + 1] == '-') {
      i = text.find('\n', i);
      if (i == std::string::npos) break;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t j = i;
      while (j < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_'))
        ++j;
      tokens.push_back(text.substr(i, j - i));
      i = j;
    } else if (c == ':' && i + 1 < text.size() && text[i + 1] == '=') {
      tokens.emplace_back(":=");
      i += 2;
    } else {
      tokens.emplace_back(1, c);
      ++i;
    }
  }
  return tokens;
}

bool is_identifier(const std::string& t) {
  return !t.empty() && (std::isalpha(static_cast<unsigned char>(t[0])) || t[0] == '_');
}

const std::set<std::string> kSections = {"MODULE", "VAR",       "IVAR",    "DEFINE", "ASSIGN",
                                         "TRANS",  "INVARSPEC", "CTLSPEC", "INIT",   "INVAR"};
const std::set<std::string> kExpressionWords = {"TRUE", "FALSE", "EX", "AX", "EF", "AF",
                                                "EG",   "AG",    "E",  "A",  "U",  "boolean"};

struct SmvModel {
  std::map<std::string, int> declared;  ///< identifier -> number of declarations
  std::set<std::string> used;
  std::set<std::string> vars;
  std::map<std::string, int> inits, nexts;
  std::vector<std::string> problems;  ///< the reader's own complaints (unexpected tokens)
};

SmvModel read_smv(const std::string& text) {
  SmvModel m;
  const auto t = smv_tokens(text);
  std::size_t i = 0;
  auto expect = [&](const std::string& what) {
    if (i < t.size() && t[i] == what) {
      ++i;
      return true;
    }
    m.problems.push_back("expected '" + what + "' at token " + std::to_string(i) + ": '" +
                         (i < t.size() ? t[i] : "end") + "'");
    return false;
  };
  // Uses up to the next ';' (or the next section keyword).
  auto expression = [&] {
    while (i < t.size() && t[i] != ";" && !kSections.count(t[i])) {
      if (is_identifier(t[i]) && !kExpressionWords.count(t[i])) m.used.insert(t[i]);
      ++i;
    }
    if (i < t.size() && t[i] == ";") ++i;
  };
  std::string section;
  while (i < t.size()) {
    if (kSections.count(t[i])) {
      section = t[i++];
      if (section == "MODULE") {
        expect("main");
      } else if (section == "TRANS" || section == "INIT" || section == "INVAR") {
        expression();
      } else if (section == "INVARSPEC" || section == "CTLSPEC") {
        if (!expect("NAME") || i >= t.size()) break;
        ++m.declared[t[i++]];
        expect(":=");
        expression();
      }
      continue;
    }
    if (section == "VAR" || section == "IVAR") {
      const auto id = t[i++];
      ++m.declared[id];
      if (section == "VAR") m.vars.insert(id);
      expect(":");
      expect("boolean");
      expect(";");
    } else if (section == "DEFINE") {
      ++m.declared[t[i++]];
      expect(":=");
      expression();
    } else if (section == "ASSIGN") {
      const auto which = t[i++];
      if (which != "init" && which != "next") m.problems.push_back("ASSIGN of '" + which + "'");
      expect("(");
      if (i >= t.size()) break;
      const auto id = t[i++];
      m.used.insert(id);
      ++(which == "init" ? m.inits : m.nexts)[id];
      expect(")");
      expect(":=");
      expression();
    } else {
      m.problems.push_back("token '" + t[i] + "' outside a section");
      ++i;
    }
  }
  return m;
}

// Checks one export; returns the number of declared identifiers.
std::size_t expect_well_declared(const std::string& smv, const std::string& what) {
  SCOPED_TRACE(what);
  const auto m = read_smv(smv);
  for (const auto& p : m.problems) ADD_FAILURE() << p << "\n" << smv;
  for (const auto& [id, n] : m.declared) EXPECT_EQ(n, 1) << "declared " << n << " times: " << id;
  for (const auto& id : m.used) EXPECT_TRUE(m.declared.count(id)) << "used, never declared: " << id;
  for (const auto& v : m.vars) {
    EXPECT_EQ(m.inits.count(v) ? m.inits.at(v) : 0, 1) << "init of " << v;
    EXPECT_EQ(m.nexts.count(v) ? m.nexts.at(v) : 0, 1) << "next of " << v;
  }
  return m.declared.size();
}

// Cadence SMV: `x : boolean;` and `x : assert ...;` are the declarations.
void expect_casmv_declared_once(const std::string& smv, const std::string& what) {
  SCOPED_TRACE(what);
  const auto t = smv_tokens(smv);
  std::map<std::string, int> declared;
  for (std::size_t i = 0; i + 2 < t.size(); ++i)
    if (is_identifier(t[i]) && t[i + 1] == ":" && (t[i + 2] == "boolean" || t[i + 2] == "assert"))
      ++declared[t[i]];
  EXPECT_FALSE(declared.empty());
  for (const auto& [id, n] : declared) EXPECT_EQ(n, 1) << "declared " << n << " times: " << id;
}

struct Exports {
  std::string nusmv, casmv;
};

Exports export_chart(const std::string& text, const std::string& file,
                     const std::vector<std::string>& ctl) {
  auto loaded = io::load_iec_text(text, file);
  EXPECT_TRUE(loaded.ok()) << file;
  if (!loaded.ok()) return {};
  model::Diagnostics diags;
  auto ts = semantics::make_iec61131_system(*loaded.project, {}, diags);
  EXPECT_TRUE(ts) << file;
  if (!ts) return {};
  logic::CheckInputs in;
  in.ctl = ctl;
  auto parsed = logic::parse_check_inputs(in);
  logic::CheckTask task;
  logic::resolve_into(parsed.spec, *ts, task, diags);
  for (const auto& d : diags) ADD_FAILURE() << d.str();
  ExportRequest request;
  request.properties = task.properties;
  request.reachability = true;
  const auto e = build_export(*ts, request);
  std::ostringstream nusmv, casmv;
  write_nusmv(nusmv, e.model);
  write_casmv(casmv, e.model);
  return {nusmv.str(), casmv.str()};
}

TEST(SmvIdentifiers, TheReaderCatchesADoubleDeclarationAndAnUndeclaredUse) {
  const auto m = read_smv(
      "MODULE main\nIVAR\n  in_a : boolean;\nVAR\n  s_x : boolean;  -- c\nDEFINE\n"
      "  s_x := in_a & !ghost;\nASSIGN\n  init(s_x) := FALSE;\n  next(s_x) := in_a;\n"
      "INVARSPEC NAME p_q := !(s_x);\nCTLSPEC NAME p_r := AG EF s_x;\n");
  EXPECT_TRUE(m.problems.empty());
  EXPECT_EQ(m.declared.at("s_x"), 2);
  EXPECT_EQ(m.used.count("ghost"), 1u);
  EXPECT_EQ(m.declared.count("p_r"), 1u);
  EXPECT_EQ(m.nexts.at("s_x"), 1);
}

TEST(SmvIdentifiers, ChemicalPlantDeclaresEveryIdentifierOnce) {
  std::ifstream f(test::source_path("examples/chemical_plant/chemical_plant.st"));
  std::stringstream text;
  text << f.rdbuf();
  const auto e = export_chart(text.str(), "chemical_plant.st",
                              {"AG !(V1 & V3)", "AG !(V2 & V4)", "AG EF s1", "AG (s7 -> AF s1)"});
  EXPECT_GT(expect_well_declared(e.nusmv, "chemical plant"), 50u);
  expect_casmv_declared_once(e.casmv, "chemical plant");
}

TEST(SmvIdentifiers, RandomChartsWithNestedActionsDeclareEveryIdentifierOnce) {
  bench::RandomChartFeatures features;
  features.nested_chart = true;
  std::size_t nested = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto text =
        bench::random_chart_iec(8 + static_cast<std::uint32_t>(seed % 5), 3, seed, features);
    nested += text.find("ACTION Sub") != std::string::npos;
    const auto e = export_chart(text, "random.st", {"AG !(S1 & S2)", "EF S3"});
    expect_well_declared(e.nusmv, "seed " + std::to_string(seed));
    expect_casmv_declared_once(e.casmv, "seed " + std::to_string(seed));
  }
  EXPECT_GE(nested, 15u) << "too few charts had a nested action";
}

// A Boolean action of a function block instance and the variable it drives bear one name
// ("Main.Lift.Extend": the action's activity and the variable are two latches). The exports
// once gave both one identifier, declared twice (every xPPU scenario, 22 to 113 times).
TEST(SmvIdentifiers, ABooleanActionAndItsVariableAreDeclaredApart) {
  const auto e =
      export_chart(test::kCylinderChart, "cylinder.st", {"AG (Lift.Out -> Lift.Extend)"});
  const auto m = read_smv(e.nusmv);
  EXPECT_TRUE(m.vars.count("s_Main_Lift_Extend")) << e.nusmv;
  EXPECT_TRUE(m.vars.count("s_Main_Lift_Extend_2")) << e.nusmv;
  expect_well_declared(e.nusmv, "Boolean action of an instance, NuSMV");
  expect_casmv_declared_once(e.casmv, "Boolean action of an instance, Cadence SMV");
}

// Hostile names (tests/support/hostile_names.hpp) as inputs, steps and variables: every name
// reaches the export only inside a comment, so the SMV reader above sees exactly the model
// (a name's "\nINIT FALSE" once became a live INIT section), and no line of the file starts
// with what follows a line break inside a name.
struct HostileExport {
  test::HostileChart chart;
  semantics::TransitionSystemPtr ts;
  logic::CheckTask task;
  std::string nusmv, casmv, promela, aag;
};

std::unique_ptr<HostileExport> hostile_export() {
  auto h = std::make_unique<HostileExport>();
  h->chart = test::hostile_chart();
  model::Diagnostics diags;
  h->ts = semantics::make_iec61131_system(h->chart.project, {}, diags);
  EXPECT_TRUE(h->ts);
  if (!h->ts) return nullptr;
  logic::CheckInputs in;
  in.ctl = {"AG !Bad", "AG !(Start & Bad)", "AG EF Start", "EF Bad"};
  auto parsed = logic::parse_check_inputs(in);
  h->task.system = h->ts.get();
  h->task.project = &h->chart.project;
  logic::resolve_into(parsed.spec, *h->ts, h->task, diags);
  for (const auto& d : diags) ADD_FAILURE() << d.str();
  ExportRequest request;
  request.properties = h->task.properties;
  request.reachability = true;
  request.header = {"model " + test::hostile_names()[0], test::hostile_names()[1]};
  const auto e = build_export(*h->ts, request);
  std::ostringstream nusmv, casmv;
  write_nusmv(nusmv, e.model);
  write_casmv(casmv, e.model);
  h->nusmv = nusmv.str();
  h->casmv = casmv.str();
  // Promela and AIGER take invariants only.
  ExportRequest circuit_request = request;
  circuit_request.target = ExportTarget::Circuit;
  circuit_request.properties.resize(2);
  const auto c = build_export(*h->ts, circuit_request);
  std::ostringstream promela, aag;
  write_promela(promela, c.model);
  write_aiger(aag, aiger_circuit(c.model), AigerMode::Ascii, "comment\nlines");
  h->promela = promela.str();
  h->aag = aag.str();
  return h;
}

// What follows a line break in a hostile name never starts a line of `text`.
void expect_no_line_from_a_name(const std::string& text) {
  std::set<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.insert(line);
  for (const auto& name : test::hostile_names())
    for (auto nl = name.find('\n'); nl != std::string::npos; nl = name.find('\n', nl + 1)) {
      const auto rest = name.substr(nl + 1, name.find('\n', nl + 1) - nl - 1);
      if (rest.size() < 2) continue;
      for (const auto& line : lines)
        EXPECT_NE(line.rfind(rest, 0), 0u) << "a line starts with '" << rest << "' of a name";
    }
}

TEST(SmvIdentifiers, HostileNamesStayInsideComments) {
  const auto h = hostile_export();
  ASSERT_TRUE(h);
  EXPECT_GT(expect_well_declared(h->nusmv, "hostile names, NuSMV"), 40u);
  expect_casmv_declared_once(h->casmv, "hostile names, Cadence SMV");
  expect_no_line_from_a_name(h->nusmv);
  expect_no_line_from_a_name(h->casmv);
  // Lines starting with a section keyword are the writer's own: one of each at most, and
  // none of the keywords the names hold (INIT, VAR twice, MODULE twice).
  std::map<std::string, int> sections;
  std::istringstream in(h->nusmv);
  for (std::string line; std::getline(in, line);) {
    const auto word = line.substr(0, line.find_first_of(" \t"));
    if (kSections.count(word)) ++sections[word];
  }
  EXPECT_EQ(sections["MODULE"], 1);
  EXPECT_EQ(sections["VAR"], 1);
  EXPECT_EQ(sections["IVAR"], 1);
  EXPECT_EQ(sections["INIT"], 0);
  // Every hostile name is in a comment, escaped, so a reader of the file finds its chart name.
  EXPECT_NE(h->nusmv.find("-- input z\\nINIT FALSE\\nVAR --"), std::string::npos) << h->nusmv;
}

// Comment text is one line that cannot close its comment, and distinct names stay distinct.
TEST(ExportNames, CommentTextIsOneLineWithoutACloser) {
  EXPECT_EQ(comment_text("a */\n#define", CommentKind::Block), "a *\\/\\n#define");
  EXPECT_EQ(comment_text("a */\n#define"), "a */\\n#define");  // `--` ends at the line end
  EXPECT_EQ(comment_text(std::string("t\tr\r\x01\x7f", 6)), "t\\tr\\r\\x01\\x7f");
  EXPECT_NE(comment_text("a\n"), comment_text("a\\n"));   // the backslash is doubled
  EXPECT_EQ(comment_text("\xc3\xbc"), "\xc3\xbc");        // UTF-8 kept
  EXPECT_EQ(aiger_symbol("\xc3\xbc x"), "\\xc3\\xbc x");  // AIGER: printable ASCII
  IdentifierTable ids({"in_MODULE"});
  EXPECT_EQ(ids.get("in_", "MODULE"), "in_MODULE_2");  // never a reserved word
  EXPECT_EQ(ids.get("in_", "x,y"), "in_x_y");
  EXPECT_EQ(ids.get("in_", "x y"), "in_x_y_2");  // unique
}

// Promela goes through the C preprocessor: with its comments removed as cpp removes them,
// the only directives are the writer's own and every assertion is there.
TEST(ExportNames, HostileNamesStayInsidePromelaComments) {
  const auto h = hostile_export();
  ASSERT_TRUE(h);
  std::string code;
  for (std::size_t i = 0; i < h->promela.size();) {
    if (h->promela.compare(i, 2, "/*") == 0) {
      const auto end = h->promela.find("*/", i + 2);
      ASSERT_NE(end, std::string::npos) << "a comment is not closed";
      i = end + 2;
      code += ' ';
    } else {
      code += h->promela[i++];
    }
  }
  std::istringstream in(code);
  std::size_t asserts = 0;
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find_first_not_of(' ');
    if (first != std::string::npos && line[first] == '#') {
      EXPECT_EQ(line.rfind("#define sfcv_", first), first) << line;
    }
    asserts += line.find("assert(") != std::string::npos;
  }
  EXPECT_EQ(asserts, 2 + h->chart.steps.size() + 2) << "two properties, each step reachable";
  for (const char* payload : {"skip\n", "INIT FALSE", "l0 evil", "javascript:", "%s"})
    EXPECT_EQ(code.find(payload), std::string::npos) << payload << " outside a comment";
}

// AIGER: every symbol is one line of printable ASCII, and the table has exactly one line per
// input, latch, output, bad and constraint before the comment section.
TEST(ExportNames, HostileNamesGiveOneAigerSymbolLineEach) {
  const auto h = hostile_export();
  ASSERT_TRUE(h);
  std::istringstream in(h->aag);
  std::string magic;
  std::size_t m = 0, i = 0, l = 0, o = 0, a = 0, b = 0, c = 0;
  in >> magic >> m >> i >> l >> o >> a >> b >> c;
  ASSERT_EQ(magic, "aag");
  std::string line;
  std::getline(in, line);
  for (std::size_t k = 0; k < i + l + o + b + c + a; ++k) std::getline(in, line);
  std::size_t symbols = 0;
  while (std::getline(in, line) && line != "c") {
    ++symbols;
    ASSERT_GE(line.size(), 3u) << line;
    EXPECT_NE(std::string("ilobc").find(line[0]), std::string::npos) << line;
    for (char ch : line) EXPECT_TRUE(ch >= 0x20 && ch < 0x7f) << "not printable ASCII: " << line;
  }
  EXPECT_EQ(line, "c");
  EXPECT_EQ(symbols, i + l + o + b + c);
  EXPECT_NE(h->aag.find("z\\nINIT FALSE\\nVAR --"), std::string::npos) << h->aag;
}

// NuSMV on the hostile export agrees with sfcv's explicit engine; skipped, visibly, without
// a NuSMV on PATH (it is not packaged: CI builds it by hand).
TEST(SmvIdentifiers, HostileNamesNusmvAgreesWithSfcv) {
  const auto nusmv = find_nusmv();
  if (!nusmv) GTEST_SKIP() << "NuSMV not on PATH";
  const auto h = hostile_export();
  ASSERT_TRUE(h);
  const auto expected = make_explicit_model_checker()->check(h->task);
  const auto got = make_nusmv_model_checker(*nusmv)->check(h->task);
  ASSERT_EQ(got.results.size(), expected.results.size());
  for (std::size_t p = 0; p < got.results.size(); ++p)
    EXPECT_EQ(got.results[p].verdict, expected.results[p].verdict)
        << got.results[p].name << ": " << got.results[p].message;
  EXPECT_EQ(expected.results.at(0).verdict, logic::Verdict::Violated);
  EXPECT_EQ(expected.results.at(1).verdict, logic::Verdict::Holds);
}

}  // namespace
}  // namespace sfcv::engine
