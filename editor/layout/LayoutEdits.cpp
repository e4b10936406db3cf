#include "editor/layout/LayoutEdits.h"

#include "editor/commands/ChangeValuesCommand.h"
#include "simcore/layout/LayoutApply.h"

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {

template <class T>
void addOnce(std::vector<T>& list, const T& value)
{
    if (std::find(list.begin(), list.end(), value) == list.end())
        list.push_back(value);
}

}  // namespace

sim::AgentSelector selectorFor(const sim::Scene& scene, const Selection& selection,
                               std::optional<std::uint32_t> clicked)
{
    sim::AgentSelector agents;
    if (clicked && *clicked != 0) {
        agents.ids.push_back(*clicked);
        return agents;
    }
    for (const SceneItem& item : selection) {
        const std::size_t i = item.index;
        if (i >= itemCount(scene, item.kind))
            continue;
        switch (item.kind) {
        case ItemKind::Agent: addOnce(agents.ids, scene.agents[i].id); break;
        case ItemKind::Hero: addOnce(agents.ids, scene.heroes[i].id); break;
        case ItemKind::Vehicle: addOnce(agents.ids, scene.vehicles[i].id); break;
        case ItemKind::Group: addOnce(agents.groups, scene.groups[i].name); break;
        case ItemKind::AgentType: addOnce(agents.types, scene.agentTypes[i].name); break;
        default: break;
        }
    }
    std::sort(agents.ids.begin(), agents.ids.end());
    return agents;
}

sim::LayoutOp newLayoutOp(sim::LayoutKind kind, sim::AgentSelector agents, const sim::LayoutLayer& layer,
                          std::size_t frame, double fps, glm::vec2 centre)
{
    sim::LayoutOp op;
    op.kind = kind;
    op.agents = std::move(agents);
    switch (kind) {
    case sim::LayoutKind::TimeOffset: op.frames = std::max(1, int(std::lround(fps))); break;
    case sim::LayoutKind::Mirror:
        op.axis[0] = {centre.x, centre.y - 1.0f};
        op.axis[1] = {centre.x, centre.y + 1.0f};
        break;
    case sim::LayoutKind::Delete: op.firstFrame = frame; break;
    case sim::LayoutKind::Duplicate: op.offset = {1.0f, 0.0f}; break;
    case sim::LayoutKind::Swap: op.look = 0; break;
    case sim::LayoutKind::ReplaceClip: op.clip = sim::Clip::Wave; op.firstFrame = frame; break;
    default: break;
    }
    const QString base = layoutKindTitle(kind);
    for (std::size_t n = 1;; ++n) {
        const std::string name = QStringLiteral("%1 %2").arg(base).arg(n).toStdString();
        if (std::none_of(layer.ops.begin(), layer.ops.end(), [&](const sim::LayoutOp& o) { return o.name == name; })) {
            op.name = name;
            break;
        }
    }
    return op;
}

glm::vec2 shownCentre(const sim::FrameCache& frames, const sim::Scene& scene, const sim::AgentSelector& agents,
                      std::size_t frame)
{
    const glm::vec2 fallback = 0.5f * (scene.settings.boundsMin + scene.settings.boundsMax);
    if (frame >= frames.frameCount())
        return fallback;
    sim::LayoutLayer probe;
    probe.ops.push_back({});
    probe.ops.back().agents = agents;
    const sim::LayoutSelection selected = sim::selectLayoutAgents(scene, probe, frames);
    glm::dvec2 sum(0.0);
    std::size_t n = 0;
    for (const std::size_t i : selected.agents.front()) {
        const sim::AgentFrame& a = frames.at(frame, i);
        if (!a.present || a.out)
            continue;
        sum += glm::dvec2(a.position.x, a.position.z);
        ++n;
    }
    if (n == 0)
        return fallback;
    const glm::dvec2 centre = sum / double(n) + glm::dvec2(frames.origin().x, frames.origin().z);
    return glm::vec2(centre);
}

QUndoCommand* changeLayoutCommand(SceneDocument& document, sim::LayoutLayer after, const QString& text,
                                  const QString& mergeKey)
{
    using Command = ChangeValuesCommand<sim::LayoutLayer>;
    // Operations may come and go and shift: every one of them is named as changed.
    const SceneChange change =
        SceneChange::ofAll(ItemKind::LayoutOp, SceneField::Items) |
        SceneChange::ofAll(ItemKind::LayoutOp, SceneField::Parameters);
    return new Command(document, mergeKey, {[](sim::Scene& s) -> sim::LayoutLayer& { return s.layout; }},
                       {std::move(after)}, text, change);
}

}  // namespace throng::editor
