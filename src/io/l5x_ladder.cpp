#include "io/l5x_ladder.hpp"

#include <cctype>

#include "model/names.hpp"
#include "model/nesting.hpp"

namespace sfcv::io::l5x {

namespace {

using model::ExprKind;

class RungParser {
 public:
  explicit RungParser(std::string_view text) : text_(text) {}

  std::optional<RungSequence> run(std::string& error) {
    RungSequence rung;
    if (!sequence(rung)) {
      error = error_;
      return std::nullopt;
    }
    skip_spaces();
    if (at_ != text_.size() && text_[at_] == ';') ++at_;
    skip_spaces();
    if (at_ != text_.size()) {
      error = "unexpected '" + std::string(1, text_[at_]) + "' at offset " + std::to_string(at_) +
              " of the rung";
      return std::nullopt;
    }
    return rung;
  }

 private:
  void skip_spaces() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }

  bool fail(std::string message) {
    error_ = std::move(message) + " at offset " + std::to_string(at_) + " of the rung";
    return false;
  }

  // Instructions and branches up to `]`, `,` or `;` (or the end).
  bool sequence(RungSequence& out) {
    for (;;) {
      skip_spaces();
      if (at_ == text_.size()) return true;
      const char c = text_[at_];
      if (c == ']' || c == ',' || c == ';') return true;
      if (c == '[') {
        // Later passes walk expressions recursively: a deeper nesting is refused, not a crash.
        if (++depth_ > model::kMaxNesting / 4) return fail("branches nested too deep");
        ++at_;
        RungElement branch;
        for (;;) {
          branch.legs.emplace_back();
          if (!sequence(branch.legs.back())) return false;
          if (at_ == text_.size()) return fail("a branch '[' without its ']'");
          if (text_[at_] == ']') break;
          if (text_[at_] != ',') return fail("';' inside a branch");
          ++at_;
        }
        ++at_;
        --depth_;
        out.push_back(std::move(branch));
        continue;
      }
      if (!(std::isalpha(static_cast<unsigned char>(c)) || c == '_'))
        return fail("unexpected '" + std::string(1, c) + "'");
      const auto start = at_;
      while (at_ < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[at_])) || text_[at_] == '_'))
        ++at_;
      if (++instructions_ > kMaxInstructions)
        return fail("more than " + std::to_string(kMaxInstructions) + " instructions in one rung");
      RungElement e;
      e.mnemonic = model::to_upper(text_.substr(start, at_ - start));
      skip_spaces();
      if (at_ == text_.size() || text_[at_] != '(')
        return fail("instruction " + e.mnemonic + " without its '('");
      ++at_;
      int depth = 0;
      std::string operand;
      for (;; ++at_) {
        if (at_ == text_.size()) return fail("instruction " + e.mnemonic + " without its ')'");
        const char d = text_[at_];
        if (depth == 0 && (d == ',' || d == ')')) {
          e.operands.push_back(trimmed(operand));
          operand.clear();
          if (d == ')') break;
          continue;
        }
        if (d == '(' || d == '[') ++depth;
        if (d == ')' || d == ']') --depth;
        operand += d;
      }
      ++at_;
      if (e.operands.size() == 1 && e.operands[0].empty()) e.operands.clear();
      out.push_back(std::move(e));
    }
  }

  static std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
  }

  static constexpr int kMaxInstructions = 10000;

  std::string_view text_;
  std::size_t at_ = 0;
  int depth_ = 0;
  int instructions_ = 0;
  std::string error_;
};

// The upper-case names `e` reads: variables, and the instance of a member (`T2.Q` reads T2).
void names_read(const model::ExprPtr& e, std::set<std::string>& out) {
  if (!e) return;
  if (e->kind == ExprKind::Name || e->kind == ExprKind::Member)
    out.insert(model::to_upper(e->name));
  for (const auto& a : e->args) names_read(a, out);
}

// The upper-case names `body` writes (assignment targets, called instances), at any depth.
void names_written(const model::StmtList& body, std::set<std::string>& out) {
  for (const auto& s : body) {
    if (!s->target.empty()) {
      const auto dot = s->target.find('.');
      out.insert(model::to_upper(s->target.substr(0, dot)));
    }
    for (const auto& b : s->bodies) names_written(b, out);
    names_written(s->else_body, out);
  }
}

