#pragma once
// GLSL 3.30 sources of the agent renderer: the instanced glyph (a mesh per agent) and the
// impostor (one small quad per agent that draws the glyph's silhouette, shading and
// nose, for agents a few pixels wide). Both read two vec4 per instance at locations 3, 4.

namespace throng::editor::shaders {

extern const char* const kGlyphVertex;
extern const char* const kGlyphFragment;
extern const char* const kImpostorVertex;
extern const char* const kImpostorFragment;

}  // namespace throng::editor::shaders
