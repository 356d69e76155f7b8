#include <catch2/catch.hpp>

#include "nome/ops/subdivide.hpp"
#include "support/point_sets.hpp"
#include "support/shapes.hpp"
#include "support/skip.hpp"

#ifdef NOME_HAVE_OPENMESH
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#endif

using namespace nome;

#ifdef NOME_HAVE_OPENMESH
namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

std::vector<Vec3> openmesh_catmull_clark(const PolygonSoup& soup, int levels) {
  OmMesh om;
  std::vector<OmMesh::VertexHandle> handles;
  for (const Vec3& p : soup.positions) handles.push_back(om.add_vertex(OmMesh::Point(p.x, p.y, p.z)));
  for (Index f = 0; f < soup.num_faces(); ++f) {
    std::vector<OmMesh::VertexHandle> face;
    for (Index c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c)
      face.push_back(handles[soup.face_vertices[c]]);
    om.add_face(face);
  }
  OpenMesh::Subdivider::Uniform::CatmullClarkT<OmMesh> subdivider;
  subdivider.attach(om);
  subdivider(size_t(levels));
  subdivider.detach();
  std::vector<Vec3> out;
  for (auto v : om.vertices()) out.emplace_back(om.point(v)[0], om.point(v)[1], om.point(v)[2]);
  return out;
}

// A closed mesh mixing triangles, quads and a pentagon-fan: a square pyramid on a cube's top face.
PolygonSoup capped_cube() {
  PolygonSoup s = test::cube();
  s.face_offsets.erase(s.face_offsets.begin() + 2);  // drop face 1 (z = +1) ...
  s.face_vertices.erase(s.face_vertices.begin() + 4, s.face_vertices.begin() + 8);
  for (Index& o : s.face_offsets) o = o > 4 ? o - 4 : o;
  const Index apex = s.add_vertex(Vec3(0.1, -0.2, 2.0));  // ... and cap it with four triangles
  for (auto [a, b] : {std::pair<Index, Index>{4, 5}, {5, 7}, {7, 6}, {6, 4}}) s.add_face({a, b, apex});
  return s;
}

}  // namespace

TEST_CASE("the classic rule agrees with OpenMesh's CatmullClarkT on closed meshes", "[kernel]") {
  const std::pair<const char*, PolygonSoup> shapes[] = {
      {"cube", test::cube()},
      {"tetrahedron", test::tetrahedron()},
      {"torus", test::torus(8, 6)},
      {"capped cube", capped_cube()},
  };
  for (const auto& [name, soup] : shapes) {
    for (int levels = 1; levels <= 3; ++levels) {
      INFO(name << ", " << levels << " levels");
      const auto ours = subdivide(build_mesh(soup), {levels, SubdivisionRule::classic}).positions();
      CHECK(test::compare_point_sets(ours, openmesh_catmull_clark(soup, levels), 1e-12) == "");
    }
  }
}
#else
TEST_CASE("the classic rule agrees with OpenMesh's CatmullClarkT on closed meshes", "[kernel]") {
  NOME_SKIP("OpenMesh (libopenmesh-dev) not found at configure time: comparison with CatmullClarkT skipped");
}
#endif
