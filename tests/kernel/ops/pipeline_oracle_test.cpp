#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <tuple>

#include <glm/geometric.hpp>

#include "nome/ops/pipeline.hpp"
#include "support/shapes.hpp"

using namespace nome;

// The pipeline's cached and positions-only results against oracles that share no code with it: Catmull-Clark
// and the offset written out here from their formulas, and a fresh pipeline built from scratch on the moved
// input (another path through the code). Only the public API is used.
namespace {

// A polygon mesh as the oracles make it: positions and faces, no adjacency kept.
struct PipelineOracleMesh {
  std::vector<Vec3> positions;
  std::vector<std::vector<Index>> faces;
};

PipelineOracleMesh pipeline_oracle_from(const PolygonSoup& soup) {
  PipelineOracleMesh m;
  m.positions.assign(soup.positions.begin(), soup.positions.end());
  for (Index f = 0; f < soup.num_faces(); ++f)
    m.faces.emplace_back(soup.face_vertices.begin() + soup.face_offsets[f],
                         soup.face_vertices.begin() + soup.face_offsets[f + 1]);
  return m;
}

// One level of Catmull-Clark from the formulas (report 004 section 4, OpenSubdiv's crease rules at borders):
// face point = centroid; edge point = (a + b + both face points) / 4, a border edge's midpoint; an inner
// vertex of valence n with Q the mean of its face points, R of its edge midpoints and E of its edge points:
// classic ((n - 3) v + 2 R + Q) / n, report ((n - 2) v + E + Q) / n; a border vertex (6 v + a + b) / 8 from
// its two border neighbours, or v itself where `pins_corners` and it has one face. Face f's corner i becomes
// the quad (vertex point, edge point to the next corner, face point, edge point from the previous corner).
PipelineOracleMesh pipeline_oracle_catmull_clark(const PipelineOracleMesh& in, SubdivisionRule rule,
                                                 bool pins_corners = false) {
  const Index nv = Index(in.positions.size()), nf = Index(in.faces.size());
  std::map<std::pair<Index, Index>, Index> edge_of;
  std::vector<std::pair<Index, Index>> ends;
  std::vector<std::vector<Index>> edge_faces;
  auto edge = [&](Index a, Index b) {
    const auto key = std::minmax(a, b);
    const auto [it, is_new] = edge_of.try_emplace({key.first, key.second}, Index(ends.size()));
    if (is_new) {
      ends.emplace_back(key.first, key.second);
      edge_faces.emplace_back();
    }
    return it->second;
  };
  std::vector<Vec3> face_point(nf, Vec3(0.0));
  std::vector<std::vector<Index>> vertex_faces(nv), vertex_edges(nv);
  for (Index f = 0; f < nf; ++f) {
    const auto& fv = in.faces[f];
    for (std::size_t i = 0; i < fv.size(); ++i) {
      face_point[f] += in.positions[fv[i]] / double(fv.size());
      const Index e = edge(fv[i], fv[(i + 1) % fv.size()]);
      edge_faces[e].push_back(f);
      vertex_faces[fv[i]].push_back(f);
    }
  }
  const Index ne = Index(ends.size());
  std::vector<Vec3> edge_point(ne);
  for (Index e = 0; e < ne; ++e) {
    const Vec3 &a = in.positions[ends[e].first], &b = in.positions[ends[e].second];
    vertex_edges[ends[e].first].push_back(e);
    vertex_edges[ends[e].second].push_back(e);
    edge_point[e] = edge_faces[e].size() == 1
                        ? 0.5 * (a + b)
                        : 0.25 * (a + b + face_point[edge_faces[e][0]] + face_point[edge_faces[e][1]]);
  }
  PipelineOracleMesh out;
  out.positions.resize(nv + ne + nf);
  for (Index v = 0; v < nv; ++v) {
    const Vec3& p = in.positions[v];
    std::vector<Index> border;
    for (const Index e : vertex_edges[v])
      if (edge_faces[e].size() == 1) border.push_back(ends[e].first == v ? ends[e].second : ends[e].first);
    Vec3 q(0.0), r(0.0), e_mean(0.0);
    const double n = double(vertex_edges[v].size());
    for (const Index f : vertex_faces[v]) q += face_point[f] / double(vertex_faces[v].size());
    for (const Index e : vertex_edges[v]) {
      r += 0.5 * (in.positions[ends[e].first] + in.positions[ends[e].second]) / n;
      e_mean += edge_point[e] / n;
    }
    if (border.size() == 2)
      out.positions[v] = pins_corners && vertex_faces[v].size() == 1
                             ? p
                             : (6.0 * p + in.positions[border[0]] + in.positions[border[1]]) / 8.0;
    else if (rule == SubdivisionRule::classic)
      out.positions[v] = ((n - 3.0) * p + 2.0 * r + q) / n;
    else
      out.positions[v] = ((n - 2.0) * p + e_mean + q) / n;
  }
  for (Index e = 0; e < ne; ++e) out.positions[nv + e] = edge_point[e];
  for (Index f = 0; f < nf; ++f) out.positions[nv + ne + f] = face_point[f];
  for (Index f = 0; f < nf; ++f) {
    const auto& fv = in.faces[f];
    const std::size_t k = fv.size();
    for (std::size_t i = 0; i < k; ++i)
      out.faces.push_back({fv[i], nv + edge_of.at(std::minmax(fv[i], fv[(i + 1) % k])), nv + ne + f,
                           nv + edge_of.at(std::minmax(fv[(i + k - 1) % k], fv[i]))});
  }
  return out;
}

// The offset of a closed, consistently oriented surface from its definition: n_v the normalized sum of the
// unit Newell normals of v's faces, v + d n_v and v - d n_v, the positive copy of each face as it is and the
// negative copy reversed.
PipelineOracleMesh pipeline_oracle_offset(const PipelineOracleMesh& in, double d) {
  const Index nv = Index(in.positions.size());
  std::vector<Vec3> normal(nv, Vec3(0.0));
  for (const auto& fv : in.faces) {
    Vec3 newell(0.0);
    for (std::size_t i = 0; i < fv.size(); ++i)
      newell += glm::cross(in.positions[fv[i]], in.positions[fv[(i + 1) % fv.size()]]);
    for (const Index v : fv) normal[v] += glm::normalize(newell);
  }
  PipelineOracleMesh out;
  for (Index v = 0; v < nv; ++v) out.positions.push_back(in.positions[v] + d * glm::normalize(normal[v]));
  for (Index v = 0; v < nv; ++v) out.positions.push_back(in.positions[v] - d * glm::normalize(normal[v]));
  for (const auto& fv : in.faces) out.faces.push_back(fv);
  for (const auto& fv : in.faces) {
    std::vector<Index> back(fv.rbegin(), fv.rend());
    for (Index& v : back) v += nv;
    out.faces.push_back(back);
  }
  return out;
}

// A face's vertices rotated to start at the smallest: the same polygon however its corners are numbered.
std::vector<Index> pipeline_oracle_canonical(std::vector<Index> face) {
  std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
  return face;
}

// The mesh is the oracle's up to numbering: every vertex at its own expected point (within `tolerance`
// relative to the size of the points), and the faces the same polygons with the same orientation.
void pipeline_oracle_require_same(const Mesh& mesh, const PipelineOracleMesh& expected,
                                  double tolerance = 1e-12) {
  REQUIRE(mesh.num_vertices() == expected.positions.size());
  REQUIRE(mesh.num_faces() == expected.faces.size());
  double scale = 1.0;
  for (const Vec3& p : expected.positions) scale = std::max(scale, glm::length(p));
  std::vector<Index> match(mesh.num_vertices(), no_index);
  std::vector<char> taken(expected.positions.size(), 0);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    Index best = 0;
    for (Index w = 1; w < expected.positions.size(); ++w)
      if (glm::distance(mesh.position(v), expected.positions[w]) <
          glm::distance(mesh.position(v), expected.positions[best]))
        best = w;
    INFO("vertex " << v << " at " << mesh.position(v).x << " " << mesh.position(v).y << " "
                   << mesh.position(v).z << ", expected " << expected.positions[best].x << " "
                   << expected.positions[best].y << " " << expected.positions[best].z);
    REQUIRE(glm::distance(mesh.position(v), expected.positions[best]) <= tolerance * scale);
    REQUIRE_FALSE(taken[best]);
    taken[best] = 1;
    match[v] = best;
  }
  std::vector<std::vector<Index>> found, wanted;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    std::vector<Index> face;
    for (const Index v : mesh.face_vertices(f)) face.push_back(match[v]);
    found.push_back(pipeline_oracle_canonical(face));
  }
  for (const auto& face : expected.faces) wanted.push_back(pipeline_oracle_canonical(face));
  std::sort(found.begin(), found.end());
  std::sort(wanted.begin(), wanted.end());
  CHECK(found == wanted);
}

