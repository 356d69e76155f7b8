#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/viewer_support.hpp"
#include "render/image.hpp"
#include "render/image_diff.hpp"
#include "support/scratch_files.hpp"
#include "support/shared_examples.hpp"
#include "support/skip.hpp"

// The web page (`make web`) in headless Chromium, SwiftShader drawing its WebGL2: it opens scenes from its
// address, runs the viewer's script commands and draws what the desktop viewer draws.
namespace {

using nome::render::Image;
using nome::test::CommandResult;

const std::filesystem::path web_folder = std::filesystem::path(NOME_SOURCE_DIR) / "build" / "web";
// The page's bar above the viewer's canvas.
constexpr int bar_height = 28;
constexpr int canvas_height = nome::test::viewer_height - bar_height;

bool answers(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(std::uint16_t(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const bool is_open = ::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  ::close(fd);
  return is_open;
}

// web/serve.py (the server of `make serve`, with its cross-origin isolation) on a port of this process.
class PageServer {
 public:
  PageServer() : port_(20000 + int(::getpid() % 20000)) {
    const std::string pid_file = nome::test::private_scratch_dir("web_server") + "/pid";
    std::filesystem::remove(pid_file);
    const std::string command = "sh -c 'echo $$ > " + pid_file + "; exec python3 " + NOME_SOURCE_DIR +
                                "/web/serve.py " + web_folder.string() + " " + std::to_string(port_) +
                                "' >/dev/null 2>&1 &";
    REQUIRE(std::system(command.c_str()) == 0);
    for (int i = 0; i < 100 && !answers(port_); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::ifstream(pid_file) >> pid_;
    REQUIRE(answers(port_));
  }
  ~PageServer() {
    if (pid_ > 0) ::kill(pid_, SIGTERM);
  }
  PageServer(const PageServer&) = delete;
  PageServer& operator=(const PageServer&) = delete;

  std::string address(const std::string& query) const {
    return "http://127.0.0.1:" + std::to_string(port_) + "/?" + query;
  }

 private:
  int port_;
  pid_t pid_ = 0;
};

std::string url_encoded(const std::string& text) {
  std::string out;
  for (const unsigned char c : text) {
    if (std::isalnum(c) || c == '.' || c == '_' || c == '-' || c == '/') {
      out += char(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

struct PageRun {
  std::string log;
  Image canvas;  // the viewer's canvas, below the page's bar
};

// The page in headless Chromium (tests/app/web_page_driver.js): once its model is drawn and the address's
// script has run, `picked_file` is chosen in the page's Open dialog and `script` runs through the page's
// nomeScript(); then its log and a picture are taken, and its downloads are in `downloads`. A kept profile
// holds the browser's storage from one visit to the next.
PageRun open_page(const PageServer& server, const std::string& query, const std::string& name,
                  const std::string& script = {}, const std::string& picked_file = {},
                  const std::string& downloads = {}, const std::string& kept_profile = {}) {
  const std::string file = nome::test::private_scratch_dir("web_pictures") + "/" + name;
  const CommandResult r = nome::test::run_command(
      (kept_profile.empty() ? "" : "NOME_PAGE_PROFILE=" + kept_profile + " ") +
      "node --experimental-websocket " + std::string(NOME_SOURCE_DIR) + "/tests/app/web_page_driver.js '" +
      server.address(query) + "' " + file + " '" + script + "'" +
      (picked_file.empty() ? "" : " " + picked_file + " " + downloads));
  INFO(r.err);
  REQUIRE(r.status == 0);
  const Image page = nome::render::read_png(file);
  REQUIRE(page.width == nome::test::viewer_width);
  REQUIRE(page.height == nome::test::viewer_height);
  PageRun run{r.out, Image(page.width, canvas_height)};
  std::copy(page.rgba.begin() + std::ptrdiff_t(bar_height) * page.width * 4, page.rgba.end(),
            run.canvas.rgba.begin());
  return run;
}

std::vector<std::string> state_lines(const std::string& log) {
  std::vector<std::string> lines;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);)
    if (line.starts_with("nome: state: ")) lines.push_back(line);
  return lines;
}

// Pixels of the front (gold) and back (blue) colours.
std::pair<int, int> model_pixels(const Image& picture) {
  int front = 0, back = 0;
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x) {
      const auto* p = picture.pixel(x, y);
      front += p[0] > p[2] + 40;
      back += p[2] > p[0] + 40;
    }
  return {front, back};
}

// Ends the test case when the page or Chromium is missing (NOME_SKIP: a failure under CI).
#define NOME_NEEDS_WEB_PAGE()                                                                     \
  if (!std::filesystem::exists(web_folder / "nome.js") ||                                         \
      !std::filesystem::exists(web_folder / "nome-threads.js"))                                   \
    NOME_SKIP(web_folder.string() + " has no page: `make web` builds it");                        \
  if (std::system("command -v chromium >/dev/null 2>&1 && command -v node >/dev/null 2>&1") != 0) \
  NOME_SKIP("no chromium or node (make web-deps installs chromium)")

const std::string slider_script = "state\nset fp_n 5\nstate\n";

}  // namespace

TEST_CASE(
    "The web page draws the funnel cube as the desktop viewer does, and its slider changes the topology",
    "[app][web]") {
  NOME_NEEDS_WEB_PAGE();
  const std::string dir = nome::test::private_scratch_dir("web_desktop");
  const std::string script =
      nome::test::write_script(dir, slider_script + "screenshot " + dir + "/desktop.png\nquit\n");
  const CommandResult desktop = nome::test::run_viewer(nome::test::assets + "funnel_cube.nome --size 1280x" +
                                                       std::to_string(canvas_height) + " --script " + script);
  INFO(desktop.err);
  REQUIRE(desktop.status == 0);
  const std::vector<std::string> desktop_states = state_lines(desktop.err);
  REQUIRE(desktop_states.size() == 2);
  REQUIRE(desktop_states[0] != desktop_states[1]);

  const PageServer server;
  const PageRun page = open_page(
      server, "threads=0&scene=funnel_cube.nome&script=" + url_encoded(slider_script), "funnel_cube.png");
  INFO(page.log);
  CHECK(page.log.find("page: first model frame") != std::string::npos);
  CHECK(page.log.find("one-thread build") != std::string::npos);
  CHECK(state_lines(page.log) == desktop_states);
  const auto [front, back] = model_pixels(page.canvas);
  CHECK(front > 20000);
  CHECK(back > 20000);
  const auto difference =
      nome::render::compare_images(nome::render::read_png(dir + "/desktop.png"), page.canvas, 24);
  REQUIRE(difference.same_size);
  // Antialiased edges differ between SwiftShader and llvmpipe; the panels and the model do not.
  CHECK(difference.differing_fraction < 0.01);
}

TEST_CASE(
    "The page's script call moves a slider and drags a vertex, and the threaded page computes what the "
    "one-thread page does",
    "[app][web]") {
  NOME_NEEDS_WEB_PAGE();
  const PageServer server;
  // A drag as the page's script makes it: the vertex's sliders solved for, as on the desktop.
  const std::string script = slider_script + "subdiv 3\noffset 0.05\ndrag fun1_bc3 z -0.2\nstate";
  const PageRun threaded = open_page(server, "scene=funnel_cube.nome", "threaded.png", script);
  const PageRun single = open_page(server, "threads=0&scene=funnel_cube.nome", "single.png", script);
  INFO(threaded.log);
  CHECK(threaded.log.find("threads build") != std::string::npos);
  CHECK(threaded.log.find("drag: fp_z -0.8 to -1") != std::string::npos);
  const std::vector<std::string> states = state_lines(threaded.log);
  REQUIRE(states.size() == 3);
  CHECK(states[0] != states[1]);
  CHECK(states == state_lines(single.log));
  CHECK(nome::render::compare_images(single.canvas, threaded.canvas, 0).differing_pixels == 0);
}

TEST_CASE("The web page opens a JIPCAD example named in its address", "[app][web]") {
  NOME_NEEDS_WEB_PAGE();
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const std::string example = nome::test::shared_examples_dir("jipcad") + "geom__mobius_strip.nom";
  const std::string dir = nome::test::private_scratch_dir("web_jipcad");
  const CommandResult desktop =
      nome::test::run_viewer(example + " --script " + nome::test::write_script(dir, "state\nquit\n"));
  REQUIRE(desktop.status == 0);
  const PageServer server;
  const PageRun page =
      open_page(server, "threads=0&scene=jipcad/geom__mobius_strip.nom&script=state", "mobius.png");
  INFO(page.log);
  const std::vector<std::string> states = state_lines(page.log);
  REQUIRE(states.size() == 1);
  CHECK(states == state_lines(desktop.err));
  CHECK(states[0].find("non-orientable") != std::string::npos);
  const auto [front, back] = model_pixels(page.canvas);
  CHECK(front > 2000);
  CHECK(back > 2000);
}

TEST_CASE(
    "A scene picked from the user's disk opens in the page, and saving it downloads what the desktop saves",
    "[app][web]") {
  NOME_NEEDS_WEB_PAGE();
  const std::string dir = nome::test::private_scratch_dir("web_upload");
  const std::string picked = dir + "/picked_funnels.nome";
  std::filesystem::copy_file(nome::test::assets + "funnel_cube.nome", picked,
                             std::filesystem::copy_options::overwrite_existing);
  const std::string desktop_copy = dir + "/desktop/picked_funnels.nome";
  std::filesystem::create_directories(dir + "/desktop");
  std::filesystem::copy_file(picked, desktop_copy);
  const CommandResult desktop = nome::test::run_viewer(
      desktop_copy + " --script " + nome::test::write_script(dir, "set fp_n 6\nstate\nkey Ctrl+S\nquit\n"));
  INFO(desktop.err);
  REQUIRE(desktop.status == 0);

  const std::string downloads = dir + "/downloads";
  std::filesystem::create_directories(downloads);
  const PageServer server;
  const PageRun page = open_page(server, "threads=0&scene=funnel_cube.nome", "picked.png",
                                 "set fp_n 6\nstate\nkey Ctrl+S", picked, downloads);
  INFO(page.log);
  CHECK(state_lines(page.log) == state_lines(desktop.err));
  REQUIRE(std::filesystem::exists(downloads + "/picked_funnels.nome"));
  CHECK(nome::test::file_bytes(downloads + "/picked_funnels.nome") == nome::test::file_bytes(desktop_copy));
  CHECK(nome::test::file_bytes(desktop_copy) != nome::test::file_bytes(picked));
}

namespace {

// The mean brightness of the left sidebar: light or dark theme.
double sidebar_brightness(const Image& canvas) {
  double sum = 0.0;
  int count = 0;
  for (int y = 100; y < canvas.height - 100; ++y)
    for (int x = 0; x < 240; ++x, ++count) {
      const auto* p = canvas.pixel(x, y);
      sum += (p[0] + p[1] + p[2]) / 3.0;
    }
  return sum / count;
}

// A browser profile with no storage yet, kept from one visit to the next.
std::string empty_profile(const std::string& name) {
  const std::string profile = nome::test::private_scratch_dir(name);
  std::filesystem::remove_all(profile);
  std::filesystem::create_directories(profile);
  return profile;
}

// The one-thread page on the funnel cube: its storage is the same in both builds.
const std::string kept_query = "threads=0&scene=funnel_cube.nome";

}  // namespace

TEST_CASE("The page keeps its layout in the browser's storage for the next visit", "[app][web]") {
  NOME_NEEDS_WEB_PAGE();
  const std::string profile = empty_profile("web_kept_profile");
  const PageServer server;
  const PageRun fresh = open_page(server, kept_query, "fresh.png", "state");
  const PageRun dark = open_page(server, kept_query, "dark.png", "action theme", {}, {}, profile);
  const PageRun next_visit = open_page(server, kept_query, "next_visit.png", "state", {}, {}, profile);
  INFO(next_visit.log);
  CHECK(sidebar_brightness(fresh.canvas) > 150.0);
  CHECK(sidebar_brightness(dark.canvas) < 100.0);
  CHECK(sidebar_brightness(next_visit.canvas) < 100.0);
}

TEST_CASE("Unsaved changes in the page are offered back on the next visit", "[app][web]") {
  NOME_NEEDS_WEB_PAGE();
  const std::string profile = empty_profile("web_recovery_profile");
  const PageServer server;
  // The visit ends without saving, as a closed tab or a crash ends it.
  const PageRun edited = open_page(server, kept_query, "edited.png", slider_script, {}, {}, profile);
  const std::vector<std::string> edited_states = state_lines(edited.log);
  REQUIRE(edited_states.size() == 2);
  REQUIRE(edited_states[0] != edited_states[1]);
  const PageRun recovered =
      open_page(server, kept_query, "recovered.png", "recover restore\nstate", {}, {}, profile);
  INFO(recovered.log);
  const std::vector<std::string> recovered_states = state_lines(recovered.log);
  REQUIRE(recovered_states.size() == 1);
  CHECK(recovered_states[0] == edited_states[1]);
}

TEST_CASE("A script in the page's address that is not one ends with the desktop's located error in the log",
          "[app][web]") {
  NOME_NEEDS_WEB_PAGE();
  const std::string dir = nome::test::private_scratch_dir("web_bad_script");
  const std::string script = nome::test::write_script(dir, "subdivide 2\n");
  const CommandResult desktop =
      nome::test::run_window(nome::test::assets + "funnel_cube.nome --script " + script);
  CHECK(desktop.status == 1);
  const std::string error = ":1:1: expected a command (";
  const auto at = desktop.err.find(error);
  REQUIRE(at != std::string::npos);
  const std::string message = desktop.err.substr(at, desktop.err.find('\n', at) - at);
  CHECK_THAT(message, Catch::EndsWith("found 'subdivide'"));

  const PageServer server;
  const PageRun page = open_page(server, "threads=0&scene=funnel_cube.nome&script=subdivide%202", "bad.png");
  INFO(page.log);
  // The page's script file, named as the desktop names its own, with the same message; the scene stays.
  CHECK_THAT(page.log, Catch::Contains("nome: error: /tmp/page_script.txt" + message));
  CHECK(page.log.find("page: first model frame") != std::string::npos);
  const auto [front, back] = model_pixels(page.canvas);
  CHECK(front > 20000);
  // A command the viewer refuses (a value past its slider) is an error in the log, as on the desktop; the
  // page goes on with the next command.
  const PageRun refused =
      open_page(server, "threads=0&scene=funnel_cube.nome", "refused.png", "set fp_n 99\nstate");
  INFO(refused.log);
  CHECK_THAT(refused.log, Catch::Contains("nome: error: page script:1: ") && Catch::Contains("fp_n"));
  const std::vector<std::string> states = state_lines(refused.log);
  REQUIRE(states.size() == 1);
  CHECK_THAT(states[0], Catch::Contains(", F 48,"));
}
