#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
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
  int status = -1;  // exit status, or 128 + signal
  std::string out, err;
  double seconds = 0;
  long max_rss_mb = 0;
};

// Runs `nome ARGS...` in a child with a CPU-time limit, measuring its wall time and peak memory. (An
// address-space limit cannot be used: the sanitizers reserve terabytes of shadow memory.)
LimitedRun run_limited(const std::vector<std::string>& args, const fs::path& scratch) {
  const fs::path out = scratch / "stdout", err = scratch / "stderr";
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = ::fork();
  if (child == 0) {
    const rlimit cpu{20, 20};
    ::setrlimit(RLIMIT_CPU, &cpu);
    ::dup2(::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
    ::dup2(::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
    std::vector<char*> argv{const_cast<char*>(NOME_EXECUTABLE)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(NOME_EXECUTABLE, argv.data());
    ::_exit(127);
  }
  LimitedRun r;
  int raw = 0;
  rusage usage{};
  ::wait4(child, &raw, 0, &usage);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.max_rss_mb = usage.ru_maxrss / 1024;
  std::ostringstream o, e;
  o << std::ifstream(out).rdbuf();
  e << std::ifstream(err).rdbuf();
  r.out = o.str();
  r.err = e.str();
  fs::remove(out);
  fs::remove(err);
  return r;
}

// tests/data/bad/EXPECTED: one line per file, `NAME<TAB>part of the message`.
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

// Formats whose parser recovers (the scene languages) may report several errors, one per line.
void check_refused(const LimitedRun& r, const std::string& expected, bool several_errors) {
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  // One message per line, each in the `nome: FILE...: what` form.
  CHECK_THAT(r.err, Catch::StartsWith("nome: ") && Catch::EndsWith("\n") && Catch::Contains(expected));
  const auto lines = std::count(r.err.begin(), r.err.end(), '\n');
  CHECK((several_errors ? lines >= 1 : lines == 1));
  std::istringstream each(r.err);
  for (std::string line; std::getline(each, line);) CHECK_THAT(line, Catch::StartsWith("nome: "));
  CHECK(r.seconds < 15.0);
  CHECK(r.max_rss_mb < 600);
}

// Every file of the given kind (by extension; "" for the rest) is refused by `nome info` and `nome export`,
// given after the files `before` (the scene an .anom file applies to).
void check_catalogue(const std::vector<std::string>& extensions, bool several_errors = false,
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
    const std::string path = (catalogue / name).string();
    std::vector<std::string> files_args = before;
    files_args.push_back(path);
    std::vector<std::string> info_args{"info"}, export_args{"export"};
    info_args.insert(info_args.end(), files_args.begin(), files_args.end());
    export_args.insert(export_args.end(), files_args.begin(), files_args.end());
    export_args.insert(export_args.end(), {"-o", (scratch / "out.obj").string()});
    const LimitedRun info = run_limited(info_args, scratch);
    INFO("nome info: " << info.err);
    check_refused(info, it->second, several_errors);
    CHECK_THAT(info.err, Catch::Contains(path));

    // Export writes nothing at all: no output file, no temporary left behind.
    const LimitedRun exported = run_limited(export_args, scratch);
    INFO("nome export: " << exported.err);
    check_refused(exported, it->second, several_errors);
    CHECK(fs::is_empty(scratch));
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

TEST_CASE("bad OBJ files are refused with one clear message", "[app]") {
  check_catalogue({".obj"});
}

TEST_CASE("bad STL files and unknown formats are refused with one clear message", "[app]") {
  check_catalogue({".stl", ".ply", ".OFF", ""});
}

TEST_CASE("bad scene files (.nome, .slf, .sif) are refused with located messages", "[app]") {
  check_catalogue({".nome", ".slf", ".sif"}, true);
}

TEST_CASE("bad .anom files are refused with messages located in them", "[app]") {
  check_catalogue({".anom"}, true, {anom_scene});
}
