// A sweep's soup carries its grid layout, from which build_mesh finds the edges without searching; the mesh
// must be the one the search gives, on every kind of sweep.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/scene/sweep.hpp"
#include "support/same_mesh.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

CrossSection polygon_section(int points, bool is_closed) {
  CrossSection s{{}, is_closed};
  for (int j = 0; j < points; ++j) {
    const double a = 2 * std::numbers::pi * j / points;
    s.points.emplace_back(0.5 * std::cos(a), 0.3 * std::sin(a) + 0.05 * j);
  }
  return s;
}

std::vector<PathSample> circle_path(int samples, bool is_closed) {
  std::vector<PathSample> path;
  for (int i = 0; i < samples; ++i) {
    const double t = (is_closed ? 2 : 1.5) * std::numbers::pi * i / samples;
    path.push_back({Vec3(3 * std::cos(t), 3 * std::sin(t), 0.2 * std::sin(3 * t))});
  }
  return path;
}

// The sweep's mesh through its layout, checked against the search's; whether the layout was used.
bool builds_the_same_from_its_grid(const std::vector<PathSample>& path, const CrossSection& section,
                                   const SweepOptions& o) {
  const PolygonSoup soup = sweep(path, {&section, 1}, o).piece.soup;
  REQUIRE(soup.grid);
  PolygonSoup searched = soup;
  searched.grid.reset();
  const std::uint64_t before = build_mesh_grid_count();
  const Mesh from_grid = build_mesh(soup);
  const bool used = build_mesh_grid_count() == before + 1;
  test::check_same_mesh(from_grid, build_mesh(searched));
  return used;
}

}  // namespace

TEST_CASE("a sweep's mesh from its grid layout is the one the edge search builds", "[scene]") {
  for (const bool is_path_closed : {false, true})
    for (const bool is_section_closed : {true, false})
      for (const int points : {2, 3, 4, 7})
        for (const double twist : {0.0, 90.0, 180.0})
          for (const FaceShape faces : {FaceShape::quadrilaterals, FaceShape::triangles})
            for (const bool caps : {false, true}) {
              if ((is_path_closed && caps) || (points == 2 && is_section_closed)) continue;  // no surface
              SweepOptions o;
              o.is_path_closed = is_path_closed;
              o.twist = twist;
              o.faces = faces;
              o.has_begin_cap = o.has_end_cap = caps;
              o.is_reversed = points == 4;
              o.is_cut_begin = !is_path_closed && points == 7;
              o.frames = twist == 90 ? FrameKind::minimal_torsion : FrameKind::frenet;
              INFO("closed path " << is_path_closed << ", closed section " << is_section_closed << ", "
                                  << points << " points, twist " << twist << ", triangles "
                                  << (faces == FaceShape::triangles) << ", caps " << caps);
              CHECK(builds_the_same_from_its_grid(circle_path(9, is_path_closed),
                                                  polygon_section(points, is_section_closed), o));
            }
}

TEST_CASE("a half-twisted segment swept around a closed path is a Möbius band from its grid layout",
          "[scene]") {
  SweepOptions o;
  o.is_path_closed = true;
  o.twist = 180;
  CrossSection segment{{{-0.4, 0.0}, {0.0, 0.0}, {0.4, 0.0}}, false};
  const std::uint64_t before = build_mesh_grid_count();
  const Mesh band = build_mesh(sweep(circle_path(40, true), {&segment, 1}, o).piece.soup);
  REQUIRE(build_mesh_grid_count() == before + 1);
  const TopologyReport r = topology_report(band);
  CHECK_FALSE(r.orientable);
  CHECK(r.borders == 1);
  CHECK(r.chi == 0);
}

TEST_CASE("a soup whose faces no longer follow its grid layout is built by the search", "[scene]") {
  const CrossSection square = polygon_section(4, true);
  PolygonSoup soup = sweep(circle_path(6, false), {&square, 1}, SweepOptions{}).piece.soup;
  std::reverse(soup.face_vertices.begin(), soup.face_vertices.begin() + 4);  // one face turned over
  const std::uint64_t before = build_mesh_grid_count();
  PolygonSoup searched = soup;
  searched.grid.reset();
  const Mesh mesh = build_mesh(soup);
  CHECK(build_mesh_grid_count() == before);
  test::check_same_mesh(mesh, build_mesh(searched));
}
