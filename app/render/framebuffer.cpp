#include "render/framebuffer.hpp"

#include <algorithm>
#include <string>

#include "nome/error.hpp"

namespace nome::render {
namespace {

void require_complete(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error(std::string("Framebuffer: ") + what + " is incomplete (status " + std::to_string(status) +
                ")");
}

}  // namespace

Framebuffer::Framebuffer(int width, int height, int samples) : width_(width), height_(height) {
  GLint max_size = 0, max_samples = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throw InvalidInputError("Framebuffer: size " + std::to_string(width) + "x" + std::to_string(height) +
                            " outside 1.." + std::to_string(max_size));
  samples = std::clamp(samples, 0, int(max_samples));

  glGenRenderbuffers(1, &colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  glGenFramebuffers(1, &multisampled_);
  glBindFramebuffer(GL_FRAMEBUFFER, multisampled_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  require_complete("the multisampled target");

  glGenRenderbuffers(1, &resolved_colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, resolved_colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenFramebuffers(1, &resolved_);
  glBindFramebuffer(GL_FRAMEBUFFER, resolved_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolved_colour_);
  require_complete("the resolve target");
  glBindFramebuffer(GL_FRAMEBUFFER, multisampled_);
}

Framebuffer::~Framebuffer() {
  glDeleteFramebuffers(1, &multisampled_);
  glDeleteFramebuffers(1, &resolved_);
  const GLuint buffers[] = {colour_, depth_, resolved_colour_};
  glDeleteRenderbuffers(3, buffers);
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, multisampled_);
  glViewport(0, 0, width_, height_);
}

Image Framebuffer::read(bool unpremultiply) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_);
  Image bottom_up(width_, height_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.rgba.data());
  bind();

  Image image(width_, height_);
  const std::size_t row = std::size_t(width_) * 4;
  for (int y = 0; y < height_; ++y)
    std::copy_n(bottom_up.rgba.data() + std::size_t(height_ - 1 - y) * row, row,
                image.rgba.data() + std::size_t(y) * row);
  if (unpremultiply) {
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
      const unsigned alpha = image.rgba[i + 3];
      if (alpha == 0 || alpha == 255) continue;
      for (int k = 0; k < 3; ++k)
        image.rgba[i + k] = std::uint8_t(std::min(255u, (image.rgba[i + k] * 255u + alpha / 2) / alpha));
    }
  }
  return image;
}

}  // namespace nome::render
