#include "nome/query/display_triangles.hpp"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "nome/mesh/normals.hpp"
#include "ops/parallel_for.hpp"

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
  const size_t n = vertices.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = mesh.position(vertices[(i + n - 1) % n]);
    const Vec3& b = mesh.position(vertices[i]);
    const Vec3& c = mesh.position(vertices[(i + 1) % n]);
    if (glm::dot(glm::cross(b - a, c - b), normal) < 0.0) return false;
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

// A quad's two triangles from its first corner, when it is convex in the plane of its normal (or
// degenerate); the same test as for any face, without the general case's modular indexing.
bool fan_quad(const Mesh& mesh, Index f, Index first, DisplayTriangles& out) {
  const std::span<const Index> vertices = mesh.face_vertices(f);
  const Vec3 normal = polygon_area_normal(vertices, mesh.positions());
  const Vec3* p[4];
  for (int i = 0; i < 4; ++i) p[i] = &mesh.position(vertices[i]);
  if (glm::length(normal) > 0.0)
    for (int i = 0; i < 4; ++i)
      if (glm::dot(glm::cross(*p[i] - *p[(i + 3) & 3], *p[(i + 1) & 3] - *p[i]), normal) < 0.0) return false;
  const Index t = first - 2 * f;
  out.corners[t] = {first, first + 1, first + 2};
  out.corners[t + 1] = {first, first + 2, first + 3};
  out.faces[t] = out.faces[t + 1] = f;
  return true;
}

// Face f's triangles into out from out.corners[first - 2f] on (a face of n corners has n - 2), with
// `local` as scratch.
void triangulate_face(const Mesh& mesh, Index f, DisplayTriangles& out,
                      std::vector<std::array<Index, 3>>& local) {
  const Index first = mesh.face_first_corner(f);
  const Index degree = mesh.face_degree(f);
  if (degree == 4 && fan_quad(mesh, f, first, out)) return;
  local.clear();
  const Vec3 normal = face_area_normal(mesh, f);
  const double length = glm::length(normal);
  if (degree == 3 || !(length > 0.0) || is_convex(mesh, mesh.face_vertices(f), normal)) {
    for (Index i = 1; i + 1 < degree; ++i) local.push_back({0, i, i + 1});
  } else {
    clip_ears(project(mesh, mesh.face_vertices(f), normal / length), local);
  }
  Index t = first - 2 * f;
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
