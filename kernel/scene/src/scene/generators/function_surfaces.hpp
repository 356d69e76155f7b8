#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "nome/scene/statement_kinds.hpp"
#include "scene/definition_context.hpp"
#include "scene/generators/function_string.hpp"

namespace nome::scene {

// The function texts of generator `decl` under `keywords`, read over `variables`.
std::vector<FunctionString> read_functions(const DefinitionContext& context, Index decl,
                                           std::initializer_list<std::string_view> keywords,
                                           std::span<const std::string_view> variables);

// A sample range of a function surface: `segs` segments from `min` to `max`.
struct SampleRange {
  double min = 0, max = 1;
  int segs = 1;
  double at(int i) const { return min + (max - min) * i / segs; }
};
// `(min max)` at arguments a[first], a[first + 1] and the segment count at a[count]: max above min.
SampleRange sample_range(DefinitionContext& context, const std::vector<Value>& a, size_t first, size_t count,
                         const char* name);

// A finite value of function `f`, or an EvaluationError at the generator's name saying where it is not.
double finite_value(const DefinitionContext& context, Index decl, double value, std::string_view where);

}  // namespace nome::scene
