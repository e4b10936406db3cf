#pragma once
// Writes a run's recorded frames as one small text file per agent, the format Maya and
// Houdini scripts read to drive a locator per agent. Reads the FrameCache only; never
// simulates, and never leaves a partial set of files behind.

#include "export/ExportResult.h"
#include "simcore/world/FrameCache.h"

#include <string>

namespace throng::exporting {

// The axis a character faces at rotY 0 in the program that reads the cache: +X is
// Throng's own heading (AgentFrame::headingRad); Maya's rigs face +Z, where rotY is the
// heading plus 90 degrees.
enum class ForwardAxis { PlusX, PlusZ };

struct AgentCacheOptions {
    ForwardAxis forward = ForwardAxis::PlusX;
    // Also writes `<directory>/throng_cache.txt`: the frame rate, the frame count, the
    // forward axis, the unit and each agent's file, first frame and frame count, for a
    // script that builds the crowd (resources/maya/throngCrowd.mel).
    bool manifest = false;
};

// Writes `<directory>/agent_<id>.txt` for every agent (AgentId, not dense index), one line
// `x y z rotYdeg speed clip` per recorded frame: metres, degrees about +Y (with +X forward,
// 0 = +x, counter-clockwise seen from above, as AgentFrame::headingRad; with +Z forward,
// that plus 90; never wrapped, so curves stay continuous), m/s, the clip the agent
// plays (idle, walk, run or its brain's action, as the CSV's clip); floats as the shortest
// text that reads back exactly. An agent that leaves through an exit (AgentFrame::out)
// has lines only for the frames before it left, so its file may be shorter; one an edit
// added at frame k (AgentFrame::present) starts with the line `# first_frame k`, then
// its lines from frame k; one an edit removed ends there. Creates `directory` when missing. All files are written to
// a staging directory first and renamed into place only when every one is complete.
ExportResult writeAgentTextCache(const sim::FrameCache& cache, const std::string& directory,
                                 const ProgressFn& progress = {}, const AgentCacheOptions& options = {});

// The manifest's name in the directory (AgentCacheOptions::manifest).
inline constexpr const char* kAgentCacheManifest = "throng_cache.txt";

}  // namespace throng::exporting
