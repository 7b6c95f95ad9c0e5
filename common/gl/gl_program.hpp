// A linked GLSL program and its uniforms by name. Compile and link errors throw
// std::runtime_error with the program's name and the driver's log.
#pragma once

#include "common/gl/gl_api.hpp"

#include <Eigen/Core>

#include <string>

namespace fedsim::gl {

class GlProgram {
 public:
  GlProgram(const GlApi& gl, const std::string& name, const char* vertex_source,
            const char* fragment_source);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  void use() const;
  // Setters for the program in use; a uniform the compiler removed is ignored.
  void set(const char* name, float v) const;
  void set(const char* name, int v) const;
  void set(const char* name, const Eigen::Vector2f& v) const;
  void set(const char* name, const Eigen::Vector3f& v) const;
  void set(const char* name, const Eigen::Matrix3f& m) const;
  void set(const char* name, const Eigen::Matrix4f& m) const;

 private:
  GLint location(const char* name) const;
  const GlApi* gl_;
  std::string name_;
  GLuint program_ = 0;
};

}  // namespace fedsim::gl
