#include "render/shader_program.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "nome/error.hpp"
#include "render/shader_sources.hpp"

namespace nome::render {
namespace {

// One set of sources for both languages, which differ in their first lines: GLSL ES has no default
// precision for floats in fragment shaders nor for integer samplers.
const char* prelude(GlslDialect dialect) {
  return dialect == GlslDialect::es ? "#version 300 es\n"
                                      "precision highp float;\nprecision highp int;\n"
                                      "precision highp sampler2D;\nprecision highp isampler2D;\n"
                                      "precision highp usampler2D;\n"
                                    : "#version 330 core\n";
}

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  is_program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
             : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  is_program ? glGetProgramInfoLog(object, length, nullptr, log.data())
             : glGetShaderInfoLog(object, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& name, const std::vector<ShaderStage>& stages,
                             const std::string& defines, GlslDialect dialect) {
  const auto folders = shader_search_path();
  std::vector<GLuint> shaders;
  auto release = [&] {
    for (GLuint s : shaders) glDeleteShader(s);
  };
  for (const ShaderStage& stage : stages) {
    std::string text = prelude(dialect) + defines;
    std::string origins;
    for (const std::string& file : stage.files) {
      const ShaderSource source = find_shader_source(file, folders);
      text += "#line 1\n" + source.text + "\n";
      origins += (origins.empty() ? "" : " + ") + source.origin;
    }
    const GLuint shader = glCreateShader(stage.type);
    shaders.push_back(shader);
    const char* pointer = text.c_str();
    glShaderSource(shader, 1, &pointer, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      const std::string log = info_log(shader, false);
      release();
      throw Error("shader program " + name + ": " + origins + " does not compile:\n" + log);
    }
  }
  program_ = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(program_, s);
  glLinkProgram(program_);
  release();
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(program_, true);
    glDeleteProgram(program_);
    throw Error("shader program " + name + " does not link:\n" + log);
  }
}

ShaderProgram::~ShaderProgram() {
  glDeleteProgram(program_);
}

void ShaderProgram::set(const char* name, const glm::vec2& value) const {
  glUniform2fv(location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec3& value) const {
  glUniform3fv(location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec4& value) const {
  glUniform4fv(location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat4& value) const {
  glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace nome::render
