// `sphere NAME (radius theta_max phi_min phi_max theta_segs phi_segs) endsphere` and `ellipsoid` (JIPCAD).
#include "nome/scene/generators/sphere.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {

namespace {

// A place on the globe written with any latitude: beyond a pole the meridian comes down the other side,
// half a turn of longitude away. Both in degrees; the canonical form has latitude in [-90, 90] and
// longitude in [0, 360), 0 at a pole.
struct GlobePlace {
  double latitude, longitude;
};

GlobePlace canonical_place(double latitude, double longitude) {
  double lat = std::remainder(latitude, 360.0);  // (-180, 180]
  if (lat > 90) {
    lat = 180 - lat;
    longitude += 180;
  } else if (lat < -90) {
    lat = -180 - lat;
    longitude += 180;
  }
  double lon = std::fmod(longitude, 360.0);
  if (lon < 0) lon += 360;
  if (std::abs(std::abs(lat) - 90) < 1e-9 || std::abs(lon - 360) < 1e-9) lon = 0;
  return {lat, lon};
}

// JIPCAD's Sphere.cpp sweeps the meridian arc from phi_min to phi_max whatever the range: past a pole it
// comes down the other side, so `(1 180 0 360 10 10)` (a whole meridian circle turned half a turn) is a
// whole sphere. The arc is cut at every pole it passes (a row of its own, one vertex), places the arc
// reaches twice are one vertex, and a face the sweep makes twice (`(1 360 0 180 ...)` covers a hemisphere
// twice) is made once; faces beyond a pole are turned over, so that all point outwards.
Piece sphere_any_latitudes(const SphereParams& p) {
  std::vector<double> rows;
  for (int j = 0; j <= p.latitude_segs; ++j) {
    const double lat = p.latitude_min + (p.latitude_max - p.latitude_min) * j / p.latitude_segs;
    if (!rows.empty())
      for (double pole = 90 * (2 * std::floor((rows.back() - 90) / 180) + 3); pole < lat - 1e-9; pole += 180)
        if (pole > rows.back() + 1e-9) rows.push_back(pole);
    rows.push_back(lat);
  }
  Piece piece;
  std::map<std::pair<long long, long long>, Index> placed;
  const int columns = p.longitude_segs;
  std::vector<Index> ids(rows.size() * size_t(columns + 1));
  for (size_t j = 0; j < rows.size(); ++j)
    for (int i = 0; i <= columns; ++i) {
      const GlobePlace at = canonical_place(rows[j], p.longitude_max * i / columns);
      const std::pair<long long, long long> key{std::llround(at.latitude * 1e6),
                                                std::llround(at.longitude * 1e6) % 360000000};
      auto [it, is_new] = placed.emplace(key, 0);
      if (is_new) {
        const double lat = at.latitude * std::numbers::pi / 180, lon = at.longitude * std::numbers::pi / 180;
        const bool is_pole = std::abs(std::abs(at.latitude) - 90) < 1e-9;
        const double ring = is_pole ? 0 : p.radius * std::cos(lat);
        const std::string name = is_pole ? (at.latitude > 0 ? "north" : "south")
                                         : "v" + std::to_string(i) + "_" + std::to_string(j);
        it->second = piece.add_vertex(
            Vec3(ring * std::cos(lon), ring * std::sin(lon),
                 is_pole ? (at.latitude > 0 ? p.radius_z : -p.radius_z) : p.radius_z * std::sin(lat)),
            name);
      }
      ids[j * size_t(columns + 1) + size_t(i)] = it->second;
    }
  std::set<std::vector<Index>> made;
  for (size_t j = 0; j + 1 < rows.size(); ++j)
    for (int i = 0; i < columns; ++i) {
      auto id = [&](int di, size_t dj) { return ids[(j + dj) * size_t(columns + 1) + size_t(i + di)]; };
      std::vector<Index> face{id(0, 0), id(1, 0), id(1, 1), id(0, 1)};
      face.erase(std::unique(face.begin(), face.end()), face.end());
      if (face.size() > 1 && face.front() == face.back()) face.pop_back();
      if (face.size() < 3) continue;
      std::vector<Index> key = face;
      std::sort(key.begin(), key.end());
      if (!made.insert(key).second) continue;
      if (std::abs(std::remainder((rows[j] + rows[j + 1]) / 2, 360.0)) > 90)
        std::reverse(face.begin(), face.end());
      piece.add_face(face, "f" + std::to_string(i) + "_" + std::to_string(j));
    }
  return piece;
}

}  // namespace

