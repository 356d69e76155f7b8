#include "render/table_texture.hpp"

#include <algorithm>
#include <string>

#include "nome/error.hpp"

namespace nome::render {

TableTexture::TableTexture(TexelFormat format, std::size_t count) : format_(format) {
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  // Integer textures are incomplete, hence unreadable, under the default mipmapped filter.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  resize(count);
}

TableTexture::~TableTexture() {
  glDeleteTextures(1, &texture_);
}

void TableTexture::resize(std::size_t count) {
  // An empty table still gets a row: a texture of no texels is incomplete.
  const auto rows = GLsizei(std::max<std::size_t>((count + table_width - 1) / table_width, 1));
  if (rows == rows_) return;
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (rows > max_size)
    throw Error("TableTexture::resize: " + std::to_string(count) + " elements need " + std::to_string(rows) +
                " rows, the GPU takes " + std::to_string(max_size));
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(format_.internal_format), GLsizei(table_width), rows, 0,
               format_.format, format_.type, nullptr);
  rows_ = rows;
}

void TableTexture::write(const void* data, std::size_t count) const {
  if (count == 0) return;
  glBindTexture(GL_TEXTURE_2D, texture_);
  const auto address = reinterpret_cast<std::uintptr_t>(data);
  const std::size_t full_rows = count / table_width, rest = count % table_width;
  if (full_rows > 0)
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, GLsizei(table_width), GLsizei(full_rows), format_.format,
                    format_.type, data);
  if (rest > 0)
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, GLint(full_rows), GLsizei(rest), 1, format_.format, format_.type,
                    reinterpret_cast<const void*>(address + full_rows * table_width * format_.bytes));
}

}  // namespace nome::render
