#pragma once

#include <cstddef>
#include <cstdint>

#include "render/gl.hpp"

namespace nome::render {

// Tables of one texel per element (face, vertex) are 2D textures of a fixed width, as WebGL2 has no
// buffer textures: element i sits at (i % table_width, i / table_width). Shaders find it with
// table_texel() (shaders/tables.glsl), whose width comes from the TABLE_WIDTH_BITS define.
inline constexpr int table_width_bits = 12;
inline constexpr std::uint32_t table_width = 1u << table_width_bits;

// A texel layout both GL 3.3 and GLES 3.0 take for glTexImage2D and glTexSubImage2D.
struct TexelFormat {
  GLenum internal_format;
  GLenum format;
  GLenum type;
  std::size_t bytes;
};
inline constexpr TexelFormat int_texels{GL_R32I, GL_RED_INTEGER, GL_INT, 4};
inline constexpr TexelFormat rgba8_texels{GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4};
inline constexpr TexelFormat byte_texels{GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, 1};
inline constexpr TexelFormat vec3_texels{GL_RGB32F, GL_RGB, GL_FLOAT, 12};

// One table on the GPU, read with texelFetch (nearest, no mipmaps). Needs a current context.
class TableTexture {
 public:
  TableTexture(TexelFormat format, std::size_t count);
  ~TableTexture();
  TableTexture(const TableTexture&) = delete;
  TableTexture& operator=(const TableTexture&) = delete;

  // Room for `count` elements; the content is undefined after a change of rows.
  void resize(std::size_t count);
  // Elements [0, count) from `data`: host memory, or an offset into the bound GL_PIXEL_UNPACK_BUFFER (a
  // copy on the GPU's side). Whole rows in one call, then the last, partial row.
  void write(const void* data, std::size_t count) const;

  GLuint id() const { return texture_; }

 private:
  TexelFormat format_;
  GLuint texture_ = 0;
  GLsizei rows_ = 0;
};

}  // namespace nome::render
