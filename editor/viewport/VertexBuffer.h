#pragma once
// One vertex array over one buffer of interleaved float attributes, drawn as triangles:
// the GL objects that the ground, the set's shapes and its solids each hold, laid out,
// filled and drawn the same way (GridRenderer, ShapeRenderer, SolidRenderer). Knows
// nothing of shaders; create, fill, draw and destroy it with its GL context current.

#include <cassert>
#include <cstddef>
#include <initializer_list>
#include <vector>

class QOpenGLFunctions_3_3_Core;

namespace throng::editor {

// One attribute of a vertex: its count of floats (1 to 4) and its place in the vertex.
struct VertexAttribute {
    int floats = 1;
    std::size_t offset = 0;  // bytes from the vertex's start
};

class VertexBuffer {
public:
    // Makes the array and its buffer, attributes 0, 1, ... in the order listed, for vertices
    // of `stride` bytes.
    void create(QOpenGLFunctions_3_3_Core& gl, std::size_t stride, std::initializer_list<VertexAttribute> attributes);
    void destroy(QOpenGLFunctions_3_3_Core& gl);
    bool created() const { return m_vao != 0; }

    // Copies `count` vertices of the stride's size to the GPU, in place of the last.
    void upload(QOpenGLFunctions_3_3_Core& gl, const void* vertices, std::size_t count);
    template <class Vertex>
    void upload(QOpenGLFunctions_3_3_Core& gl, const std::vector<Vertex>& vertices)
    {
        assert(sizeof(Vertex) == m_stride || !created());  // the layout create was given
        upload(gl, vertices.data(), vertices.size());
    }
    int vertexCount() const { return m_count; }

    // Draws the vertices uploaded last as triangles, with the program the caller bound.
    void drawTriangles(QOpenGLFunctions_3_3_Core& gl) const;

private:
    unsigned m_vao = 0, m_vbo = 0;
    std::size_t m_stride = 0;
    int m_count = 0;
};

}  // namespace throng::editor
