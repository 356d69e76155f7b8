#include "nome/scene/expression.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nome/number_text.hpp"

namespace nome::scene {
namespace {

constexpr FunctionSignature functions[] = {
    {"sin", Function::sin, 1, 1, 1},     {"cos", Function::cos, 1, 1, 1},
    {"tan", Function::tan, 1, 1, 1},     {"asin", Function::asin, 1, 1, 1},
    {"acos", Function::acos, 1, 1, 1},   {"atan", Function::atan, 1, 1, 1},
    {"atan2", Function::atan2, 2, 2, 2}, {"sinh", Function::sinh, 0, 1, 1},
    {"cosh", Function::cosh, 0, 1, 1},   {"tanh", Function::tanh, 0, 1, 1},
    {"sqrt", Function::sqrt, 1, 1, 1},   {"abs", Function::abs, 1, 1, 1},
    {"exp", Function::exp, 1, 1, 1},     {"log", Function::log, 1, 1, 1},
    {"log10", Function::log10, 0, 1, 1}, {"floor", Function::floor, 1, 1, 1},
    {"ceil", Function::ceil, 1, 1, 1},   {"round", Function::round, 0, 1, 1},
    {"sgn", Function::sgn, 0, 1, 1},     {"pow", Function::pow, 2, 2, 2},
    {"hypot", Function::hypot, 0, 2, 2}, {"min", Function::min, 2, 1, 0},
    {"max", Function::max, 2, 1, 0},     {"avg", Function::avg, 0, 1, 0},
    {"sum", Function::sum, 0, 1, 0},
};

const char* operator_text(ExprOp op) {
  switch (op) {
    case ExprOp::add:
      return "+";
    case ExprOp::subtract:
      return "-";
    case ExprOp::multiply:
      return "*";
    case ExprOp::divide:
      return "/";
    case ExprOp::modulo:
      return "%";
    case ExprOp::power:
      return "^";
    case ExprOp::less:
      return "<";
    case ExprOp::less_equal:
      return "<=";
    case ExprOp::greater:
      return ">";
    case ExprOp::greater_equal:
      return ">=";
    case ExprOp::equal:
      return "==";
    case ExprOp::not_equal:
      return "!=";
    default:
      return "?";
  }
}

double sum(std::span<const double> a) {
  double s = 0;
  for (double x : a) s += x;
  return s;
}

}  // namespace

ExprId ExpressionPool::add(ExprNode node) {
  nodes_.push_back(std::move(node));
  return static_cast<ExprId>(nodes_.size() - 1);
}

const FunctionSignature* find_function(std::string_view name) {
  for (const FunctionSignature& f : functions)
    if (name == f.name) return &f;
  return nullptr;
}

const char* function_name(Function function) {
  for (const FunctionSignature& f : functions)
    if (f.function == function) return f.name;
  return "?";
}

double apply_function(Function f, std::span<const double> a) {
  switch (f) {
    case Function::sin:
      return std::sin(a[0]);
    case Function::cos:
      return std::cos(a[0]);
    case Function::tan:
      return std::tan(a[0]);
    case Function::asin:
      return std::asin(a[0]);
    case Function::acos:
      return std::acos(a[0]);
    case Function::atan:
      return std::atan(a[0]);
    case Function::atan2:
      return std::atan2(a[0], a[1]);
    case Function::sqrt:
      return std::sqrt(a[0]);
    case Function::abs:
      return std::abs(a[0]);
    case Function::pow:
      return std::pow(a[0], a[1]);
    case Function::exp:
      return std::exp(a[0]);
    case Function::log:
      return std::log(a[0]);
    case Function::floor:
      return std::floor(a[0]);
    case Function::ceil:
      return std::ceil(a[0]);
    case Function::min:
      return *std::min_element(a.begin(), a.end());
    case Function::max:
      return *std::max_element(a.begin(), a.end());
    case Function::sinh:
      return std::sinh(a[0]);
    case Function::cosh:
      return std::cosh(a[0]);
    case Function::tanh:
      return std::tanh(a[0]);
    case Function::log10:
      return std::log10(a[0]);
    case Function::round:
      return std::round(a[0]);
    case Function::sgn:
      return double((a[0] > 0) - (a[0] < 0));
    case Function::hypot:
      return std::hypot(a[0], a[1]);
    case Function::avg:
      return sum(a) / double(a.size());
    case Function::sum:
      return sum(a);
  }
  return 0;
}

double apply_operator(ExprOp op, double a, double b) {
  switch (op) {
    case ExprOp::add:
      return a + b;
    case ExprOp::subtract:
      return a - b;
    case ExprOp::multiply:
      return a * b;
    case ExprOp::divide:
      return a / b;
    case ExprOp::modulo:
      return std::fmod(a, b);
    case ExprOp::power:
      return std::pow(a, b);
    case ExprOp::less:
      return a < b;
    case ExprOp::less_equal:
      return a <= b;
    case ExprOp::greater:
      return a > b;
    case ExprOp::greater_equal:
      return a >= b;
    case ExprOp::equal:
      return a == b;
    case ExprOp::not_equal:
      return a != b;
    case ExprOp::logical_and:
      return a != 0 && b != 0;
    case ExprOp::logical_or:
      return a != 0 || b != 0;
    default:
      return 0;
  }
}

double evaluate(const ExpressionPool& pool, ExprId id, std::span<const double> parameters,
                ParameterReads* reads) {
  const ExprNode& n = pool.node(id);
  auto arg = [&](int i) { return evaluate(pool, n.args[i], parameters, reads); };
  switch (n.op) {
    case ExprOp::number:
      return n.number;
    case ExprOp::pi:
      return std::numbers::pi;
    case ExprOp::parameter:
      if (!n.parameter.is_valid() || n.parameter.index() >= parameters.size())
        throw EvaluationError(n.location, "unknown parameter '$" + n.parameter_name + "'");
      if (reads) reads->push_back(n.parameter);
      return parameters[n.parameter.index()];
    case ExprOp::negate:
      return -arg(0);
    case ExprOp::script:
      if (!pool.script())
        throw EvaluationError(n.location, "this value is a program, and no program runs here");
      return pool.script()->evaluate(n.script_expression, parameters, reads);
    case ExprOp::call: {
      const double a = arg(0);
      const double b = n.args[1] == no_index ? 0.0 : arg(1);
      const double both[2] = {a, b};
      const double result =
          apply_function(n.function, std::span<const double>(both, n.args[1] == no_index ? 1 : 2));
      if (!std::isfinite(result))
        throw EvaluationError(n.location, std::string(function_name(n.function)) + "(" + format_number(a) +
                                              (n.args[1] == no_index ? "" : ", " + format_number(b)) +
                                              ") is not a finite number");
      return result;
    }
    default:
      break;
  }
  const double a = arg(0), b = arg(1);
  if (b == 0 && (n.op == ExprOp::divide || n.op == ExprOp::modulo))
    throw EvaluationError(n.location, std::string("division by zero in '") + operator_text(n.op) + "'");
  const double result = apply_operator(n.op, a, b);
  if (!std::isfinite(result))
    throw EvaluationError(n.location,
                          std::string("the result of '") + operator_text(n.op) + "' is not finite");
  return result;
}

double evaluate(const ExpressionPool& pool, const Value& value, std::span<const double> parameters,
                ParameterReads* reads) {
  return value.expr == no_index ? value.literal : evaluate(pool, value.expr, parameters, reads);
}

std::string format_number(double x) {
  char buffer[64];
  const auto r = shortest_to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, r.ptr);
}

