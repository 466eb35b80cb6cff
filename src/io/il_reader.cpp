#include "io/il_reader.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/st_lexer.hpp"
#include "io/st_names.hpp"
#include "io/st_parser.hpp"
#include "model/names.hpp"
#include "model/nesting.hpp"

// IL as ST, without new variables: the current result (CR) is an expression over the values
// the program reads, built as the instructions load and combine operands; ST/S/R assign it.
// Two readings keep that exact: after `ST x` the CR equals x (after `STN x`, NOT x), so it
// becomes x (a later write of what the old expression read cannot change it); any other write
// of a variable the CR (or a value saved by an open parenthesis) reads is refused. A conditional
// jump or return splits the rest of the body into the two branches of an IF (the code after a label
// is repeated per path: forward jumps only, within a statement budget).

namespace sfcv::io {

namespace {

using model::ExprKind;
using model::ExprPtr;

struct Instruction {
  std::string op;       ///< upper case: "LD", "ANDN", ")", "JMPC", or a function's name
  bool open = false;    ///< "AND(": the operand opens a parenthesised sub-result
  std::string operand;  ///< as written (lines of a CAL joined)
  model::SourceLocation where, operand_at;
};

struct IlError {
  model::SourceLocation where;
  std::string message;
};

/// Statements an unfolded body may hold before it is refused (each conditional jump repeats
/// the code after it).
constexpr std::size_t kMaxUnfoldedStatements = 20000;
/// CR expressions deeper than this are refused (later passes walk trees recursively).
constexpr std::uint32_t kMaxResultHeight = model::kMaxNesting - 20;

model::SourceLocation at(const model::SourceLocation& start, int line, int column) {
  return st::Locator(start).at(line, column);
}

/// Comments, `(* ... *)` and CODESYS/TwinCAT `// ...` to the end of the line, become blanks,
/// so that positions stay.
std::string without_comments(std::string text) {
  for (std::size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] == '/' && text[i + 1] == '/') {
      for (; i < text.size() && text[i] != '\n'; ++i) text[i] = ' ';
      continue;
    }
    if (text[i] != '(' || text[i + 1] != '*') continue;
    const auto end = text.find("*)", i + 2);
    const auto stop = end == std::string::npos ? text.size() : end + 2;
    for (std::size_t k = i; k < stop; ++k)
      if (text[k] != '\n') text[k] = ' ';
    i = stop - 1;
  }
  return text;
}

int paren_balance(const std::string& s) {
  int depth = 0;
  for (char c : s) depth += c == '(' ? 1 : c == ')' ? -1 : 0;
  return depth;
}

/// The instructions, and the index each label names.
std::vector<Instruction> split(const plcopen::BodyText& body,
                               std::map<std::string, std::size_t>& labels,
                               std::vector<IlError>& errors) {
  std::vector<std::string> lines;
  {
    const std::string text = without_comments(body.text);
    std::size_t from = 0;
    while (from <= text.size()) {
      const auto nl = text.find('\n', from);
      lines.push_back(text.substr(from, nl == std::string::npos ? std::string::npos : nl - from));
      if (nl == std::string::npos) break;
      from = nl + 1;
    }
  }
  std::vector<Instruction> out;
  for (std::size_t li = 0; li < lines.size(); ++li) {
    const std::string& line = lines[li];
    const int line_no = static_cast<int>(li) + 1;
    std::size_t i = line.find_first_not_of(" \t\r");
    if (i == std::string::npos) continue;
    // A label: `name:` (not `name :=`).
    if (is_st_identifier_start(line[i])) {
      std::size_t j = i;
      while (j < line.size() && is_st_identifier_char(line[j])) ++j;
      std::size_t k = line.find_first_not_of(" \t", j);
      if (k != std::string::npos && line[k] == ':' &&
          (k + 1 >= line.size() || line[k + 1] != '=')) {
        const std::string name = model::to_upper(line.substr(i, j - i));
        if (!labels.emplace(name, out.size()).second)
          errors.push_back({at(body.start, line_no, static_cast<int>(i) + 1),
                            "IL: label '" + line.substr(i, j - i) + "' is defined twice"});
        i = line.find_first_not_of(" \t\r", k + 1);
        if (i == std::string::npos) continue;
      }
    }
    Instruction in;
    in.where = at(body.start, line_no, static_cast<int>(i) + 1);
    std::size_t j = i;
    if (line[i] == ')') {
      j = i + 1;
      in.op = ")";
    } else if (is_st_identifier_start(line[i]) || line[i] == '&') {
      j = i + 1;
      while (j < line.size() && is_st_identifier_char(line[j])) ++j;
      in.op = model::to_upper(line.substr(i, j - i));
    } else {
      errors.push_back({in.where, "IL: expected an operator, found '" + line.substr(i) + "'"});
      continue;
    }
    std::size_t k = line.find_first_not_of(" \t\r", j);
    const bool call = in.op.rfind("CAL", 0) == 0;
    if (!call && k != std::string::npos && line[k] == '(') {
      in.open = true;
      k = line.find_first_not_of(" \t\r", k + 1);
    }
    if (k != std::string::npos) {
      in.operand = line.substr(k);
      while (!in.operand.empty() && std::isspace(static_cast<unsigned char>(in.operand.back())))
        in.operand.pop_back();
      in.operand_at = at(body.start, line_no, static_cast<int>(k) + 1);
      // A call's arguments may go on over the next lines.
      while (call && paren_balance(in.operand) > 0 && li + 1 < lines.size())
        in.operand += "\n" + lines[++li];
    }
    out.push_back(std::move(in));
  }
  return out;
}

