// Every input that once broke a fuzz target, replayed through that target's own entry point (linked into
// this binary from tests/fuzz/): a crash, a sanitizer report, an escaped exception or an unlocated
// refusal fails the suite, as it failed the fuzzer.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "fuzz/fuzz_target.hpp"

namespace nome::fuzz {
int anom_target(const uint8_t*, size_t);
int anom_scene_target(const uint8_t*, size_t);
int nome_target(const uint8_t*, size_t);
int obj_target(const uint8_t*, size_t);
int pick_target(const uint8_t*, size_t);
int pipeline_target(const uint8_t*, size_t);
int polygon_soup_target(const uint8_t*, size_t);
int save_reload_target(const uint8_t*, size_t);
int sif_target(const uint8_t*, size_t);
int slf_target(const uint8_t*, size_t);
int stl_target(const uint8_t*, size_t);
int zipper_target(const uint8_t*, size_t);
}  // namespace nome::fuzz

namespace fs = std::filesystem;

namespace {

const fs::path regressions = fs::path(NOME_SOURCE_DIR) / "tests/data/fuzz";

// The folder of each target's regressions, as `make fuzz` names it (tests/fuzz/run_fuzzers.sh).
const std::map<std::string, nome::fuzz::FuzzTarget> targets = {
    {"anom_fuzzer", nome::fuzz::anom_target},
    {"anom_scene_fuzzer", nome::fuzz::anom_scene_target},
    {"nome_fuzzer", nome::fuzz::nome_target},
    {"obj_fuzzer", nome::fuzz::obj_target},
    {"pick_fuzzer", nome::fuzz::pick_target},
    {"pipeline_fuzzer", nome::fuzz::pipeline_target},
    {"polygon_soup_fuzzer", nome::fuzz::polygon_soup_target},
    {"save_reload_fuzzer", nome::fuzz::save_reload_target},
    {"sif_fuzzer", nome::fuzz::sif_target},
    {"slf_fuzzer", nome::fuzz::slf_target},
    {"stl_fuzzer", nome::fuzz::stl_target},
    {"zipper_fuzzer", nome::fuzz::zipper_target}};

std::string bytes_of(const fs::path& p) {
  std::ostringstream s;
  s << std::ifstream(p, std::ios::binary).rdbuf();
  return s.str();
}

int replay(nome::fuzz::FuzzTarget target, const fs::path& input) {
  const std::string bytes = bytes_of(input);
  return target(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}

}  // namespace

TEST_CASE("every input that once broke a fuzz target goes through that target cleanly", "[io]") {
  int folders = 0, inputs = 0;
  for (const auto& folder : fs::directory_iterator(regressions)) {
    if (!folder.is_directory() || folder.path().filename() == "seeds") continue;
    const std::string name = folder.path().filename().string();
    INFO("tests/data/fuzz/" << name);
    const auto target = targets.find(name);
    REQUIRE(target != targets.end());  // a folder of no known target would never be replayed
    ++folders;
    int here = 0;
    for (const auto& input : fs::directory_iterator(folder.path())) {
      INFO(input.path().filename().string());
      CHECK(replay(target->second, input.path()) == 0);
      ++here;
    }
    CHECK(here > 0);
    inputs += here;
  }
  CHECK(folders > 0);
  CHECK(inputs >= folders);
}

TEST_CASE("the fuzz targets take the seeds and the example files without a finding", "[io]") {
  // The replay's own check: the valid files every fuzzing run starts from pass every target's checks.
  const fs::path assets = fs::path(NOME_SOURCE_DIR) / "assets";
  int replayed = 0;
  for (const auto& [extension, target] :
       std::multimap<std::string, nome::fuzz::FuzzTarget>{{".nome", nome::fuzz::nome_target},
                                                          {".nome", nome::fuzz::save_reload_target},
                                                          {".obj", nome::fuzz::obj_target},
                                                          {".sif", nome::fuzz::sif_target},
                                                          {".slf", nome::fuzz::slf_target},
                                                          {".stl", nome::fuzz::stl_target}})
    for (const auto& input : fs::directory_iterator(assets))
      if (input.path().extension() == extension && fs::file_size(input.path()) < 16384) {
        INFO(input.path().filename().string());
        CHECK(replay(target, input.path()) == 0);
        ++replayed;
      }
  // tests/data/fuzz/seeds/<format>/: the target whose folder is <format>_fuzzer.
  for (const auto& folder : fs::directory_iterator(regressions / "seeds")) {
    const auto target = targets.find(folder.path().filename().string() + "_fuzzer");
    INFO("seeds/" << folder.path().filename().string());
    REQUIRE(target != targets.end());
    for (const auto& input : fs::directory_iterator(folder.path())) {
      INFO(input.path().filename().string());
      CHECK(replay(target->second, input.path()) == 0);
      ++replayed;
    }
  }
  CHECK(replayed > 15);
}
