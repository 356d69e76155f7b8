// The frames a sweep carries its cross-section in: tangents that bisect a polyline's corners, Frenet
// normals towards the centre of curvature, or rotation-minimising normals (double reflection).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "nome/error.hpp"
#include "nome/scene/sweep.hpp"
#include "scene/sweep_geometry.hpp"

namespace nome::scene {
namespace {

constexpr double tiny = 1e-12;

Vec3 any_perpendicular(const Vec3& t) {
  const Vec3 axis = std::abs(t.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  return glm::normalize(glm::cross(t, axis));
}

// `v` without its component along the unit vector `t`, normalised; `fallback` when nothing is left.
Vec3 perpendicular_part(const Vec3& v, const Vec3& t, const Vec3& fallback) {
  const Vec3 p = v - glm::dot(v, t) * t;
  const double length = glm::length(p);
  return length > 1e-9 ? p / length : fallback;
}

// Double reflection: the normal at `from` carried to the frame at `to` without turning about the path.
Vec3 reflect_along(const Vec3& normal, const Vec3& from, const Vec3& to, const Vec3& tangent_from,
                   const Vec3& tangent_to) {
  const Vec3 v1 = to - from;
  const double c1 = glm::dot(v1, v1);
  if (c1 < tiny) return perpendicular_part(normal, tangent_to, any_perpendicular(tangent_to));
  const Vec3 r = normal - (2 / c1) * glm::dot(v1, normal) * v1;
  const Vec3 t = tangent_from - (2 / c1) * glm::dot(v1, tangent_from) * v1;
  const Vec3 v2 = tangent_to - t;
  const double c2 = glm::dot(v2, v2);
  const Vec3 carried = c2 < tiny ? r : r - (2 / c2) * glm::dot(v2, r) * v2;
  return perpendicular_part(carried, tangent_to, any_perpendicular(tangent_to));
}

}  // namespace

PathShape path_shape(std::span<const Vec3> points, bool is_closed) {
  const std::size_t n = points.size();
  const std::size_t segments = is_closed ? n : n - 1;
  // Segment directions; a segment of no length takes its neighbour's (JIPCAD's paths repeat points).
  std::vector<Vec3> direction(segments, Vec3(0.0));
  std::vector<unsigned char> has_direction(segments, 0);
  for (std::size_t k = 0; k < segments; ++k) {
    const Vec3 d = points[(k + 1) % n] - points[k];
    const double length = glm::length(d);
    if (length > 1e-12) {
      direction[k] = d / length;
      has_direction[k] = 1;
    }
  }
  std::size_t first = 0;
  while (first < segments && !has_direction[first]) ++first;
  if (first == segments) throw InvalidInputError("sweep: the path has no length");
  for (std::size_t step = 0; step < segments; ++step) {
    const std::size_t k = (first + step) % segments;
    if (!has_direction[k]) direction[k] = direction[(k + segments - 1) % segments];
  }
  if (!is_closed)
    for (std::size_t k = 0; k < first; ++k) direction[k] = direction[first];
  PathShape shape;
  shape.tangent.resize(n);
  shape.bend.resize(n, Vec3(0.0));
  shape.stretch.resize(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const bool has_in = is_closed || i > 0, has_out = is_closed || i + 1 < n;
    const Vec3 in = has_in ? direction[(i + segments - 1) % segments] : direction[0];
    const Vec3 out = has_out ? direction[i % segments] : in;
    const Vec3 sum = in + out;
    shape.tangent[i] = glm::length(sum) > 1e-9 ? glm::normalize(sum) : out;
    const Vec3 bend = out - in;
    if (glm::length(bend) > 1e-9) shape.bend[i] = glm::normalize(bend);
    // A corner's section lies in the bisecting plane: stretched across the bend it keeps the width.
    const double half_cos = std::sqrt(std::max(0.0, (1 + glm::dot(in, out)) / 2));
    shape.stretch[i] = 1 / std::max(half_cos, 0.2);
  }
  return shape;
}

std::vector<Frame> frames_of(std::span<const Vec3> points, const PathShape& shape, bool is_closed,
                             FrameKind kind) {
  const std::size_t n = points.size();
  // The first normal: towards the first bend (carried back to the start), else any perpendicular.
  std::size_t first_bend = 0;
  while (first_bend < n && glm::length(shape.bend[first_bend]) == 0) ++first_bend;
  const Vec3& t0 = shape.tangent[0];
  const Vec3 start = first_bend < n ? perpendicular_part(shape.bend[first_bend], t0, any_perpendicular(t0))
                                    : any_perpendicular(t0);
  std::vector<Frame> frames(is_closed ? n + 1 : n);
  Vec3 normal = start;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::size_t s = i % n;
    const Vec3& t = shape.tangent[s];
    if (i > 0 && kind == FrameKind::minimal_torsion)
      normal = reflect_along(normal, points[i - 1], points[s], shape.tangent[i - 1], t);
    else if (kind == FrameKind::frenet)
      normal = glm::length(shape.bend[s]) > 0 ? shape.bend[s] : perpendicular_part(normal, t, start);
    frames[i] = {normal, glm::cross(t, normal), t};
  }
  if (is_closed && kind == FrameKind::frenet) frames[n] = frames[0];
  return frames;
}

std::vector<Frame> path_frames(std::span<const Vec3> points, bool is_closed, FrameKind kind) {
  if (points.size() < (is_closed ? 3u : 2u))
    throw InvalidInputError("path_frames: a path needs at least 2 points (3 when closed)");
  return frames_of(points, path_shape(points, is_closed), is_closed, kind);
}

}  // namespace nome::scene