// The same result as a pipeline made anew for this input and these settings: positions bit for bit,
// the same polygons.
void pipeline_oracle_require_fresh(const Mesh& result, const PipelineInput& input,
                                   const PipelineSettings& s) {
  Pipeline fresh;
  fresh.set_input(input);
  const Mesh& expected = fresh.run(s);
  CHECK(result.positions() == expected.positions());
  CHECK(result.face_offsets() == expected.face_offsets());
  CHECK(result.corner_vertices() == expected.corner_vertices());
}

// The positions moved smoothly and by a seeded random amount each (every new point distinct).
Buffer<Vec3> pipeline_oracle_moved(const Buffer<Vec3>& positions, double amount, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Buffer<Vec3> out = positions;
  for (Vec3& p : out)
    p = p + Vec3(amount * p.y, 0.5 * amount * p.z * p.x, 0.0) +
        0.1 * amount * Vec3(unit(rng), unit(rng), unit(rng));
  return out;
}

PipelineOracleMesh pipeline_oracle_with(PipelineOracleMesh m, const Buffer<Vec3>& positions) {
  m.positions.assign(positions.begin(), positions.end());
  return m;
}

}  // namespace

TEST_CASE("a cube's level-1 points are the Catmull-Clark points computed by hand", "[kernel]") {
  // Corner (1, 1, 1): Q = (1/3, 1/3, 1/3), R = (2/3, 2/3, 2/3), n = 3: (Q + 2 R) / 3 = (5/9, 5/9, 5/9). Edge
  // (1, 1, -1)-(1, 1, 1): ((1, 1, 0) 2 + (1, 0, 0) + (0, 1, 0)) / 4 = (3/4, 3/4, 0). Face points: the
  // face centres.
  Pipeline pipeline;
  pipeline.set_input(PipelineInput{test::cube(), {}, {}});
  PipelineSettings s;
  s.stage = Stage::subdivided;
  s.subdivision_levels = 1;
  const Mesh& level_1 = pipeline.run(s);
  REQUIRE(level_1.num_vertices() == 26);
  int corners = 0, edges = 0, faces = 0;
  for (const Vec3& p : level_1.positions()) {
    const Vec3 a = glm::abs(p);
    if (glm::distance(a, Vec3(5.0 / 9.0)) < 1e-14) ++corners;
    if (glm::distance(a, Vec3(0.75, 0.75, 0.0)) < 1e-14 || glm::distance(a, Vec3(0.75, 0.0, 0.75)) < 1e-14 ||
        glm::distance(a, Vec3(0.0, 0.75, 0.75)) < 1e-14)
      ++edges;
    if (glm::distance(a, Vec3(1, 0, 0)) < 1e-14 || glm::distance(a, Vec3(0, 1, 0)) < 1e-14 ||
        glm::distance(a, Vec3(0, 0, 1)) < 1e-14)
      ++faces;
  }
  CHECK(corners == 8);
  CHECK(edges == 12);
  CHECK(faces == 6);
  pipeline_oracle_require_same(
      level_1, pipeline_oracle_catmull_clark(pipeline_oracle_from(test::cube()), SubdivisionRule::classic));
  // The report's rule: corner ((n - 2) v + E + Q) / n with E the mean of its edge points (3/4, 3/4, 0)...:
  // (v + (1/2, 1/2, 1/2) + (1/3, 1/3, 1/3)) / 3 = (11/18, 11/18, 11/18).
  s.rule = SubdivisionRule::report;
  const Mesh& report = pipeline.run(s);
  CHECK(std::count_if(report.positions().begin(), report.positions().end(), [](const Vec3& p) {
          return glm::distance(glm::abs(p), Vec3(11.0 / 18.0)) < 1e-14;
        }) == 8);
}

