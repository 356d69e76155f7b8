// The expression grammar of `{expr ...}` values: comparison, sum, product, unary and power, primaries.
#include <algorithm>

#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

// Expressions are parsed and evaluated recursively: deeper ones (a million parentheses, a sum of
// 200,000 terms) would overflow the stack, so they are refused. No real scene comes close.
constexpr int max_expression_depth = 256;

// Counts one level of recursion for as long as it lives.
struct DepthGuard {
  explicit DepthGuard(int& depth) : depth_(++depth) {}
  ~DepthGuard() { --depth_; }
  DepthGuard(const DepthGuard&) = delete;
  DepthGuard& operator=(const DepthGuard&) = delete;
  int& depth_;
};

}  // namespace

Value StatementParser::value() {
  const Token start = peek();
  if (is_slf_ && start.is_symbol("{")) {
    ast_->script_values.push_back(take_braced_script());
    const ExprId e = node(ExprOp::script, start.location);
    ast_->expressions.node(e).script_expression = Index(ast_->script_values.size() - 1);
    if (peek().is_symbol(",")) take();
    return {0, e, start.location};
  }
  if (start.is_symbol("{") && !is_operator_next()) {
    take();
    if (peek().is_word("expr")) take();
    const ExprId e = expression();
    expect_symbol("}");
    if (peek().is_symbol(",")) take();
    return {0, e, start.location};
  }
  const bool can_start = start.kind == TokenKind::number || start.kind == TokenKind::parameter ||
                         start.is_symbol("-") || start.is_symbol("+") || start.is_symbol("(") ||
                         start.is_symbol("{") || (start.kind == TokenKind::word && peek(1).is_symbol("(")) ||
                         start.is_word("pi") ||
                         (start.kind == TokenKind::word && start.text.find('.') != std::string::npos);
  if (!can_start) fail(start, "a number or '{expr ...}'");
  // The successor writes bare expressions in tuples: `(1/2 -sqrt(2) 2*$s.h)`. A sign with a space
  // before it and none after starts the next value (`(1 -1 1)` is three values); commas may separate.
  is_bare_value_ = true;
  ExprId e = no_index;
  try {
    e = expression();
  } catch (const SyntaxError&) {
    is_bare_value_ = false;
    throw;
  }
  is_bare_value_ = false;
  if (peek().is_symbol(",")) take();
  const ExprNode& n = ast_->expressions.node(e);
  if (n.op == ExprOp::number) return {n.number, no_index, start.location};
  if (n.op == ExprOp::negate && ast_->expressions.node(n.args[0]).op == ExprOp::number)
    return {-ast_->expressions.node(n.args[0]).number, no_index, start.location};
  return {0, e, start.location};
}

// After a `{expr ...}` group that starts a value: does an operator follow it (`{expr $a} * 2`)?
bool StatementParser::is_operator_next() const {
  int depth = 0;
  for (size_t i = pos_; i < tokens_.size(); ++i) {
    if (tokens_[i].is_symbol("{")) ++depth;
    if (tokens_[i].is_symbol("}") && --depth == 0) {
      const Token& next = tokens_[std::min(i + 1, tokens_.size() - 1)];
      return next.is_symbol("*") || next.is_symbol("/") || next.is_symbol("^") || next.is_symbol("%") ||
             ((next.is_symbol("+") || next.is_symbol("-")) && !is_value_separator(i + 1));
    }
    if (tokens_[i].kind == TokenKind::end) return false;
  }
  return false;
}

// A `+` or `-` at `at` with a space before it and none after: a sign starting the next bare value.
bool StatementParser::is_value_separator(size_t at) const {
  if (at == 0 || at + 1 >= tokens_.size()) return false;
  const Token &before = tokens_[at - 1], &sign = tokens_[at], &after = tokens_[at + 1];
  const int before_end =
      before.location.column + int(before.text.size()) + (before.kind == TokenKind::parameter ? 1 : 0);
  return before.location.line != sign.location.line || before_end < sign.location.column
             ? after.location.line == sign.location.line && after.location.column == sign.location.column + 1
             : false;
}

Value StatementParser::grouped_value() {
  const Token start = peek();
  if (!start.is_symbol("(")) return value();
  take();
  const ExprId e = expression();
  expect_symbol(")");
  return {0, e, start.location};
}

ExprId StatementParser::node(ExprOp op, SourceLocation at, ExprId a, ExprId b) {
  int depth = 1;
  for (ExprId child : {a, b})
    if (child != no_index) depth = std::max(depth, expression_depth_[child] + 1);
  if (depth > max_expression_depth) expression_too_deep(at);
  ExprNode n;
  n.op = op;
  n.location = at;
  n.args[0] = a;
  n.args[1] = b;
  const ExprId id = ast_->expressions.add(std::move(n));
  expression_depth_.resize(size_t(id) + 1, 0);
  expression_depth_[id] = depth;
  return id;
}

