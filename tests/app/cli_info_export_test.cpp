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

TEST_CASE("nome export keeps an OBJ's OpenSubdiv tags without subdivision and applies them with it",
          "[app]") {
  const std::string dir = nome::test::scratch_dir("export_tags");
  // A 3x3 grid of quads with a semi-sharp crease across it, a corner, a hole and edge-and-corner borders.
  std::ofstream obj(dir + "/grid.obj");
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) obj << "v " << i << ' ' << j << " 0\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      obj << "f " << 4 * j + i + 1 << ' ' << 4 * j + i + 2 << ' ' << 4 * j + i + 6 << ' ' << 4 * j + i + 5
          << '\n';
  obj << "t crease 2/1/0 4 5 1.5\nt crease 2/1/0 5 6 1.5\nt corner 1/1/0 5 0.5\nt hole 1/0/0 8\n"
         "t interpolateboundary 1/0/0 1\nt vertexedit 1/0/1 0 add\n";
  obj.close();
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
