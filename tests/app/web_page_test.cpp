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

// Chromium headless with a fresh profile (no storage of another run), given time for the page to load,
// open its scene and run its script.
CommandResult chromium(const std::string& output_flag, const std::string& address) {
  const std::string profile = nome::test::private_scratch_dir("web_profile");
  std::filesystem::remove_all(profile);
  return nome::test::run_command(
      "chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader "
      "--hide-scrollbars --window-size=1280,800 --virtual-time-budget=20000 --user-data-dir=" +
      profile + " " + output_flag + " '" + address + "'");
}

// What the page's log held once the budget ran out.
std::string page_log(const PageServer& server, const std::string& query) {
  const CommandResult r = chromium("--dump-dom", server.address(query));
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto begin = r.out.find("<pre id=\"log\">");
  REQUIRE(begin != std::string::npos);
  return r.out.substr(begin, r.out.find("</pre>", begin) - begin);
}

// The viewer's canvas, below the page's bar.
Image page_picture(const PageServer& server, const std::string& query, const std::string& name) {
  const std::string file = nome::test::private_scratch_dir("web_pictures") + "/" + name;
  const CommandResult r = chromium("--screenshot=" + file, server.address(query));
  INFO(r.err);
  REQUIRE(r.status == 0);
  const Image page = nome::render::read_png(file);
  REQUIRE(page.width == nome::test::viewer_width);
  REQUIRE(page.height == nome::test::viewer_height);
  Image canvas(page.width, canvas_height);
  std::copy(page.rgba.begin() + std::ptrdiff_t(bar_height) * page.width * 4, page.rgba.end(),
            canvas.rgba.begin());
  return canvas;
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
#define NOME_NEEDS_WEB_PAGE()                                              \
  if (!std::filesystem::exists(web_folder / "nome.js") ||                  \
      !std::filesystem::exists(web_folder / "nome-threads.js"))            \
    NOME_SKIP(web_folder.string() + " has no page: `make web` builds it"); \
  if (std::system("command -v chromium >/dev/null 2>&1") != 0)             \
  NOME_SKIP("no chromium (make web-deps installs it)")

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
  const std::vector<std::string> desktop_states = state_lines(desktop.out);
  REQUIRE(desktop_states.size() == 2);
  REQUIRE(desktop_states[0] != desktop_states[1]);

  const PageServer server;
  const std::string query = "threads=0&scene=funnel_cube.nome&script=" + url_encoded(slider_script);
  const std::string log = page_log(server, query);
  INFO(log);
  CHECK(log.find("page: first model frame") != std::string::npos);
  CHECK(log.find("one-thread build") != std::string::npos);
  CHECK(state_lines(log) == desktop_states);

  const Image page = page_picture(server, query, "funnel_cube.png");
  const auto [front, back] = model_pixels(page);
  CHECK(front > 20000);
  CHECK(back > 20000);
  const auto difference =
      nome::render::compare_images(nome::render::read_png(dir + "/desktop.png"), page, 24);
  REQUIRE(difference.same_size);
  // Antialiased edges differ between SwiftShader and llvmpipe; the panels and the model do not.
  CHECK(difference.differing_fraction < 0.01);
}

TEST_CASE("The threaded web page computes what the one-thread page does", "[app][web]") {
  NOME_NEEDS_WEB_PAGE();
  const PageServer server;
  const std::string query =
      "scene=funnel_cube.nome&script=" + url_encoded(slider_script + "subdiv 3\noffset 0.05\nstate\n");
  const std::string threaded_log = page_log(server, query);
  const std::string single_log = page_log(server, "threads=0&" + query);
  INFO(threaded_log);
  CHECK(threaded_log.find("threads build") != std::string::npos);
  const std::vector<std::string> states = state_lines(threaded_log);
  REQUIRE(states.size() == 3);
  CHECK(states == state_lines(single_log));
  const auto difference =
      nome::render::compare_images(page_picture(server, "threads=0&" + query, "single.png"),
                                   page_picture(server, query, "threaded.png"), 0);
  CHECK(difference.differing_pixels == 0);
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
  const std::string query = "threads=0&scene=jipcad/geom__mobius_strip.nom&script=state";
  const std::string log = page_log(server, query);
  INFO(log);
  const std::vector<std::string> states = state_lines(log);
  REQUIRE(states.size() == 1);
  CHECK(states == state_lines(desktop.out));
  CHECK(states[0].find("non-orientable") != std::string::npos);
  const auto [front, back] = model_pixels(page_picture(server, query, "mobius.png"));
  CHECK(front > 2000);
  CHECK(back > 2000);
}
