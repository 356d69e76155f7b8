// A hole can leave two fans of a subdivided surface meeting at one vertex: the mesh keeps one copy per fan
// (a 2-manifold), the OBJ writer writes the vertex once, as OpenSubdiv's refinement has it.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "nome/io/obj.hpp"
#include "nome/io/obj_tags.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/stl.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/subdivide.hpp"
#include "support/opensubdiv_refiner.hpp"
#include "support/scratch_files.hpp"
#include "support/shared_examples.hpp"

#ifdef NOME_HAVE_OPENSUBDIV
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#endif

using namespace nome;
namespace fs = std::filesystem;

namespace {

struct HoleObj {
  std::vector<Vec3> positions;
  std::vector<std::vector<Index>> faces;  // 0-based
};

HoleObj hole_parse_obj(const fs::path& path) {
  HoleObj obj;
  std::istringstream in(test::file_bytes(path));
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "v") {
      Vec3 p;
      words >> p.x >> p.y >> p.z;
      obj.positions.push_back(p);
    } else if (kind == "f") {
      obj.faces.emplace_back();
      for (long i; words >> i;) obj.faces.back().push_back(Index(i - 1));
    }
  }
  return obj;
}

// OpenSubdiv's catmark_hole_test4: five quads in a plane, the middle one a hole, which leaves the faces at
// vertex 2 (0-based) touching at it only.
PolygonSoup hole_test4_shape() {
  PolygonSoup soup;
  for (const Vec3& p :
       {Vec3(-1, 0, 1), Vec3(-1, 0, 0), Vec3(-0.5, 0, 0), Vec3(-0.5, 0, 1), Vec3(0, 0, 1), Vec3(0.5, 0, 0),
        Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(-0.5, 0, -1), Vec3(0, 0, -1), Vec3(1, 0, -1)})
    soup.add_vertex(p);
  soup.add_face({0, 1, 2, 3});
  soup.add_face({3, 2, 5, 4});
  soup.add_face({4, 5, 6, 7});
  soup.add_face({2, 8, 9, 5});
  soup.add_face({5, 9, 10, 6});
  soup.hole_faces = {1};
  return soup;
}

}  // namespace

TEST_CASE("a vertex where a hole leaves two fans meeting is written once, its faces all naming it", "[io]") {
  const Mesh base = build_mesh(hole_test4_shape());
  const Mesh refined = subdivide(base, {1});
  // 11 vertex points, 15 edge points, 5 face points, less the hole's face point and the point of the
  // edge only the hole has: 29; the vertex at (-0.5, 0, 0) is one per fan in the mesh.
  CHECK(refined.num_faces() == 16);
  CHECK(refined.num_vertices() == 30);
  const fs::path path = test::scratch_path("nome_hole_export", "hole4.obj");
  write_obj(path, refined);
  const HoleObj obj = hole_parse_obj(path);
  CHECK(obj.positions.size() == 29);
  REQUIRE(obj.faces.size() == refined.num_faces());
  std::set<std::array<double, 3>> distinct;
  for (const Vec3& p : obj.positions) distinct.insert({p.x, p.y, p.z});
  CHECK(distinct.size() == obj.positions.size());
  for (Index f = 0; f < refined.num_faces(); ++f) {
    const auto vs = refined.face_vertices(f);
    REQUIRE(obj.faces[f].size() == vs.size());
    for (std::size_t i = 0; i < vs.size(); ++i) {
      REQUIRE(obj.faces[f][i] < obj.positions.size());
      CHECK(obj.positions[obj.faces[f][i]] == refined.position(vs[i]));
    }
  }
  // Read back, the vertex is split again into one per fan: the same surface.
  const GluedFaces back = glue_faces(read_obj(path));
  CHECK(back.mesh.num_vertices() == refined.num_vertices());
  CHECK(back.mesh.num_faces() == refined.num_faces());
  CHECK(back.problems.empty());
  // nome reads its own file back as the surface it wrote: the tag splits the vertex into its fans again.
  const Mesh reread = build_mesh(read_polygons(path.string()));
  CHECK(reread.num_vertices() == refined.num_vertices());
  CHECK(topology_report(reread).chi == topology_report(refined).chi);
  CHECK(topology_report(reread).borders == topology_report(refined).borders);
  // The other writers are indexed per triangle or per side: STL keeps every triangle.
  const fs::path stl = test::scratch_path("nome_hole_export", "hole4.stl");
  write_stl(stl, refined, StlFormat::binary);
  CHECK(fs::file_size(stl) == 84 + 50 * 2 * 16);
}

