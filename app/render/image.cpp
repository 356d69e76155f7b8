#include "render/image.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <ostream>

#include "nome/atomic_file.hpp"
#include "nome/error.hpp"

namespace nome::render {

void write_png(const std::filesystem::path& path, const Image& image) {
  write_file_atomically(path, [&](std::ostream& out) {
    auto append = [](void* stream, void* data, int size) {
      static_cast<std::ostream*>(stream)->write(static_cast<const char*>(data), size);
    };
    if (!stbi_write_png_to_func(append, &out, image.width, image.height, 4, image.rgba.data(),
                                image.width * 4))
      throw IoError(path.string() + ": PNG encoding failed");
  });
}

Image read_png(const std::filesystem::path& path) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
  if (!data) throw IoError(path.string() + ": cannot read PNG (" + stbi_failure_reason() + ")");
  Image image(width, height);
  std::copy(data, data + image.rgba.size(), image.rgba.begin());
  stbi_image_free(data);
  return image;
}

Image crop(const Image& image, int x, int y, int width, int height) {
  x = std::clamp(x, 0, image.width);
  y = std::clamp(y, 0, image.height);
  Image part(std::clamp(width, 0, image.width - x), std::clamp(height, 0, image.height - y));
  if (part.rgba.empty()) return part;
  for (int row = 0; row < part.height; ++row)
    std::copy_n(image.pixel(x, y + row), std::size_t(part.width) * 4, part.pixel(0, row));
  return part;
}

}  // namespace nome::render
