#pragma once
// What every skinned-crowd writer (glTF, USD, FBX) checks and sets up before its first
// agent: the input's checks, every frame's time, the frames joints are keyed on, and the
// characters the agents' types wear. Pure; writes nothing.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/character/CharacterLibrary.h"
#include "export/detail/ExactBake.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <string>
#include <string_view>
#include <vector>

namespace throng::exporting::detail {

// Empty when `cache` can be written to `path`; else what is wrong, naming the file: no
// path, a suffix not among `suffixes` (lower case; empty: any), nothing recorded, a frame
// rate not above 0, a joint frame step below 1, an agent type the scene lacks.
std::string checkCrowdInput(const sim::Scene& scene, const sim::FrameCache& cache, const std::string& path,
                            const std::vector<std::string_view>& suffixes, int jointFrameStep);
// Frame f's time, f / fps, s.
std::vector<float> frameTimes(const sim::FrameCache& cache);
// Every `step`-th frame and the last, with their times (no accessor).
JointClock jointFrames(const std::vector<float>& times, int step);
// Resolves the characters of the types some agent has, at `lod`; an error naming the file.
std::string resolveCharacters(const sim::Scene& scene, const sim::FrameCache& cache, Lod lod,
                              const std::string& sceneDirectory, const std::string& path, CharacterLibrary& library);

}  // namespace throng::exporting::detail
