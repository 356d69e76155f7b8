#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

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

namespace {

// Beside the torus (288 faces, minor radius 0.35: an offset of 0.4 turns every face over, one place):
// a 2 x 1 square at z = 10 under a strip of two quads 0.2 above it (4 + 6 vertices closer than a wall
// of 0.3, a place on each sheet), and three pairs of squares crossing at right angles (each pair's two
// triangles by two: 4 triangle pairs on one curve). Faces 288 (square), 289 and 290 (strip), 291 to 296.
const char* const thin_and_crossing_obj =
    "v 10 10 10\nv 12 10 10\nv 12 11 10\nv 10 11 10\n"
    "v 10 10 10.2\nv 11 10 10.2\nv 12 10 10.2\nv 10 11 10.2\nv 11 11 10.2\nv 12 11 10.2\n"
    "v 19 -1 0\nv 21 -1 0\nv 21 1 0\nv 19 1 0\nv 20 -1 -1\nv 20 1 -1\nv 20 1 1\nv 20 -1 1\n"
    "v 29 -1 0\nv 31 -1 0\nv 31 1 0\nv 29 1 0\nv 30 -1 -1\nv 30 1 -1\nv 30 1 1\nv 30 -1 1\n"
    "v 39 -1 0\nv 41 -1 0\nv 41 1 0\nv 39 1 0\nv 40 -1 -1\nv 40 1 -1\nv 40 1 1\nv 40 -1 1\n"
    "f 1 2 3 4\nf 5 6 9 8\nf 6 7 10 9\n"
    "f 11 12 13 14\nf 15 16 17 18\nf 19 20 21 22\nf 23 24 25 26\nf 27 28 29 30\nf 31 32 33 34\n";

}  // namespace

// Each count of the print check under its own label, in text and in JSON: 288 fold-over faces in 1
// place, 10 near-miss vertices in 2 places, 12 crossing triangle pairs on 3 curves, offset 0.4 and wall
// 0.3, all worked out above by hand.
TEST_CASE("nome check puts every count under its own label, in text and in JSON", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("check_labels");
  std::ofstream(dir + "/thin.obj") << thin_and_crossing_obj;
  const std::vector<std::string> input = {
      "check", assets + "torus.obj", dir + "/thin.obj", "--offset", "0.4", "--min-wall", "0.3"};
  const auto text = run_nome_in_process(input);
  INFO(text.err);
  CHECK(text.status == 3);
  CHECK_THAT(text.out,
             Catch::StartsWith(
                 "printable:    no\n"
                 "offset:       0.4 (minimum wall 0.3)\n"
                 "fold-overs:   288 faces in 1 places (the offset turns inside out there)\n"
                 "near misses:  10 vertices in 2 places (two sheets closer than the wall)\n"
                 "crossings:    12 triangle pairs on 3 curves (the slab fuses there: by design in one-sided "
                 "surfaces)\n"
                 "worst places (faces of the surface before the offset):\n"
                 "  fold-over at ("));
  CHECK_THAT(text.out,
             Catch::Contains("), face 0 (288 faces)\n"
                             "  near miss 0.2 thin at (10, 10, 10), face 288 and face 289 (4 vertices)\n"
                             "  near miss 0.2 thin at (10, 10, 10.2), face 289 and face 288 (6 vertices)\n"
                             "  crossing at (20, -0.5, 0), face 291 and face 292 (4 triangle pairs)\n"
                             "  crossing at (30, -0.5, 0), face 293 and face 294 (4 triangle pairs)\n"
                             "  crossing at (40, -0.5, 0), face 295 and face 296 (4 triangle pairs)\n"));

  std::vector<std::string> as_json = input;
  as_json.push_back("--json");
  const auto json = run_nome_in_process(as_json);
  CHECK(json.status == 3);
  CHECK_THAT(json.out,
             Catch::StartsWith("{\"printable\": false, \"offset\": 0.40000000000000002, \"min_wall\": "
                               "0.29999999999999999, \"fold_overs\": 288, \"crossing_pairs\": 12, "
                               "\"crossing_curves\": 3, \"near_misses\": 10, \"places\": [{\"kind\": "
                               "\"fold-over\", \"position\": ["));
  CHECK_THAT(json.out,
             Catch::Contains("\"face\": 0, \"other_face\": null, \"distance\": 0, \"size\": 288}, "
                             "{\"kind\": \"near miss\", \"position\": [10, 10, 10], \"face\": 288, "
                             "\"other_face\": 289, \"distance\": 0.19999999999999") &&
                 Catch::Contains("\"size\": 4}, {\"kind\": \"near miss\"") &&
                 Catch::Contains("\"face\": 289, \"other_face\": 288") &&
                 Catch::Contains("\"size\": 6}, {\"kind\": \"crossing\", \"position\": [20, -0.5, 0], "
                                 "\"face\": 291, \"other_face\": 292, \"distance\": 0, \"size\": 4}"));

  // The crossings alone, a wall of twice the offset (0.1) below the sheets' 0.2: printable.
  const auto crossing = run_nome_in_process({"check", dir + "/thin.obj", "--offset", "0.05"});
  CHECK(crossing.status == 0);
  CHECK_THAT(crossing.out, Catch::StartsWith("printable:    yes\n"
                                             "offset:       0.05 (minimum wall 0.1)\n"
                                             "fold-overs:   0 faces in 0 places"));
}
