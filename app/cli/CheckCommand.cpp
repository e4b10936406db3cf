#include "CliCommands.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/GeometryCheck.h"
#include "simcore/world/WorldBrain.h"

#include <ostream>
#include <utility>
#include <vector>

namespace throng::cli {

int checkCommand(const CliArguments& args, std::ostream& out, std::ostream& err)
{
    const sim::LoadResult loaded = sim::loadScene(args.scene);
    std::vector<sim::Diagnostic> diagnostics = loaded.diagnostics;
    // Brains compile only once the scene around them is whole.
    if (loaded.ok()) {
        for (sim::Diagnostic& d : sim::checkSceneBrains(loaded.scene))
            diagnostics.push_back(std::move(d));
        // What a run would trip on: far coordinates, agents inside the set, goals out of reach.
        for (sim::Diagnostic& d : sim::checkSceneGeometry(loaded.scene, args.scene))
            diagnostics.push_back(std::move(d));
    }
    int errors = 0, warnings = 0;
    for (const sim::Diagnostic& d : diagnostics) {
        err << d.format() << '\n';
        (d.severity == sim::Severity::Error ? errors : warnings) += 1;
    }
    if (errors > 0) {
        out << args.scene << ": invalid: " << errors << (errors == 1 ? " error" : " errors") << ", " << warnings
            << (warnings == 1 ? " warning" : " warnings") << '\n';
        return 1;
    }
    const sim::Scene& s = loaded.scene;
    std::uint64_t spawned = 0;
    for (const sim::SpawnGroup& g : s.groups)
        spawned += g.count;
    out << args.scene << ": valid (" << s.agentTypes.size() << " agent types, " << s.agents.size()
        << " placed agents, " << spawned << " spawned, " << s.walls.size() << " walls, " << s.brains.size()
        << " brains";
    if (warnings > 0)
        out << "; " << warnings << (warnings == 1 ? " warning" : " warnings");
    out << ")\n";
    return 0;
}

}  // namespace throng::cli
