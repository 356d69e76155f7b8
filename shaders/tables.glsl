// Element i of a table texture (render/table_texture.hpp): row i / width, column i % width, the width a
// power of two (TABLE_WIDTH_BITS, defined by the renderer).
ivec2 table_texel(int i) {
  return ivec2(i & ((1 << TABLE_WIDTH_BITS) - 1), i >> TABLE_WIDTH_BITS);
}
