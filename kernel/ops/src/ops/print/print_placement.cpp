#include "nome/ops/print_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "nome/error.hpp"
#include "nome/mesh/normals.hpp"

namespace nome {
namespace {

struct PlacementBounds {
  Vec3 low{std::numeric_limits<double>::max()};
  Vec3 high{std::numeric_limits<double>::lowest()};
};

PlacementBounds placement_bounds(const Mesh& mesh, const glm::dmat4& m) {
  PlacementBounds b;
  for (const Vec3& p : mesh.positions()) {
    const Vec3 q = Vec3(m * glm::dvec4(p, 1.0));
    b.low = glm::min(b.low, q);
    b.high = glm::max(b.high, q);
  }
  return b;
}

double mesh_diagonal(const Mesh& mesh) {
  const PlacementBounds b = placement_bounds(mesh, glm::dmat4(1.0));
  return mesh.num_vertices() == 0 ? 0.0 : glm::length(b.high - b.low);
}

Vec3 placement_face_centre(const Mesh& mesh, Index f) {
  Vec3 c(0.0);
  for (Index v : mesh.face_vertices(f)) c += mesh.position(v);
  return c / double(mesh.face_degree(f));
}

// The outward side of the plane through `at` with unit normal n: the side no vertex lies beyond (within
// tol), +1 or -1; 0 when vertices lie beyond both sides (the plane cuts the mesh).
int supporting_side(const Mesh& mesh, const Vec3& n, const Vec3& at, double tol) {
  const double d = glm::dot(n, at);
  double low = d, high = d;
  for (const Vec3& p : mesh.positions()) {
    const double h = glm::dot(n, p);
    low = std::min(low, h);
    high = std::max(high, h);
  }
  if (high <= d + tol) return 1;
  if (low >= d - tol) return -1;
  return 0;
}

// A face's outward unit normal: away from the mesh where the face touches its hull, else away from the
// centroid of the vertices (a face in a hollow still has an outside).
Vec3 outward_normal(const Mesh& mesh, Index f, double tol) {
  const Vec3 area = face_area_normal(mesh, f);
  const Vec3 n = area / glm::length(area);
  const Vec3 at = placement_face_centre(mesh, f);
  if (const int side = supporting_side(mesh, n, at, tol); side != 0) return double(side) * n;
  Vec3 centre(0.0);
  for (const Vec3& p : mesh.positions()) centre += p;
  centre /= double(mesh.num_vertices());
  return glm::dot(n, centre - at) > 0.0 ? -n : n;
}

// The rotation taking the unit vector n to -z.
glm::dmat4 rotation_to_down(const Vec3& n) {
  const Vec3 down(0.0, 0.0, -1.0);
  const double c = std::clamp(glm::dot(n, down), -1.0, 1.0);
  const Vec3 axis = glm::cross(n, down);
  if (glm::length(axis) < 1e-12)
    return c > 0.0 ? glm::dmat4(1.0) : glm::rotate(glm::dmat4(1.0), glm::pi<double>(), Vec3(1.0, 0.0, 0.0));
  return glm::rotate(glm::dmat4(1.0), std::acos(c), glm::normalize(axis));
}

struct PlaneGroup {
  double area = 0.0;
  Index largest_face = no_index;
  double largest_area = 0.0;
};

}  // namespace

Index flattest_face(const Mesh& mesh) {
  const double size = mesh_diagonal(mesh);
  // Faces of one plane share their normal to rounding; the key is the normal (sign fixed so that both
  // orientations of a plane meet) and the plane's distance, quantised.
  std::map<std::tuple<long, long, long, long>, PlaneGroup> planes;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Vec3 area_normal = face_area_normal(mesh, f);
    const double area = 0.5 * glm::length(area_normal);
    if (!(area > 1e-12 * size * size)) continue;
    Vec3 n = area_normal / (2.0 * area);
    if (n.x < 0 || (n.x == 0 && (n.y < 0 || (n.y == 0 && n.z < 0)))) n = -n;
    const double d = glm::dot(n, placement_face_centre(mesh, f)) / size;
    const auto q = [](double x) { return long(std::lround(x * 1e4)); };
    PlaneGroup& g = planes[{q(n.x), q(n.y), q(n.z), q(d)}];
    g.area += area;
    if (area > g.largest_area) g.largest_area = area, g.largest_face = f;
  }
  if (planes.empty()) throw InvalidInputError("flattest_face: the mesh has no face of positive area");
  std::vector<PlaneGroup> by_area;
  for (const auto& [key, g] : planes) by_area.push_back(g);
  std::sort(by_area.begin(), by_area.end(), [](const PlaneGroup& a, const PlaneGroup& b) {
    return a.area != b.area ? a.area > b.area : a.largest_face < b.largest_face;
  });
  const double tol = 1e-5 * size;
  for (const PlaneGroup& g : by_area) {
    const Vec3 area_normal = face_area_normal(mesh, g.largest_face);
    if (supporting_side(mesh, glm::normalize(area_normal), placement_face_centre(mesh, g.largest_face),
                        tol) != 0)
      return g.largest_face;
  }
  // No plane touches the hull (nothing flat outside): the largest plane still gives a steady direction.
  return by_area.front().largest_face;
}

PrintPlacement print_placement(const Mesh& mesh, const PrintPlacementOptions& options) {
  if (options.fit != FitTarget::none && !(options.fit_size > 0.0 && std::isfinite(options.fit_size)))
    throw InvalidInputError("print_placement: the fit size must be positive and finite, found " +
                            std::to_string(options.fit_size));
  PrintPlacement out;
  if (options.is_identity()) return out;
  if (mesh.num_vertices() == 0) throw InvalidInputError("print_placement: the mesh is empty");
  glm::dmat4 rotation(1.0);
  if (options.rest != RestOn::none) {
    Index f = options.rest_face;
    if (options.rest == RestOn::flattest) f = flattest_face(mesh);
    if (f >= mesh.num_faces())
      throw InvalidInputError("print_placement: no face " + std::to_string(f) + " (the mesh has " +
                              std::to_string(mesh.num_faces()) + ")");
    if (!(glm::length(face_area_normal(mesh, f)) > 0.0))
      throw InvalidInputError("print_placement: face " + std::to_string(f) + " has no area to rest on");
    out.rest_face = f;
    out.rest_normal = outward_normal(mesh, f, 1e-5 * mesh_diagonal(mesh));
    rotation = rotation_to_down(out.rest_normal);
  }
  const PlacementBounds turned = placement_bounds(mesh, rotation);
  const Vec3 extent = turned.high - turned.low;
  if (options.fit != FitTarget::none) {
    const double size =
        options.fit == FitTarget::height ? extent.z : std::max({extent.x, extent.y, extent.z});
    if (!(size > 0.0))
      throw InvalidInputError("print_placement: the mesh is flat in the fitted direction: nothing to scale");
    out.scale = options.fit_size / size;
  }
  const Vec3 lift = options.rest != RestOn::none ? Vec3(0.0, 0.0, -out.scale * turned.low.z) : Vec3(0.0);
  out.transform =
      glm::translate(glm::dmat4(1.0), lift) * glm::scale(glm::dmat4(1.0), Vec3(out.scale)) * rotation;
  return out;
}

Mesh placed_for_print(const Mesh& mesh, const PrintPlacementOptions& options) {
  if (options.is_identity()) return mesh;
  return transformed(mesh, print_placement(mesh, options).transform);
}

}  // namespace nome
