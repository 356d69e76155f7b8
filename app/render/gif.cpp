#include "render/gif.hpp"

#include <gif_lib.h>

#include <cstring>
#include <ostream>
#include <string>

#include "nome/atomic_file.hpp"
#include "nome/error.hpp"

namespace nome::render {
namespace {

int write_gif_bytes(GifFileType* gif, const GifByteType* bytes, int count) {
  auto* out = static_cast<std::ostream*>(gif->UserData);
  out->write(reinterpret_cast<const char*>(bytes), count);
  return *out ? count : 0;
}

void check_gif(int status, GifFileType* gif, const std::filesystem::path& path) {
  if (status == GIF_OK) return;
  throw IoError(path.string() + ": write_gif: " + GifErrorString(gif ? gif->Error : 0));
}

// The NETSCAPE2.0 block that makes viewers loop the animation forever.
void put_gif_loop(GifFileType* gif, const std::filesystem::path& path) {
  static const GifByteType name[] = "NETSCAPE2.0";
  static const GifByteType loop[] = {1, 0, 0};
  check_gif(EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE), gif, path);
  check_gif(EGifPutExtensionBlock(gif, 11, name), gif, path);
  check_gif(EGifPutExtensionBlock(gif, 3, loop), gif, path);
  check_gif(EGifPutExtensionTrailer(gif), gif, path);
}

void put_gif_frame(GifFileType* gif, const Image& frame, int delay_ms, const std::filesystem::path& path) {
  const std::size_t n = std::size_t(frame.width) * std::size_t(frame.height);
  std::vector<GifByteType> red(n), green(n), blue(n), indices(n);
  for (std::size_t i = 0; i < n; ++i) {
    red[i] = frame.rgba[4 * i];
    green[i] = frame.rgba[4 * i + 1];
    blue[i] = frame.rgba[4 * i + 2];
  }
  int colors = 256;
  GifColorType palette[256];
  check_gif(GifQuantizeBuffer(unsigned(frame.width), unsigned(frame.height), &colors, red.data(),
                              green.data(), blue.data(), indices.data(), palette),
            gif, path);
  ColorMapObject* map = GifMakeMapObject(256, palette);
  GraphicsControlBlock control{};
  control.DisposalMode = DISPOSE_BACKGROUND;
  control.DelayTime = delay_ms / 10;  // hundredths of a second
  control.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType extension[4];
  const std::size_t length = EGifGCBToExtension(&control, extension);
  int status = EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, int(length), extension);
  if (status == GIF_OK) status = EGifPutImageDesc(gif, 0, 0, frame.width, frame.height, false, map);
  for (int y = 0; status == GIF_OK && y < frame.height; ++y)
    status = EGifPutLine(gif, indices.data() + std::size_t(y) * std::size_t(frame.width), frame.width);
  GifFreeMapObject(map);
  check_gif(status, gif, path);
}

}  // namespace

void write_gif(const std::filesystem::path& path, const std::vector<Image>& frames, int delay_ms) {
  if (frames.empty()) throw InvalidInputError("write_gif: no frames");
  for (const Image& f : frames)
    if (f.width != frames[0].width || f.height != frames[0].height)
      throw InvalidInputError("write_gif: the frames differ in size");
  write_file_atomically(path, [&](std::ostream& out) {
    int error = 0;
    GifFileType* gif = EGifOpen(&out, write_gif_bytes, &error);
    if (!gif) throw IoError(path.string() + ": write_gif: " + GifErrorString(error));
    try {
      EGifSetGifVersion(gif, true);
      check_gif(EGifPutScreenDesc(gif, frames[0].width, frames[0].height, 8, 0, nullptr), gif, path);
      put_gif_loop(gif, path);
      for (const Image& frame : frames) put_gif_frame(gif, frame, delay_ms, path);
    } catch (...) {
      EGifCloseFile(gif, &error);
      throw;
    }
    if (EGifCloseFile(gif, &error) != GIF_OK)
      throw IoError(path.string() + ": write_gif: " + GifErrorString(error));
  });
}

}  // namespace nome::render
