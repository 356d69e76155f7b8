#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "app/cli_support.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path catalogue = fs::path(NOME_SOURCE_DIR) / "tests/data/bad";
// An .anom file holds saved slider values and a working mesh for a scene: the bad ones are applied to this.
const std::string anom_scene = std::string(NOME_SOURCE_DIR) + "/assets/funnel_cube.nome";

struct LimitedRun {
  int status = -1;
  std::string out, err;
  double seconds = 0;
  long peak_growth_mb = 0;  // peak resident memory above what the test process held before the run
};

long status_field_kb(const std::string& field) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind(field + ":", 0) == 0) return std::stol(line.substr(field.size() + 1));
  return 0;
}

// Runs `nome ARGS...` inside the test process (a process start under the sanitizers costs more than most
// refusals), measuring its wall time and how far it raised the peak memory: writing 5 to clear_refs resets
// the peak (VmHWM) to the current resident size.
LimitedRun run_measured(const std::vector<std::string>& args) {
  std::ofstream("/proc/self/clear_refs") << "5";
  const long resident_before_kb = status_field_kb("VmRSS");
  const auto start = std::chrono::steady_clock::now();
  const nome::test::CommandResult result = nome::test::run_nome_in_process(args);
  LimitedRun r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.peak_growth_mb = (status_field_kb("VmHWM") - resident_before_kb) / 1024;
  r.status = result.status;
  r.out = result.out;
  r.err = result.err;
  return r;
}

// tests/data/bad/EXPECTED: one line per file, `NAME<TAB>first line of the message`, which starts with NAME.
std::map<std::string, std::string> expected_messages() {
  std::map<std::string, std::string> out;
  std::ifstream in(catalogue / "EXPECTED");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const size_t tab = line.find('\t');
    out[line.substr(0, tab)] = line.substr(tab + 1);
  }
  return out;
}

// The whole first line is `nome: FOLDER/` and the expected text; formats whose parser recovers (the scene
// languages) and topology errors may report several problems, one per line, each in the same form.
void check_refused(const LimitedRun& r, const std::string& expected_first_line) {
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::EndsWith("\n"));
  std::istringstream each(r.err);
  std::string first;
  std::getline(each, first);
  CHECK(first == expected_first_line);
  for (std::string line; std::getline(each, line);) CHECK_THAT(line, Catch::StartsWith("nome: "));
  CHECK(r.seconds < 15.0);
  CHECK(r.peak_growth_mb < 600);
}

// Every file of the given kind (by extension; "" for the rest) is refused by `nome info`, `nome export`
// and `nome render`, given after the files `before` (the scene an .anom file applies to).
void check_catalogue(const std::vector<std::string>& extensions,
                     const std::vector<std::string>& before = {}) {
  const auto expected = expected_messages();
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(catalogue)) {
    const std::string ext = entry.path().extension().string();
    const bool listed = std::find(extensions.begin(), extensions.end(), ext) != extensions.end();
    if (entry.path().filename() != "EXPECTED" && listed) files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  CHECK(!files.empty());

  const fs::path scratch = nome::test::scratch_dir("bad_input_" + std::to_string(::getpid()));
  for (const std::string& name : files) {
    INFO(name);
    const auto it = expected.find(name);
    REQUIRE(it != expected.end());
    REQUIRE_THAT(it->second, Catch::StartsWith(name));
    const std::string first_line = "nome: " + catalogue.string() + "/" + it->second;
    std::vector<std::string> files_args = before;
    files_args.push_back((catalogue / name).string());
    const std::vector<std::pair<std::string, std::string>> commands{
        {"info", ""}, {"export", (scratch / "out.obj").string()}, {"render", (scratch / "out.png").string()}};
    for (const auto& [command, output] : commands) {
      std::vector<std::string> args{command};
      args.insert(args.end(), files_args.begin(), files_args.end());
      if (!output.empty()) args.insert(args.end(), {"-o", output});
      const LimitedRun run = run_measured(args);
      INFO("nome " << command << ": " << run.err);
      check_refused(run, first_line);
      // Nothing is written at all: no output file, no temporary left behind.
      CHECK(fs::is_empty(scratch));
    }
  }
  fs::remove_all(scratch);
}

}  // namespace

TEST_CASE("the bad-input catalogue has at least 60 files, each with its expected message", "[app]") {
  const auto expected = expected_messages();
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(catalogue)) {
    if (entry.path().filename() == "EXPECTED") continue;
    ++files;
    CHECK(expected.count(entry.path().filename().string()) == 1);
  }
  CHECK(files >= 60);
  CHECK(files == expected.size());
}

TEST_CASE("bad OBJ files are refused with one located message", "[app]") {
  check_catalogue({".obj"});
}

TEST_CASE("bad STL files and unknown formats are refused with one located message", "[app]") {
  check_catalogue({".stl", ".ply", ".dae", ".OFF", ""});
}

TEST_CASE("bad scene files (.nome, .slf, .sif) are refused with located messages", "[app]") {
  check_catalogue({".nome", ".slf", ".sif"});
}

TEST_CASE("bad .anom files are refused with messages located in them", "[app]") {
  check_catalogue({".anom"}, {anom_scene});
}
