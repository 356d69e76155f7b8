#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "nome/error.hpp"
#include "nome/mesh/types.hpp"
#include "nome/scene/diagnostic.hpp"
#include "nome/scene/expression_script.hpp"
#include "nome/scene/ids.hpp"

namespace nome::scene {

using ExprId = Index;

enum class ExprOp {
  number,
  parameter,
  pi,
  negate,
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
  call,
  // Only in JIPCAD's bracketed functions (expression_compiler.hpp):
  variable,
  logical_not,
  logical_and,
  logical_or,
  condition,
  // A value the scene's script computes (ExpressionScript, SLIDE's Tcl).
  script
};

enum class Function {
  sin,
  cos,
  tan,
  asin,
  acos,
  atan,
  atan2,
  sqrt,
  abs,
  pow,
  exp,
  log,
  floor,
  ceil,
  min,
  max,
  // Only in JIPCAD's bracketed functions:
  sinh,
  cosh,
  tanh,
  log10,
  round,
  sgn,
  hypot,
  avg,
  sum
};

// One node of an expression tree; children are ids into the same pool.
struct ExprNode {
  ExprOp op = ExprOp::number;
  double number = 0;                      // ExprOp::number
  std::string parameter_name;             // ExprOp::parameter, normalised `bank_name`
  ParameterId parameter;                  // resolved: the scene's value it reads
  Function function = Function::sin;      // ExprOp::call
  ExprId args[2] = {no_index, no_index};  // operands / call arguments
  Index script_expression = no_index;     // ExprOp::script: which of the script's expressions
  SourceLocation location;
};

// The arithmetic of `{expr ...}`: nodes of every expression of one scene, index-based.
class ExpressionPool {
 public:
  ExprId add(ExprNode node);
  const ExprNode& node(ExprId id) const { return nodes_[id]; }
  ExprNode& node(ExprId id) { return nodes_[id]; }
  Index size() const { return static_cast<Index>(nodes_.size()); }
  // The script that computes the ExprOp::script nodes; shared by copies of the scene.
  ExpressionScript* script() const { return script_.get(); }
  void set_script(std::shared_ptr<ExpressionScript> script) { script_ = std::move(script); }

 private:
  std::vector<ExprNode> nodes_;
  std::shared_ptr<ExpressionScript> script_;
};

// A number slot of the language: a literal or an expression (`{expr ...}`), with where it stands.
struct Value {
  double literal = 0;
  ExprId expr = no_index;
  SourceLocation location;
};

// An expression that cannot be computed (division by zero, a non-finite result, an unresolved name).
class EvaluationError : public Error {
 public:
  EvaluationError(SourceLocation where, const std::string& message) : Error(message), where_(where) {}
  SourceLocation where() const { return where_; }

 private:
  SourceLocation where_;
};

// Evaluates with the given parameter values (radians for trigonometry). Appends every parameter read to
// `reads` when given. Throws EvaluationError with the location of the offending operation.
double evaluate(const ExpressionPool& pool, ExprId id, std::span<const double> parameters,
                ParameterReads* reads = nullptr);
double evaluate(const ExpressionPool& pool, const Value& value, std::span<const double> parameters,
                ParameterReads* reads = nullptr);

// The expression as source text that parses back to the same tree (`$bank_name` references).
std::string to_source(const ExpressionPool& pool, ExprId id);
// A value as source text: a literal (shortest exact form) or `{expr ...}`.
std::string to_source(const ExpressionPool& pool, const Value& value);
// The shortest text that reads back as exactly `x`.
std::string format_number(double x);

// A function by name, with its argument counts: in `{expr ...}` exactly `arity` (0: not there); in JIPCAD's
// bracketed functions from `min_args` to `max_args` (0: any count).
struct FunctionSignature {
  const char* name;
  Function function;
  int arity;
  int min_args, max_args;
};
// The function of a name (`sin`, `atan2`, ...), or null.
const FunctionSignature* find_function(std::string_view name);
const char* function_name(Function function);

// The value of a function at its arguments (radians); NaN or infinite where it is undefined.
double apply_function(Function function, std::span<const double> args);
// The value of a binary operator (add to not_equal, logical_and, logical_or): comparisons and logic give 1
// or 0, `%` is the floating remainder.
double apply_operator(ExprOp op, double a, double b);

}  // namespace nome::scene
