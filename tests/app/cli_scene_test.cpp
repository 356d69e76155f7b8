#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "app/cli_support.hpp"
#include "support/shared_examples.hpp"

using nome::test::run_nome;

namespace {
using nome::test::assets;
const std::string originals = nome::test::shared_examples_dir("original");
}  // namespace

TEST_CASE("nome info lists a scene's banks, sliders and top-level instances", "[app]") {
  const auto r = run_nome("info " + assets + "funnel_cube.nome");
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("bank fp"));
  CHECK_THAT(r.out, Catch::Contains("$fp_n = 8  [3, 10] step 1"));
  CHECK_THAT(r.out, Catch::Contains("instance cf: 96 vertices, 48 faces"));
  CHECK_THAT(r.out, Catch::Contains("components 6"));
  const auto json = run_nome("info " + assets + "funnel_cube.nome --json");
  CHECK_THAT(json.out, Catch::Contains("\"faces\": 48, \"chi\": 0, \"orientable\": true, \"borders\": 12"));
  CHECK_THAT(json.out, Catch::Contains("\"scenes\": [{\"file\": "));
  CHECK_THAT(json.out,
             Catch::Contains("{\"name\": \"fp_n\", \"value\": 8, \"min\": 3, \"max\": 10, \"step\": 1}"));
}

TEST_CASE("nome info --set overrides a slider", "[app]") {
  const auto r = run_nome("info " + assets + "funnel_cube.nome --set fp_n=6 --json");
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("\"vertices\": 72, \"edges\": 108, \"faces\": 36"));
  const auto dotted = run_nome("info " + assets + "funnel_cube.nome --set fp.n=5 --set fp_ro=0.3 --json");
  CHECK_THAT(dotted.out, Catch::Contains("\"faces\": 30"));
  const auto outside = run_nome("info " + assets + "funnel_cube.nome --set fp_n=20");
  CHECK(outside.status == 1);
  CHECK_THAT(outside.err, Catch::Contains("fp_n=20 is outside its slider range [3, 10]"));
  const auto unknown = run_nome("info " + assets + "funnel_cube.nome --set fp_m=4");
  CHECK(unknown.status == 2);
  CHECK_THAT(unknown.err, Catch::Contains("no parameter 'fp_m' (did you mean fp_n"));
}

TEST_CASE("nome reports scene errors as FILE:LINE:COL", "[app]") {
  const std::string dir = nome::test::scratch_dir("scene_errors");
  std::ofstream(dir + "/bad.nome") << "funnel f (8 1 0) endfunnel\ninstance i g endinstance\n";
  const auto r = run_nome("info " + dir + "/bad.nome");
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("bad.nome:1:10: funnel 'f' takes 4 arguments (n ro ratio h), found 3"));
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const auto hild = run_nome("info " + originals + "hild.nom");
  CHECK(hild.status == 0);
  CHECK_THAT(hild.err,
             Catch::Contains("hild.nom:110:58: warning: expected 'endinstance', found 'enintance'"));
}

TEST_CASE("an empty scene file is an empty scene: info and export accept it", "[app]") {
  const std::string dir = nome::test::scratch_dir("scene_empty");
  std::ofstream(dir + "/empty.nome").flush();
  const auto info = run_nome("info " + dir + "/empty.nome");
  CHECK(info.status == 0);
  CHECK_THAT(info.out, Catch::Contains("vertices 0, edges 0, faces 0"));
  CHECK(run_nome("export " + dir + "/empty.nome -o " + dir + "/empty.obj").status == 0);
  CHECK_THAT(run_nome("info " + dir + "/empty.nome --json").out, Catch::Contains("\"faces\": 0"));
}

TEST_CASE("nome export writes a scene's instances", "[app]") {
  const std::string dir = nome::test::scratch_dir("scene_export");
  CHECK(run_nome("export " + assets + "klein_bottle.nome -o " + dir + "/kb.obj").status == 0);
  CHECK_THAT(run_nome("info " + dir + "/kb.obj --json").out, Catch::Contains("\"faces\": 80"));
}

TEST_CASE("nome export -o OUT.nome saves the scene with the sliders as set", "[app]") {
  const std::string dir = nome::test::scratch_dir("scene_save");
  const auto r = run_nome("export " + assets + "funnel_cube.nome --set fp_n=5 -o " + dir + "/five.nome");
  CHECK(r.status == 0);
  const auto back = run_nome("info " + dir + "/five.nome --json");
  CHECK_THAT(back.out, Catch::Contains("\"faces\": 30"));
  CHECK_THAT(back.out, Catch::Contains("{\"name\": \"fp_n\", \"value\": 5,"));
  CHECK(run_nome("export " + assets + "cube.obj -o " + dir + "/x.nome").status == 2);
}