// CPT's expression (1756-RM003, Compute/Math Instructions): integer operands and literals,
// parentheses, unary -, * / MOD, + -, ABS(); other operators and functions are refused by name.
class ComputeExpression {
 public:
  ComputeExpression(std::string_view text, RungOperands& operands, model::SourceLocation where)
      : text_(text), operands_(operands), where_(std::move(where)) {}

  model::ExprPtr run(std::string& error) {
    auto e = sum();
    skip_spaces();
    if (e && at_ != text_.size()) fail("unexpected '" + std::string(text_.substr(at_, 1)) + "'");
    error = error_;
    return error_.empty() ? e : nullptr;
  }

 private:
  void skip_spaces() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  model::ExprPtr fail(std::string message) {
    if (error_.empty())
      error_ = "CPT expression '" + std::string(text_) + "': " + std::move(message);
    return nullptr;
  }
  bool take(char c) {
    skip_spaces();
    if (at_ < text_.size() && text_[at_] == c) return ++at_, true;
    return false;
  }
  std::string word() const { return word_at(text_, at_); }

 public:
  // A word (operand, MOD, a function name) at `at`: an operand may hold indices and members.
  static std::string word_at(std::string_view text, std::size_t at) {
    auto end = at;
    int depth = 0;
    while (end < text.size()) {
      const char c = text[end];
      if (c == '[') ++depth;
      if (c == ']') --depth;
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == ':' ||
            c == '[' || c == ']' || c == '#' || (depth > 0 && c == ',')))
        break;
      ++end;
    }
    return std::string(text.substr(at, end - at));
  }

 private:
  model::ExprPtr sum() {
    if (++depth_ > model::kMaxNesting / 4) return fail("nested too deep");
    auto e = product();
    while (e) {
      const auto kind = take('+') ? ExprKind::Add : take('-') ? ExprKind::Sub : ExprKind::Name;
      if (kind == ExprKind::Name) break;
      auto rhs = product();
      if (!rhs) return nullptr;
      e = model::make_binary(kind, e, rhs, where_);
    }
    --depth_;
    return e;
  }
  model::ExprPtr product() {
    auto e = unary();
    while (e) {
      skip_spaces();
      ExprKind kind = ExprKind::Name;
      if (take('*')) {
        if (at_ < text_.size() && text_[at_] == '*') return fail("'**' is not read");
        kind = ExprKind::Mul;
      } else if (take('/')) {
        kind = ExprKind::Div;
      } else if (model::to_upper(word()) == "MOD") {
        at_ += 3;
        kind = ExprKind::Mod;
      } else {
        break;
      }
      auto rhs = unary();
      if (!rhs) return nullptr;
      e = model::make_binary(kind, e, rhs, where_);
    }
    return e;
  }
  model::ExprPtr unary() {
    if (++depth_ > model::kMaxNesting / 4) return fail("nested too deep");
    model::ExprPtr e;
    if (take('-')) {
      auto arg = unary();
      e = arg ? model::make_unary(ExprKind::Neg, arg, where_) : nullptr;
    } else if (take('(')) {
      e = sum();
      if (e && !take(')')) e = fail("a '(' without its ')'");
    } else {
      skip_spaces();
      const auto w = word();
      if (w.empty())
        return fail(at_ == text_.size() ? "ends too early"
                                        : "unexpected '" + std::string(text_.substr(at_, 1)) + "'");
      at_ += w.size();
      const auto up = model::to_upper(w);
      if (take('(')) {
        if (up != "ABS") return fail("the function " + up + " is not read (ABS is)");
        auto arg = sum();
        if (arg && !take(')')) return fail("a '(' without its ')'");
        if (!arg) return nullptr;
        e = model::make_call("ABS", {arg}, where_);  // the standard function
      } else if (up == "AND" || up == "OR" || up == "XOR" || up == "NOT") {
        return fail("the operator " + up + " is not read");
      } else if (w.find('.') != std::string::npos &&
                 std::isdigit(static_cast<unsigned char>(w[0]))) {
        return fail("the REAL literal " + w + " is not read");
      } else {
        std::string error;
        e = operands_.value(w, error);
        if (!e) return fail(error);
      }
    }
    --depth_;
    return e;
  }

  std::string_view text_;
  RungOperands& operands_;
  model::SourceLocation where_;
  std::size_t at_ = 0;
  int depth_ = 0;
  std::string error_;
};

}  // namespace

