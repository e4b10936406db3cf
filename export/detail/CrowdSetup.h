#pragma once
// What every skinned-crowd writer (glTF, USD, FBX) checks and sets up before its first
// agent: the input's checks, every frame's time, the frames joints are keyed on, and the
// characters the agents' types wear; and its opening, startCrowd, made of those. Writes
// no file.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/ExportResult.h"
#include "export/character/CharacterLibrary.h"
#include "export/detail/ExactBake.h"
#include "export/detail/ExportCancel.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace throng::exporting::detail {

// Empty when `cache` can be written to `path`; else what is wrong, naming the file: no
// path, a suffix not among `suffixes` (lower case; empty: any), nothing recorded, a frame
// rate not above 0, a joint frame step below 1, an agent type the scene lacks.
std::string checkCrowdInput(const sim::Scene& scene, const sim::FrameCache& cache, const std::string& path,
                            const std::vector<std::string_view>& suffixes, int jointFrameStep);
// checkCrowdInput, then the key tolerances (each >= 0; NaN is not).
std::string checkCrowdInput(const sim::Scene& scene, const sim::FrameCache& cache, const std::string& path,
                            const std::vector<std::string_view>& suffixes, int jointFrameStep,
                            std::initializer_list<float> tolerances);
// Frame f's time, f / fps, s.
std::vector<float> frameTimes(const sim::FrameCache& cache);
// Every `step`-th frame and the last, with their times (no accessor).
JointClock jointFrames(const std::vector<float>& times, int step);
// Resolves the characters of the types some agent has, at `lod`; an error naming the file.
std::string resolveCharacters(const sim::Scene& scene, const sim::FrameCache& cache, Lod lod,
                              const std::string& sceneDirectory, const std::string& path, CharacterLibrary& library);

// What a skinned-crowd writer starts from. The baker (AgentBake.h) keeps references to
// `times` and `jointClock`: the CrowdStart outlives it.
struct CrowdStart {
    CharacterLibrary library;  // the characters the agents' types wear
    std::uint64_t seed = 0;    // the variation seed: the options', else the scene's
    std::vector<float> times;  // every frame's (frameTimes)
    JointClock jointClock;     // the frames joints are keyed on (jointFrames)
};

// The opening every skinned-crowd writer shares, for its options (path, lod,
// sceneDirectory, seed, jointFrameStep): `inputError` (its checks: checkCrowdInput),
// else a cancel at 0 %, else the characters resolved, and `start` filled. Returns the
// result the export ends with at once, or nothing to go on.
template <class Options>
std::optional<ExportResult> startCrowd(std::string inputError, const sim::Scene& scene, const sim::FrameCache& cache,
                                       const Options& options, const ProgressFn& progress, CrowdStart& start)
{
    ExportResult failed;
    failed.error = std::move(inputError);
    if (!failed.error.empty())
        return failed;
    if (cancelledAt(progress, 0.0f))
        return cancelledExport(options.path);
    failed.error = resolveCharacters(scene, cache, options.lod, options.sceneDirectory, options.path, start.library);
    if (!failed.error.empty())
        return failed;
    start.seed = options.seed.value_or(scene.settings.seed);
    start.times = frameTimes(cache);
    start.jointClock = jointFrames(start.times, options.jointFrameStep);
    return std::nullopt;
}

}  // namespace throng::exporting::detail
