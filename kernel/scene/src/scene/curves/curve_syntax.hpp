#pragma once

#include "nome/scene/statement_kinds.hpp"
#include "scene/curves.hpp"

namespace nome::scene {

// A curve's row completed with what beziercurve and bspline share: `keyword NAME [order K] (points)
// [segs N] [closed] end_keyword` (options before or after the list, as JIPCAD's files write them),
// saved as written, named among the definitions, evaluated into a rim line through its samples.
StatementKind with_curve_syntax(StatementKind kind);

// The segment count of a curve (`segs`, JIPCAD's default 8).
int curve_segments(DefinitionContext& context, const CurveDecl& curve);
// The control points of a curve, resolved.
std::vector<CurvePoint> control_points(DefinitionContext& context, const CurveDecl& curve);

}  // namespace nome::scene
