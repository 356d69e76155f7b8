#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "app/cli_support.hpp"

using nome::test::run_nome;

namespace {
using nome::test::assets;
}

TEST_CASE("nome info --json reports every example surface", "[app]") {
  struct Row {
    const char* file;
    const char* expected;
  };
  const Row rows[] = {
      {"tetrahedron.obj", "\"chi\": 2, \"orientable\": true, \"borders\": 0"},
      {"cube.obj", "\"chi\": 2, \"orientable\": true, \"borders\": 0"},
      {"grid.obj", "\"chi\": 1, \"orientable\": true, \"borders\": 1"},
      {"torus.obj", "\"chi\": 0, \"orientable\": true, \"borders\": 0"},
      {"torus_mixed.obj", "\"chi\": 0, \"orientable\": true, \"borders\": 0"},
      {"mobius_band.obj", "\"chi\": 0, \"orientable\": false, \"borders\": 1"},
      {"mobius_band_narrow.obj", "\"chi\": 0, \"orientable\": false, \"borders\": 1"},
      {"klein_bottle.obj", "\"chi\": 0, \"orientable\": false, \"borders\": 0"},
      {"projective_plane.obj",
       "\"vertices\": 4, \"edges\": 6, \"faces\": 3, \"chi\": 1, \"orientable\": false"},
  };
  for (const Row& row : rows) {
    INFO(row.file);
    const auto r = run_nome("info " + assets + row.file + " --json");
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains(row.expected));
    CHECK_THAT(r.out, Catch::Contains("\"parts\": [{"));
    CHECK_THAT(r.out, Catch::Contains("\"manifold\": true"));
  }
}

TEST_CASE("nome export writes OBJ and STL that read back the same", "[app]") {
  const std::string dir = nome::test::scratch_dir("export");
  CHECK(run_nome("export " + assets + "klein_bottle.obj -o " + dir + "/kb.obj").status == 0);
  CHECK_THAT(run_nome("info " + dir + "/kb.obj --json").out,
             Catch::Contains("\"vertices\": 288, \"edges\": 576"));
  CHECK(run_nome("export " + assets + "torus.obj -o " + dir + "/t.stl --ascii").status == 0);
  CHECK_THAT(run_nome("info " + dir + "/t.stl --json").out,
             Catch::Contains("\"chi\": 0, \"orientable\": true"));
}

TEST_CASE("nome reports errors with location and exit status 1, usage errors with 2", "[app]") {
  const std::string dir = nome::test::scratch_dir("errors");
  std::ofstream(dir + "/bad.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
  auto r = run_nome("info " + dir + "/bad.obj");
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::StartsWith("nome: ") && Catch::Contains("bad.obj:4:7:"));
  std::ofstream(dir + "/fin.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 2 1 3\n";
  r = run_nome("info " + dir + "/fin.obj");
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("third face"));
  CHECK(run_nome("info").status == 2);
  CHECK(run_nome("info --frobnicate x.obj").status == 2);
  CHECK(run_nome("export " + assets + "cube.obj").status == 2);
  CHECK(run_nome("export " + assets + "cube.obj -o " + dir + "/x.png").status == 2);
  CHECK(run_nome("wat").status == 2);
  r = run_nome("export " + dir + "/bad.obj -o " + dir + "/never.obj");
  CHECK(r.status == 1);
  CHECK_FALSE(std::filesystem::exists(dir + "/never.obj"));
}

TEST_CASE("every command explains its options", "[app]") {
  const auto top = run_nome("--help");
  CHECK(top.status == 0);
  CHECK_THAT(top.out, Catch::Contains("info") && Catch::Contains("export"));
  for (const char* cmd : {"info", "export"}) {
    const auto r = run_nome(std::string(cmd) + " --help");
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("usage: nome"));
  }
}

namespace {

// An OBJ grid of n x n unit quads in the plane z = 0, vertices row by row, then `tags`.
void write_grid_obj(const std::string& path, int n, const std::string& tags) {
  std::ofstream obj(path);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) obj << "v " << i << ' ' << j << " 0\n";
  const int row = n + 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      obj << "f " << row * j + i + 1 << ' ' << row * j + i + 2 << ' ' << row * (j + 1) + i + 2 << ' '
          << row * (j + 1) + i + 1 << '\n';
  obj << tags;
}

}  // namespace

