#pragma once

#include <array>
#include <cmath>
#include <string_view>
#include <vector>

#include "nome/scene/statement_kinds.hpp"
#include "scene/definition_context.hpp"
#include "scene/expression_compiler.hpp"

namespace nome::scene {

// The function texts of generator `decl` under `keywords`, read over `variables`.
std::vector<CompiledExpression> read_functions(const DefinitionContext& context, Index decl,
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

// An EvaluationError at generator `decl`'s function saying where (`where`, a sample) it has no finite value.
[[noreturn]] void throw_not_finite(const DefinitionContext& context, Index decl, std::string_view where);

// `value` if finite; otherwise throw_not_finite() with the text `where()` gives. The text is made only
// then: a function surface asks at each of millions of samples.
template <typename Where>
double finite_value(const DefinitionContext& context, Index decl, double value, const Where& where) {
  if (!std::isfinite(value)) throw_not_finite(context, decl, where());
  return value;
}

}  // namespace nome::scene