/// The written form of a variable an expression names: "x", "inst.Q".
std::string name_of(const model::Expr& e) {
  return e.kind == ExprKind::Member ? e.name + "." + e.member : e.name;
}

/// A result the code still holds: null when undefined, `why` saying since when.
struct Held {
  ExprPtr result;
  std::string why = "undefined here (load a value first)";
};

struct Saved {
  std::string op;  ///< the operator waiting for the parenthesis ("AND", "ADDN"...)
  Held held;
};

struct State {
  Held current;
  std::vector<Saved> saved;
};

class Translator {
 public:
  Translator(const std::vector<Instruction>& code, const std::map<std::string, std::size_t>& labels)
      : code_(code), labels_(labels) {}

  /// The statements of the path from instruction `pc` with `state`, into `out`.
  void run(std::size_t pc, State state, model::StmtList& out) {
    for (; pc < code_.size(); ++pc) {
      const Instruction& in = code_[pc];
      const std::string& op = in.op;
      if (op == "LD" || op == "LDN") {
        state.current = {negate_if(op == "LDN", operand(in))};
      } else if (op == "ST" || op == "STN") {
        const ExprPtr target = variable(in);
        const std::string name = name_of(*target);
        ExprPtr value = negate_if(op == "STN", result(in, state));
        emit(out, model::make_assign(name, value, in.where));
        forget_what_reads(in, state, name);
        state.current = {negate_if(op == "STN", target)};  // the target now holds it (negated)
      } else if (op == "S" || op == "R") {
        const ExprPtr target = variable(in);
        const std::string name = name_of(*target);
        const ExprPtr cond = result(in, state);
        emit(out,
             guarded(cond,
                     {model::make_assign(name, model::make_bool(op == "S", in.where), in.where)},
                     in.where));
        // `LD x S x` leaves x as it was; otherwise a result reading x is stale.
        const bool stays = op == "S" && cond->kind == target->kind && name_of(*cond) == name &&
                           (cond->kind == ExprKind::Name || cond->kind == ExprKind::Member);
        forget_what_reads(in, state, name);
        if (stays) state.current = {cond};
      } else if (op == "NOT") {
        state.current.result = model::make_unary(ExprKind::Not, result(in, state), in.where);
      } else if (const auto kind = binary(op)) {
        if (in.open) {
          state.saved.push_back({op, {result(in, state)}});
          state.current = in.operand.empty()
                              ? Held{nullptr, "undefined after '" + op + "(' (load a value first)"}
                              : Held{operand(in)};
          continue;
        }
        state.current.result = combine(in, op, result(in, state), operand(in));
      } else if (op == ")") {
        if (state.saved.empty()) fail(in, "')' without an open parenthesis");
        const Saved s = state.saved.back();
        state.saved.pop_back();
        if (!s.held.result)
          fail(in, "')' combines the result saved at '" + s.op + "(', which is " + s.held.why);
        state.current.result = combine(in, s.op, s.held.result, result(in, state));
      } else if (op == "JMP" || op == "JMPC" || op == "JMPCN") {
        const std::size_t target = label(in, pc);
        if (op == "JMP") {
          pc = target - 1;
          continue;
        }
        const ExprPtr cond = negate_if(op == "JMPCN", result(in, state));
        auto branch = std::make_shared<model::Stmt>();
        branch->kind = model::StmtKind::If;
        branch->where = in.where;
        branch->conditions.push_back(cond);
        branch->bodies.emplace_back();
        run(target, state, branch->bodies.back());
        run(pc + 1, state, branch->else_body);
        emit(out, branch);
        return;
      } else if (op == "RET") {
        return;
      } else if (op == "RETC" || op == "RETCN") {
        // The rest of the body runs when the return is not taken.
        const ExprPtr cond = negate_if(op == "RETC", result(in, state));
        model::StmtList rest;
        run(pc + 1, state, rest);
        emit(out, guarded(cond, std::move(rest), in.where));
        return;
      } else if (op == "CAL" || op == "CALC" || op == "CALCN") {
        if (in.operand.empty()) fail(in, "'" + op + "' needs an instance");
        model::Diagnostics d;
        // `CAL inst` (its inputs stored before) or `CAL inst(IN := x, ...)`.
        auto body = in.operand.find('(') == std::string::npos
                        ? model::StmtList{model::make_fb_call(in.operand, {}, in.where)}
                        : parse_st_statements(in.operand + ";", in.operand_at, d);
        if (model::has_errors(d)) throw IlError{d.front().where, d.front().message};
        if (body.size() != 1 || body.front()->kind != model::StmtKind::FbCall)
          fail(in, "CAL needs an instance call, e.g. 'CAL T1(IN := x, PT := T#1s)'");
        const std::string instance = body.front()->target;
        if (op == "CAL") {
          emit(out, body.front());
        } else {
          emit(out, guarded(negate_if(op == "CALCN", result(in, state)), {body.front()}, in.where));
        }
        forget_what_reads(in, state, instance);
        state.current = {nullptr, "undefined after a CAL (load a value first)"};
      } else if (is_st_identifier_start(op.front())) {
        // A function as an operator: `MAX 10` is CR := MAX(CR, 10); `LIMIT 0, 9` is
        // LIMIT(CR, 0, 9).
        std::vector<ExprPtr> args{result(in, state)};
        for (const auto& a : operands(in)) args.push_back(a);
        state.current.result = model::make_call(op, std::move(args), in.where);
      } else {
        fail(in, "unsupported operator '" + op + "'");
      }
      if (state.current.result && state.current.result->height > kMaxResultHeight)
        fail(in, "the current result grows too deep (store it in a variable)");
    }
    if (!state.saved.empty()) throw IlError{code_.back().where, "IL: a parenthesis is not closed"};
  }