std::vector<std::string> compute_operands(std::string_view expression) {
  std::vector<std::string> out;
  for (std::size_t at = 0; at < expression.size();) {
    const char c = expression[at];
    if (!(std::isalpha(static_cast<unsigned char>(c)) || c == '_')) {
      // Numbers (with their digits and letters, 16#FF) are no operands.
      if (std::isdigit(static_cast<unsigned char>(c)))
        at += ComputeExpression::word_at(expression, at).size();
      else
        ++at;
      continue;
    }
    const auto w = ComputeExpression::word_at(expression, at);
    at += w.size();
    auto next = at;
    while (next < expression.size() && std::isspace(static_cast<unsigned char>(expression[next])))
      ++next;
    const auto up = model::to_upper(w);
    const bool function = next < expression.size() && expression[next] == '(';
    if (!function && up != "MOD" && up != "AND" && up != "OR" && up != "XOR" && up != "NOT")
      out.push_back(w);
  }
  return out;
}

namespace {

bool is_output(const std::string& m) {
  return m == "OTE" || m == "OTL" || m == "OTU" || m == "MOV" || m == "CLR" || m == "ADD" ||
         m == "DIV" || m == "MOD" || m == "NEG" || m == "CPT" || m == "SUB" || m == "MUL" ||
         m == "ONS" || m == "TON" || m == "CTU" || m == "CTD" || m == "RES" || m == "JSR";
}

}  // namespace

std::optional<RungSequence> parse_rung(std::string_view text, std::string& error) {
  return RungParser(text).run(error);
}

void each_instruction(const RungSequence& rung,
                      const std::function<void(const RungElement&)>& visit) {
  for (const auto& e : rung) {
    if (e.mnemonic.empty()) {
      for (const auto& leg : e.legs) each_instruction(leg, visit);
    } else {
      visit(e);
    }
  }
}

RungTranslator::RungTranslator(RungOperands& operands, std::string temporary_prefix)
    : operands_(operands), prefix_(std::move(temporary_prefix)) {}

bool RungTranslator::translate(const RungSequence& rung, const model::SourceLocation& where,
                               model::StmtList& out, std::vector<std::string>& errors) {
  where_ = where;
  out_ = &out;
  errors_ = &errors;
  live_.clear();
  const auto before = errors.size();
  run(rung, Power{}, false);
  return errors.size() == before;
}

void RungTranslator::fail(std::string message) {
  errors_->push_back(std::move(message));
}

RungTranslator::Power RungTranslator::run(const RungSequence& seq, Power in, bool result_needed) {
  Power p = std::move(in);
  for (std::size_t i = 0; i < seq.size(); ++i) {
    const auto& e = seq[i];
    // The condition is kept from later writes only where something after this element reads it.
    const bool needed = i + 1 < seq.size() || result_needed;
    if (!e.mnemonic.empty()) {
      if (needed) live_.push_back(&p);
      instruction(e, p);
      if (needed) live_.pop_back();
      continue;
    }
    // Every leg starts from the condition before the branch; the branch passes on their OR.
    Power branch_in = std::move(p);
    p = Power{};
    std::vector<Power> outs;
    outs.reserve(e.legs.size());
    for (std::size_t j = 0; j < e.legs.size(); ++j) {
      const bool in_needed = j + 1 < e.legs.size();
      if (in_needed) live_.push_back(&branch_in);
      outs.push_back(run(e.legs[j], branch_in, needed));
      if (in_needed) live_.pop_back();
      if (needed) live_.push_back(&outs.back());
    }
    if (needed) live_.resize(live_.size() - outs.size());
    std::vector<model::ExprPtr> alternatives;
    bool always = false;
    for (auto& o : outs) {
      if (!o.unknown_after.empty()) {
        p.unknown_after = o.unknown_after;
        continue;
      }
      p.reads.insert(o.reads.begin(), o.reads.end());
      if (!o.expr)
        always = true;
      else
        alternatives.push_back(o.expr);
    }
    if (!p.unknown_after.empty()) continue;
    if (always)
      p.expr = nullptr;
    else
      p.expr = alternatives.size() == 1 ? alternatives[0]
                                        : model::make_nary(ExprKind::Or, alternatives, where_);
  }
  return p;
}

bool RungTranslator::known(const Power& p, const RungElement& e) {
  if (p.unknown_after.empty()) return true;
  fail("unsupported: " + e.mnemonic + " after " + p.unknown_after +
       " in the same rung or branch leg (the rung condition after " + p.unknown_after +
       " is not read)");
  return false;
}

