#include "editor/viewport/VertexBuffer.h"

#include <QOpenGLFunctions_3_3_Core>

namespace throng::editor {

void VertexBuffer::create(QOpenGLFunctions_3_3_Core& gl, std::size_t stride,
                          std::initializer_list<VertexAttribute> attributes)
{
    m_stride = stride;
    m_count = 0;
    gl.glGenVertexArrays(1, &m_vao);
    gl.glGenBuffers(1, &m_vbo);
    gl.glBindVertexArray(m_vao);
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    GLuint index = 0;
    for (const VertexAttribute& a : attributes) {
        gl.glEnableVertexAttribArray(index);
        gl.glVertexAttribPointer(index, a.floats, GL_FLOAT, GL_FALSE, GLsizei(stride),
                                 reinterpret_cast<const void*>(a.offset));
        ++index;
    }
    gl.glBindVertexArray(0);
}

void VertexBuffer::destroy(QOpenGLFunctions_3_3_Core& gl)
{
    gl.glDeleteBuffers(1, &m_vbo);
    gl.glDeleteVertexArrays(1, &m_vao);
    m_vbo = m_vao = 0;
    m_count = 0;
}

void VertexBuffer::upload(QOpenGLFunctions_3_3_Core& gl, const void* vertices, std::size_t count)
{
    if (!created())
        return;
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(count * m_stride), vertices, GL_STATIC_DRAW);
    m_count = int(count);
}

void VertexBuffer::drawTriangles(QOpenGLFunctions_3_3_Core& gl) const
{
    if (m_count == 0)
        return;
    gl.glBindVertexArray(m_vao);
    gl.glDrawArrays(GL_TRIANGLES, 0, m_count);
    gl.glBindVertexArray(0);
}

}  // namespace throng::editor
