#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "nome/io/obj.hpp"
#include "support/scratch_files.hpp"

using namespace nome;
namespace fs = std::filesystem;

// Regression: tinyobjloader's file reader opened whatever `mtllib` named, relative to the OBJ's folder,
// and read it line by line: /dev/zero grew one line until memory ran out. Materials are not read at all.
TEST_CASE("an OBJ whose material library is /dev/zero or missing reads at once", "[io]") {
  const fs::path dir = test::scratch_path("nome_mtllib", "").parent_path();
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (const std::string& library : {fs::relative("/dev/zero", dir).string(), std::string("missing.mtl")}) {
    INFO(library);
    std::ofstream(dir / "scene.obj") << "mtllib " << library << "\nusemtl red\n" << triangle;
    const PolygonSoup soup = read_obj(dir / "scene.obj");
    CHECK(soup.num_faces() == 1);
    CHECK(soup.num_vertices() == 3);
  }
  fs::remove_all(dir);
}
