#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/polygon_soup_bytes.hpp"
#include "nome/error.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/stl.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/mesh/topology_report.hpp"
#include "support/brute_force_topology.hpp"

using namespace nome;
namespace fs = std::filesystem;

namespace {

const fs::path regressions = fs::path(NOME_SOURCE_DIR) / "tests/data/fuzz";

std::string bytes_of(const fs::path& p) {
  std::ostringstream s;
  s << std::ifstream(p, std::ios::binary).rdbuf();
  return s.str();
}

// What the reader fuzz targets do with one input: read, build, report. Errors are fine; crashes and
// sanitizer reports are not (make test runs this under ASan + UBSan).
void replay_reader(const fs::path& input, const std::string& extension) {
  const fs::path copy =
      fs::temp_directory_path() / ("nome_fuzz_replay_" + std::to_string(::getpid()) + extension);
  fs::copy_file(input, copy, fs::copy_options::overwrite_existing);
  try {
    const Mesh mesh = build_mesh(extension == ".obj" ? read_obj(copy) : read_stl(copy));
    const TopologyReport report = topology_report(mesh);
    CHECK(report.faces == mesh.num_faces());
    compute_normals(mesh);
  } catch (const Error& e) {
    SUCCEED(e.what());
  }
  fs::remove(copy);
}

std::vector<fs::path> inputs_of(const std::string& target) {
  std::vector<fs::path> out;
  if (fs::exists(regressions / target))
    for (const auto& entry : fs::directory_iterator(regressions / target)) out.push_back(entry.path());
  return out;
}

}  // namespace

TEST_CASE("inputs that once broke a fuzz target now read or fail cleanly", "[io]") {
  for (const auto& [target, extension] : {std::pair{"obj_fuzzer", ".obj"}, std::pair{"stl_fuzzer", ".stl"}})
    for (const fs::path& input : inputs_of(target)) {
      INFO(input);
      replay_reader(input, extension);
    }
  for (const fs::path& input : inputs_of("polygon_soup_fuzzer")) {
    INFO(input);
    const std::string bytes = bytes_of(input);
    const PolygonSoup soup =
        fuzz::polygon_soup_from_bytes(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    const test::BruteForceTopology brute = test::brute_force_topology(soup);
    if (brute.is_manifold) {
      CHECK(topology_report(build_mesh(soup)).chi == brute.report.chi);
    } else {
      CHECK_THROWS_AS(build_mesh(soup), TopologyError);
    }
  }
}
