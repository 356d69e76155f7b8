#include "scene/generators/function_string.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "nome/scene/expression.hpp"

namespace nome::scene {
namespace {

constexpr size_t max_call_arguments = 16;

struct FunctionInfo {
  const char* name;
  int min_args, max_args;  // max 0: any count from min_args
  double (*apply)(std::span<const double> a);
};

double sum(std::span<const double> a) {
  double s = 0;
  for (double x : a) s += x;
  return s;
}

constexpr FunctionInfo functions[] = {
    {"sin", 1, 1, [](auto a) { return std::sin(a[0]); }},
    {"cos", 1, 1, [](auto a) { return std::cos(a[0]); }},
    {"tan", 1, 1, [](auto a) { return std::tan(a[0]); }},
    {"asin", 1, 1, [](auto a) { return std::asin(a[0]); }},
    {"acos", 1, 1, [](auto a) { return std::acos(a[0]); }},
    {"atan", 1, 1, [](auto a) { return std::atan(a[0]); }},
    {"atan2", 2, 2, [](auto a) { return std::atan2(a[0], a[1]); }},
    {"sinh", 1, 1, [](auto a) { return std::sinh(a[0]); }},
    {"cosh", 1, 1, [](auto a) { return std::cosh(a[0]); }},
    {"tanh", 1, 1, [](auto a) { return std::tanh(a[0]); }},
    {"sqrt", 1, 1, [](auto a) { return std::sqrt(a[0]); }},
    {"abs", 1, 1, [](auto a) { return std::abs(a[0]); }},
    {"exp", 1, 1, [](auto a) { return std::exp(a[0]); }},
    {"log", 1, 1, [](auto a) { return std::log(a[0]); }},
    {"log10", 1, 1, [](auto a) { return std::log10(a[0]); }},
    {"floor", 1, 1, [](auto a) { return std::floor(a[0]); }},
    {"ceil", 1, 1, [](auto a) { return std::ceil(a[0]); }},
    {"round", 1, 1, [](auto a) { return std::round(a[0]); }},
    {"sgn", 1, 1, [](auto a) { return double((a[0] > 0) - (a[0] < 0)); }},
    {"pow", 2, 2, [](auto a) { return std::pow(a[0], a[1]); }},
    {"hypot", 2, 2, [](auto a) { return std::hypot(a[0], a[1]); }},
    {"min", 1, 0, [](auto a) { return *std::min_element(a.begin(), a.end()); }},
    {"max", 1, 0, [](auto a) { return *std::max_element(a.begin(), a.end()); }},
    {"avg", 1, 0, [](auto a) { return sum(a) / double(a.size()); }},
    {"sum", 1, 0, sum},
};

using Op = FunctionString::Op;
using Node = FunctionString::Node;

// Recursive descent over the bracket text, loosest binding first: or, and, comparison, sum, product
// (written or implied), unary, power, primary.
class Reader {
 public:
  Reader(std::string_view text, std::span<const std::string_view> variables, SourceLocation at,
         std::vector<Node>& nodes)
      : text_(text), variables_(variables), at_(at), nodes_(nodes) {}

