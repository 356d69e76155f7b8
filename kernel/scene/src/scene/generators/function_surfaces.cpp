#include "scene/generators/function_surfaces.hpp"

#include <cmath>

#include "scene/generators/generator_support.hpp"

namespace nome::scene {

std::vector<CompiledExpression> read_functions(const DefinitionContext& context, Index decl,
                                               std::initializer_list<std::string_view> keywords,
                                               std::span<const std::string_view> variables) {
  std::vector<CompiledExpression> result;
  for (const FunctionText* f : generator_functions(context, decl, keywords))
    result.emplace_back(f->text, variables, f->location);
  return result;
}

SampleRange sample_range(DefinitionContext& context, const std::vector<Value>& a, size_t first, size_t count,
                         const char* name) {
  SampleRange r{context.number(a[first]), context.number(a[first + 1]), 1};
  if (!(r.min < r.max))
    throw EvaluationError(a[first + 1].location, std::string(name) + "_max must be above " + name + "_min");
  r.segs = context.whole(a[count], 1, (std::string(name) + "_segs").c_str());
  return r;
}

void throw_not_finite(const DefinitionContext& context, Index decl, std::string_view where) {
  const GeneratorDecl& g = context.ast().generators[decl];
  throw EvaluationError(g.functions.empty() ? g.name.location : g.functions.front().location,
                        "the function of '" + g.name.text + "' has no finite value at " + std::string(where));
}

}  // namespace nome::scene
