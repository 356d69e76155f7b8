// The successor's files through the command line: stage blocks set the pipeline unless the options do,
// the dialect is printed with its cue, and --dialect overrides it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "app/cli_support.hpp"
#include "support/shared_examples.hpp"

using nome::test::run_nome;

TEST_CASE("hello_cube: --merge makes one closed sphere, its subdivision block two levels", "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const std::string cube = nome::test::shared_examples_dir("jipcad") + "intro_files__hello_cube.nom";
  const auto r = run_nome("info " + cube + " --merge --json");
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("\"faces\": 96, \"chi\": 2, \"orientable\": true, \"borders\": 0"));
  CHECK_THAT(r.out, Catch::Contains("\"dialect\": \"jipcad (decided by 'list' in a bank at "));
  const auto coarse = run_nome("info " + cube + " --merge --subdiv 0 --json");
  CHECK_THAT(coarse.out, Catch::Contains("\"vertices\": 8, \"edges\": 12, \"faces\": 6, \"chi\": 2"));
  const auto slider = run_nome("info " + cube + " --merge --set sub_level_level=1 --json");
  CHECK_THAT(slider.out, Catch::Contains("\"faces\": 24, \"chi\": 2"));
}

TEST_CASE("hello_cube: without --merge its subdivision welds first, as JIPCAD's, and says so", "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const std::string cube = nome::test::shared_examples_dir("jipcad") + "intro_files__hello_cube.nom";
  const auto r = run_nome("info " + cube + " --json");
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("\"faces\": 96, \"chi\": 2, \"orientable\": true, \"borders\": 0"));
  CHECK_THAT(r.out, Catch::Contains("\"components\": 1"));
  CHECK_THAT(r.err,
             Catch::Contains("nome: note: subdividing the merged mesh: the successor's dialect welds"));
  // Unrefined, the six faces stay apart; the 2016 reading of the same file does not weld either.
  const auto coarse = run_nome("info " + cube + " --subdiv 0 --json");
  CHECK_THAT(coarse.out, Catch::Contains("\"vertices\": 24, \"edges\": 24, \"faces\": 6"));
  CHECK_THAT(coarse.err, !Catch::Contains("welds"));
  const auto report = run_nome("info " + cube + " --dialect 2016 --json");
  CHECK_THAT(report.out, Catch::Contains("\"faces\": 96, \"chi\": 6"));
  CHECK_THAT(report.err, !Catch::Contains("welds"));
}

TEST_CASE("the --dialect option overrides what the statements say, for every command that reads files",
          "[app]") {
  const std::string dir = nome::test::scratch_dir("dialect");
  const std::string file = dir + "/funnel.nome";
  std::ofstream(file) << "funnel f (1 0.5 2 6) endfunnel\ninstance i f endinstance\n";
  const auto as_2016 = run_nome("info " + file);
  CHECK(as_2016.status == 1);  // n = 1: not a funnel in the 2016 order
  CHECK_THAT(as_2016.err, Catch::Contains("funnel.nome:1:11: n must be a whole number"));
  const auto jip = run_nome("info " + file + " --dialect jipcad");
  CHECK(jip.status == 0);
  CHECK_THAT(jip.out, Catch::Contains("dialect jipcad (decided by --dialect)"));
  CHECK_THAT(jip.out, Catch::Contains("instance i: 12 vertices, 6 faces"));
  const auto exported = run_nome("export " + file + " --dialect jipcad -o " + dir + "/out.nome");
  CHECK(exported.status == 0);
  const auto again = run_nome("info " + dir + "/out.nome");
  CHECK(again.status == 0);
  CHECK_THAT(again.out, Catch::Contains("dialect jipcad (decided by the line '# nome-dialect: jipcad'"));
  const auto bad = run_nome("info " + file + " --dialect nome3");
  CHECK(bad.status == 2);
  CHECK_THAT(bad.err, Catch::Contains("--dialect expects 2016 or jipcad, found 'nome3'"));
}

TEST_CASE("41 of JIPCAD's 42 example files open, the malformed one is refused with a location", "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(nome::test::shared_examples_dir("jipcad")))
    if (entry.path().extension() == ".nom") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  CHECK(files.size() == 42);
  std::vector<std::string> refused;
  for (const std::string& file : files) {
    // Opening is reading and joining: the files' own subdivision blocks are tested elsewhere.
    const auto r = nome::test::run_nome_in_process({"info", file, "--subdiv", "0"});
    INFO(file << "\n" << r.err);
    if (r.status == 0) {
      CHECK_THAT(r.out, Catch::Contains("components"));
    } else {
      CHECK(r.status == 1);
      CHECK_THAT(r.err, Catch::Matches("nome: " + file + ":[0-9]+:[0-9]+: (.|\n)*"));
      refused.push_back(std::filesystem::path(file).filename().string());
    }
  }
  // Its `instance assembly scale (...)` names no definition and its background reads `(0.l 0.8 0.9)`:
  // JIPCAD's own grammar (Nom.g4) refuses both.
  CHECK(refused == std::vector<std::string>{"render__render_setting.nom"});
}

TEST_CASE("13-EdgePoly.nom opens: its faces that name missing points are left out, its paths resolve",
          "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const std::string file = nome::test::shared_examples_dir("jipcad") + "geom___13-EdgePoly.nom";
  const auto r = nome::test::run_nome_in_process({"info", file, "--subdiv", "0"});
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains(file + ":49:13: warning: unknown point 'txb': face 'tf3' left out"));
  CHECK_THAT(r.err, Catch::Contains(file + ":50:17: warning: unknown point 'txy': face 'tf4' left out"));
  // The prism keeps 6 of its 8 faces (two open ends), the cube all 7; both polylines find their vertices.
  CHECK_THAT(r.out, Catch::Contains("instance iP3P: 7 vertices, 6 faces"));
  CHECK_THAT(r.out, Catch::Contains("instance iWCube: 8 vertices, 7 faces"));
  CHECK_THAT(r.out, Catch::Contains("instance ibar: 2 vertices, 0 faces, 1 rim lines"));
  CHECK_THAT(r.out, Catch::Contains("instance instTempPoly0: 2 vertices, 0 faces, 1 rim lines"));
}

TEST_CASE("Generators.nom's pieces that meet at a point are split there, with a warning", "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const std::string file = nome::test::shared_examples_dir("jipcad") + "intro_files__Generators.nom";
  const auto r = nome::test::run_nome_in_process({"info", file, "--subdiv", "0"});
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("warning: scene: faces meet at 12 vertices without sharing an edge there "
                                    "(middle0_pa, middle0_pb"));
  // A flat file's bowtie is still refused (tests/data/bad/bowtie_vertex.obj), and so is a scene's three-face
  // edge (a topology error, not a warning).
  const std::string dir = nome::test::scratch_dir("fin");
  std::ofstream(dir + "/fin.nome")
      << "point a (0 0 0) endpoint\npoint b (1 0 0) endpoint\n"
         "point c (0 1 0) endpoint\npoint d (0 -1 0) endpoint\n"
         "point e (0 0 1) endpoint\n"
         "mesh m face f1 (a b c) endface face f2 (b a d) endface face f3 (a b e) "
         "endface endmesh\ninstance i m endinstance\n";
  const auto fin = nome::test::run_nome_in_process({"info", dir + "/fin.nome"});
  CHECK(fin.status == 1);
  CHECK_THAT(fin.err, Catch::Contains("fin.nome") && Catch::Contains("has a third face"));
}