TEST_CASE("moved vertices flow through every cached stage to the results computed from the formulas",
          "[kernel]") {
  std::mt19937 rng{42};
  const PolygonSoup cube = test::cube();
  const PipelineOracleMesh base = pipeline_oracle_from(cube);
  PipelineInput input{cube, {}, {}};
  Pipeline pipeline;
  pipeline.set_input(input);
  PipelineSettings s;
  s.stage = Stage::subdivided;
  s.subdivision_levels = 1;
  pipeline.run(s);

  // Each step: new positions through move_input_vertices or a setting changed, then the result against the
  // formulas and against a fresh pipeline.
  auto check = [&](const Mesh& result, const PipelineOracleMesh& expected) {
    pipeline_oracle_require_same(result, expected);
    pipeline_oracle_require_fresh(result, input, s);
  };
  auto move = [&](double amount) {
    input.soup.positions = pipeline_oracle_moved(cube.positions, amount, rng);
    pipeline.move_input_vertices(input.soup.positions);
    return pipeline_oracle_with(base, input.soup.positions);
  };
  auto cc = [](const PipelineOracleMesh& m, SubdivisionRule rule = SubdivisionRule::classic) {
    return pipeline_oracle_catmull_clark(m, rule);
  };

  PipelineOracleMesh moved = move(0.2);
  check(pipeline.run(s), cc(moved));
  CHECK(pipeline.work(Stage::scene) == StageWork::positions);
  CHECK(pipeline.work(Stage::subdivided) == StageWork::positions);

  s.subdivision_levels = 2;
  check(pipeline.run(s), cc(cc(moved)));
  moved = move(-0.15);
  check(pipeline.run(s), cc(cc(moved)));
  CHECK(pipeline.work(Stage::subdivided) == StageWork::positions);

  s.stage = Stage::offset;
  s.offset_distance = 0.05;
  check(pipeline.run(s), pipeline_oracle_offset(cc(cc(moved)), 0.05));
  moved = move(0.1);
  check(pipeline.run(s), pipeline_oracle_offset(cc(cc(moved)), 0.05));
  CHECK(pipeline.work(Stage::subdivided) == StageWork::positions);
  CHECK(pipeline.work(Stage::offset) == StageWork::positions);
  s.offset_distance = 0.08;
  check(pipeline.run(s), pipeline_oracle_offset(cc(cc(moved)), 0.08));
  CHECK(pipeline.work(Stage::subdivided) == StageWork::cached);
  CHECK(pipeline.work(Stage::offset) == StageWork::positions);

  s.stage = Stage::subdivided_offset;
  s.subdivision_after = 1;
  check(pipeline.run(s), cc(pipeline_oracle_offset(cc(cc(moved)), 0.08)));
  s.rule = SubdivisionRule::report;
  check(pipeline.run(s), cc(pipeline_oracle_offset(cc(cc(moved, s.rule), s.rule), 0.08), s.rule));
  moved = move(0.25);
  check(pipeline.run(s), cc(pipeline_oracle_offset(cc(cc(moved, s.rule), s.rule), 0.08), s.rule));
  CHECK(pipeline.work(Stage::subdivided_offset) == StageWork::positions);
  s.rule = SubdivisionRule::classic;
  check(pipeline.run(s), cc(pipeline_oracle_offset(cc(cc(moved)), 0.08)));

  // Back: no subdivision after, then none before, then the subdivision alone again.
  s.stage = Stage::offset;
  check(pipeline.run(s), pipeline_oracle_offset(cc(cc(moved)), 0.08));
  s.subdivision_levels = 0;
  check(pipeline.run(s), pipeline_oracle_offset(moved, 0.08));
  // Levels after the offset only: another rule reaches them though nothing before them changed.
  s.stage = Stage::subdivided_offset;
  check(pipeline.run(s), cc(pipeline_oracle_offset(moved, 0.08)));
  s.rule = SubdivisionRule::report;
  check(pipeline.run(s), cc(pipeline_oracle_offset(moved, 0.08), s.rule));
  CHECK(pipeline.work(Stage::offset) == StageWork::cached);
  s.rule = SubdivisionRule::classic;
  s.stage = Stage::offset;
  moved = move(-0.1);
  check(pipeline.run(s), pipeline_oracle_offset(moved, 0.08));
  s.stage = Stage::subdivided;
  s.subdivision_levels = 1;
  check(pipeline.run(s), cc(moved));
  // The same positions again: every stage cached, still the same result.
  pipeline.move_input_vertices(input.soup.positions);
  check(pipeline.run(s), cc(moved));
}

