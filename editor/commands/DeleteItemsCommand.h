#pragma once
// Deletes the selected items: placed agents, agent types, groups, paths, walls,
// obstacles, goals, action points, sources, traffic lights, lanes, crosswalks, vehicles,
// flow strokes, heroes and brains. Records each removed item with its index (and every
// reference it changed), so undo puts the scene back bit for bit. An item others still refer to by name is not deleted: refusal() says who uses
// it. Never touches widgets or the selection.

#include "editor/SceneDocument.h"
#include "editor/SceneItem.h"

#include <QString>
#include <QUndoCommand>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace throng::editor {

class DeleteItemsCommand : public QUndoCommand {
public:
    // True for the kinds this command deletes.
    static bool deletable(ItemKind kind);
    // The deletable items of `items`; the others are left alone.
    DeleteItemsCommand(SceneDocument& document, const Selection& items);

    // Nothing to delete (no deletable item was given).
    bool isEmpty() const { return m_count == 0; }
    // Why this delete must not be pushed ("Path "a" is still used by group g"), or empty.
    const QString& refusal() const { return m_refusal; }

    void redo() override;
    void undo() override;

private:
    template <class Item>
    using Removed = std::vector<std::pair<std::size_t, Item>>;  // ascending by index
    // Calls f(list, removed) for every list this command deletes from.
    template <class Scene, class F>
    void forEachList(Scene& scene, F f);
    void checkReferences(const sim::Scene& scene, const Selection& items);
    // What redo and undo change: the lists deleted from, and the followers of a deleted leader.
    SceneChange change();

    SceneDocument& m_document;
    std::size_t m_count = 0;
    QString m_refusal;
    Removed<sim::Agent> m_agents;
    Removed<sim::AgentType> m_types;
    Removed<sim::SpawnGroup> m_groups;
    Removed<sim::Path> m_paths;
    Removed<sim::Wall> m_walls;
    Removed<sim::Obstacle> m_obstacles;
    Removed<sim::Goal> m_goals;
    Removed<sim::TrafficLight> m_lights;
    Removed<sim::Lane> m_lanes;
    Removed<sim::FlowStroke> m_strokes;
    Removed<sim::Hero> m_heroes;
    Removed<sim::Crosswalk> m_crosswalks;
    Removed<sim::ActionPoint> m_actionPoints;
    Removed<sim::Source> m_sources;
    Removed<sim::Measurement> m_measurements;
    Removed<sim::LayoutOp> m_layoutOps;
    Removed<sim::Vehicle> m_vehicles;
    Removed<sim::BrainGraph> m_brains;
    // Leaders cleared because the agent, vehicle or hero they name is deleted, with the old id.
    std::vector<std::pair<std::function<std::uint32_t&(sim::Scene&)>, std::uint32_t>> m_clearedLeaders;
    std::vector<SceneItem> m_leaderUsers;  // who those leaders belong to, as indexed before the delete
};

}  // namespace throng::editor
