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
#include "engine/external/circuit_export.hpp"
#include "engine/external/export_model.hpp"
#include "io/load.hpp"
#include "logic/check_inputs.hpp"
#include "semantics/iec61131_system.hpp"
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

}  // namespace
}  // namespace sfcv::engine
