// Which wins when the command line and a scene's own stage blocks disagree: `--offset D` against
// `offset ... height H ... endoffset`, `--subdiv N` against `subdivision ... sd_level L`, and several blocks
// of one kind (the highest wins, docs/language.md). Measured on the exported OBJ, read by the test: a unit
// square in z = 0 thickened by D spans 2 D in z, and L levels of Catmull-Clark make 4^L quads of it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_support.hpp"

using nome::test::run_nome_in_process;

namespace {

constexpr const char* unit_square =
    "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint point d (0 1 0) endpoint\n"
    "mesh m face f (a b c d) endface endmesh\n";

// What the test reads of an exported OBJ: the z extent of its vertices and its number of faces.
struct ObjMeasure {
  double low_z = std::numeric_limits<double>::infinity();
  double high_z = -std::numeric_limits<double>::infinity();
  int faces = 0;
  double thickness() const { return high_z - low_z; }
};

ObjMeasure measure_obj(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  ObjMeasure m;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "v") {
      double x = 0, y = 0, z = 0;
      words >> x >> y >> z;
      m.low_z = std::min(m.low_z, z);
      m.high_z = std::max(m.high_z, z);
    } else if (kind == "f") {
      ++m.faces;
    }
  }
  return m;
}

// Writes the scene (the square, then `blocks`) as NAME.nom in `dir`, exports it with the options and
// measures the OBJ.
ObjMeasure exported(const std::string& dir, const std::string& name, const std::string& blocks,
                    const std::string& options) {
  const std::string scene = dir + "/" + name + ".nom";
  std::ofstream(scene) << unit_square << blocks;
  const auto r = run_nome_in_process("export " + scene + " " + options + " -o " + dir + "/" + name + ".obj");
  INFO(r.err);
  REQUIRE(r.status == 0);
  return measure_obj(dir + "/" + name + ".obj");
}

std::string offset_block(const std::string& name, double height, bool has_instance) {
  std::ostringstream out;
  out << "offset " << name << " height " << height << (has_instance ? " instance i m endinstance" : "")
      << " endoffset\n";
  return out.str();
}

std::string subdivision_block(const std::string& name, int level, bool has_instance) {
  return "subdivision " + name + " sd_level " + std::to_string(level) +
         (has_instance ? " instance i m endinstance" : "") + " endsubdivision\n";
}

}  // namespace

TEST_CASE("--offset wins over a scene's offset block, thinner or thicker; without it the block's height",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("stage_blocks_offset");
  const std::string block = offset_block("o", 0.1, true);
  const ObjMeasure own = exported(dir, "own", block, "");
  CHECK(own.thickness() == Approx(0.2).margin(1e-6));
  CHECK(own.low_z == Approx(-0.1).margin(1e-6));
  CHECK(exported(dir, "thicker", block, "--offset 0.25").thickness() == Approx(0.5).margin(1e-6));
  CHECK(exported(dir, "thinner", block, "--offset 0.05").thickness() == Approx(0.1).margin(1e-6));
  // The solid of one quad: its two sheets and a rim quad on each of its four border edges.
  CHECK(own.faces == 2 + 4);
}

TEST_CASE("--subdiv wins over a scene's sd_level, --subdiv 0 included; without it the block's level",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("stage_blocks_subdiv");
  const std::string block = subdivision_block("s", 1, true);
  CHECK(exported(dir, "own", block, "").faces == 4);
  CHECK(exported(dir, "more", block, "--subdiv 2").faces == 16);
  CHECK(exported(dir, "none", block, "--subdiv 0").faces == 1);
  // A block at level 2 and the command line at 1.
  CHECK(exported(dir, "fewer", subdivision_block("s", 2, true), "--subdiv 1").faces == 4);
}

TEST_CASE("of several subdivision blocks the highest level wins, whichever comes first", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("stage_blocks_levels");
  for (const auto& [first, second] : {std::pair{2, 1}, std::pair{1, 2}, std::pair{0, 2}, std::pair{2, 0}}) {
    INFO(first << " then " << second);
    const std::string blocks = subdivision_block("s1", first, true) + subdivision_block("s2", second, false);
    CHECK(exported(dir, "both", blocks, "").faces == 16);
    CHECK(exported(dir, "told", blocks, "--subdiv 1").faces == 4);
  }
  // Three blocks: the highest is the middle one.
  const std::string three = subdivision_block("s1", 1, true) + subdivision_block("s2", 3, false) +
                            subdivision_block("s3", 2, false);
  CHECK(exported(dir, "three", three, "").faces == 64);
}

TEST_CASE("of several offset blocks the thickest wins, whichever comes first; --offset wins over all",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("stage_blocks_offsets");
  for (const auto& [first, second] : {std::pair{0.3, 0.1}, std::pair{0.1, 0.3}}) {
    INFO(first << " then " << second);
    const std::string blocks = offset_block("o1", first, true) + offset_block("o2", second, false);
    CHECK(exported(dir, "both", blocks, "").thickness() == Approx(0.6).margin(1e-6));
    CHECK(exported(dir, "told", blocks, "--offset 0.05").thickness() == Approx(0.1).margin(1e-6));
  }
}

TEST_CASE("the blocks of several files: the highest level and the thickest offset of any file", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("stage_blocks_files");
  std::ofstream(dir + "/low.nom") << unit_square << subdivision_block("s", 1, true)
                                  << offset_block("o", 0.3, false);
  std::ofstream(dir + "/high.nom") << unit_square << subdivision_block("s", 2, false)
                                   << offset_block("o", 0.1, false);
  for (const std::string& files :
       {dir + "/low.nom " + dir + "/high.nom", dir + "/high.nom " + dir + "/low.nom"}) {
    INFO(files);
    const auto r = run_nome_in_process("export " + files + " -o " + dir + "/both.obj");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const ObjMeasure both = measure_obj(dir + "/both.obj");
    CHECK(both.thickness() == Approx(0.6).margin(1e-6));
    // One square (low.nom's instance) at level 2, thickened: two sheets of 16 quads and 16 rim quads.
    CHECK(both.faces == 2 * 16 + 16);
  }
}

TEST_CASE("a scene's subdivision and offset blocks together, each overridden by its own option alone",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("stage_blocks_both");
  const std::string blocks = subdivision_block("s", 1, true) + offset_block("o", 0.2, false);
  const ObjMeasure own = exported(dir, "own", blocks, "");
  CHECK(own.thickness() == Approx(0.4).margin(1e-6));
  CHECK(own.faces == 2 * 4 + 8);
  const ObjMeasure flat = exported(dir, "flat", blocks, "--subdiv 0");
  CHECK(flat.thickness() == Approx(0.4).margin(1e-6));
  CHECK(flat.faces == 2 + 4);
  const ObjMeasure thin = exported(dir, "thin", blocks, "--offset 0.05");
  CHECK(thin.thickness() == Approx(0.1).margin(1e-6));
  CHECK(thin.faces == 2 * 4 + 8);
}
