#pragma once

#include "nome/scene/statement_kinds.hpp"
#include "nome/scene/sweep.hpp"
#include "scene/definition_context.hpp"

namespace nome::scene {

// The row of `sweep` or `sweepmorph` completed with their shared syntax, names, evaluator and the
// vertex lists of their curves.
StatementKind with_sweep_syntax(StatementKind kind);

// What sweep() is given for a sweep statement: its path's samples, one cross-section per sample for a
// sweepmorph (blended between the control points that give one), and its options.
struct SweepInput {
  std::vector<PathSample> path;
  std::vector<CrossSection> sections;
  SweepOptions options;
};
SweepInput sweep_input(DefinitionContext& context, const SweepDecl& decl);

}  // namespace nome::scene
