// `bspline NAME [order K] (p1 p2 ...) [segs N] [closed] endbspline`: a uniform B-spline of degree K-1.
#include <cmath>

#include "scene/curves/curve_syntax.hpp"

namespace nome::scene {
namespace {

// The K non-zero basis functions at t over the integer knots 0, 1, 2, ... whose span starts at knot r
// (The NURBS Book, algorithm A2.2).
void basis(double t, int r, int order, std::vector<double>& n) {
  const std::size_t k = std::size_t(order);
  std::vector<double> left(k, 0.0), right(k, 0.0);
  n.assign(k, 0.0);
  n[0] = 1;
  for (std::size_t j = 1; j < k; ++j) {
    left[j] = t - (double(r) + 1 - double(j));
    right[j] = double(r) + double(j) - t;
    double saved = 0;
    for (std::size_t q = 0; q < j; ++q) {
      const double temp = n[q] / (right[q + 1] + left[j - q]);
      n[q] = saved + right[q + 1] * temp;
      saved = left[j - q] * temp;
    }
    n[j] = saved;
  }
}

// The curve's segs + 1 samples, evenly spaced in the parameter over the span (count - K + 1 knots) where
// all K basis functions live: positions, scales and rotations blended alike.
SampledCurve sampled_points(const std::vector<CurvePoint>& cps, int order, double span, int segs) {
  const int count = int(cps.size());
  SampledCurve curve;
  std::vector<double> n;
  for (int s = 0; s <= segs; ++s) {
    const double t = double(order - 1) + span * s / segs;
    const int r = std::min(int(std::floor(t)), count - 1);
    basis(t, r, order, n);
    CurvePoint p{Vec3(0.0), glm::dvec2(0.0), Vec3(0.0)};
    const std::size_t base = std::size_t(r) + 1 - std::size_t(order);
    for (std::size_t k = 0; k < n.size(); ++k) {
      const CurvePoint& cp = cps[base + k];
      p.position += n[k] * cp.position;
      p.scale += n[k] * cp.scale;
      p.rotate += n[k] * cp.rotate;
    }
    curve.points.push_back(p);
  }
  return curve;
}

// JIPCAD's curve: uniform knots, sampled over the parameters where a full set of K basis functions
// lives, so it starts and ends near (not at) the end points. Closed: the first K-1 points again at the end.
SampledCurve sample_bspline(DefinitionContext& context, Index decl) {
  const CurveDecl& c = context.ast().curves[decl];
  const int order = c.order ? context.whole(*c.order, 2, "order") : 3;
  const int segs = curve_segments(context, c);
  std::vector<CurvePoint> cps = control_points(context, c);
  if (c.is_closed)
    for (int i = 0; i < order - 1 && std::size_t(i) < c.points.size(); ++i) {
      const CurvePoint again = cps[std::size_t(i)];
      cps.push_back(again);
    }
  const int count = int(cps.size());
  if (count < order)
    throw EvaluationError(c.name.location, "bspline '" + c.name.text + "' of order " + std::to_string(order) +
                                               " needs at least " + std::to_string(order) +
                                               " points, found " + std::to_string(count));
  const double span = double(count - order + 1);
  SampledCurve curve = sampled_points(cps, order, span, segs);
  // A control point's own cross-section and reversal land where it weighs most: its basis peaks at i + K/2.
  const auto peak = [&](int i) { return std::lround((i + order / 2.0 - (order - 1)) / span * segs); };
  for (int i = 0; i < count; ++i) {
    const CurvePoint& cp = cps[std::size_t(i)];
    if (!cp.section && !cp.is_reversing) continue;
    const long s = peak(i);
    if (s < 0 || s > segs) continue;
    if (cp.section) curve.points[std::size_t(s)].section = cp.section;
    curve.points[std::size_t(s)].is_reversing = curve.points[std::size_t(s)].is_reversing != cp.is_reversing;
  }
  close_if_repeated(curve);
  // An open curve's end points peak before its first sample or after its last: as in JIPCAD, their
  // cross-sections go to the end samples (a sweepmorph runs from the first section to the last), the
  // point nearest the curve winning and one that peaks on the end sample itself winning over both. A
  // closed curve's repeated points bring theirs in already.
  if (!c.is_closed && !curve.is_closed) {
    const auto nearest = [&](int from, int step, auto is_outside) {
      const Name* section = nullptr;
      for (int i = from; i >= 0 && i < count && is_outside(peak(i)); i += step)
        if (cps[std::size_t(i)].section) section = cps[std::size_t(i)].section;
      return section;
    };
    const Name* first = nearest(0, 1, [](long s) { return s < 0; });
    const Name* last = nearest(count - 1, -1, [&](long s) { return s > segs; });
    if (first && !curve.points.front().section) curve.points.front().section = first;
    if (last && !curve.points.back().section) curve.points.back().section = last;
  }
  return curve;
}

void vertex_lists_bspline(const DefinitionScope& scope, Index decl,
                          std::vector<const std::vector<Name>*>& out) {
  out.push_back(&scope.ast().curves[decl].points);
}

}  // namespace

StatementKind bspline_statement() {
  return with_curve_syntax({.keyword = "bspline",
                            .end_keyword = "endbspline",
                            .dialect = StatementDialect::successor,
                            .vertex_lists = vertex_lists_bspline,
                            .sample = sample_bspline,
                            .example = "order 3 (p0 p1 p2 p3) segs 6"});
}

}  // namespace nome::scene
