#include "nome/scene/expression.hpp"

#include <charconv>
#include <cmath>
#include <numbers>

namespace nome::scene {
namespace {

struct FunctionInfo {
  const char* name;
  Function function;
  int arity;
};

constexpr FunctionInfo functions[] = {
    {"sin", Function::sin, 1},     {"cos", Function::cos, 1},   {"tan", Function::tan, 1},
    {"asin", Function::asin, 1},   {"acos", Function::acos, 1}, {"atan", Function::atan, 1},
    {"atan2", Function::atan2, 2}, {"sqrt", Function::sqrt, 1}, {"abs", Function::abs, 1},
    {"pow", Function::pow, 2},     {"exp", Function::exp, 1},   {"log", Function::log, 1},
    {"floor", Function::floor, 1}, {"ceil", Function::ceil, 1}, {"min", Function::min, 2},
    {"max", Function::max, 2},
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

double apply(Function f, double a, double b) {
  switch (f) {
    case Function::sin:
      return std::sin(a);
    case Function::cos:
      return std::cos(a);
    case Function::tan:
      return std::tan(a);
    case Function::asin:
      return std::asin(a);
    case Function::acos:
      return std::acos(a);
    case Function::atan:
      return std::atan(a);
    case Function::atan2:
      return std::atan2(a, b);
    case Function::sqrt:
      return std::sqrt(a);
    case Function::abs:
      return std::abs(a);
    case Function::pow:
      return std::pow(a, b);
    case Function::exp:
      return std::exp(a);
    case Function::log:
      return std::log(a);
    case Function::floor:
      return std::floor(a);
    case Function::ceil:
      return std::ceil(a);
    case Function::min:
      return std::min(a, b);
    case Function::max:
      return std::max(a, b);
  }
  return 0;
}

}  // namespace

ExprId ExpressionPool::add(ExprNode node) {
  nodes_.push_back(std::move(node));
  return static_cast<ExprId>(nodes_.size() - 1);
}

bool find_function(const std::string& name, Function& function, int& arity) {
  for (const FunctionInfo& f : functions)
    if (name == f.name) {
      function = f.function;
      arity = f.arity;
      return true;
    }
  return false;
}

const char* function_name(Function function) {
  for (const FunctionInfo& f : functions)
    if (f.function == function) return f.name;
  return "?";
}

namespace {

// An arithmetic or comparison operator on its two evaluated operands.
double binary(ExprOp op, double a, double b) {
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
    default:
      return 0;
  }
}

}  // namespace

double evaluate(const ExpressionPool& pool, ExprId id, std::span<const double> parameters,
                std::vector<Index>* reads) {
  const ExprNode& n = pool.node(id);
  auto arg = [&](int i) { return evaluate(pool, n.args[i], parameters, reads); };
  switch (n.op) {
    case ExprOp::number:
      return n.number;
    case ExprOp::pi:
      return std::numbers::pi;
    case ExprOp::parameter:
      if (n.parameter >= parameters.size())
        throw EvaluationError(n.location, "unknown parameter '$" + n.parameter_name + "'");
      if (reads) reads->push_back(n.parameter);
      return parameters[n.parameter];
    case ExprOp::negate:
      return -arg(0);
    case ExprOp::call: {
      const double a = arg(0);
      const double b = n.args[1] == no_index ? 0.0 : arg(1);
      const double result = apply(n.function, a, b);
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
  const double result = binary(n.op, a, b);
  if (!std::isfinite(result))
    throw EvaluationError(n.location,
                          std::string("the result of '") + operator_text(n.op) + "' is not finite");
  return result;
}

double evaluate(const ExpressionPool& pool, const Value& value, std::span<const double> parameters,
                std::vector<Index>* reads) {
  return value.expr == no_index ? value.literal : evaluate(pool, value.expr, parameters, reads);
}

std::string format_number(double x) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
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
  return "{expr " + to_source(pool, value.expr) + "}";
}

}  // namespace nome::scene
