#pragma once
// Compiles and links one GLSL 3.30 program from source strings, reporting compiler logs
// through qWarning. Needs the caller's GL context current; holds no state of its own.

#include <QOpenGLShaderProgram>

#include <memory>

namespace throng::editor {

// Null when a stage fails to compile or the program fails to link; `name` labels the log.
std::unique_ptr<QOpenGLShaderProgram> buildShaderProgram(const char* name, const char* vertexSource,
                                                         const char* fragmentSource);

}  // namespace throng::editor