TEST_CASE("a border's subdivision follows the crease rules, and a new boundary mode is no cached result",
          "[kernel]") {
  std::mt19937 rng{7};
  const PolygonSoup grid = test::grid(3, 2);
  PipelineInput input{grid, {}, {}};
  Pipeline pipeline;
  pipeline.set_input(input);
  PipelineSettings s;
  s.stage = Stage::subdivided;
  s.subdivision_levels = 1;
  const PipelineOracleMesh base = pipeline_oracle_from(grid);
  pipeline_oracle_require_same(pipeline.run(s), pipeline_oracle_catmull_clark(base, s.rule));
  input.soup.positions = pipeline_oracle_moved(grid.positions, 0.3, rng);
  pipeline.move_input_vertices(input.soup.positions);
  const PipelineOracleMesh moved = pipeline_oracle_with(base, input.soup.positions);
  pipeline_oracle_require_same(pipeline.run(s), pipeline_oracle_catmull_clark(moved, s.rule));
  // Corners of one face stay put; nothing else changes.
  s.boundary = BoundaryMode::edge_and_corner;
  pipeline_oracle_require_same(pipeline.run(s), pipeline_oracle_catmull_clark(moved, s.rule, true));
  pipeline_oracle_require_fresh(pipeline.run(s), input, s);
  s.boundary = BoundaryMode::edge_only;
  pipeline_oracle_require_same(pipeline.run(s), pipeline_oracle_catmull_clark(moved, s.rule));
  s.subdivision_levels = 2;
  pipeline_oracle_require_same(
      pipeline.run(s), pipeline_oracle_catmull_clark(pipeline_oracle_catmull_clark(moved, s.rule), s.rule));
  pipeline_oracle_require_fresh(pipeline.run(s), input, s);
}