TEST_CASE("nome info reads .sif (optionally as quads), .slf and .anom on top of a scene", "[app]") {
  CHECK_THAT(run_nome("info " + assets + "mobius_band.sif --json").out,
             Catch::Contains("\"faces\": 48, \"chi\": 0, \"orientable\": false, \"borders\": 1"));
  CHECK_THAT(run_nome("info " + assets + "mobius_band.sif --quads --json").out,
             Catch::Contains("\"faces\": 24"));
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const auto anom = run_nome("info " + originals + "kleinbottle.nom " + originals + "kleinbottle_s1.anom");
  CHECK(anom.status == 0);
  CHECK_THAT(anom.out, Catch::Contains("consolidated mesh: 16 vertices, 8 faces"));
  CHECK_THAT(
      run_nome("info " + originals + "kleinbottle.nom " + originals + "kleinbottle_s1.anom --json").out,
      Catch::Contains("\"edits\": {\"consolidated_vertices\": 16, \"consolidated_faces\": 8, "
                      "\"deleted_faces\": 0, \"sharp_edges\": 0}"));
  const auto alone = run_nome("info " + originals + "kleinbottle_s1.anom");
  CHECK(alone.status == 2);
  CHECK_THAT(alone.err, Catch::Contains("an .anom file applies to an open scene"));
  const auto slf = run_nome("info " + originals + "minSubdiv.slf");
  CHECK(slf.status == 0);
  CHECK_THAT(slf.out, Catch::Contains("vertices 26, edges 48, faces 24, chi 2"));
}

TEST_CASE("merged, the report's corner patches close the funnel cube into one surface with six rims",
          "[app]") {
  const auto r = run_nome("info " + assets + "funnel_cube_consolidated.nome --merge --json");
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains(
                        "\"vertices\": 96, \"edges\": 180, \"faces\": 80, \"chi\": -4, \"orientable\": true, "
                        "\"borders\": 6, \"components\": 1"));
}

// The CLI reads a scene's edits through the viewer's document: the consolidated faces, deleted faces and
// sharp edges are applied one way, and an edit a --set leaves without its vertices is left out with a
// warning, as the viewer leaves it out.
TEST_CASE("nome reads a scene's edits as the viewer does, and says which a slider value leaves out",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("cli_scene_edits");
  const std::string file = dir + "/edits.nome";
  std::ofstream(file) << "bank b\n  set n 6 3 10 1\nendbank\n"
                         "funnel fun ({expr $b_n} 1 0.5 1) endfunnel\n"
                         "instance f1 fun endinstance\ninstance f2 fun translate (3 0 0) endinstance\n"
                         "consolidate\n  consolidateface vertex f1_hc5 endvertex vertex f2_hc0 endvertex "
                         "vertex f2_hc1 endvertex endconsolidateface\nendconsolidate\n"
                         "delete face f2_f0 endface enddelete\n";
  const auto info = run_nome("info " + file);
  INFO(info.err);
  REQUIRE(info.status == 0);
  CHECK_THAT(info.out, Catch::Contains("  consolidated mesh: 3 vertices, 1 faces\n  deleted faces: 1\n"));
  // Six faces of each funnel, one deleted, one consolidated.
  CHECK_THAT(info.out, Catch::Contains("faces 12,"));
  const auto fewer = run_nome("info " + file + " --set b_n=4 --json");
  INFO(fewer.err);
  REQUIRE(fewer.status == 0);
  CHECK_THAT(fewer.err,
             Catch::Contains("nome: warning: " + file +
                             ": edit 'edit1' left out: vertex f1_hc5 is gone at these slider values"));
  CHECK_THAT(fewer.out, Catch::Contains("\"faces\": 7,"));
  // Saving with -o refuses to lose the edit this value hides, as the viewer's Save does.
  const auto refused = run_nome("export " + file + " --set b_n=4 -o " + dir + "/saved.nome");
  CHECK(refused.status == 1);
  CHECK_THAT(refused.err,
             Catch::Contains("save: refused, the file would lose 1 edits whose vertices or faces "
                             "are gone at the current slider values (edit1)"));
  CHECK_FALSE(std::filesystem::exists(dir + "/saved.nome"));
  const auto saved = run_nome("export " + file + " --set b_n=7 -o " + dir + "/saved.nome");
  INFO(saved.err);
  REQUIRE(saved.status == 0);
  const auto reread = run_nome("info " + dir + "/saved.nome --set b_n=6");
  CHECK_THAT(reread.out, Catch::Contains("consolidated mesh: 3 vertices, 1 faces") &&
                             Catch::Contains("deleted faces: 1") && Catch::Contains("faces 12,"));
}
