#include "editor/viewport/ViewportPalette.h"

#include <array>

namespace throng::editor::palette {

glm::vec4 agentColour(std::size_t typeIndex)
{
    // Tableau 10 without its red and green, which the traffic lights use.
    static constexpr std::array<glm::vec4, 8> kTypes{{
        {0.949f, 0.557f, 0.169f, 1.0f},  // orange
        {0.365f, 0.647f, 0.855f, 1.0f},  // blue
        {0.929f, 0.788f, 0.282f, 1.0f},  // yellow
        {0.690f, 0.478f, 0.631f, 1.0f},  // purple
        {0.463f, 0.718f, 0.698f, 1.0f},  // teal
        {1.000f, 0.616f, 0.655f, 1.0f},  // pink
        {0.612f, 0.459f, 0.373f, 1.0f},  // brown
        {0.729f, 0.690f, 0.675f, 1.0f},  // grey
    }};
    return kTypes[typeIndex % kTypes.size()];
}

}  // namespace throng::editor::palette
