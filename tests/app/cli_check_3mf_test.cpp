#include <catch2/catch.hpp>

#include <filesystem>

#include "app/cli_support.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/three_mf.hpp"

using nome::test::assets;
using nome::test::run_nome_in_process;

namespace {
nome::Index soup_triangles(const nome::PolygonSoup& soup) {
  return soup.face_vertices.size() - 2 * soup.num_faces();
}

}  // namespace

TEST_CASE("nome check says whether the torus's offset prints and exits 3 when not", "[app]") {
  const auto safe = run_nome_in_process({"check", assets + "torus.obj", "--offset", "0.05"});
  CHECK(safe.status == 0);
  CHECK_THAT(safe.out, Catch::Contains("printable:    yes"));
  CHECK_THAT(safe.out, Catch::Contains("minimum wall 0.1"));
  // The torus's minor radius is 0.35: a thicker offset turns its inner side inside out.
  const auto folded = run_nome_in_process({"check", assets + "torus.obj", "--offset", "0.4", "--json"});
  CHECK(folded.status == 3);
  CHECK_THAT(folded.out, Catch::Contains("\"printable\": false") && Catch::Contains("\"fold_overs\": 288") &&
                             Catch::Contains("\"kind\": \"fold-over\""));
  const auto walled = run_nome_in_process({"check", assets + "torus.obj", "--min-wall", "-1"});
  CHECK(walled.status == 2);
}

TEST_CASE("nome export checks the solid it writes, or says why it did not", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("export_check");
  const auto folded =
      run_nome_in_process({"export", assets + "torus.obj", "--offset", "0.4", "-o", dir + "/t.stl"});
  CHECK(folded.status == 0);
  CHECK_THAT(folded.err, Catch::Contains("warning: print check: NOT printable: 288 fold-over faces"));
  const auto safe =
      run_nome_in_process({"export", assets + "torus.obj", "--offset", "0.05", "-o", dir + "/t.stl"});
  CHECK_THAT(safe.err, Catch::Contains("print check: printable"));
  const auto skipped = run_nome_in_process(
      {"export", assets + "torus.obj", "--offset", "0.4", "--no-check", "-o", dir + "/t.stl"});
  CHECK_THAT(skipped.err, !Catch::Contains("print check"));
  const auto obj =
      run_nome_in_process({"export", assets + "torus.obj", "--offset", "0.4", "-o", dir + "/t.obj"});
  CHECK_THAT(obj.err, !Catch::Contains("print check"));
}

TEST_CASE("a 3MF export holds the solid's parts, unit and colours", "[app][io]") {
  const std::string dir = nome::test::private_scratch_dir("export_3mf");
  const std::vector<std::string> solid = {assets + "mobius_band.nome", "--offset", "0.02"};
  auto with = [&](std::vector<std::string> args) {
    args.insert(args.begin() + 1, solid.begin(), solid.end());
    return run_nome_in_process(args);
  };
  REQUIRE(with({"export", "-o", dir + "/band.3mf", "--unit", "in", "--no-check"}).status == 0);
  REQUIRE(with({"export", "-o", dir + "/band.obj"}).status == 0);
  const nome::PolygonSoup reference = nome::read_polygons(dir + "/band.obj");
  const nome::ThreeMfModel model = nome::read_3mf(dir + "/band.3mf");
  CHECK(model.unit == nome::LengthUnit::inch);
  REQUIRE(model.objects.size() == 1);
  CHECK(model.objects[0].vertices.size() == reference.num_vertices());
  CHECK(model.objects[0].triangles.size() == soup_triangles(reference));
  REQUIRE(model.objects[0].colors.size() == model.objects[0].triangles.size());
  // The scene's surface "gold" is (0.9 0.7 0.2), stored as bytes.
  for (const nome::Color& c : model.objects[0].colors) CHECK(c == nome::Color(230, 179, 51) / 255.0f);
  // nome info reads it back as the same closed solid.
  const auto info = run_nome_in_process({"info", dir + "/band.3mf", "--json"});
  CHECK(info.status == 0);
  CHECK_THAT(info.out, Catch::Contains("\"chi\": 0, \"orientable\": true, \"borders\": 0"));
}

TEST_CASE("3MF scales, keeps one object per part and is smaller than binary STL", "[app][io]") {
  const std::string dir = nome::test::private_scratch_dir("export_3mf_size");
  const std::vector<std::string> common = {
      assets + "funnel_cube.nome", "--subdiv", "2", "--offset", "0.05", "--no-check"};
  auto export_to = [&](const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = {"export"};
    args.insert(args.end(), common.begin(), common.end());
    args.insert(args.end(), {"-o", out});
    args.insert(args.end(), extra.begin(), extra.end());
    return run_nome_in_process(args).status;
  };
  REQUIRE(export_to(dir + "/cube.3mf", {"--scale", "10"}) == 0);
  REQUIRE(export_to(dir + "/cube.stl", {}) == 0);
  const nome::ThreeMfModel model = nome::read_3mf(dir + "/cube.3mf");
  CHECK(model.unit == nome::LengthUnit::millimeter);
  CHECK(model.objects.size() == 6);  // six funnels, each thickened on its own
  double largest = 0;
  for (const auto& object : model.objects)
    for (const nome::Vec3& p : object.vertices) largest = std::max(largest, std::abs(p.x));
  CHECK(largest > 8.0);  // the cube is about 2 across before scaling
  CHECK(std::filesystem::file_size(dir + "/cube.3mf") < std::filesystem::file_size(dir + "/cube.stl"));
  CHECK(run_nome_in_process({"export", assets + "torus.obj", "-o", dir + "/t.3mf", "--unit", "ft"}).status ==
        2);
}
