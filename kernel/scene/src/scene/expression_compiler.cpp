#include "scene/expression_compiler.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

#include "nome/scene/expression.hpp"

namespace nome::scene {
namespace {

constexpr size_t max_call_arguments = 16;

using Step = CompiledExpression::Step;

// Recursive descent over the bracket text, loosest binding first: or, and, comparison, sum, product
// (written or implied), unary, power, primary. Each rule emits its operands' steps, then its own.
class BracketReader {
 public:
  BracketReader(std::string_view text, std::span<const std::string_view> variables, SourceLocation at,
                std::vector<Step>& steps)
      : text_(text), variables_(variables), at_(at), steps_(steps) {}

  // Emits the whole text's steps; returns the most values they hold at once.
  size_t whole() {
    disjunction();
    skip_space();
    if (pos_ < text_.size()) fail("an operator or ']'");
    return most_held_;
  }

 private:
  static constexpr int max_depth = 200;

  [[noreturn]] void fail(const std::string& expected) {
    const std::string found = pos_ < text_.size() ? "'" + std::string(1, text_[pos_]) + "'" : "the end";
    throw EvaluationError(at_, "in the function [" + std::string(text_) + "], at character " +
                                   std::to_string(pos_ + 1) + ": expected " + expected + ", found " + found);
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(std::string_view s) {
    skip_space();
    if (text_.substr(pos_, s.size()) != s) return false;
    pos_ += s.size();
    return true;
  }
  // A word operator (`and`) at the position, not the start of a longer name (`android`).
  bool is_at_word(std::string_view w) {
    skip_space();
    const size_t end = pos_ + w.size();
    return text_.substr(pos_, w.size()) == w &&
           !(end < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[end])) || text_[end] == '_'));
  }
  bool accept_word(std::string_view w) {
    if (!is_at_word(w)) return false;
    pos_ += w.size();
    return true;
  }
  // A step that takes `operands` values off the stack and puts its result on.
  void emit(Step step, size_t operands) {
    steps_.push_back(step);
    held_ = held_ - operands + 1;
    most_held_ = std::max(most_held_, held_);
  }
  void emit_operator(ExprOp op, size_t operands) { emit({.op = op}, operands); }
  void emit_number(double value) { emit({.op = ExprOp::number, .number = value}, 0); }