TEST_CASE("nome export keeps an OBJ's OpenSubdiv tags without subdivision and applies them with it",
          "[app]") {
  const std::string dir = nome::test::scratch_dir("export_tags");
  // A 3x3 grid of quads with a semi-sharp crease across it, a corner, a hole and edge-and-corner borders.
  write_grid_obj(dir + "/grid.obj", 3,
                 "t crease 2/1/0 4 5 1.5\nt crease 2/1/0 5 6 1.5\nt corner 1/1/0 5 0.5\nt hole 1/0/0 8\n"
                 "t interpolateboundary 1/0/0 1\nt vertexedit 1/0/1 0 add\n");
  const auto kept = nome::test::run_nome_in_process({"export", dir + "/grid.obj", "-o", dir + "/base.obj"});
  REQUIRE(kept.status == 0);
  CHECK_THAT(kept.err, Catch::Contains("grid.obj:31: 't vertexedit' ignored"));
  std::ifstream in(dir + "/base.obj");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t creases = 0;
  for (size_t at = text.find("t crease 2/1/0 "); at != std::string::npos;
       at = text.find("t crease 2/1/0 ", at + 1))
    creases += text.compare(text.find('\n', at) - 4, 4, " 1.5") == 0 ? 1 : 0;
  CHECK(creases == 2);
  CHECK_THAT(text, Catch::Contains("t corner 1/1/0 5 0.5\n") && Catch::Contains("t hole 1/0/0 8\n") &&
                       Catch::Contains("t interpolateboundary 1/0/0 1\n"));
  // Subdivided: the hole's 16 quads are not output and the tags are used up.
  const auto refined = nome::test::run_nome_in_process(
      {"export", dir + "/grid.obj", "--subdiv", "2", "-o", dir + "/fine.obj"});
  REQUIRE(refined.status == 0);
  CHECK_THAT(refined.err, Catch::Contains("128 faces"));
  CHECK_THAT(nome::test::run_nome_in_process(std::string("export --help")).out,
             Catch::Contains("--boundary none|edge-only|edge-and-corner") && Catch::Contains("t crease"));
}

// Two holes on a diagonal leave the other two quads' children touching at the centre alone: the mesh
// splits that vertex, one copy per fan, and the OBJ writes it once. The count reported is the file's.
TEST_CASE("nome export counts a vertex that holes split once, as the OBJ writes it", "[app]") {
  const std::string dir = nome::test::scratch_dir("export_split_vertex");
  write_grid_obj(dir + "/grid.obj", 2, "t hole 1/0/0 1\nt hole 1/0/0 2\n");
  const auto r = nome::test::run_nome_in_process(
      {"export", dir + "/grid.obj", "--subdiv", "1", "-o", dir + "/fine.obj"});
  REQUIRE(r.status == 0);
  std::ifstream in(dir + "/fine.obj");
  std::size_t vertices = 0, faces = 0;
  for (std::string line; std::getline(in, line);) {
    vertices += line.rfind("v ", 0) == 0;
    faces += line.rfind("f ", 0) == 0;
  }
  CHECK(faces == 8);
  CHECK(vertices == 17);  // 2 x 9 children less the centre written once
  CHECK_THAT(r.err, Catch::Contains("(" + std::to_string(vertices) + " vertices, 8 faces"));
}

namespace {

// Four parts whose counts all differ, and a vertex in no face: a Möbius band of six quads with its third
// quad turned over (Möbius edges: the twist's rung and the turned quad's two rungs), a tetrahedron, a strip
// of two quads and a cube. Every number of the report is worked out here by hand.
const char* const four_parts_obj =
    // Möbius band: a0..a5 (1..6) on top, b0..b5 (7..12) below.
    "v 2 0 0.5\nv 1 1.7 0.5\nv -1 1.7 0.5\nv -2 0 0.5\nv -1 -1.7 0.5\nv 1 -1.7 0.5\n"
    "v 2 0 -0.5\nv 1 1.7 -0.5\nv -1 1.7 -0.5\nv -2 0 -0.5\nv -1 -1.7 -0.5\nv 1 -1.7 -0.5\n"
    "f 1 2 8 7\nf 2 3 9 8\nf 9 10 4 3\nf 4 5 11 10\nf 5 6 12 11\nf 6 7 1 12\n"
    // Tetrahedron (13..16).
    "v 5 0 0\nv 6 0 0\nv 5 1 0\nv 5 0 1\n"
    "f 13 15 14\nf 13 14 16\nf 14 15 16\nf 13 16 15\n"
    // Strip of two quads (17..22).
    "v 8 0 0\nv 9 0 0\nv 10 0 0\nv 8 1 0\nv 9 1 0\nv 10 1 0\n"
    "f 17 18 21 20\nf 18 19 22 21\n"
    // Cube (23..30).
    "v 12 0 0\nv 13 0 0\nv 13 1 0\nv 12 1 0\nv 12 0 1\nv 13 0 1\nv 13 1 1\nv 12 1 1\n"
    "f 23 26 25 24\nf 27 28 29 30\nf 23 24 28 27\nf 25 26 30 29\nf 23 27 30 26\nf 24 25 29 28\n"
    // A vertex in no face.
    "v 20 20 20\n";

}  // namespace

