#pragma once
// Checks a scene just read for sizes the World could not build (a navigation grid, a
// crowd or a sketched field past SceneLimits) and reports each as an error at the key
// that asks for it, with the estimate; warns about walls and obstacles given twice or far
// from the bounds. Never changes the scene and never allocates in proportion to a size.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/io/detail/YamlFields.h"
#include "simcore/scene/Scene.h"

namespace throng::sim::detail {

void checkSceneSizes(YamlFields& f, const YAML::Node& root, const Scene& scene);

}  // namespace throng::sim::detail
