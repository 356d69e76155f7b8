// `genimplicitsurf NAME func [f(x,y,z)] (x_min x_max y_min y_max z_min z_max x_segs y_segs z_segs)
// endgenimplicitsurf` (JIPCAD): the surface f = 0 in a box, by marching tetrahedra.
//
// Why tetrahedra: marching cubes' cube cases are ambiguous (two cubes sharing a face may cut it
// differently, leaving holes or edges of three faces), and dual contouring can pinch one vertex between two
// sheets; both need extra rules to give a 2-manifold. Each cube is split into six tetrahedra around its
// main diagonal (Freudenthal), a split that neighbouring cubes agree on, and in a tetrahedron the surface
// of the linear interpolant is one triangle or one planar quad. With every sample classed strictly inside
// (f < 0) or outside (f >= 0), the result is the zero set of a piecewise-linear function: a 2-manifold
// whose only borders are where it leaves the box. Faces point towards f > 0.
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "scene/generators/function_surfaces.hpp"
#include "scene/generators/generator_support.hpp"

namespace nome::scene {
namespace {

// The corners of a cube as bit masks (1: +x, 2: +y, 4: +z); a tetrahedron of the split walks from corner 0
// to corner 7 adding one axis at a time, in one of the six orders.
constexpr std::array<std::array<int, 4>, 6> tetrahedra{
    {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};

struct Box {
  SampleRange x, y, z;
  int nx() const { return x.segs + 1; }
  int ny() const { return y.segs + 1; }
  Index sample(int i, int j, int k) const {
    return Index((size_t(k) * size_t(ny()) + size_t(j)) * size_t(nx()) + size_t(i));
  }
  Vec3 position(Index s) const {
    const int i = int(s % Index(nx())), j = int((s / Index(nx())) % Index(ny())),
              k = int(s / Index(nx() * ny()));
    return {x.at(i), y.at(j), z.at(k)};
  }
};

class Contour {
 public:
  Contour(const Box& box, const std::vector<double>& values, Piece& piece)
      : box_(box), values_(values), piece_(piece) {}

  void cube(int i, int j, int k) {
    std::array<Index, 8> corner;
    for (int c = 0; c < 8; ++c)
      corner[size_t(c)] = box_.sample(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1));
    for (size_t t = 0; t < tetrahedra.size(); ++t) {
      std::array<Index, 4> v;
      for (size_t n = 0; n < 4; ++n) v[n] = corner[size_t(tetrahedra[t][n])];
      tetrahedron(v, "f" + std::to_string(i) + "_" + std::to_string(j) + "_" + std::to_string(k) + "_" +
                         std::to_string(t));
    }
  }

 private:
  bool is_outside(Index s) const { return values_[s] >= 0; }

  // The vertex where the surface crosses the segment between samples a and b (one inside, one out).
  Index crossing(Index a, Index b) {
    if (a > b) std::swap(a, b);
    const auto [it, is_new] = crossings_.try_emplace((std::uint64_t(a) << 32) | b, no_index);
    if (!is_new) return it->second;
    // Kept off the samples themselves, so that no two crossings coincide.
    const double t = std::clamp(values_[a] / (values_[a] - values_[b]), 1e-4, 1 - 1e-4);
    const Vec3 p = box_.position(a) + t * (box_.position(b) - box_.position(a));
    it->second = piece_.add_vertex(p, "v" + std::to_string(a) + "_" + std::to_string(b));
    return it->second;
  }

  static double volume(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& c) {
    return glm::dot(a - o, glm::cross(b - o, c - o));
  }

  void tetrahedron(const std::array<Index, 4>& v, const std::string& name) {
    std::array<Index, 4> outside{}, inside{};
    size_t n_out = 0, n_in = 0;
    for (Index s : v) (is_outside(s) ? outside[n_out++] : inside[n_in++]) = s;
    if (n_out == 0 || n_in == 0) return;
    if (n_out == 2) return quad(outside[0], outside[1], inside[0], inside[1], name);
    // One sample alone on its side: a triangle around it, facing it if it is outside.
    const bool is_lone_outside = n_out == 1;
    const Index lone = is_lone_outside ? outside[0] : inside[0];
    std::array<Index, 3> others = is_lone_outside ? std::array<Index, 3>{inside[0], inside[1], inside[2]}
                                                  : std::array<Index, 3>{outside[0], outside[1], outside[2]};
    const double det = volume(box_.position(lone), box_.position(others[0]), box_.position(others[1]),
                              box_.position(others[2]));
    // det > 0: the triangle in this order faces away from `lone`.
    if ((det > 0) == is_lone_outside) std::swap(others[1], others[2]);
    const std::array<Index, 3> face{crossing(lone, others[0]), crossing(lone, others[1]),
                                    crossing(lone, others[2])};
    piece_.add_face(face, name);
  }

  // Two samples out (a, b), two in (c, d): the planar quad through the four crossing edges, facing a, b.
  void quad(Index a, Index b, Index c, Index d, const std::string& name) {
    const double det = volume(box_.position(a), box_.position(b), box_.position(c), box_.position(d));
    std::array<Index, 4> face{crossing(a, c), crossing(a, d), crossing(b, d), crossing(b, c)};
    if (det > 0) std::reverse(face.begin(), face.end());
    piece_.add_face(face, name);
  }

  const Box& box_;
  const std::vector<double>& values_;
  Piece& piece_;
  std::unordered_map<std::uint64_t, Index> crossings_;
};

Piece evaluate_implicit_surface(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  constexpr std::array<std::string_view, 3> variables{"x", "y", "z"};
  const std::vector<CompiledExpression> f = read_functions(c, decl, {"func"}, variables);
  const Box box{sample_range(c, a, 0, 6, "x"), sample_range(c, a, 2, 7, "y"), sample_range(c, a, 4, 8, "z")};
  const double samples = double(box.nx()) * box.ny() * (box.z.segs + 1);
  if (samples > 8e6)
    throw EvaluationError(a[6].location, "x_segs * y_segs * z_segs is too large (at most 8 million samples)");
  std::vector<double> values(static_cast<size_t>(samples));
  for (Index s = 0; s < values.size(); ++s) {
    const Vec3 p = box.position(s);
    const std::array<double, 3> at{p.x, p.y, p.z};
    values[s] = finite_value(c, decl, f[0](at), [&] {
      return "x = " + format_number(p.x) + ", y = " + format_number(p.y) + ", z = " + format_number(p.z);
    });
  }
  Piece piece;
  Contour contour(box, values, piece);
  for (int k = 0; k < box.z.segs; ++k)
    for (int j = 0; j < box.y.segs; ++j)
      for (int i = 0; i < box.x.segs; ++i) contour.cube(i, j, k);
  return piece;
}

}  // namespace

StatementKind implicit_statement() {
  return with_generator_syntax(
      {.keyword = "genimplicitsurf",
       .end_keyword = "endgenimplicitsurf",
       .signature = "func [f(x,y,z)] (x_min x_max y_min y_max z_min z_max x_segs y_segs z_segs)",
       .argument_count = 9,
       .dialect = StatementDialect::successor,
       .evaluate = evaluate_implicit_surface,
       .example = "func [x^2+y^2+z^2-1] (-1.5 1.5 -1.5 1.5 -1.5 1.5 3 3 3)"});
}

}  // namespace nome::scene
