#pragma once
// Reads the set's places and geometry: goals, paths, walls, obstacles, terrain, flow
// strokes, sound sources, action points and measurements, each name claimed as it is read.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/io/detail/SceneNames.h"
#include "simcore/io/detail/YamlFields.h"
#include "simcore/scene/Scene.h"

#include <string>

namespace throng::sim::detail {

class SetReader {
public:
    SetReader(YamlFields& fields, SceneNames& names) : m_f(fields), m_names(names) {}

    void readGoals(const YAML::Node& node, Scene& scene);
    void readPaths(const YAML::Node& node, Scene& scene);
    void readWalls(const YAML::Node& node, Scene& scene);
    void readObstacles(const YAML::Node& node, Scene& scene);
    void readTerrain(const YAML::Node& node, Terrain& t);
    void readFlowStrokes(const YAML::Node& node, Scene& scene);
    void readSoundSources(const YAML::Node& node, Scene& scene);
    void readActionPoints(const YAML::Node& node, Scene& scene);
    void readMeasurements(const YAML::Node& node, Scene& scene);

private:
    YamlFields& m_f;
    SceneNames& m_names;
};

// What an agent type emits (`emits`: channel, strength, radius) at `key`.
void readEmission(YamlFields& f, const YAML::Node& node, const std::string& key, SoundEmission& e);

}  // namespace throng::sim::detail
