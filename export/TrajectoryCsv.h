#pragma once
// Writes a run's recorded frames as one CSV table (one row per agent per frame) for
// spreadsheets, pandas and pipeline scripts. Reads the FrameCache only; never simulates
// and never leaves a partial file at the target path.

#include "export/ExportResult.h"
#include "simcore/world/FrameCache.h"

#include <string>

namespace throng::exporting {

// Header `frame,agent,x,y,z,heading,speed,clip,phase`, then frame-major rows, agents in
// the cache's dense order. frame: cache frame index (0 = time 0, time = frame / fps);
// agent: AgentId; x y z: metres; heading: degrees, 0 = +x, counter-clockwise seen from
// above (AgentFrame::headingRad converted, not wrapped); speed: m/s; clip: its name
// (sim::toString: idle, walk, run or an action such as wave); phase: gait phase in
// [0, 1). Floats are the shortest text that reads back exactly.
// An agent that has left through an exit (AgentFrame::out) has no rows from that frame on.
// Written to a temporary file beside `path`, then renamed over it.
ExportResult writeTrajectoryCsv(const sim::FrameCache& cache, const std::string& path,
                                const ProgressFn& progress = {});

}  // namespace throng::exporting
