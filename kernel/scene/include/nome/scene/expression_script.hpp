#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>

#include "nome/scene/ids.hpp"

namespace nome::scene {

// A program inside the scene text that computes some of its values (SLIDE's Tcl): an ExprOp::script node
// names one of its expressions. The program reads sliders through its own variables, each bound to one
// of the scene's parameters, so that moving a slider re-evaluates what read its variable.
class ExpressionScript {
 public:
  virtual ~ExpressionScript() = default;
  // Binds the script's slider variables to the scene's parameters, found by full name (`find` gives none
  // for an unknown name); the scene calls it once its parameters are registered.
  virtual void bind(const std::function<std::optional<ParameterId>(const std::string&)>& find) = 0;
  // The value of expression `expression` with the parameters' current values; appends every parameter it
  // read to `reads` when given. Throws EvaluationError located at the expression.
  virtual double evaluate(Index expression, std::span<const double> parameters, ParameterReads* reads) = 0;
  // The expression as written, for saving and messages.
  virtual std::string text(Index expression) const = 0;
};

}  // namespace nome::scene
