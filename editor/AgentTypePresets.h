#pragma once
// The agent types a user starts from when creating one in the editor (pedestrian, runner,
// car, bird, rider): plain sim::AgentType values with names not yet used in the scene.
// Plain functions; never edits a scene.

#include "simcore/scene/Scene.h"

#include <QString>

#include <array>

namespace throng::editor {

enum class TypePreset { Pedestrian, Runner, Car, Bird, Rider };
inline constexpr std::array<TypePreset, 5> kTypePresets{TypePreset::Pedestrian, TypePreset::Runner, TypePreset::Car,
                                                        TypePreset::Bird, TypePreset::Rider};

// The menu text ("Pedestrian") and a one-line description for its tooltip.
QString presetLabel(TypePreset preset);
QString presetDescription(TypePreset preset);
// The preset's type, named after it ("runner", or "runner_2" when the scene has one).
sim::AgentType makeTypePreset(TypePreset preset, const sim::Scene& scene);
// A copy of `type` under a name the scene does not use yet ("pedestrian_copy").
sim::AgentType duplicateType(const sim::AgentType& type, const sim::Scene& scene);
// What File > New starts from: an empty set and one pedestrian type, so a brush or the
// group tool has something to place.
sim::Scene newSceneTemplate();

}  // namespace throng::editor
