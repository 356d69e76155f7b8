// CGAL's whole process for the export benchmark (bench/export.cpp): reads an OBJ into a Surface_mesh,
// applies Catmull-Clark `levels` times and writes a binary STL (each quad as the two triangles nome
// writes). Usage: nome_peer_cgal_subdivide IN.obj LEVELS OUT.stl
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

using Kernel = CGAL::Simple_cartesian<double>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

namespace {

void put(std::vector<char>& out, const Kernel::Vector_3& v) {
  const float f[3] = {float(v.x()), float(v.y()), float(v.z())};
  const char* bytes = reinterpret_cast<const char*>(f);
  out.insert(out.end(), bytes, bytes + 12);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s IN.obj LEVELS OUT.stl\n", argv[0]);
    return 2;
  }
  SurfaceMesh mesh;
  if (!CGAL::IO::read_polygon_mesh(argv[1], mesh)) return 1;
  CGAL::Subdivision_method_3::CatmullClark_subdivision(
      mesh, CGAL::parameters::number_of_iterations(std::atoi(argv[2])));
  std::ofstream out(argv[3], std::ios::binary);
  char header[80] = {};
  out.write(header, 80);
  const std::uint32_t triangles = std::uint32_t(2 * mesh.number_of_faces());
  out.write(reinterpret_cast<const char*>(&triangles), 4);
  std::vector<char> block;
  for (const auto f : mesh.faces()) {
    std::vector<Kernel::Point_3> p;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) p.push_back(mesh.point(v));
    const Kernel::Vector_3 n = CGAL::cross_product(p[2] - p[0], p[3] - p[1]);
    for (size_t i = 1; i + 1 < p.size(); ++i) {
      put(block, n / std::sqrt(n.squared_length()));
      for (const auto& q : {p[0], p[i], p[i + 1]}) put(block, q - CGAL::ORIGIN);
      block.push_back(0);
      block.push_back(0);
    }
    if (block.size() > (1 << 20)) {
      out.write(block.data(), std::streamsize(block.size()));
      block.clear();
    }
  }
  out.write(block.data(), std::streamsize(block.size()));
  return out ? 0 : 1;
}
