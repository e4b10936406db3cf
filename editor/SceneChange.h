#pragma once
// What one edit of the scene changed: which items, which of their fields, and whether a
// World built from the scene reads any of it. Plain data the document sends with each
// edit (SceneDocument::sceneChanged); it never holds or reads a scene.

#include "editor/SceneItem.h"

#include <QString>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace throng::editor {

// The parts of an item an edit may change, as bits of SceneChange::fields.
enum class SceneField : std::uint32_t {
    Items = 1u << 0,        // items added or removed (the indices after them may shift)
    Position = 1u << 1,     // where an item stands: its points, centre, corners or start
    Heading = 1u << 2,
    Shape = 1u << 3,        // sizes, radii, widths, shape kinds, closed, planned, loop
    Type = 1u << 4,         // the agent type of an agent, group, hero or vehicle
    Look = 1u << 5,         // look, tint and height scale; a type's looks, tints, height range, character
    Name = 1u << 6,
    Group = 1u << 7,        // a placed agent's group (Agent::group: a set the user names)
    Route = 1u << 8,        // goal, path, leader, lane, stop lines
    Brain = 1u << 9,        // which brain runs, or a brain's nodes, links and parameters
    BrainLayout = 1u << 10, // where a brain's nodes sit on the canvas, and their labels
    Parameters = 1u << 11,  // the other numbers and switches: a type's motion, a group's count, phases, exits
    Settings = 1u << 12,    // fps, duration, seed, bounds, navigation cell
};
inline constexpr int kSceneFieldCount = 13;

constexpr std::uint32_t fieldBit(SceneField field)
{
    return std::uint32_t(field);
}

// Whether a World built from a scene reads `field` of items of `kind`. Not read: a
// placed agent's look, tint, height scale and group (export only), a type's looks,
// tints, height range and character (export only), a brain's layout, and the names of
// walls, obstacles, heroes and paths (display only: what refers to a path by name is an
// item of its own), and anything of a measurement (the analysis reads it). Everything else
// is read.
bool simulationReads(ItemKind kind, SceneField field);

struct SceneChange {
    // An index that stands for every item of its kind: a list-wide edit such as a delete,
    // which shifts the indices after it.
    static constexpr std::size_t kAllOfKind = std::numeric_limits<std::size_t>::max();

    std::vector<SceneItem> items;  // ascending by kind, then index, without repeats
    std::uint32_t fields = 0;      // SceneField bits
    bool simulationReads = false;

    // `field` of the items `indices` of `kind`; simulationReads as the free function says.
    static SceneChange of(ItemKind kind, std::vector<std::size_t> indices, SceneField field);
    static SceneChange of(SceneItem item, SceneField field);
    // `field` of every item of `kind`.
    static SceneChange ofAll(ItemKind kind, SceneField field);

    // The union: the items and fields of both, read when either is read.
    SceneChange& operator|=(const SceneChange& other);
    friend SceneChange operator|(SceneChange a, const SceneChange& b) { return a |= b; }

    bool empty() const { return items.empty(); }
    bool has(SceneField field) const { return (fields & fieldBit(field)) != 0; }
    // Whether any of the fields of `mask` (SceneField bits) changed.
    bool hasAny(std::uint32_t mask) const { return (fields & mask) != 0; }
    // Whether an item of `kind` changed (one of them or all).
    bool touches(ItemKind kind) const;
    // Whether `item` changed, by its index or as one of all of its kind.
    bool touches(SceneItem item) const;

    bool operator==(const SceneChange&) const = default;
};

// "Agent 3, all Walls: look, group; read by the simulation: no" (for messages and tests).
QString describe(const SceneChange& change);

}  // namespace throng::editor
