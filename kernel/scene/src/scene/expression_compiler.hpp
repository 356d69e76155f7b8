#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "nome/scene/expression.hpp"

namespace nome::scene {

// An expression over named variables (`x y`, `u v`, `x y z`), compiled once into a flat program that a
// generator runs at each of its samples: JIPCAD's bracketed functions (`func [(7*x*y)/exp((x^2)+(y^2))]`).
// Its operators and functions are those of `{expr ...}` (radians), extended to what JIPCAD's files write
// there (its exprtk language): implied products (`5x`, `10(x+1)`), `sinh cosh tanh log10 round sgn hypot`,
// `min max avg sum` of any count, `if(condition, then, else)`, `and`, `or`, `not`, and `=` for equality.
class CompiledExpression {
 public:
  // Compiles `text` over `variables`. Throws EvaluationError at `at` (the '[') for text that is not such a
  // function, naming what was expected and where in the brackets.
  CompiledExpression(std::string_view text, std::span<const std::string_view> variables, SourceLocation at);

  // The value at the variables' values (in the order given); NaN where the function is undefined.
  double operator()(std::span<const double> values) const;

  // One step of the program, on a stack of values: pushes a number or a variable, or replaces the values
  // on top by an operator's or a function's result.
  struct Step {
    ExprOp op = ExprOp::number;
    Function function = Function::sin;  // ExprOp::call
    std::uint32_t count = 0;            // ExprOp::call: its arguments; ExprOp::variable: its index
    double number = 0;                  // ExprOp::number
  };

 private:
  double run(std::span<const double> values, double* stack) const;

  std::vector<Step> steps_;
  std::size_t stack_size_ = 0;  // the most values the program holds at once
};

}  // namespace nome::scene