#ifdef NOME_HAVE_OPENSUBDIV
namespace {

namespace HoleFar = OpenSubdiv::Far;

struct HolePoint {
  Vec3 p{0.0};
  void Clear() { p = Vec3(0.0); }
  void AddWithWeight(const HolePoint& s, double w) { p += w * s.p; }
};

// OpenSubdiv's level `levels`: the positions of the vertices its faces that are not holes use, and those
// faces as vertex sets.
std::pair<std::vector<Vec3>, std::multiset<std::set<Index>>> hole_osd_refine(const PolygonSoup& soup,
                                                                             BoundaryMode mode, int levels) {
  const auto refiner = test::opensubdiv_refiner(soup, mode, CreaseOptions{}, levels, false);
  std::vector<HolePoint> in;
  for (const Vec3& p : soup.positions) in.push_back({p});
  const HoleFar::PrimvarRefinerReal<double> primvars(*refiner);
  for (int k = 1; k <= levels; ++k) {
    std::vector<HolePoint> out(std::size_t(refiner->GetLevel(k).GetNumVertices()));
    HolePoint* from = in.data();
    HolePoint* to = out.data();
    primvars.Interpolate(k, from, to);
    in = out;
  }
  const HoleFar::TopologyLevel& last = refiner->GetLevel(levels);
  std::map<int, Index> used;
  std::vector<Vec3> positions;
  std::multiset<std::set<Index>> faces;
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    if (last.IsFaceHole(f)) continue;
    std::set<Index> face;
    for (int v : last.GetFaceVertices(f)) {
      const auto [it, is_new] = used.emplace(v, Index(positions.size()));
      if (is_new) positions.push_back(in[std::size_t(v)].p);
      face.insert(it->second);
    }
    faces.insert(face);
  }
  return {positions, faces};
}

}  // namespace

TEST_CASE("subdivided OpenSubdiv hole shapes are written with OpenSubdiv's vertices, each once", "[io]") {
  NOME_NEEDS_SHARED_EXAMPLES("opensubdiv");
  for (const char* name : {"catmark_hole_test1.obj", "catmark_hole_test2.obj", "catmark_hole_test3.obj",
                           "catmark_hole_test4.obj"})
    for (int levels : {1, 2}) {
      INFO(name << " level " << levels);
      const fs::path path = fs::path(test::shared_examples_dir("opensubdiv")) / name;
      const PolygonSoup soup = read_obj(path);
      const BoundaryMode mode = read_obj_subdivision_tags(path).boundary.value_or(BoundaryMode::edge_only);
      const Mesh refined = subdivide(build_mesh(soup), {levels, SubdivisionRule::classic, mode});
      const fs::path out = test::scratch_path("nome_hole_export", "osd.obj");
      write_obj(out, refined);
      const HoleObj obj = hole_parse_obj(out);
      const auto [positions, faces] = hole_osd_refine(soup, mode, levels);
      CHECK(obj.positions.size() == positions.size());
      // Each written vertex is one of OpenSubdiv's, no two the same one, and the faces name the same sets.
      std::vector<Index> theirs(obj.positions.size(), no_index);
      std::set<Index> matched;
      for (std::size_t v = 0; v < obj.positions.size(); ++v)
        for (Index w = 0; w < positions.size(); ++w)
          if (glm::length(obj.positions[v] - positions[w]) < 1e-9) theirs[v] = w, matched.insert(w);
      CHECK(matched.size() == obj.positions.size());
      std::multiset<std::set<Index>> written;
      for (const auto& face : obj.faces) {
        std::set<Index> mapped;
        for (Index v : face) mapped.insert(theirs.at(v));
        written.insert(mapped);
      }
      CHECK(written == faces);
    }
}
#endif

TEST_CASE("t splitvertex gives each fan at a vertex its own copy, sharp marks following their faces",
          "[io]") {
  // Two triangles touching at v1 (a bowtie), the crease on one of them and a corner weight at v1.
  const fs::path path = test::scratch_path("nome_hole_export", "bowtie.obj");
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 2 0 0\nv 2 -1 0\n"
                         "f 1 2 3\nf 2 4 5\n"
                         "t crease 2/1/0 1 3 2\nt corner 1/1/0 1 3\nt splitvertex 1/0/0 1\n";
  const PolygonSoup soup = read_polygons(path.string());
  REQUIRE(soup.num_vertices() == 6);
  CHECK(soup.positions[5] == Vec3(1, 0, 0));
  // The first face keeps v1; the second names the copy.
  CHECK(std::vector<Index>(soup.face_vertices.begin(), soup.face_vertices.end()) ==
        std::vector<Index>{0, 1, 2, 5, 3, 4});
  REQUIRE(soup.sharp_edges.size() == 1);
  CHECK(soup.sharp_edges[0] == std::pair<Index, Index>(5, 3));
  CHECK(soup.sharp_vertices.size() == 2);
  const Mesh mesh = build_mesh(soup);
  CHECK(mesh.num_components() == 2);
  // Without the tag the same faces are refused, as any flat file whose faces touch at a vertex.
  const fs::path plain = test::scratch_path("nome_hole_export", "bowtie_plain.obj");
  std::ofstream(plain) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 2 0 0\nv 2 -1 0\nf 1 2 3\nf 2 4 5\n";
  CHECK_THROWS(build_mesh(read_polygons(plain.string())));
}
