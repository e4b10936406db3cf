#include "editor/viewport/ShaderProgram.h"

#include <QDebug>

namespace throng::editor {

std::unique_ptr<QOpenGLShaderProgram> buildShaderProgram(const char* name, const char* vertexSource,
                                                         const char* fragmentSource)
{
    auto program = std::make_unique<QOpenGLShaderProgram>();
    if (!program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertexSource) ||
        !program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragmentSource) || !program->link()) {
        qWarning().noquote() << "throng: the" << name << "shader failed:" << program->log();
        return nullptr;
    }
    return program;
}

}  // namespace throng::editor