  void disjunction() {
    conjunction();
    while (accept_word("or") || accept("||") || accept("|")) {
      conjunction();
      emit_operator(ExprOp::logical_or, 2);
    }
  }
  void conjunction() {
    comparison();
    while (accept_word("and") || accept("&&") || accept("&")) {
      comparison();
      emit_operator(ExprOp::logical_and, 2);
    }
  }
  void comparison() {
    sum();
    static constexpr std::pair<std::string_view, ExprOp> ops[] = {
        {"<=", ExprOp::less_equal}, {">=", ExprOp::greater_equal}, {"==", ExprOp::equal},
        {"!=", ExprOp::not_equal},  {"<>", ExprOp::not_equal},     {"<", ExprOp::less},
        {">", ExprOp::greater},     {"=", ExprOp::equal}};
    for (auto [text, op] : ops)
      if (accept(text)) {
        sum();
        emit_operator(op, 2);
        return;
      }
  }
  void sum() {
    product();
    for (;;) {
      if (accept("+")) {
        product();
        emit_operator(ExprOp::add, 2);
      } else if (accept("-")) {
        product();
        emit_operator(ExprOp::subtract, 2);
      } else {
        return;
      }
    }
  }
  // What may follow a factor with an implied `*`: a number, a name or '(' (`5x`, `2(x+1)`, `(x)(y)`).
  bool starts_implied_factor() {
    skip_space();
    if (pos_ >= text_.size() || is_at_word("and") || is_at_word("or")) return false;
    const char c = text_[pos_];
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '(';
  }
  void product() {
    unary();
    for (;;) {
      if (accept("*")) {
        unary();
        emit_operator(ExprOp::multiply, 2);
      } else if (accept("/")) {
        unary();
        emit_operator(ExprOp::divide, 2);
      } else if (accept("%")) {
        unary();
        emit_operator(ExprOp::modulo, 2);
      } else if (starts_implied_factor()) {
        power();
        emit_operator(ExprOp::multiply, 2);
      } else {
        return;
      }
    }
  }
  void unary() {
    if (++depth_ > max_depth) fail("a shallower expression (nested over 200 levels)");
    if (accept("-")) {
      unary();
      emit_operator(ExprOp::negate, 1);
    } else if (accept("+")) {
      unary();
    } else if (accept_word("not") || accept("!")) {
      unary();
      emit_operator(ExprOp::logical_not, 1);
    } else {
      power();
    }
    --depth_;
  }
  // `a^b^c` is a^(b^c), and `-x^2` is -(x^2), as in `{expr ...}`.
  void power() {
    primary();
    if (accept("^") || accept("**")) {
      unary();
      emit_operator(ExprOp::power, 2);
    }
  }
  void primary() {
    skip_space();
    if (accept("(")) {
      disjunction();
      if (!accept(")")) fail("')'");
      return;
    }
    if (pos_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.'))
      return number();
    if (pos_ < text_.size() && (std::isalpha(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      return name();
    fail("a number, a variable, a function or '('");
  }
  void number() {
    const char* begin = text_.data() + pos_;
    char* end = nullptr;
    // strtod reads `5x` as 5 (and leaves x), but also hex and `inf`: keep to digits, '.' and exponents.
    size_t n = 0;
    while (pos_ + n < text_.size() &&
           (std::isdigit(static_cast<unsigned char>(text_[pos_ + n])) || text_[pos_ + n] == '.'))
      ++n;
    if (pos_ + n < text_.size() && (text_[pos_ + n] == 'e' || text_[pos_ + n] == 'E')) {
      size_t m = n + 1;
      if (pos_ + m < text_.size() && (text_[pos_ + m] == '+' || text_[pos_ + m] == '-')) ++m;
      if (pos_ + m < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_ + m]))) {
        n = m;
        while (pos_ + n < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_ + n]))) ++n;
      }
    }
    const std::string digits(begin, n);
    const double value = std::strtod(digits.c_str(), &end);
    if (end != digits.c_str() + digits.size()) fail("a number");
    pos_ += n;
    emit_number(value);
  }
  void name() {
    const size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    const std::string_view word = text_.substr(start, pos_ - start);
    if (accept("(")) return call(word, start);
    for (size_t i = 0; i < variables_.size(); ++i)
      if (variables_[i] == word) return emit({.op = ExprOp::variable, .count = std::uint32_t(i)}, 0);
    if (word == "pi") return emit_number(std::numbers::pi);
    pos_ = start;
    std::string names;
    for (std::string_view v : variables_) names += (names.empty() ? "" : ", ") + std::string(v);
    fail("a variable (" + names + "), pi or a function");
  }
  void call(std::string_view word, size_t start) {
    size_t n = 0;
    if (!accept(")")) {
      do {
        disjunction();
        ++n;
      } while (accept(","));
      if (!accept(")")) fail("',' or ')'");
    }
    if (word == "if") {
      if (n != 3) fail_at(start, "if(condition, then, else): 3 arguments");
      return emit_operator(ExprOp::condition, 3);
    }
    const FunctionSignature* f = find_function(word);
    if (!f) fail_at(start, "a known function");
    if (n > max_call_arguments) fail_at(start, "at most 16 arguments");
    if (int(n) < f->min_args || (f->max_args != 0 && int(n) > f->max_args))
      fail_at(start, std::string(f->name) + " with " + std::to_string(f->min_args) + " argument" +
                         (f->min_args == 1 ? "" : "s") + (f->max_args == 0 ? " or more" : ""));
    emit({.op = ExprOp::call, .function = f->function, .count = std::uint32_t(n)}, n);
  }
  [[noreturn]] void fail_at(size_t at, const std::string& expected) {
    pos_ = at;
    fail(expected);
  }

  std::string_view text_;
  std::span<const std::string_view> variables_;
  SourceLocation at_;
  std::vector<Step>& steps_;
  size_t pos_ = 0;
  int depth_ = 0;
  size_t held_ = 0;       // values on the stack after the steps so far
  size_t most_held_ = 0;  // the most at any step
};

}  // namespace

CompiledExpression::CompiledExpression(std::string_view text, std::span<const std::string_view> variables,
                                       SourceLocation at) {
  stack_size_ = BracketReader(text, variables, at, steps_).whole();
}

double CompiledExpression::operator()(std::span<const double> values) const {
  // No allocation for the usual function: an implicit surface runs its program millions of times.
  constexpr size_t usual = 64;
  if (stack_size_ <= usual) {
    std::array<double, usual> stack;
    return run(values, stack.data());
  }
  std::vector<double> stack(stack_size_);
  return run(values, stack.data());
}

double CompiledExpression::run(std::span<const double> values, double* stack) const {
  double* top = stack;  // one past the last value held
  for (const Step& s : steps_) {
    switch (s.op) {
      case ExprOp::number:
        *top++ = s.number;
        break;
      case ExprOp::variable:
        *top++ = values[s.count];
        break;
      case ExprOp::negate:
        top[-1] = -top[-1];
        break;
      case ExprOp::logical_not:
        top[-1] = top[-1] == 0 ? 1 : 0;
        break;
      case ExprOp::condition:
        top -= 2;
        top[-1] = top[-1] != 0 ? top[0] : top[1];
        break;
      case ExprOp::call:
        top -= s.count;
        *top = apply_function(s.function, std::span<const double>(top, s.count));
        ++top;
        break;
      default:
        --top;
        top[-1] = apply_operator(s.op, top[-1], top[0]);
    }
  }
  return stack[0];
}

}  // namespace nome::scene
