#include "render/image.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

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

}  // namespace nome::render