// Each number under its own label: V 12 + 4 + 6 + 8 = 30, E 18 + 6 + 7 + 12 = 43, F 6 + 4 + 2 + 6 = 18,
// chi 0 + 2 + 1 + 2 = 5 (the vertex in no face counts in no part), 4 parts, borders 1 + 1 = 2, Möbius
// edges 3; the band's chi 0 = 2 - k - 1 gives one cross-cap.
TEST_CASE("nome info puts every count under its own label, in text and in JSON", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("info_labels");
  std::ofstream(dir + "/parts.obj") << four_parts_obj;
  const auto text = nome::test::run_nome_in_process("info " + dir + "/parts.obj");
  INFO(text.err);
  REQUIRE(text.status == 0);
  CHECK(text.out ==
        "vertices 30, edges 43, faces 18, chi 5\n"
        "components 4, orientable no, borders 2, Möbius edges 3\n"
        "isolated vertices (in no face) 1\n"
        "  part 0: V 12, E 18, F 6, chi 0, non-orientable, borders 1, cross-caps 1, Möbius edges 3\n"
        "  part 1: V 4, E 6, F 4, chi 2, orientable, borders 0, genus 0, Möbius edges 0\n"
        "  part 2: V 6, E 7, F 2, chi 1, orientable, borders 1, genus 0, Möbius edges 0\n"
        "  part 3: V 8, E 12, F 6, chi 2, orientable, borders 0, genus 0, Möbius edges 0\n");
  const auto json = nome::test::run_nome_in_process("info " + dir + "/parts.obj --json");
  REQUIRE(json.status == 0);
  CHECK(json.out ==
        "{\"vertices\": 30, \"edges\": 43, \"faces\": 18, \"chi\": 5, \"orientable\": false, \"borders\": 2, "
        "\"components\": 4, \"mobius_edges\": 3, \"manifold\": true, \"isolated_vertices\": 1, \"parts\": ["
        "{\"vertices\": 12, \"edges\": 18, \"faces\": 6, \"chi\": 0, \"orientable\": false, \"borders\": 1, "
        "\"genus\": 1, \"mobius_edges\": 3}, "
        "{\"vertices\": 4, \"edges\": 6, \"faces\": 4, \"chi\": 2, \"orientable\": true, \"borders\": 0, "
        "\"genus\": 0, \"mobius_edges\": 0}, "
        "{\"vertices\": 6, \"edges\": 7, \"faces\": 2, \"chi\": 1, \"orientable\": true, \"borders\": 1, "
        "\"genus\": 0, \"mobius_edges\": 0}, "
        "{\"vertices\": 8, \"edges\": 12, \"faces\": 6, \"chi\": 2, \"orientable\": true, \"borders\": 0, "
        "\"genus\": 0, \"mobius_edges\": 0}]}\n");

  // One subdivision level: a point per vertex, edge and face (30 + 43 + 18 = 91), each edge halved and an
  // edge from each face's centre to each of its sides (2 * 43 + 14 * 4 + 4 * 3 = 154), a quad per corner
  // (14 * 4 + 4 * 3 = 68); chi, borders and parts stay, each Möbius rung halved into two.
  const auto subdivided = nome::test::run_nome_in_process("info " + dir + "/parts.obj --subdiv 1");
  REQUIRE(subdivided.status == 0);
  CHECK_THAT(subdivided.out, Catch::Contains("vertices 91, edges 154, faces 68, chi 5\n"
                                             "components 4, orientable no, borders 2, Möbius edges 6\n"));
}