void RungTranslator::and_into(Power& p, model::ExprPtr e) {
  names_read(e, p.reads);
  if (!p.expr) {
    p.expr = std::move(e);
    return;
  }
  // One n-ary AND per run of examine instructions, not a chain as deep as the rung is long.
  std::vector<model::ExprPtr> args;
  if (p.expr->kind == ExprKind::And)
    args = p.expr->args;
  else
    args.push_back(p.expr);
  args.push_back(std::move(e));
  p.expr = model::make_nary(ExprKind::And, std::move(args), where_);
}

void RungTranslator::before_write(const std::string& name) {
  const auto key = model::to_upper(name.substr(0, name.find('.')));
  for (Power* q : live_) {
    if (!q->expr || !q->unknown_after.empty() || !q->reads.count(key)) continue;
    const std::string t = prefix_ + std::to_string(temporaries_.size() + 1);
    temporaries_.push_back(t);
    out_->push_back(model::make_assign(t, q->expr, where_));
    q->expr = model::make_name(t, where_);
    q->reads = {model::to_upper(t)};
  }
}

void RungTranslator::instruction(const RungElement& e, Power& p) {
  const auto& m = e.mnemonic;
  const auto& ops = e.operands;
  auto arity = [&](std::size_t n) {
    if (ops.size() == n) return true;
    fail(m + " with " + std::to_string(ops.size()) + " operands (it takes " + std::to_string(n) +
         ")");
    return false;
  };
  if (!known(p, e)) return;
  std::string error;
  auto checked = [&](auto value) {
    if (!error.empty()) fail(error);
    return value;
  };
  const auto rail = [&] { return p.expr ? p.expr : model::make_bool(true, where_); };
  if (m == "NOP") return;
  if (m == "AFI") {
    p.expr = model::make_bool(false, where_);
    p.reads.clear();
    return;
  }
  if (m == "XIC" || m == "XIO") {
    if (!arity(1)) return;
    auto b = checked(operands_.bit(ops[0], error));
    if (!b) return;
    and_into(p, m == "XIC" ? b : model::make_unary(ExprKind::Not, b, where_));
    return;
  }
  static const std::map<std::string, ExprKind> kCompare = {
      {"EQU", ExprKind::Eq}, {"NEQ", ExprKind::Ne}, {"GRT", ExprKind::Gt},
      {"GEQ", ExprKind::Ge}, {"LES", ExprKind::Lt}, {"LEQ", ExprKind::Le}};
  if (const auto c = kCompare.find(m); c != kCompare.end()) {
    if (!arity(2)) return;
    auto a = checked(operands_.value(ops[0], error));
    if (!a) return;
    auto b = checked(operands_.value(ops[1], error));
    if (!b) return;
    and_into(p, model::make_binary(c->second, a, b, where_));
    return;
  }
  if (m == "LIM") {
    // LIM(low, test, high): low <= test <= high; when low > high, the range wraps: test >= low
    // or test <= high (1756-RM003, Compare Instructions).
    if (!arity(3)) return;
    std::vector<model::ExprPtr> v;
    for (const auto& o : ops) {
      v.push_back(checked(operands_.value(o, error)));
      if (!v.back()) return;
    }
    using model::make_binary;
    const auto within = model::make_nary(ExprKind::And,
                                         {make_binary(ExprKind::Le, v[0], v[1], where_),
                                          make_binary(ExprKind::Le, v[1], v[2], where_)},
                                         where_);
    const auto wrapped = model::make_nary(ExprKind::Or,
                                          {make_binary(ExprKind::Ge, v[1], v[0], where_),
                                           make_binary(ExprKind::Le, v[1], v[2], where_)},
                                          where_);
    and_into(
        p, model::make_nary(
               ExprKind::Or,
               {model::make_nary(ExprKind::And,
                                 {make_binary(ExprKind::Le, v[0], v[2], where_), within}, where_),
                model::make_nary(ExprKind::And,
                                 {make_binary(ExprKind::Gt, v[0], v[2], where_), wrapped}, where_)},
               where_));
    return;
  }
  if (!is_output(m)) {
    fail("unsupported: RLL instruction " + m +
         " (read: XIC XIO OTE OTL OTU ONS TON CTU CTD RES JSR MOV CLR ADD SUB MUL DIV MOD NEG "
         "CPT NOP AFI EQU NEQ GRT GEQ LES LEQ LIM)");
    return;
  }
  if (m == "OTE" || m == "OTL" || m == "OTU") {
    if (!arity(1)) return;
    write(ops[0], true, [&](const std::string& target) -> model::StmtPtr {
      if (m == "OTE") return model::make_assign(target, rail(), where_);
      const auto set = model::make_assign(target, model::make_bool(m == "OTL", where_), where_);
      return p.expr ? make_if(p.expr, {set}) : set;
    });
    return;
  }
  if (m == "ONS") {
    // Rung-condition-out is TRUE on the scan the condition in becomes TRUE; the storage bit
    // keeps the condition in.
    if (!arity(1)) return;
    const auto storage = checked(operands_.bit_target(ops[0], error));
    if (storage.empty()) return;
    const auto stored = checked(operands_.bit(ops[0], error));
    if (!stored) return;
    const auto in = rail();
    and_into(p, model::make_unary(ExprKind::Not, stored, where_));
    before_write(storage);
    out_->push_back(model::make_assign(storage, in, where_));
    return;
  }
  if (m == "MOV" || m == "CLR") {
    if (!arity(m == "MOV" ? 2 : 1)) return;
    auto v = m == "MOV" ? checked(operands_.value(ops[0], error)) : model::make_int(0, where_);
    if (!v) return;
    write(ops.back(), false, [&](const std::string& target) -> model::StmtPtr {
      const auto assign = model::make_assign(target, v, where_);
      return p.expr ? make_if(p.expr, {assign}) : assign;
    });
    return;
  }
  if (m == "ADD" || m == "SUB" || m == "MUL" || m == "DIV" || m == "MOD" || m == "NEG" ||
      m == "CPT") {
    // Integer arithmetic into the destination when the condition is TRUE. A result out of the
    // destination's range, and a division by zero, are the range error of the model's
    // assignment, where Logix wraps and sets S:V, or faults (docs/semantics.md 1.14). With
    // integer operands DIV truncates toward zero and MOD is A - TRN(A / B) * B: the model's
    // `/` and MOD.
    const bool cpt = m == "CPT";
    if (!arity(m == "NEG" || cpt ? 2 : 3)) return;
    model::ExprPtr value;
    if (cpt) {
      value = checked(ComputeExpression(ops[1], operands_, where_).run(error));
    } else if (m == "NEG") {
      auto a = checked(operands_.value(ops[0], error));
      if (a) value = model::make_unary(ExprKind::Neg, a, where_);
    } else {
      auto a = checked(operands_.value(ops[0], error));
      if (!a) return;
      auto b = checked(operands_.value(ops[1], error));
      if (!b) return;
      static const std::map<std::string, ExprKind> kArithmetic = {{"ADD", ExprKind::Add},
                                                                  {"SUB", ExprKind::Sub},
                                                                  {"MUL", ExprKind::Mul},
                                                                  {"DIV", ExprKind::Div},
                                                                  {"MOD", ExprKind::Mod}};
      value = model::make_binary(kArithmetic.at(m), a, b, where_);
    }
    if (!value) return;
    write(cpt ? ops[0] : ops.back(), false, [&](const std::string& target) -> model::StmtPtr {
      const auto assign = model::make_assign(target, value, where_);
      return p.expr ? make_if(p.expr, {assign}) : assign;
    });
    return;
  }
  if (m == "RES") {
    if (!arity(1)) return;
    auto reset = checked(operands_.reset(ops[0], error));
    if (!reset) return;
    for (const auto& s : *reset) before_write(s->target);
    if (p.expr)
      out_->push_back(make_if(p.expr, std::move(*reset)));
    else
      for (auto& s : *reset) out_->push_back(std::move(s));
    return;
  }
  if (m == "CTU" || m == "CTD") {
    // 1756-RM003, CTU (CTD): with the rung TRUE and .CU (.CD) clear, .ACC goes up (down) by 1;
    // with the rung TRUE, .CU (.CD) is set and .DN becomes .ACC >= .PRE; with the rung FALSE,
    // .CU (.CD) is cleared and .DN kept. CTU(counter, ?, ?): the `?` are the editor's display.
    if (!arity(3)) return;
    const auto c = checked(operands_.counter(ops[0], error));
    if (!c) return;
    const bool up = m == "CTU";
    const auto& enable = up ? c->up : c->down;
    for (const auto* name : {&c->accumulated, &enable, &c->done}) before_write(*name);
    using model::make_name;
    const auto acc = make_name(c->accumulated, where_);
    model::StmtList counting = {
        make_if(model::make_unary(ExprKind::Not, make_name(enable, where_), where_),
                {model::make_assign(c->accumulated,
                                    model::make_binary(up ? ExprKind::Add : ExprKind::Sub, acc,
                                                       model::make_int(1, where_), where_),
                                    where_)}),
        model::make_assign(enable, model::make_bool(true, where_), where_),
        model::make_assign(
            c->done,
            model::make_binary(ExprKind::Ge, acc, model::make_int(c->preset, where_), where_),
            where_)};
    if (!p.expr) {
      for (auto& s : counting) out_->push_back(std::move(s));
      return;
    }
    auto s = std::make_shared<model::Stmt>();
    s->kind = model::StmtKind::If;
    s->where = where_;
    s->conditions.push_back(p.expr);
    s->bodies.push_back(std::move(counting));
    s->else_body = {model::make_assign(enable, model::make_bool(false, where_), where_)};
    out_->push_back(std::move(s));
    return;
  }
  if (m == "TON") {
    // TON(timer, ?, ?): the preset and accumulator are the TIMER tag's; the two `?` are the
    // editor's display of them.
    if (!arity(3)) return;
    const auto timer = checked(operands_.timer(ops[0], error));
    if (!timer) return;
    before_write(timer->first);
    out_->push_back(model::make_fb_call(
        timer->first, {{"IN", rail()}, {"PT", model::make_time(timer->second, where_)}}, where_));
    p.unknown_after = "TON";
    return;
  }
  // JSR(routine, 0): the routine's rungs run where the call is, when the condition is TRUE.
  if (ops.size() != 2 || ops[1] != "0") {
    fail("unsupported: JSR with parameters (" + std::to_string(ops.size()) +
         " operands; JSR(routine, 0) is read)");
    return;
  }
  auto body = checked(operands_.subroutine(ops[0], error));
  if (!body) return;
  std::set<std::string> written;
  names_written(*body, written);
  for (const auto& w : written) before_write(w);
  if (!p.expr) {
    for (auto& s : *body) out_->push_back(std::move(s));
  } else {
    out_->push_back(make_if(p.expr, std::move(*body)));
  }
  p.unknown_after = "JSR";
}

