#pragma once
// Height of the scene's terrain under a ground point, as the simulation samples it
// (bilinear, clamped at the edges; 0 without a terrain). Plain function, no Qt.

#include "simcore/scene/Scene.h"

namespace throng::editor {

float terrainHeight(const sim::Terrain& terrain, float x, float z);

}  // namespace throng::editor
