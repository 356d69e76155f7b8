#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "nome/scene/diagnostic.hpp"

namespace nome::scene {

// A function written in brackets by JIPCAD's function surfaces (`func [(7*x*y)/exp((x^2)+(y^2))]`): the
// arithmetic of `{expr ...}` (+ - * / % ^, comparisons, the same functions, radians) over the surface's
// variables, extended to what JIPCAD's files write there (its exprtk language): implicit products
// (`5x`, `10(x+1)`), `sinh cosh tanh log10 round sgn hypot`, `min max avg` of any count,
// `if(condition, then, else)`, `and`, `or`, `not`, and `=` for equality.
class FunctionString {
 public:
  // Reads `text` over `variables` (`x y`, `u v`, ...). Throws EvaluationError at `at` (the '[') for text
  // that is not such a function, naming what was expected and where in the brackets.
  FunctionString(std::string_view text, std::span<const std::string_view> variables, SourceLocation at);

  // The value at the variables' values (in the order given); NaN where the function is undefined.
  double operator()(std::span<const double> values) const;

  enum class Op {
    number,
    variable,
    negate,
    logical_not,
    add,
    subtract,
    multiply,
    divide,
    modulo,
    power,
    less,
    less_equal,
    greater,
    greater_equal,
    equal,
    not_equal,
    logical_and,
    logical_or,
    condition,
    call
  };
  struct Node {
    Op op = Op::number;
    double number = 0;  // Op::number; the variable's index for Op::variable
    int function = 0;   // Op::call: index into the function table
    std::vector<int> args;
  };

 private:
  double evaluate(int node, std::span<const double> values) const;

  std::vector<Node> nodes_;
  int root_ = 0;
};

}  // namespace nome::scene
