#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "app/cli_support.hpp"
#include "render/image.hpp"
#include "render/render_support.hpp"

using namespace nome;

namespace {

// A GIF reader independent of giflib: Python walks the blocks and counts the image descriptors, and tells
// whether a NETSCAPE2.0 block (one sub-block of 3 bytes: 1, then a loop count of 0) loops it forever.
const char* const gif_frame_counter = R"(import sys
data = open(sys.argv[1], 'rb').read()
assert data[:6] in (b'GIF87a', b'GIF89a'), 'not a GIF'
flags = data[10]
at = 13 + (3 * 2 ** ((flags & 7) + 1) if flags & 0x80 else 0)
frames = 0
loops = 'once'
def skip_blocks(at):
    while data[at]:
        at += data[at] + 1
    return at + 1
while data[at] != 0x3B:
    if data[at] == 0x21:
        if data[at + 1] == 0xFF and data[at + 2:at + 14] == bytes([11]) + b'NETSCAPE2.0':
            if data[at + 14:at + 19] == bytes([3, 1, 0, 0, 0]):
                loops = 'forever'
        at = skip_blocks(at + 2)
    elif data[at] == 0x2C:
        frames += 1
        local = data[at + 9]
        at += 10 + (3 * 2 ** ((local & 7) + 1) if local & 0x80 else 0)
        at = skip_blocks(at + 1)
    else:
        raise SystemExit('unexpected block %d at %d' % (data[at], at))
print(frames, data[6] | data[7] << 8, data[8] | data[9] << 8, loops)
)";

std::string python_output(const std::string& script, const std::string& argument) {
  std::string out;
  if (FILE* pipe = ::popen(("python3 " + script + " " + argument + " 2>&1").c_str(), "r")) {
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
    ::pclose(pipe);
  }
  return out;
}

}  // namespace

TEST_CASE("nome render --turntable 8 -o OUT.gif writes an animated GIF of 8 frames", "[app]") {
  const std::string dir = test::private_scratch_dir("cli_turntable");
  const std::string band = std::string(NOME_SOURCE_DIR) + "/assets/mobius_band.nome";
  const auto r =
      test::run_nome_in_process("render " + band + " --turntable 8 -o " + dir + "/spin.gif --size 96x72");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("8 frames of 96x72"));
  std::ofstream(dir + "/count_frames.py") << gif_frame_counter;
  CHECK(python_output(dir + "/count_frames.py", dir + "/spin.gif") == "8 96 72 forever\n");

  const auto frames =
      test::run_nome_in_process("render " + band + " --turntable 4 -o " + dir + "/f.png --size 64x48");
  REQUIRE(frames.status == 0);
  const render::Image first = render::read_png(dir + "/f_001.png");
  const render::Image second = render::read_png(dir + "/f_002.png");
  CHECK(first.width == 64);
  CHECK(first.rgba != second.rgba);  // it turned
  CHECK(std::filesystem::exists(dir + "/f_004.png"));
  CHECK_FALSE(std::filesystem::exists(dir + "/f_005.png"));

  const auto sheet = test::run_nome_in_process("render " + band + " --turntable 4 --sheet -o " + dir +
                                               "/s.png --size 128x96");
  REQUIRE(sheet.status == 0);
  CHECK(render::read_png(dir + "/s.png").width == 128);
  CHECK(test::run_nome_in_process("render " + band + " -o " + dir + "/x.gif").status == 2);
  CHECK(
      test::run_nome_in_process("render " + band + " --turntable 4 --views 3 -o " + dir + "/x.png").status ==
      2);
}
