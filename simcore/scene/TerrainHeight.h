#pragma once
// Height of a terrain under a ground point: bilinear between the four samples around
// (x, z), clamped at the edges; 0 without a (usable) terrain. The World stands walkers
// on it, and the editor paints and picks on it, with this one function.

#include "simcore/scene/Scene.h"

namespace throng::sim {

float terrainHeight(const Terrain& terrain, float x, float z);

}  // namespace throng::sim