void RungTranslator::write(const std::string& operand, bool bit,
                           const std::function<model::StmtPtr(const std::string&)>& make) {
  std::string error;
  const auto chosen = operands_.chosen_target(operand, bit, error);
  if (!error.empty()) return fail(error);
  if (!chosen) {
    const auto target =
        bit ? operands_.bit_target(operand, error) : operands_.value_target(operand, error);
    if (target.empty()) return fail(error);
    before_write(target);
    out_->push_back(make(target));
    return;
  }
  // The element the index chooses when the instruction runs: a CASE over the elements, whose
  // ELSE (an index out of the array's bounds, where the controller faults) assigns MUX's range
  // error, as model::lower_data_types writes `a[i] := v`.
  for (const auto& t : chosen->targets) before_write(t);
  auto c = std::make_shared<model::Stmt>();
  c->kind = model::StmtKind::Case;
  c->where = where_;
  c->value = chosen->index;
  std::vector<model::ExprPtr> mux{chosen->index};
  for (std::size_t k = 0; k < chosen->targets.size(); ++k) {
    const auto v = static_cast<std::int64_t>(k);
    c->labels.push_back({model::CaseLabel{v, v, {}, {}}});
    c->bodies.push_back({make(chosen->targets[k])});
    mux.push_back(model::make_name(chosen->targets[k], where_));
  }
  c->else_body.push_back(model::make_assign(
      chosen->targets.front(), model::make_call("MUX", std::move(mux), where_), where_));
  out_->push_back(std::move(c));
}

model::StmtPtr RungTranslator::make_if(model::ExprPtr condition, model::StmtList body) const {
  auto s = std::make_shared<model::Stmt>();
  s->kind = model::StmtKind::If;
  s->where = where_;
  s->conditions.push_back(std::move(condition));
  s->bodies.push_back(std::move(body));
  return s;
}

}  // namespace sfcv::io::l5x