std::string to_source(const ExpressionPool& pool, ExprId id) {
  const ExprNode& n = pool.node(id);
  switch (n.op) {
    case ExprOp::number:
      return n.number < 0 ? "(" + format_number(n.number) + ")" : format_number(n.number);
    case ExprOp::pi:
      return "pi";
    case ExprOp::parameter:
      return "$" + n.parameter_name;
    case ExprOp::negate:
      return "(-" + to_source(pool, n.args[0]) + ")";
    case ExprOp::script:
      return pool.script() ? "{" + pool.script()->text(n.script_expression) + "}" : "{}";
    case ExprOp::call:
      return std::string(function_name(n.function)) + "(" + to_source(pool, n.args[0]) +
             (n.args[1] == no_index ? "" : ", " + to_source(pool, n.args[1])) + ")";
    default:
      return "(" + to_source(pool, n.args[0]) + " " + operator_text(n.op) + " " + to_source(pool, n.args[1]) +
             ")";
  }
}

std::string to_source(const ExpressionPool& pool, const Value& value) {
  if (value.expr == no_index) return format_number(value.literal);
  if (pool.node(value.expr).op == ExprOp::script) return to_source(pool, value.expr);
  return "{expr " + to_source(pool, value.expr) + "}";
}

}  // namespace nome::scene
