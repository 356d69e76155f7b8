#pragma once

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/gl.hpp"

namespace nome::render {

struct ShaderStage {
  GLenum type;                     // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER
  std::vector<std::string> files;  // concatenated after the #version line (shared code first)
};

// The language shader sources are compiled as: GLSL 3.30 core (desktop) or GLSL ES 3.00 (WebGL2). The
// build's own is the one its context takes; Mesa's desktop contexts take GLSL ES 3.00 as well, which lets
// the tests draw with the web's shaders.
enum class GlslDialect { desktop, es };
#ifdef __EMSCRIPTEN__
inline constexpr GlslDialect built_dialect = GlslDialect::es;
#else
inline constexpr GlslDialect built_dialect = GlslDialect::desktop;
#endif

// A linked program built from files found by find_shader_source(), with the dialect's version line, then
// `defines` (lines such as "#define FLAT_NORMALS\n"), before every stage's files. Throws Error with the
// compiler's log and the files' origins when a stage does not compile or link.
class ShaderProgram {
 public:
  ShaderProgram(const std::string& name, const std::vector<ShaderStage>& stages,
                const std::string& defines = {}, GlslDialect dialect = built_dialect);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const { glUseProgram(program_); }
  // Setters for the program in use; a uniform the compiler removed is ignored.
  void set(const char* name, int value) const { glUniform1i(location(name), value); }
  void set(const char* name, float value) const { glUniform1f(location(name), value); }
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, const glm::mat4& value) const;

 private:
  GLint location(const char* name) const { return glGetUniformLocation(program_, name); }

  GLuint program_ = 0;
};

}  // namespace nome::render
