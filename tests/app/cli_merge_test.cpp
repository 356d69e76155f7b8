#include <catch2/catch.hpp>

#include <numeric>

#include "app/cli_support.hpp"
#include "nome/io/obj.hpp"
#include "support/shapes.hpp"

using nome::test::run_nome;

namespace {

// The Möbius band of the shapes catalogue cut across into two halves, written as two OBJ files.
std::string write_halves(const std::string& dir) {
  const nome::PolygonSoup band = nome::test::mobius_band(12, 2);
  std::vector<nome::Index> part(band.num_faces());
  for (nome::Index f = 0; f < band.num_faces(); ++f) part[f] = f < band.num_faces() / 2 ? 0 : 1;
  const auto halves = nome::test::split_faces(band, part);
  nome::write_obj(dir + "/a.obj", nome::build_mesh(halves[0]));
  nome::write_obj(dir + "/b.obj", nome::build_mesh(halves[1]));
  return dir + "/a.obj " + dir + "/b.obj";
}

}  // namespace

TEST_CASE("nome info --merge joins several files into one surface", "[app]") {
  const std::string files = write_halves(nome::test::scratch_dir("merge_info"));
  const auto apart = run_nome("info " + files + " --json");
  CHECK(apart.status == 0);
  CHECK_THAT(apart.out, Catch::Contains("\"components\": 2"));

  const auto merged = run_nome("info " + files + " --merge --json");
  CHECK(merged.status == 0);
  CHECK_THAT(merged.out, Catch::Contains("\"components\": 1") && Catch::Contains("\"orientable\": false") &&
                             Catch::Contains("\"borders\": 1") && Catch::Contains("\"chi\": 0"));
  // A tolerance too small for the written positions still merges: they coincide exactly.
  CHECK_THAT(run_nome("info " + files + " --merge --tolerance 1e-9 --json").out,
             Catch::Contains("\"components\": 1"));
}

TEST_CASE("nome export --merge writes the merged surface", "[app]") {
  const std::string dir = nome::test::scratch_dir("merge_export");
  const std::string files = write_halves(dir);
  REQUIRE(run_nome("export " + files + " --merge -o " + dir + "/band.obj").status == 0);
  CHECK_THAT(
      run_nome("info " + dir + "/band.obj --json").out,
      Catch::Contains("\"vertices\": 36, \"edges\": 60, \"faces\": 24, \"chi\": 0, \"orientable\": false"));
}

TEST_CASE("nome --merge reports skipped merges and refuses a bad tolerance", "[app]") {
  const std::string dir = nome::test::scratch_dir("merge_errors");
  const std::string files = write_halves(dir);
  CHECK(run_nome("info " + files + " --tolerance 0.1").status == 2);
  CHECK(run_nome("info " + files + " --merge --tolerance -1").status == 2);
  CHECK(run_nome("info " + files + " --merge --tolerance abc").status == 2);

  // Three quads share one edge: two are glued, the third is left apart and reported.
  nome::PolygonSoup page = nome::test::grid(1, 1), other = nome::test::grid(1, 1);
  for (auto& p : other.positions) p = nome::Vec3(p.x, 0.0, p.y);  // shares the edge y = 0 with `page`
  nome::PolygonSoup third = other;
  for (auto& p : third.positions) p.z = -p.z;
  nome::write_obj(dir + "/p1.obj", nome::build_mesh(page));
  nome::write_obj(dir + "/p2.obj", nome::build_mesh(other));
  nome::write_obj(dir + "/p3.obj", nome::build_mesh(third));
  const auto r = run_nome("info " + dir + "/p1.obj " + dir + "/p2.obj " + dir + "/p3.obj --merge --json");
  CHECK(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("warning: merge:") && Catch::Contains("third face"));
  CHECK_THAT(r.out, Catch::Contains("\"components\": 2"));
}
