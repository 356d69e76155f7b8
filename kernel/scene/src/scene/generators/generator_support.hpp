#pragma once

#include <initializer_list>
#include <string_view>
#include <vector>

#include "nome/scene/statement_kinds.hpp"
#include "scene/definition_context.hpp"

namespace nome::scene {

// The arguments of generator `decl`, as written.
const std::vector<Value>& generator_arguments(const DefinitionContext& context, Index decl);
// Refuses generator `decl` before it makes its piece when about `faces` faces would pass the scene's
// budget (DefinitionContext::expect_faces, at the statement's name).
void expect_generator_faces(const DefinitionContext& context, Index decl, double faces);

// Which of the `known` option words (`botcap`, `topcap`) generator `decl` was written with; an unknown one
// is an EvaluationError at its place.
std::vector<bool> generator_options(const DefinitionContext& context, Index decl,
                                    std::initializer_list<std::string_view> known);
// The function texts of generator `decl` in the order of `keywords` (`funcX`, `funcY`, ...): each must be
// written once, and no other.
std::vector<const FunctionText*> generator_functions(const DefinitionContext& context, Index decl,
                                                     std::initializer_list<std::string_view> keywords);

// Appends an n-gon ring of named vertices (`prefix` + i, at 360*i/n degrees from +x) of the given radius
// in the plane z; returns the id of its first vertex.
Index ring(Piece& piece, int n, double radius, double z, const char* prefix);
// Quads joining ring `lower` to ring `upper` (each n vertices), normals pointing away from the axis.
void band(Piece& piece, int n, Index lower, Index upper, const char* prefix);
// A number in [lo, hi] (an angle, a fraction); otherwise an EvaluationError at its place naming `what`.
double number_in(DefinitionContext& context, const Value& v, double lo, double hi, const char* what);

// A number >= 0.
double non_negative(DefinitionContext& context, const Value& v, const char* what);
// An angle of sweep in degrees, in (0, 360].
double sweep_degrees(DefinitionContext& context, const Value& v, const char* what);

// Throws InvalidInputError(message) unless `is_ok`: the generators' own preconditions.
void require(bool is_ok, const char* message);

}  // namespace nome::scene
