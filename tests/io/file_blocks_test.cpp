#include <sys/resource.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "nome/atomic_file.hpp"
#include "nome/error.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/stl.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/ops/subdivide.hpp"
#include "support/scratch_files.hpp"
#include "support/shapes.hpp"

using namespace nome;
namespace fs = std::filesystem;

namespace {

// Bytes that differ from block to block and from any shifted copy of themselves.
std::string random_bytes(std::size_t n) {
  std::mt19937 random(7);
  std::string s(n, '\0');
  for (char& c : s) c = char(random());
  return s;
}

// The OBJ and binary STL of `mesh` written the plain way, one fprintf or fwrite at a time.
std::string plain_obj(const Mesh& mesh, const fs::path& p) {
  FILE* f = std::fopen(p.c_str(), "wb");
  std::fprintf(f, "# written by nome: %u vertices, %u faces\n", mesh.num_vertices(), mesh.num_faces());
  for (const Vec3& v : mesh.positions()) std::fprintf(f, "v %.17g %.17g %.17g\n", v.x, v.y, v.z);
  for (Index face = 0; face < mesh.num_faces(); ++face) {
    std::fputc('f', f);
    for (Index v : mesh.face_vertices(face)) std::fprintf(f, " %u", v + 1);
    std::fputc('\n', f);
  }
  std::fclose(f);
  return test::file_bytes(p);
}

std::string plain_stl(const Mesh& mesh, const fs::path& p) {
  FILE* f = std::fopen(p.c_str(), "wb");
  char header[80] = "nome binary STL";
  std::fwrite(header, 1, 80, f);
  std::uint32_t triangles = 0;
  for (Index face = 0; face < mesh.num_faces(); ++face) triangles += mesh.face_degree(face) - 2;
  std::fwrite(&triangles, 4, 1, f);
  auto put = [&](const Vec3& v) {
    const float xyz[3] = {float(v.x), float(v.y), float(v.z)};
    std::fwrite(xyz, 4, 3, f);
  };
  for (Index face = 0; face < mesh.num_faces(); ++face) {
    const auto vs = mesh.face_vertices(face);
    const Vec3 area = face_area_normal(mesh, face);
    const Vec3 n = glm::length(area) > 0.0 ? area / glm::length(area) : Vec3(0.0);
    for (size_t i = 1; i + 1 < vs.size(); ++i) {
      put(n);
      for (Index v : {vs[0], vs[i], vs[i + 1]}) put(mesh.position(v));
      std::fwrite("\0\0", 1, 2, f);
    }
  }
  std::fclose(f);
  return test::file_bytes(p);
}

}  // namespace

TEST_CASE("file blocks keep every byte in order, filled directly or through a stream", "[io]") {
  // Past three blocks (the writer thread recycles them) with a tail that is no whole disk block.
  const std::string expected = random_bytes(3 * FileBlocks::block_bytes + 4097);
  std::mt19937 random(3);
  const fs::path p = test::scratch_path("nome_file_blocks_tests", "pattern.bin");
  write_file_in_blocks(p, [&](FileBlocks& file) {
    std::ostream stream(&file);
    for (std::size_t at = 0; at < expected.size();) {
      const std::size_t n = std::min<std::size_t>(expected.size() - at, random() % 70000 + 1);
      if (random() % 2) {
        char* to = file.room(n);
        std::memcpy(to, expected.data() + at, n);
        file.commit(to + n);
      } else {
        stream.write(expected.data() + at, std::streamsize(n));
      }
      at += n;
    }
  });
  CHECK(test::file_bytes(p) == expected);
  // A file smaller than a disk block, and an empty one.
  write_file_in_blocks(p, [](FileBlocks& file) { std::ostream(&file) << "solid nome\n"; });
  CHECK(test::file_bytes(p) == "solid nome\n");
  write_file_in_blocks(p, [](FileBlocks&) {});
  CHECK(fs::file_size(p) == 0);
}

TEST_CASE("a write that fails midway throws and keeps the old file", "[io]") {
  const fs::path p = test::scratch_path("nome_file_blocks_tests", "limited.bin");
  write_file_atomically(p, [](std::ostream& out) { out << "old"; });
  // Files may grow to 1 MB only: the writer thread's write fails (EFBIG) after the first block.
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit before{};
  getrlimit(RLIMIT_FSIZE, &before);
  rlimit limited = before;
  limited.rlim_cur = 1 << 20;
  setrlimit(RLIMIT_FSIZE, &limited);
  const std::string big = random_bytes(2 * FileBlocks::block_bytes);
  CHECK_THROWS_AS(write_file_atomically(p, [&](std::ostream& out) { out << big; }), IoError);
  setrlimit(RLIMIT_FSIZE, &before);
  CHECK(test::file_bytes(p) == "old");
  for (const auto& entry : fs::directory_iterator(p.parent_path())) CHECK(entry.path().extension() != ".tmp");
}

TEST_CASE("OBJ and binary STL are the bytes of a plain fprintf and fwrite writer", "[io]") {
  // Large enough for several blocks: a 64x32 torus subdivided twice (32768 faces, 3.3 MB of STL) and a
  // Möbius band with its border.
  const Mesh torus = subdivide(build_mesh(test::torus(64, 32)), {.levels = 2});
  const Mesh band = build_mesh(test::mobius_band(12, 2));
  for (const Mesh* mesh : {&torus, &band}) {
    const fs::path obj = test::scratch_path("nome_file_blocks_tests", "mesh.obj"),
                   stl = test::scratch_path("nome_file_blocks_tests", "mesh.stl");
    write_obj(obj, *mesh);
    write_stl(stl, *mesh);
    CHECK(test::file_bytes(obj) ==
          plain_obj(*mesh, test::scratch_path("nome_file_blocks_tests", "plain.obj")));
    CHECK(test::file_bytes(stl) ==
          plain_stl(*mesh, test::scratch_path("nome_file_blocks_tests", "plain.stl")));
  }
}
