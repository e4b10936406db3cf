#pragma once
// The layout layer's edits as the editor makes them: which agents a new operation takes
// from what the user selected, what a new operation of each kind starts as, and the one
// undoable command every change of the layer goes through (add, toggle, reorder, remove,
// a gizmo drag). Never writes the scene itself.

#include "editor/SceneDocument.h"
#include "editor/SceneItem.h"
#include "simcore/layout/LayoutLayer.h"
#include "simcore/world/FrameCache.h"

#include <QString>

#include <cstddef>
#include <optional>

class QUndoCommand;

namespace throng::editor {

// The agents of `selection`: placed agents, heroes and vehicles by id, spawn groups by
// name, agent types by name. With `clicked` (an agent id, the viewport's focused agent),
// that agent alone. Empty when none of it names an agent.
sim::AgentSelector selectorFor(const sim::Scene& scene, const Selection& selection,
                               std::optional<std::uint32_t> clicked = std::nullopt);

// A new operation of `kind` on `agents`, as the Add menu makes it: a translate, rotate or
// expand that changes nothing yet (a gizmo or the properties give it its amount), a time
// offset of one second, a mirror across the line x = `centre`.x, a delete from `frame` on
// (entirely when `frame` is 0), copies a metre east, the first look, a wave from `frame`
// on. Named "<kind> N", unique in `layer`.
sim::LayoutOp newLayoutOp(sim::LayoutKind kind, sim::AgentSelector agents, const sim::LayoutLayer& layer,
                          std::size_t frame, double fps, glm::vec2 centre);

// Where the agents `agents` names stand on frame `frame` of `frames` (a recording of
// `scene`, maybe laid out): their centre, in the scene's (x, z). With none of them in the
// shot there, the centre of the scene's bounds.
glm::vec2 shownCentre(const sim::FrameCache& frames, const sim::Scene& scene, const sim::AgentSelector& agents,
                      std::size_t frame);

// The command that makes the scene's layer `after`, named `text` ("Add layout operation").
// Commands with the same non-empty `mergeKey` in a row merge into one step (a drag).
QUndoCommand* changeLayoutCommand(SceneDocument& document, sim::LayoutLayer after, const QString& text,
                                  const QString& mergeKey = {});

}  // namespace throng::editor