Piece sphere(const SphereParams& p) {
  require(p.longitude_segs >= 1 && p.latitude_segs >= 1, "sphere: needs at least one segment each way");
  if (p.latitude_min < -90 || p.latitude_max > 90) return sphere_any_latitudes(p);
  Piece piece;
  SurfaceGrid grid;
  grid.across = p.longitude_segs;
  grid.along = p.latitude_segs;
  grid.is_across_closed = is_whole_turn(p.longitude_max);
  grid.has_first_pole = p.latitude_min <= -90;
  grid.has_last_pole = p.latitude_max >= 90;
  const double lat0 = p.latitude_min * std::numbers::pi / 180;
  const double lat_span = (p.latitude_max - p.latitude_min) * std::numbers::pi / 180;
  add_surface_grid(piece, grid, [&](int i, int j) {
    const double lon = sample_angle(i, p.longitude_segs, p.longitude_max);
    // The poles are exact: sin(pi/2) is, cos(pi/2) is not quite 0.
    const bool is_pole = (j == 0 && grid.has_first_pole) || (j == grid.along && grid.has_last_pole);
    const double lat = lat0 + lat_span * j / p.latitude_segs;
    const double ring = is_pole ? 0 : p.radius * std::cos(lat);
    return Vec3(ring * std::cos(lon), ring * std::sin(lon), p.radius_z * std::sin(lat));
  });
  return piece;
}

namespace {

// The arguments after the radii, named as each statement's signature names them: the longitude swept, the
// latitude band and the segments each way.
struct AngleNames {
  const char *longitude_max, *latitude_min, *latitude_max, *longitude_segs, *latitude_segs;
};

Piece evaluate_globe(DefinitionContext& c, Index decl, size_t first, SphereParams p, const AngleNames& n) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  p.longitude_max = sweep_degrees(c, a[first], n.longitude_max);
  // The successor's latitudes may run past a pole (JIPCAD's Sphere.cpp sweeps any arc of the meridian).
  const double limit = c.ast().dialect.dialect == Dialect::jipcad ? 1e6 : 90;
  p.latitude_min = number_in(c, a[first + 1], -limit, limit, n.latitude_min);
  p.latitude_max = number_in(c, a[first + 2], -limit, limit, n.latitude_max);
  if (!(p.latitude_min < p.latitude_max))
    throw EvaluationError(a[first + 2].location,
                          std::string(n.latitude_max) + " must be above " + n.latitude_min);
  if (p.latitude_max - p.latitude_min > 360)
    throw EvaluationError(a[first + 2].location, std::string(n.latitude_max) + " must be at most 360 above " +
                                                     n.latitude_min + " (a whole meridian circle)");
  p.longitude_segs = c.whole(a[first + 3], is_whole_turn(p.longitude_max) ? 3 : 1, n.longitude_segs);
  p.latitude_segs = c.whole(a[first + 4], 2, n.latitude_segs);
  expect_generator_faces(c, decl, double(p.longitude_segs) * p.latitude_segs);
  return sphere(p);
}

Piece evaluate_sphere(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  SphereParams p;
  p.radius = p.radius_z = c.positive(a[0], "radius");
  return evaluate_globe(c, decl, 1, p, {"theta_max", "phi_min", "phi_max", "theta_segs", "phi_segs"});
}

Piece evaluate_ellipsoid(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  SphereParams p;
  p.radius = c.positive(a[0], "radius_x");
  p.radius_z = c.positive(a[1], "radius_y");
  return evaluate_globe(c, decl, 2, p, {"long_max", "latt_min", "latt_max", "segs_long", "segs_latt"});
}

}  // namespace

StatementKind sphere_statement() {
  return with_generator_syntax({.keyword = "sphere",
                                .end_keyword = "endsphere",
                                .signature = "(radius theta_max phi_min phi_max theta_segs phi_segs)",
                                .argument_count = 6,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_sphere,
                                .example = "(1 360 -90 90 8 4)"});
}

// `ellipsoid NAME (radius_x radius_y long_max latt_min latt_max segs_long segs_latt) endellipsoid`
// (JIPCAD): a sphere with a polar radius of its own.
StatementKind ellipsoid_statement() {
  return with_generator_syntax(
      {.keyword = "ellipsoid",
       .end_keyword = "endellipsoid",
       .signature = "(radius_x radius_y long_max latt_min latt_max segs_long segs_latt)",
       .argument_count = 7,
       .dialect = StatementDialect::successor,
       .evaluate = evaluate_ellipsoid,
       .example = "(2 1 360 -90 90 8 4)"});
}

}  // namespace nome::scene
