#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace nome::render {

// An 8-bit RGBA picture, top row first (as PNG stores it), alpha not premultiplied.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(std::size_t(w) * std::size_t(h) * 4, 0) {}
  std::uint8_t* pixel(int x, int y) { return rgba.data() + (std::size_t(y) * std::size_t(width) + x) * 4; }
  const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + (std::size_t(y) * std::size_t(width) + x) * 4;
  }
};

// The part of the picture from (x, y) (top-left corner, clamped to the picture) of that size.
Image crop(const Image& image, int x, int y, int width, int height);

// Writes a PNG through write_file_atomically: the target is the complete old or the complete new file.
void write_png(const std::filesystem::path& path, const Image& image);

// Reads any PNG as RGBA; throws IoError naming the file when it cannot.
Image read_png(const std::filesystem::path& path);

}  // namespace nome::render
