#pragma once
// Scenes the brain editor tests open: a brain written without editor positions, a
// crossing with a traffic light and walkers without a brain, and a broken brain.

#include <QByteArray>

namespace throng::editor::test {

// "walk": goal distance -> trapezoid -> output speed; rule.and with two inputs; no positions.
inline const QByteArray kWalkBrainScene = R"(throng: 1
settings: {fps: 24, seed: 3, duration: 20, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types: [{name: walker, max_speed: 1.4, max_force: 3, brain: walk}]
goals: [{name: g, position: [15, 0], radius: 0.6}]
agents:
  - {id: 1, type: walker, position: [0, 0, 0], goal: g}
  - {id: 2, type: walker, position: [0, 0, 3], goal: g}
brains:
  - name: walk
    nodes:
      - {id: 1, type: input, params: {sensor: goal_distance}}
      - {id: 2, type: fuzz.trapezoid, params: {points: [0, 3, 1000, 1000]}}
      - {id: 3, type: input, params: {sensor: speed}}
      - {id: 4, type: fuzz.triangle, params: {points: [0, 0.7, 1.4]}}
      - {id: 5, type: rule.and}
      - {id: 6, type: output, params: {channel: speed, scale: 1.4}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [3, 0], to: [4, 0]}
      - {from: [2, 0], to: [5, 0]}
      - {from: [4, 0], to: [5, 1]}
      - {from: [2, 0], to: [6, 0]}
)";

// A crossing from z = -6 to z = 6; the light is red for t < 10 s, then green 10 s. The
// walkers' type has no brain yet.
inline const QByteArray kCrossingScene = R"(throng: 1
settings: {fps: 24, seed: 3, duration: 30, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types: [{name: walker, max_speed: 1.4, max_force: 3}]
goals: [{name: across, position: [0, 12], radius: 1}]
crosswalks: [{name: zebra, from: [0, -6], to: [0, 6], width: 4}]
traffic_lights:
  - {name: signal, green: 10, yellow: 2, red: 10, offset: 12, stop_lines: [{crosswalk: zebra}]}
agents:
  - {id: 1, type: walker, position: [0, 0, -14], heading: 270, goal: across}
  - {id: 2, type: walker, position: [1, 0, -16], heading: 270, goal: across}
)";

// rule.and (node 3) has only its input 0 connected: the compiler says input 1 is not.
inline const QByteArray kBrokenBrainScene = R"(throng: 1
agent_types: [{name: walker, brain: half}]
agents: [{id: 1, type: walker, position: [0, 0, 0]}]
brains:
  - name: half
    nodes:
      - {id: 1, type: input, position: [0, 0], params: {sensor: speed}}
      - {id: 2, type: fuzz.triangle, position: [260, 0], params: {points: [0, 1, 2]}}
      - {id: 3, type: rule.and, position: [520, 0]}
      - {id: 4, type: output, position: [780, 0], params: {channel: speed}}
      - {id: 5, type: input.constant, position: [260, 200], params: {value: 1}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [3, 0], to: [4, 0]}
)";

}  // namespace throng::editor::test
