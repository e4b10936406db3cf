#pragma once
// Paints a top view of a run over its set (walls, obstacles, exits, measurement lines
// and areas, with metre axes): the walkers' trajectories, or the density heatmap with its
// colour scale. Qt Charts has no heatmap, so the ground plots are painted. x runs right
// and z down, as in the editor's top view. Reads the scene and the analysis only.

#include "simcore/analysis/RunAnalysis.h"
#include "simcore/scene/Scene.h"

#include <QColor>
#include <QImage>
#include <QSize>

namespace throng::report {

enum class GroundLayer { Trajectories, Density };

// At most `size`: the image keeps the plotted extent's proportions.
QImage paintGround(const sim::Scene& scene, const sim::RunAnalysis& analysis, GroundLayer layer, QSize size);

// The heatmap's colour for a density as a fraction of the scale's top, in [0, 1].
QColor densityColour(double fraction);

}  // namespace throng::report