  int whole() {
    const int root = disjunction();
    skip_space();
    if (pos_ < text_.size()) fail("an operator or ']'");
    return root;
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
  int add(Op op, std::vector<int> args, double number = 0, int function = 0) {
    nodes_.push_back({op, number, function, std::move(args)});
    return int(nodes_.size()) - 1;
  }

  int disjunction() {
    int left = conjunction();
    while (accept_word("or") || accept("||") || accept("|"))
      left = add(Op::logical_or, {left, conjunction()});
    return left;
  }
  int conjunction() {
    int left = comparison();
    while (accept_word("and") || accept("&&") || accept("&"))
      left = add(Op::logical_and, {left, comparison()});
    return left;
  }
  int comparison() {
    const int left = sum();
    static constexpr std::pair<std::string_view, Op> ops[] = {
        {"<=", Op::less_equal}, {">=", Op::greater_equal}, {"==", Op::equal},  {"!=", Op::not_equal},
        {"<>", Op::not_equal},  {"<", Op::less},           {">", Op::greater}, {"=", Op::equal}};
    for (auto [text, op] : ops)
      if (accept(text)) return add(op, {left, sum()});
    return left;
  }
  int sum() {
    int left = product();
    for (;;) {
      if (accept("+"))
        left = add(Op::add, {left, product()});
      else if (accept("-"))
        left = add(Op::subtract, {left, product()});
      else
        return left;
    }
  }
  // What may follow a factor with an implied `*`: a number, a name or '(' (`5x`, `2(x+1)`, `(x)(y)`).
  bool starts_implied_factor() {
    skip_space();
    if (pos_ >= text_.size() || is_at_word("and") || is_at_word("or")) return false;
    const char c = text_[pos_];
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '(';
  }
  int product() {
    int left = unary();
    for (;;) {
      if (accept("*"))
        left = add(Op::multiply, {left, unary()});
      else if (accept("/"))
        left = add(Op::divide, {left, unary()});
      else if (accept("%"))
        left = add(Op::modulo, {left, unary()});
      else if (starts_implied_factor())
        left = add(Op::multiply, {left, power()});
      else
        return left;
    }
  }
  int unary() {
    if (++depth_ > max_depth) fail("a shallower expression (nested over 200 levels)");
    int result = 0;
    if (accept("-"))
      result = add(Op::negate, {unary()});
    else if (accept("+"))
      result = unary();
    else if (accept_word("not") || accept("!"))
      result = add(Op::logical_not, {unary()});
    else
      result = power();
    --depth_;
    return result;
  }
  // `a^b^c` is a^(b^c), and `-x^2` is -(x^2), as in `{expr ...}`.
  int power() {
    const int base = primary();
    if (accept("^") || accept("**")) return add(Op::power, {base, unary()});
    return base;
  }
  int primary() {
    skip_space();
    if (accept("(")) {
      const int inner = disjunction();
      if (!accept(")")) fail("')'");
      return inner;
    }
    if (pos_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.'))
      return number();
    if (pos_ < text_.size() && (std::isalpha(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      return name();
    fail("a number, a variable, a function or '('");
  }
  int number() {
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
    return add(Op::number, {}, value);
  }
  int name() {
    const size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    const std::string_view word = text_.substr(start, pos_ - start);
    if (accept("(")) return call(word, start);
    for (size_t i = 0; i < variables_.size(); ++i)
      if (variables_[i] == word) return add(Op::variable, {}, double(i));
    if (word == "pi") return add(Op::number, {}, std::numbers::pi);
    pos_ = start;
    std::string names;
    for (std::string_view v : variables_) names += (names.empty() ? "" : ", ") + std::string(v);
    fail("a variable (" + names + "), pi or a function");
  }
  int call(std::string_view word, size_t start) {
    std::vector<int> args;
    if (!accept(")")) {
      do args.push_back(disjunction());
      while (accept(","));
      if (!accept(")")) fail("',' or ')'");
    }
    if (word == "if") {
      if (args.size() != 3) fail_at(start, "if(condition, then, else): 3 arguments");
      return add(Op::condition, std::move(args));
    }
    const auto* f = std::find_if(std::begin(functions), std::end(functions),
                                 [&](const FunctionInfo& fi) { return fi.name == word; });
    if (f == std::end(functions)) fail_at(start, "a known function");
    if (args.size() > max_call_arguments) fail_at(start, "at most 16 arguments");
    const int n = int(args.size());
    if (n < f->min_args || (f->max_args != 0 && n > f->max_args))
      fail_at(start, std::string(f->name) + " with " + std::to_string(f->min_args) + " argument" +
                         (f->min_args == 1 ? "" : "s") + (f->max_args == 0 ? " or more" : ""));
    return add(Op::call, std::move(args), 0, int(f - std::begin(functions)));
  }
  [[noreturn]] void fail_at(size_t at, const std::string& expected) {
    pos_ = at;
    fail(expected);
  }

  std::string_view text_;
  std::span<const std::string_view> variables_;
  SourceLocation at_;
  std::vector<Node>& nodes_;
  size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

FunctionString::FunctionString(std::string_view text, std::span<const std::string_view> variables,
                               SourceLocation at) {
  root_ = Reader(text, variables, at, nodes_).whole();
}

double FunctionString::operator()(std::span<const double> values) const {
  return evaluate(root_, values);
}

double FunctionString::evaluate(int id, std::span<const double> values) const {
  const Node& n = nodes_[size_t(id)];
  auto arg = [&](size_t k) { return evaluate(n.args[k], values); };
  switch (n.op) {
    case Op::number:
      return n.number;
    case Op::variable:
      return values[size_t(n.number)];
    case Op::negate:
      return -arg(0);
    case Op::logical_not:
      return arg(0) == 0 ? 1 : 0;
    case Op::add:
      return arg(0) + arg(1);
    case Op::subtract:
      return arg(0) - arg(1);
    case Op::multiply:
      return arg(0) * arg(1);
    case Op::divide:
      return arg(0) / arg(1);
    case Op::modulo:
      return std::fmod(arg(0), arg(1));
    case Op::power:
      return std::pow(arg(0), arg(1));
    case Op::less:
      return arg(0) < arg(1);
    case Op::less_equal:
      return arg(0) <= arg(1);
    case Op::greater:
      return arg(0) > arg(1);
    case Op::greater_equal:
      return arg(0) >= arg(1);
    case Op::equal:
      return arg(0) == arg(1);
    case Op::not_equal:
      return arg(0) != arg(1);
    case Op::logical_and:
      return arg(0) != 0 && arg(1) != 0;
    case Op::logical_or:
      return arg(0) != 0 || arg(1) != 0;
    case Op::condition:
      return arg(0) != 0 ? arg(1) : arg(2);
    case Op::call: {
      // No allocation: an implicit surface calls this a million times.
      std::array<double, max_call_arguments> a{};
      for (size_t k = 0; k < n.args.size(); ++k) a[k] = arg(k);
      return functions[n.function].apply(std::span<const double>(a.data(), n.args.size()));
    }
  }
  return std::nan("");
}

}  // namespace nome::scene
