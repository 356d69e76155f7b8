#include "nome/query/display_triangles.hpp"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "nome/mesh/normals.hpp"
#include "support/parallel_for.hpp"

namespace nome {
namespace {

using Vec2 = glm::dvec2;

double cross(const Vec2& a, const Vec2& b) {
  return a.x * b.y - a.y * b.x;
}

bool inside_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  return cross(b - a, p - a) >= 0.0 && cross(c - b, p - b) >= 0.0 && cross(a - c, p - c) >= 0.0;
}

// The face projected on the plane of its normal: counter-clockwise seen from the normal's side.
std::vector<Vec2> project(const Mesh& mesh, std::span<const Index> vertices, const Vec3& normal) {
  const Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 u = glm::normalize(glm::cross(helper, normal));
  const Vec3 v = glm::cross(normal, u);
  std::vector<Vec2> points;
  points.reserve(vertices.size());
  for (Index vertex : vertices) {
    const Vec3& p = mesh.position(vertex);
    points.emplace_back(glm::dot(p, u), glm::dot(p, v));
  }
  return points;
}

// Every corner turns the same way around the normal: the sign of the turn in the plane of the normal
// (what the projection would give), found without projecting (most faces are convex: no allocation).
bool is_convex(const Mesh& mesh, std::span<const Index> vertices, const Vec3& normal) {
  // The turn at each corner b, between its neighbours a and c, walking the face once.
  const Vec3* a = &mesh.position(vertices[vertices.size() - 2]);
  const Vec3* b = &mesh.position(vertices.back());
  for (Index v : vertices) {
    const Vec3* c = &mesh.position(v);
    if (glm::dot(glm::cross(*b - *a, *c - *b), normal) < 0.0) return false;
    a = b;
    b = c;
  }
  return true;
}

// Local corner triples; falls back to a fan of what is left when no ear is found (self-overlapping
// polygon), so the count is always n - 2.
void clip_ears(const std::vector<Vec2>& points, std::vector<std::array<Index, 3>>& out) {
  std::vector<Index> left(points.size());
  for (Index i = 0; i < left.size(); ++i) left[i] = i;
  while (left.size() > 3) {
    const size_t m = left.size();
    bool clipped = false;
    for (size_t i = 0; i < m && !clipped; ++i) {
      const Index a = left[(i + m - 1) % m], b = left[i], c = left[(i + 1) % m];
      if (cross(points[b] - points[a], points[c] - points[b]) <= 0.0) continue;
      bool is_ear = true;
      for (Index p : left) {
        if (p == a || p == b || p == c) continue;
        if (inside_triangle(points[p], points[a], points[b], points[c])) {
          is_ear = false;
          break;
        }
      }
      if (!is_ear) continue;
      out.push_back({a, b, c});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) break;
  }
  for (size_t i = 1; i + 1 < left.size(); ++i) out.push_back({left[0], left[i], left[i + 1]});
}

// Face f's triangles into out from out.corners[first - 2f] on (a face of n corners has n - 2), with
// `local` as scratch for a concave face.
void triangulate_face(const Mesh& mesh, Index f, DisplayTriangles& out,
                      std::vector<std::array<Index, 3>>& local) {
  const Index first = mesh.face_first_corner(f);
  const Index degree = mesh.face_degree(f);
  Index t = first - 2 * f;
  const Vec3 normal = face_area_normal(mesh, f);
  const double length = glm::length(normal);
  if (degree == 3 || !(length > 0.0) || is_convex(mesh, mesh.face_vertices(f), normal)) {
    for (Index i = 1; i + 1 < degree; ++i, ++t) {
      out.corners[t] = {first, first + i, first + i + 1};
      out.faces[t] = f;
    }
    return;
  }
  local.clear();
  clip_ears(project(mesh, mesh.face_vertices(f), normal / length), local);
  for (const auto& corners : local) {
    out.corners[t] = {first + corners[0], first + corners[1], first + corners[2]};
    out.faces[t++] = f;
  }
}

}  // namespace

DisplayTriangles display_triangles(const Mesh& mesh, int threads) {
  DisplayTriangles out;
  // Each face has two triangles fewer than corners, so face f's come from first corner - 2f on: the faces
  // are independent.
  const Index count = mesh.num_corners() - 2 * mesh.num_faces();
  out.corners.resize(count);
  out.faces.resize(count);
  parallel_for(mesh.num_faces(), threads, [&](Index begin, Index end) {
    std::vector<std::array<Index, 3>> local;
    for (Index f = begin; f < end; ++f) triangulate_face(mesh, f, out, local);
  });
  return out;
}

}  // namespace nome
