#pragma once
// The scene's list of brains as the brain editor changes it: new, rename (agent types,
// agents with a brain of their own and macro nodes follow the new name), duplicate,
// delete (those agents fall back to their type's brain), import and export of a
// .brain.yaml, assigning a brain to an agent type. Pure functions from the scene to the
// state an EditBrainsCommand applies; file access only in import/export.

#include "editor/brain/BrainCommands.h"

#include <QString>

#include <optional>

namespace throng::editor::brainlib {

using State = EditBrainsCommand::State;

State current(const sim::Scene& scene);
// `base`, or `base 2`, `base 3`... whichever no brain of the scene has.
std::string uniqueName(const sim::Scene& scene, const std::string& base);

State added(const sim::Scene& scene, const std::string& base);
std::optional<State> renamed(const sim::Scene& scene, std::size_t brain, const std::string& name, QString* problem);
State duplicated(const sim::Scene& scene, std::size_t brain);
State removed(const sim::Scene& scene, std::size_t brain);
State assigned(const sim::Scene& scene, std::size_t agentType, const std::string& brainName);
// Reads a .brain.yaml (errors as file:line:col in `problem`); the brain is kept in the
// scene, named after the file, laid out when it has no positions.
std::optional<State> imported(const sim::Scene& scene, const QString& path, QString* problem);
// Writes brain `brain` to `path` as a .brain.yaml; false with `problem` on failure.
bool exportBrain(const sim::Scene& scene, std::size_t brain, const QString& path, QString* problem);

}  // namespace throng::editor::brainlib
