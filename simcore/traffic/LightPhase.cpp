#include "simcore/traffic/LightPhase.h"

#include <cmath>

namespace throng::sim {

LightPhase lightPhaseAt(const TrafficLight& light, double timeS)
{
    const double cycle = double(light.greenS) + double(light.yellowS) + double(light.redS);
    if (!(cycle > 0.0))
        return LightPhase::Red;
    double t = std::fmod(timeS + double(light.offsetS), cycle);
    if (t < 0.0)
        t += cycle;
    if (t < double(light.greenS))
        return LightPhase::Green;
    if (t < double(light.greenS) + double(light.yellowS))
        return LightPhase::Yellow;
    return LightPhase::Red;
}

}  // namespace throng::sim
