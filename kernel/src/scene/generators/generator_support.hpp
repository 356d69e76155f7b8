#pragma once

#include <vector>

#include "nome/scene/statement_kinds.hpp"
#include "scene/definition_context.hpp"

namespace nome::scene {

// A generator's row completed with what all generators share: `keyword NAME (arguments) end_keyword`
// parsed with the row's argument counts and signature, saved as written, named in the definitions.
StatementKind with_generator_syntax(StatementKind kind);

// The arguments of generator `decl`, as written.
const std::vector<Value>& generator_arguments(const DefinitionContext& context, Index decl);

// Appends an n-gon ring of named vertices (`prefix` + i, at 360*i/n degrees from +x) of the given radius
// in the plane z; returns the id of its first vertex.
Index ring(Piece& piece, int n, double radius, double z, const char* prefix);
// Quads joining ring `lower` to ring `upper` (each n vertices), normals pointing away from the axis.
void band(Piece& piece, int n, Index lower, Index upper, const char* prefix);
// Throws InvalidInputError(message) unless `is_ok`: the generators' own preconditions.
void require(bool is_ok, const char* message);

}  // namespace nome::scene
