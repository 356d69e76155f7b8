// `beziercurve NAME (p1 p2 ...) [segs N] endbeziercurve`: one Bézier curve over all its points.
#include <cmath>

#include "scene/curves/curve_syntax.hpp"

namespace nome::scene {
namespace {

// de Casteljau on the points' positions, scales and turns alike.
CurvePoint at(std::vector<CurvePoint> p, double t) {
  for (std::size_t size = p.size(); size > 1; --size)
    for (std::size_t i = 0; i + 1 < size; ++i) {
      p[i].position = (1 - t) * p[i].position + t * p[i + 1].position;
      p[i].scale = (1 - t) * p[i].scale + t * p[i + 1].scale;
      p[i].rotate = (1 - t) * p[i].rotate + t * p[i + 1].rotate;
    }
  return {p[0].position, p[0].scale, p[0].rotate};
}

SampledCurve sample_bezier_curve(DefinitionContext& context, Index decl) {
  const CurveDecl& c = context.ast().curves[decl];
  const int segs = curve_segments(context, c);
  const std::vector<CurvePoint> cps = control_points(context, c);
  SampledCurve curve;
  for (int s = 0; s <= segs; ++s) curve.points.push_back(at(cps, double(s) / segs));
  // A control point's own cross-section and reversal land on the sample where it weighs most.
  for (std::size_t i = 0; i < cps.size(); ++i) {
    if (!cps[i].section && !cps[i].is_reversing) continue;
    CurvePoint& p = curve.points[std::size_t(std::lround(double(segs) * double(i) / double(cps.size() - 1)))];
    if (cps[i].section) p.section = cps[i].section;
    p.is_reversing = p.is_reversing != cps[i].is_reversing;
  }
  if (c.is_closed) curve.points.push_back(curve.points.front());
  close_if_repeated(curve);
  return curve;
}

void vertex_lists_bezier_curve(const DefinitionScope& scope, Index decl,
                               std::vector<const std::vector<Name>*>& out) {
  out.push_back(&scope.ast().curves[decl].points);
}

}  // namespace

StatementKind bezier_curve_statement() {
  return with_curve_syntax({.keyword = "beziercurve",
                            .end_keyword = "endbeziercurve",
                            .dialect = StatementDialect::successor,
                            .vertex_lists = vertex_lists_bezier_curve,
                            .sample = sample_bezier_curve,
                            .example = "(p0 p1 p2) segs 4"});
}

}  // namespace nome::scene