void StatementParser::expression_too_deep(SourceLocation at) {
  diagnostics_.error(at,
                     "expression nested more than " + std::to_string(max_expression_depth) + " levels deep");
  throw SyntaxError{};
}

ExprId StatementParser::expression() {
  const ExprId left = additive();
  static constexpr std::pair<const char*, ExprOp> comparisons[] = {
      {"<", ExprOp::less},           {"<=", ExprOp::less_equal}, {">", ExprOp::greater},
      {">=", ExprOp::greater_equal}, {"==", ExprOp::equal},      {"!=", ExprOp::not_equal}};
  for (auto [text, op] : comparisons)
    if (peek().is_symbol(text)) {
      const Token t = take();
      return node(op, t.location, left, additive());
    }
  return left;
}

ExprId StatementParser::additive() {
  ExprId left = term();
  while ((peek().is_symbol("+") || peek().is_symbol("-")) && !(is_bare_value_ && is_value_separator(pos_))) {
    const Token t = take();
    left = node(t.text == "+" ? ExprOp::add : ExprOp::subtract, t.location, left, term());
  }
  return left;
}

ExprId StatementParser::term() {
  ExprId left = unary();
  while (peek().is_symbol("*") || peek().is_symbol("/") || peek().is_symbol("%")) {
    const Token t = take();
    const ExprOp op = t.text == "*" ? ExprOp::multiply : t.text == "/" ? ExprOp::divide : ExprOp::modulo;
    left = node(op, t.location, left, unary());
  }
  return left;
}

ExprId StatementParser::unary() {
  // Every recursion of the expression grammar passes here.
  const DepthGuard guard(parse_depth_);
  if (parse_depth_ > max_expression_depth) expression_too_deep(peek().location);
  if (peek().is_symbol("-")) {
    const Token t = take();
    return node(ExprOp::negate, t.location, unary());
  }
  if (peek().is_symbol("+")) {
    take();
    return unary();
  }
  const ExprId base = primary();
  if (peek().is_symbol("^")) {
    const Token t = take();
    return node(ExprOp::power, t.location, base, unary());
  }
  return base;
}

ExprId StatementParser::primary() {
  const Token t = peek();
  if (t.kind == TokenKind::number) {
    take();
    const ExprId id = node(ExprOp::number, t.location);
    ast_->expressions.node(id).number = t.number;
    return id;
  }
  // `$bank.name` (NOME 2.x has it too: no dialect cue), and the successor's bare `bank.name`
  // (geom__trefoil.nom's `{expr trefoil_slider.speed}`).
  const bool is_bare_parameter =
      t.kind == TokenKind::word && t.text.find('.') != std::string::npos && !peek(1).is_symbol("(");
  if (t.kind == TokenKind::parameter || is_bare_parameter) {
    take();
    const ExprId id = node(ExprOp::parameter, t.location);
    ast_->expressions.node(id).parameter_name = normalize_name(t.text);
    return id;
  }
  if (t.is_symbol("(") || t.is_symbol("{")) {
    // Inside parentheses (and a `{expr ...}` within a bare value) signs are operators again.
    const bool was_bare = is_bare_value_;
    is_bare_value_ = false;
    take();
    if (t.is_symbol("{") && peek().is_word("expr")) take();
    const ExprId inner = expression();
    expect_symbol(t.is_symbol("(") ? ")" : "}");
    is_bare_value_ = was_bare;
    return inner;
  }
  if (t.is_word("pi")) {
    take();
    return node(ExprOp::pi, t.location);
  }
  if (t.kind == TokenKind::word && peek(1).is_symbol("(")) return call(t);
  if (t.kind == TokenKind::word) {
    diagnostics_.error(t.location,
                       "unknown name '" + t.text + "' in an expression (parameters are written $bank_name)");
    throw SyntaxError{};
  }
  fail(t, "a number, '$parameter', a function or '('");
}

ExprId StatementParser::call(const Token& t) {
  const FunctionSignature* f = find_function(t.text);
  if (!f || f->arity == 0) {
    diagnostics_.error(t.location,
                       "unknown function '" + t.text + "'" +
                           did_you_mean(t.text, {"sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt",
                                                 "abs", "pow", "exp", "log", "floor", "ceil", "min", "max"}));
    throw SyntaxError{};
  }
  const int arity = f->arity;
  take();
  take();
  ExprId args[2] = {no_index, no_index};
  int n = 0;
  if (!peek().is_symbol(")")) {
    do {
      const ExprId a = expression();
      if (n < 2) args[n] = a;
      ++n;
    } while (peek().is_symbol(",") && (take(), true));
  }
  expect_symbol(")");
  if (n != arity) {
    diagnostics_.error(t.location, "function '" + t.text + "' takes " + std::to_string(arity) + " argument" +
                                       (arity == 1 ? "" : "s") + ", found " + std::to_string(n));
    throw SyntaxError{};
  }
  const ExprId id = node(ExprOp::call, t.location, args[0], args[1]);
  ast_->expressions.node(id).function = f->function;
  return id;
}

}  // namespace nome::scene