TEST_CASE("merging on, off and with another tolerance is never served from the cache", "[kernel]") {
  // The cube's faces each with their own corners, the copies of a corner 1e-3 apart: a tolerance of 1e-2
  // merges them into the cube, one of 1e-4 leaves six squares.
  const PolygonSoup cube = test::cube();
  PolygonSoup split;
  for (Index f = 0; f < cube.num_faces(); ++f) {
    std::vector<Index> face;
    for (Index c = cube.face_offsets[f]; c < cube.face_offsets[f + 1]; ++c)
      face.push_back(
          split.add_vertex(cube.positions[cube.face_vertices[c]] + 1e-3 * Vec3(f % 2, f % 3, 0) / 2.0));
    split.add_face(face);
  }
  PipelineInput input{split, {}, {}};
  Pipeline pipeline;
  pipeline.set_input(input);
  PipelineSettings s;
  s.stage = Stage::subdivided;
  s.subdivision_levels = 1;
  s.should_merge = true;
  s.merge_tolerance = 1e-2;
  const Mesh& merged = pipeline.run(s);
  CHECK(merged.num_vertices() == 26);
  CHECK(pipeline.merge_summary().glued_edges == 12);
  pipeline_oracle_require_fresh(merged, input, s);
  const std::vector<std::pair<bool, double>> steps{{false, 1e-2}, {true, 1e-2}, {true, 1e-4}, {true, 1e-2},
                                                   {false, 1e-4}, {true, 1e-4}, {true, 1e-2}};
  for (const auto& [merges, tolerance] : steps) {
    INFO("merge " << merges << ", tolerance " << tolerance);
    s.should_merge = merges;
    s.merge_tolerance = tolerance;
    const Mesh& result = pipeline.run(s);
    const bool is_cube = merges && tolerance > 1e-3;
    CHECK(result.num_vertices() == (is_cube ? 26u : 6u * 9u));
    pipeline_oracle_require_fresh(result, input, s);
    // Vertices moved by a slider (each copy of a corner alike) reach the merged mesh's subdivision too.
    for (Vec3& p : input.soup.positions) p += Vec3(0.1 * p.y, 0.05 * p.x * p.z, 0.0);
    pipeline.move_input_vertices(input.soup.positions);
    pipeline_oracle_require_fresh(pipeline.run(s), input, s);
  }
  // The offset straight from the merged or the unmerged mesh.
  s.stage = Stage::offset;
  s.subdivision_levels = 0;
  s.offset_distance = 0.05;
  for (const bool merges : {true, false, true}) {
    INFO("offset, merge " << merges);
    s.should_merge = merges;
    s.merge_tolerance = 1e-2;
    pipeline_oracle_require_fresh(pipeline.run(s), input, s);
  }
  s.stage = Stage::subdivided;
  s.subdivision_levels = 1;
  // A slider that pulls one corner's copies apart past the tolerance changes the merged topology.
  s.should_merge = true;
  s.merge_tolerance = 1e-2;
  input.soup.positions = split.positions;
  pipeline.move_input_vertices(input.soup.positions);
  pipeline.run(s);
  input.soup.positions[0] += Vec3(0.0, 0.0, -0.5);
  pipeline.move_input_vertices(input.soup.positions);
  const Mesh& opened = pipeline.run(s);
  CHECK(opened.num_vertices() > 26);
  pipeline_oracle_require_fresh(opened, input, s);
}

