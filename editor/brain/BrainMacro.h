#pragma once
// Collapsing a selection of nodes into a macro brain and expanding a macro node back
// inline, as pure graph transformations (the panel pushes them as one undo step).
// Links that cross the selection become macro.in / macro.out nodes and macro ports.

#include "simcore/scene/BrainGraph.h"

#include <optional>
#include <string>
#include <vector>

namespace throng::editor {

struct MacroCollapse {
    sim::BrainGraph outer;  // the edited graph, with one macro node in place of the selection
    sim::BrainGraph inner;  // the new brain, named `name`
    sim::NodeId macroNode = 0;
};

std::optional<MacroCollapse> collapseToMacro(const sim::BrainGraph& graph, const std::vector<sim::NodeId>& nodes,
                                             const std::string& name, std::string* problem);
std::optional<sim::BrainGraph> expandMacro(const sim::BrainGraph& graph, sim::NodeId macroNode,
                                           const std::vector<sim::BrainGraph>& library, std::string* problem);

}  // namespace throng::editor
