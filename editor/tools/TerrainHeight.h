#pragma once
// Height of the scene's terrain under a ground point, exactly as the simulation samples
// it (simcore's bilinear terrainHeight).

#include "simcore/scene/TerrainHeight.h"

namespace throng::editor {

using sim::terrainHeight;

}  // namespace throng::editor
