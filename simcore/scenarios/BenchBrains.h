#pragma once
// Brains for the benchmarks, built in code so the CLI's scenarios, bench/ and the tests
// run the same programs.

#include "simcore/scene/Scene.h"

namespace throng::sim {

// A 40-node pedestrian brain: fuzzy goal, light, stop-line and crowding sets, per-neighbour
// threat logic with a filter, rules, defuzzified turn, smoothed speed with noise, weight
// outputs for separation and arrival, an action, and memory. Named "bench40".
BrainGraph benchPedestrianBrain();
// Turns toward the loudest agent heard on "chat" and slows when many are heard. Named
// "listen".
BrainGraph benchListenerBrain();

}  // namespace throng::sim
