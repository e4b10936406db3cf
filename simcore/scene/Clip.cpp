#include "simcore/scene/Clip.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::sim {

namespace {

struct ClipSpec {
    const char* name;
    float cycleS;
};

// In the enum's order.
constexpr std::array<ClipSpec, kClipCount> kClips{{
    {"idle", 0.0f},
    {"walk", 0.0f},
    {"run", 0.0f},
    {"wait", 4.0f},         // weight from foot to foot and back
    {"look_around", 4.0f},  // left, right and back
    {"wave", 1.0f},         // the hand to one side and back
    {"talk", 2.0f},         // a gesture of both hands
    {"phone", 4.0f},        // a nod while listening
    {"cheer", 0.8f},        // one pump of the arms
    {"sit", 6.0f},          // a breath and a glance while seated
    {"shift_weight", 8.0f}, // the weight onto one leg, held, then onto the other
    {"point", 2.0f},        // an arm pointing ahead, the hand bobbing once
    {"fall", 1.2f},         // knees give, onto the ground and back: played once, then lying
    {"get_up", 2.0f},       // from lying back onto the feet: played once, then standing
}};

}  // namespace

const char* toString(Clip clip)
{
    const auto c = std::size_t(clip);
    return c < kClips.size() ? kClips[c].name : "idle";
}

std::optional<Clip> clipFromName(std::string_view name)
{
    for (std::size_t c = 0; c < kClips.size(); ++c)
        if (name == kClips[c].name)
            return Clip(c);
    return std::nullopt;
}

float clipCycleS(Clip clip)
{
    const auto c = std::size_t(clip);
    return c < kClips.size() ? kClips[c].cycleS : 0.0f;
}

float oneShotProgress(Clip clip, double sinceS)
{
    const float cycle = clipCycleS(clip);
    if (!(cycle > 0.0f) || !(sinceS > 0.0))
        return 0.0f;
    return float(std::min(1.0, sinceS / double(cycle)));
}

float actionPhase(Clip clip, double timeS, std::uint32_t agentId)
{
    const float cycle = clipCycleS(clip);
    if (!(cycle > 0.0f))
        return 0.0f;
    // A fixed scramble of the id (splitmix64's finaliser): its top bits are the offset.
    std::uint64_t z = std::uint64_t(agentId) + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    const double offset = double(z >> 11) * 0x1.0p-53;
    const double cycles = timeS / double(cycle) + offset;
    const float phase = float(cycles - std::floor(cycles));
    return phase < 1.0f ? phase : 0.0f;
}

}  // namespace throng::sim