 private:
  [[noreturn]] void fail(const Instruction& in, const std::string& message) const {
    throw IlError{in.where, "IL: " + message};
  }

  static ExprPtr negate_if(bool negate, ExprPtr e) {
    if (!negate) return e;
    const auto where = e->where;
    return model::make_unary(ExprKind::Not, std::move(e), where);
  }

  ExprPtr result(const Instruction& in, const State& s) const {
    if (!s.current.result)
      fail(in, "'" + in.op + "' reads the current result, which is " + s.current.why);
    return s.current.result;
  }

  ExprPtr operand(const Instruction& in) const {
    if (in.operand.empty()) fail(in, "'" + in.op + "' needs an operand");
    model::Diagnostics d;
    auto e = parse_st_expression(in.operand, in.operand_at, d);
    if (!e) throw IlError{d.front().where, d.front().message};
    return e;
  }

  /// The comma-separated operands of a function operator, each parsed where it is written.
  std::vector<ExprPtr> operands(const Instruction& in) const {
    std::vector<ExprPtr> out;
    if (in.operand.empty()) return out;
    std::size_t from = 0;
    int depth = 0;
    bool quoted = false;
    for (std::size_t i = 0; i <= in.operand.size(); ++i) {
      const char c = i < in.operand.size() ? in.operand[i] : ',';
      if (c == '\'') quoted = !quoted;
      if (quoted) continue;
      depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      if (c != ',' || depth > 0) continue;
      model::Diagnostics d;
      const auto piece = in.operand.substr(from, i - from);
      model::SourceLocation start = in.operand_at;
      start.column += static_cast<int>(from);
      auto e = parse_st_expression(piece, start, d);
      if (!e) throw IlError{d.front().where, d.front().message};
      out.push_back(std::move(e));
      from = i + 1;
    }
    return out;
  }

