#pragma once
// A small scene for the properties-panel and delete tests: two brains, three types (one
// with listed behaviours), six walkers in a row 4 m apart heading for a goal, a group on
// a path, a spare path and goal, two lanes (one driven, with a stop line), a light and a
// hero. What refers to what is spelled out in panelScene(); trafficScene() and
// tablesScene() add crosswalks, a second car and type, obstacles, a wall and variation.

#include <QByteArray>

namespace throng::editor::test {

// Walkers 1..6 stand at x = -10, -6, -2, 2, 6, 10 on z = 0 (agent index = id - 1); walker
// 6 follows walker 1 (leader). Group "loopers" (5 walkers) follows path "loop"; path
// "lone", goal "spare" and lane "side" are used by nothing; lane "main" carries a car
// and the stop line of light "signal".
inline QByteArray panelScene()
{
    QByteArray yaml = R"(throng: 1
settings: {fps: 24, duration: 10, seed: 4, bounds: {min: [-30, -30], max: [30, 30]}}
brains:
  - name: go
    nodes:
      - {id: 1, type: input, params: {sensor: attribute, name: max_speed}}
      - {id: 2, type: output, params: {channel: speed}}
    links: [{from: [1, 0], to: [2, 0]}]
  - name: stay
    nodes:
      - {id: 1, type: input.constant, params: {value: 0}}
      - {id: 2, type: output, params: {channel: speed}}
    links: [{from: [1, 0], to: [2, 0]}]
agent_types:
  - {name: walker, max_speed: 1.4, max_force: 3, behaviours: {arrival: 1, separation: 1.5}}
  - {name: runner, max_speed: 3, max_force: 6}
  - {name: car, kind: vehicle, radius: 1.1, max_speed: 10, max_force: 5000, mass: 1200}
goals:
  - {name: east, position: [25, 0], radius: 1}
  - {name: spare, position: [-25, 15], radius: 1}
paths:
  - {name: loop, radius: 1, points: [[-20, -20], [20, -20], [20, -10]]}
  - {name: lone, radius: 1, points: [[-20, 20], [-10, 20]]}
lanes:
  - {name: main, points: [[-30, 25], [30, 25]]}
  - {name: side, points: [[-30, -27], [30, -27]]}
traffic_lights:
  - {name: signal, position: [0, 22], stop_lines: [{lane: main, at: 30}]}
vehicles:
  - {type: car, lane: main, at: 5}
groups:
  - {name: loopers, type: walker, count: 5, rect: {min: [-20, -22], max: [-15, -18]}, path: loop}
heroes:
  - name: courier
    type: runner
    keyframes:
      - {time: 0, position: [-5, 10]}
      - {time: 10, position: [15, 10]}
agents:
)";
    for (int k = 0; k < 6; ++k) {
        yaml += QByteArray("  - {id: ") + QByteArray::number(k + 1) + ", type: walker, position: [" +
                QByteArray::number(-10 + 4 * k) + ", 0, 0], goal: east";
        yaml += k == 5 ? ", leader: 1}\n" : "}\n";
    }
    return yaml;
}

// The panel scene with a second vehicle type, two crosswalks ("zebra" is a stop line of
// light "signal") and a second car (id 50) on lane "side", 10 m in at 4 m/s.
inline QByteArray trafficScene()
{
    QByteArray yaml = panelScene();
    yaml.replace("  - {name: car, kind: vehicle, radius: 1.1, max_speed: 10, max_force: 5000, mass: 1200}\n",
                 "  - {name: car, kind: vehicle, radius: 1.1, max_speed: 10, max_force: 5000, mass: 1200}\n"
                 "  - {name: bus, kind: vehicle, radius: 1.5, max_speed: 8, max_force: 9000, mass: 8000}\n");
    yaml.replace("stop_lines: [{lane: main, at: 30}]}\n",
                 "stop_lines: [{lane: main, at: 30}, {crosswalk: zebra}]}\n"
                 "crosswalks:\n"
                 "  - {name: zebra, from: [12, 20], to: [12, 29], width: 3}\n"
                 "  - {name: ladder, from: [-15, 5], to: [-15, 12], width: 2}\n");
    yaml.replace("  - {type: car, lane: main, at: 5}\n",
                 "  - {type: car, lane: main, at: 5}\n  - {id: 50, type: car, lane: side, at: 10, speed: 4}\n");
    return yaml;
}

// The panel scene with a wall, a box and a round obstacle, and looks and tints for walkers.
inline QByteArray tablesScene()
{
    QByteArray yaml = panelScene();
    yaml.replace("  - {name: walker, max_speed: 1.4, max_force: 3, behaviours: {arrival: 1, separation: 1.5}}\n",
                 "  - {name: walker, max_speed: 1.4, max_force: 3, behaviours: {arrival: 1, separation: 1.5},\n"
                 "     variation: {looks: [casual, formal], tints: [[1, 0, 0], [0, 0, 1]]}}\n");
    yaml.replace("goals:\n", "obstacles:\n"
                             "  - {name: crate, shape: box, center: [5, -10], size: [2, 1]}\n"
                             "  - {name: post, center: [8, -10], radius: 0.5}\n"
                             "walls:\n"
                             "  - {name: fence, points: [[-5, 15], [5, 15]]}\n"
                             "goals:\n");
    return yaml;
}

}  // namespace throng::editor::test
