#pragma once
// The classic steering annotations (Reynolds 1999, OpenSteer) of the watched agents, as
// ground shapes: the view cone, lines to the neighbours sensed, the feelers, each
// behaviour's weighted force and their blend as arrows, the velocity, the planned way, the
// field the agent follows and where it steers. Reads what simcore published (sim::AgentDebug); no GL.

#include "editor/viewport/AgentColours.h"
#include "editor/viewport/ShapeMesh.h"
#include "simcore/world/DebugSink.h"

#include <glm/vec4.hpp>

#include <span>
#include <string>
#include <vector>

namespace throng::editor {

class SteeringOverlay {
public:
    // Metres of arrow per newton of force, and per m/s of velocity (one second ahead).
    static constexpr float kMetresPerNewton = 0.5f;
    static constexpr float kMetresPerMps = 1.0f;

    static void add(std::span<const sim::AgentDebug> agents, ShapeMesh& mesh);
    // The colour a behaviour's force arrow is drawn in.
    static glm::vec4 behaviourColour(sim::Behaviour behaviour);
    // One agent's figures for the HUD: its speed, neighbours and steering force as the
    // title, each behaviour's weighted force in newtons as an entry in its arrow's colour,
    // strongest first.
    static ColourLegend describe(const sim::AgentDebug& agent);
};

}  // namespace throng::editor