  ExprPtr variable(const Instruction& in) const {
    ExprPtr e = operand(in);
    if (e->kind != ExprKind::Name && e->kind != ExprKind::Member)
      fail(in, "'" + in.op + "' needs a variable, not '" + in.operand + "'");
    return e;
  }

  /// After a write of `variable`, a held result that reads it no longer has its value: it is
  /// forgotten, and an instruction that uses it later is refused (docs/semantics.md 1.9.2).
  static void forget_what_reads(const Instruction& in, State& s, const std::string& variable) {
    const std::string why = "stale: '" + in.op + " " + in.operand + "' changed " + variable +
                            ", which it reads (not modelled: load it again)";
    auto forget = [&](Held& h) {
      if (h.result && model::reads(*h.result, variable)) h = {nullptr, why};
    };
    forget(s.current);
    for (auto& x : s.saved) forget(x.held);
  }

  std::size_t label(const Instruction& in, std::size_t pc) const {
    const auto it = labels_.find(model::to_upper(in.operand));
    if (it == labels_.end()) fail(in, "unknown label '" + in.operand + "'");
    if (it->second <= pc)
      fail(in, "backward jump to '" + in.operand + "' (a loop) is not modelled");
    return it->second;
  }

  static std::optional<ExprKind> binary(const std::string& op) {
    static const std::map<std::string, ExprKind> ops = {
        {"AND", ExprKind::And}, {"ANDN", ExprKind::And}, {"&", ExprKind::And},
        {"&N", ExprKind::And},  {"OR", ExprKind::Or},    {"ORN", ExprKind::Or},
        {"XOR", ExprKind::Xor}, {"XORN", ExprKind::Xor}, {"ADD", ExprKind::Add},
        {"SUB", ExprKind::Sub}, {"MUL", ExprKind::Mul},  {"DIV", ExprKind::Div},
        {"MOD", ExprKind::Mod}, {"GT", ExprKind::Gt},    {"GE", ExprKind::Ge},
        {"EQ", ExprKind::Eq},   {"NE", ExprKind::Ne},    {"LE", ExprKind::Le},
        {"LT", ExprKind::Lt}};
    const auto it = ops.find(op);
    if (it == ops.end()) return std::nullopt;
    return it->second;
  }

  ExprPtr combine(const Instruction& in, const std::string& op, ExprPtr left, ExprPtr right) const {
    const bool negated = op == "ANDN" || op == "&N" || op == "ORN" || op == "XORN";
    return model::make_binary(*binary(op), std::move(left), negate_if(negated, std::move(right)),
                              in.where);
  }

  static model::StmtPtr guarded(ExprPtr cond, model::StmtList body,
                                const model::SourceLocation& where) {
    auto s = std::make_shared<model::Stmt>();
    s->kind = model::StmtKind::If;
    s->where = where;
    s->conditions.push_back(std::move(cond));
    s->bodies.push_back(std::move(body));
    return s;
  }

  void emit(model::StmtList& out, model::StmtPtr s) {
    if (++emitted_ > kMaxUnfoldedStatements)
      throw IlError{s->where, "IL: the jumps of this body unfold into more than " +
                                  std::to_string(kMaxUnfoldedStatements) + " statements"};
    out.push_back(std::move(s));
  }

  const std::vector<Instruction>& code_;
  const std::map<std::string, std::size_t>& labels_;
  std::size_t emitted_ = 0;
};

}  // namespace

std::optional<model::StmtList> read_il_statements(const plcopen::BodyText& text,
                                                  model::Diagnostics& problems) {
  std::map<std::string, std::size_t> labels;
  std::vector<IlError> errors;
  const auto code = split(text, labels, errors);
  if (errors.empty()) {
    try {
      model::StmtList body;
      Translator(code, labels).run(0, State{}, body);
      return body;
    } catch (const IlError& e) {
      errors.push_back(e);
    }
  }
  for (auto& e : errors) problems.push_back({model::Severity::Error, e.where, e.message});
  return std::nullopt;
}

}  // namespace sfcv::io
