#pragma once
// Compiles a BrainGraph into a BrainProgram: checks node types, parameters, sensors,
// links, port kinds and cycles, expands macros, orders the nodes once and folds
// constants. Reports every problem with the node id (and file:line:col); never throws.

#include "simcore/brain/BrainProgram.h"
#include "simcore/scene/BrainGraph.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace throng::sim {

struct BrainError {
    NodeId node = 0;    // the node at fault (0 = the graph as a whole)
    int link = -1;      // index into BrainGraph::links, or -1
    std::string file;   // set when the graph came from a file
    int line = 0;       // 1-based, 0 = unknown
    int column = 0;
    std::string message;  // starts with "node <id> (<type>): " or "link <i>: "

    // "file:line:col: error: message", or just the message when there is no file.
    std::string format() const;
};

struct BrainCompileResult {
    std::shared_ptr<const BrainProgram> program;  // null when there are errors
    std::vector<BrainError> errors;
    bool ok() const { return program != nullptr; }
};

// Limits a valid brain stays within; each is an error at the node that passes it.
constexpr std::size_t kMaxMacroDepth = 64;         // macros inside macros inside ...
constexpr std::size_t kMaxExpandedNodes = 200'000;  // nodes once every macro is expanded inline
constexpr std::uint32_t kMaxVariadicInputs = 4096;  // inputs of a repeating node (rule.and, math.add, ...)

// `library` holds the brains a `macro` node may name (usually Scene::brains); the graph
// itself may be among them.
BrainCompileResult compileBrain(const BrainGraph& graph, const std::vector<BrainGraph>& library = {});

}  // namespace throng::sim
