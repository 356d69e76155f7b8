#pragma once

#include "render/gl.hpp"
#include "render/image.hpp"

namespace nome::render {

// An offscreen render target: multisampled colour + depth, resolved on read-back. Needs a current context.
class Framebuffer {
 public:
  Framebuffer(int width, int height, int samples = 4);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // Makes it the draw target.
  void bind() const;
  // The resolved pixels, top row first. With `unpremultiply`, colours over a transparent background are
  // divided by their coverage so that antialiased edges keep their colour in the PNG.
  Image read(bool unpremultiply) const;

 private:
  int width_, height_;
  GLuint multisampled_ = 0, resolved_ = 0;
  GLuint colour_ = 0, depth_ = 0, resolved_colour_ = 0;
};

}  // namespace nome::render
