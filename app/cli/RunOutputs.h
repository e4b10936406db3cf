#pragma once
// Writes what `throng-cli run` was asked for (each export through its format's writer,
// then the stats JSON) and says where each went. Every output is written atomically.

#include "CliArguments.h"

#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/RunStats.h"

#include <iosfwd>

namespace throng::cli {

// Before the run: whether every output asked for can be written where it was asked, so a
// long run does not end unwritten for a folder that does not exist. A file's folder must
// exist and be writable, and the file must not be a folder; a directory output (DIR/, the
// Maya cache) must not be a file, and its nearest existing folder must be writable (the
// writer makes the rest). Says on `err` what is wrong with each output that fails.
bool outputsWritable(const CliArguments& args, std::ostream& err);

// The command's exit status: 0; 1 when any requested output could not be written (the
// reason is on `err`); 128 + the signal when stopped by one (InterruptWatch): the outputs
// written before it are complete, the one it stopped and those after it are not written.
int writeRunOutputs(const CliArguments& args, const sim::Scene& scene, const sim::FrameCache& cache,
                    const sim::RunStats& stats, std::ostream& out, std::ostream& err);

}  // namespace throng::cli
