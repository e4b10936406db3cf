#pragma once
// Level of detail for many agents: the glyphs sorted into square ground cells, and per
// view a plan of which cells to draw at which detail. A cell outside the view is left
// out; a cell whose agents are small on screen is drawn as impostors (one point each),
// a mid-sized one with the coarse glyph, a near one with the detailed glyph. Each level
// is a list of ranges of sorted(), adjacent cells of one level merged into one range.
// CPU data only, no GL: the renderer uploads sorted() and draws the ranges.

#include "editor/viewport/AgentGlyph.h"
#include "editor/viewport/RenderView.h"

#include <glm/vec2.hpp>

#include <array>
#include <span>
#include <vector>

namespace throng::editor {

enum class AgentDetail { Detailed = 0, Coarse = 1, Impostor = 2 };
inline constexpr int kAgentDetailLevels = 3;

struct InstanceRange {
    int first = 0;  // index into AgentCells::sorted()
    int count = 0;  // > 0
};

// Radius on screen, in pixels, from which an agent gets a level's shape.
struct DetailThresholds {
    float coarseFromPx = 3.0f;     // below: an impostor
    float detailedFromPx = 10.0f;  // below: the coarse glyph
};

struct AgentDrawPlan {
    std::array<std::vector<InstanceRange>, kAgentDetailLevels> ranges;  // by AgentDetail
    std::array<int, kAgentDetailLevels> agents{};                       // instances per level
    int culledAgents = 0;                                               // outside the view

    const std::vector<InstanceRange>& at(AgentDetail d) const { return ranges[std::size_t(d)]; }
};

class AgentCells {
public:
    // Cells are at least this wide, and there are at most kMaxCellsPerSide along an axis.
    static constexpr float kMinCellM = 2.0f;
    static constexpr int kMaxCellsPerSide = 64;

    // Sorts `glyphs` by cell, stable within a cell (same input, same order).
    void build(std::span<const AgentGlyph> glyphs);
    std::span<const AgentGlyph> sorted() const { return m_sorted; }
    // order()[k]: the index in build()'s input of sorted()[k].
    std::span<const int> order() const { return m_order; }
    int cellCount() const { return int(m_cells.size()); }

    // Fills `plan` (its vectors are reused: no allocation once they have grown) for the
    // view. `heightScale` is 1 where agents stand up (perspective), 0 where they are flat.
    void plan(const RenderView& view, const DetailThresholds& thresholds, AgentDrawPlan& plan) const;

    // The height an agent of radius `radiusM` is drawn with in perspective, m.
    static float bodyHeightM(float radiusM);

private:
    struct Cell {
        int first = 0, count = 0;
        glm::vec2 min{0.0f}, max{0.0f};  // ground box of the agents' centres, x/z
        float minY = 0.0f, maxY = 0.0f;  // of the centres
        float maxRadiusM = 0.0f;
    };
    std::vector<AgentGlyph> m_sorted;
    std::vector<int> m_order;   // sorted -> input index
    std::vector<Cell> m_cells;  // non-empty cells only, in sorted() order
    std::vector<int> m_cellOf;  // scratch for build()
};

}  // namespace throng::editor
