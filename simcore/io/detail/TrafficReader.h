#pragma once
// Reads the traffic: its settings (`traffic`), lanes, crosswalks, traffic lights and
// their signals, and vehicles on their lanes.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/io/detail/SceneNames.h"
#include "simcore/io/detail/YamlFields.h"
#include "simcore/scene/Scene.h"

#include <string>

namespace throng::sim::detail {

class TrafficReader {
public:
    TrafficReader(YamlFields& fields, SceneNames& names) : m_f(fields), m_names(names) {}

    void readTraffic(const YAML::Node& node, TrafficSettings& t);
    void readLanes(const YAML::Node& node, Scene& scene);
    void readCrosswalks(const YAML::Node& node, Scene& scene);
    void readTrafficLights(const YAML::Node& node, Scene& scene);
    void readVehicles(const YAML::Node& node, Scene& scene);

private:
    YamlFields& m_f;
    SceneNames& m_names;
};

// `car_following` of map `item` into `out` when present; `inherit` allows "inherit".
void readCarFollowing(YamlFields& f, const YAML::Node& item, const std::string& key, CarFollowing& out, bool inherit);

}  // namespace throng::sim::detail