TEST_CASE("moving the vertices of an input joined across edges moves each mesh vertex from its source",
          "[kernel]") {
  // Two squares meeting only at vertex 0 are joined across edges: vertex 0 splits in two, so mesh and input
  // numbers differ.
  PolygonSoup bowtie;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0),
                        Vec3(-1, -1, 0), Vec3(0, -1, 0)})
    bowtie.add_vertex(p);
  bowtie.add_face({0, 1, 2, 3});
  bowtie.add_face({0, 4, 5, 6});
  PipelineInput input{bowtie, {}, Joining::across_edges};
  Pipeline pipeline;
  pipeline.set_input(input);
  PipelineSettings s;
  s.stage = Stage::subdivided;
  s.subdivision_levels = 1;
  pipeline.run(s);
  for (Index v = 0; v < input.soup.num_vertices(); ++v)
    input.soup.positions[v] += Vec3(0.1 * v, 0.0, 0.2 * v * v);
  pipeline.move_input_vertices(input.soup.positions);
  const Mesh& result = pipeline.run(s);
  CHECK(pipeline.work(Stage::scene) == StageWork::positions);
  pipeline_oracle_require_fresh(result, input, s);
  // Each square on its own: a face with four border corners.
  PipelineOracleMesh squares;
  squares.positions.assign(input.soup.positions.begin(), input.soup.positions.end());
  squares.positions.push_back(input.soup.positions[0]);
  squares.faces = {{0, 1, 2, 3}, {7, 4, 5, 6}};
  pipeline_oracle_require_same(result, pipeline_oracle_catmull_clark(squares, s.rule));
}

TEST_CASE("the estimate counts the faces the pipeline makes, borders and rims included", "[kernel]") {
  const PolygonSoup soups[] = {test::grid(3, 2), test::mobius_band(9, 2), test::cube()};
  for (const PolygonSoup& soup : soups) {
    const Mesh mesh = build_mesh(soup);
    for (const auto& [before, distance, after] :
         {std::tuple{0, 0.0, 0}, std::tuple{2, 0.0, 0}, std::tuple{0, 0.05, 0}, std::tuple{1, 0.05, 0},
          std::tuple{2, 0.05, 1}, std::tuple{0, 0.05, 2}}) {
      PipelineSettings s;
      s.subdivision_levels = before;
      s.offset_distance = distance;
      s.subdivision_after = after;
      INFO("faces " << mesh.num_faces() << ", levels " << before << ", distance " << distance << ", after "
                    << after);
      CHECK(estimate_pipeline(mesh, s).faces == double(Pipeline().run(mesh, s).num_faces()));
    }
  }
}
