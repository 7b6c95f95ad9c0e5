#include "common/gl/gl_program.hpp"

#include <stdexcept>
#include <vector>

namespace fedsim::gl {

namespace {

GLuint compile(const GlApi& gl, GLenum kind, const char* source, const std::string& name) {
  const GLuint shader = gl.CreateShader(kind);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
    gl.GetShaderInfoLog(shader, length, nullptr, log.data());
    gl.DeleteShader(shader);
    throw std::runtime_error("GLSL program '" + name + "' " +
                             (kind == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                             " shader: " + log.data());
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(const GlApi& gl, const std::string& name, const char* vertex_source,
                     const char* fragment_source)
    : gl_(&gl), name_(name) {
  const GLuint vertex = compile(gl, GL_VERTEX_SHADER, vertex_source, name);
  const GLuint fragment = compile(gl, GL_FRAGMENT_SHADER, fragment_source, name);
  program_ = gl.CreateProgram();
  gl.AttachShader(program_, vertex);
  gl.AttachShader(program_, fragment);
  gl.LinkProgram(program_);
  gl.DeleteShader(vertex);
  gl.DeleteShader(fragment);
  GLint ok = 0;
  gl.GetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    gl.GetProgramiv(program_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
    gl.GetProgramInfoLog(program_, length, nullptr, log.data());
    gl.DeleteProgram(program_);
    throw std::runtime_error("GLSL program '" + name + "' link: " + log.data());
  }
}

GlProgram::~GlProgram() {
  if (program_ != 0) gl_->DeleteProgram(program_);
}

void GlProgram::use() const { gl_->UseProgram(program_); }

GLint GlProgram::location(const char* name) const {
  return gl_->GetUniformLocation(program_, name);
}

void GlProgram::set(const char* name, float v) const { gl_->Uniform1f(location(name), v); }
void GlProgram::set(const char* name, int v) const { gl_->Uniform1i(location(name), v); }
void GlProgram::set(const char* name, const Eigen::Vector2f& v) const {
  gl_->Uniform2f(location(name), v.x(), v.y());
}
void GlProgram::set(const char* name, const Eigen::Vector3f& v) const {
  gl_->Uniform3f(location(name), v.x(), v.y(), v.z());
}
void GlProgram::set(const char* name, const Eigen::Matrix3f& m) const {
  gl_->UniformMatrix3fv(location(name), 1, GL_FALSE, m.data());  // Eigen: column-major
}
void GlProgram::set(const char* name, const Eigen::Matrix4f& m) const {
  gl_->UniformMatrix4fv(location(name), 1, GL_FALSE, m.data());
}

}  // namespace fedsim::gl
