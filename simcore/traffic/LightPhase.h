#pragma once
// Which lamp a traffic light shows at a time, from its phase durations alone: the
// simulation, the stats and the viewport (for any recorded frame) all ask here.

#include "simcore/scene/Scene.h"

namespace throng::sim {

enum class LightPhase { Green, Yellow, Red };

// The cycle is green, then yellow, then red (green + yellow + red seconds long) and
// starts `light.offsetS` seconds early: the phase at t is that of (t + offset) mod cycle.
LightPhase lightPhaseAt(const TrafficLight& light, double timeS);

}  // namespace throng::sim
