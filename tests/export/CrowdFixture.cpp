#include "CrowdFixture.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace throng::test {

namespace {

struct Walker {
    sim::AgentId id;
    std::uint16_t type;
    glm::vec3 start;     // m
    glm::vec3 velocity;  // m/s
    sim::Clip clip;
};

const Walker kWalkers[] = {
    {7, 0, {0.0f, 0.0f, 0.0f}, {1.2f, 0.0f, 0.0f}, sim::Clip::Walk},
    {42, 1, {5.0f, 0.5f, 2.0f}, {0.0f, 0.0f, -3.0f}, sim::Clip::Run},
    {1000, 0, {-3.0f, 0.25f, -1.0f}, {1.0f, 0.1f, 1.0f}, sim::Clip::Walk},
};

}  // namespace

glm::vec3 CrowdFixture::truePosition(std::size_t agent, std::size_t frame)
{
    const Walker& w = kWalkers[agent];
    return w.start + w.velocity * (static_cast<float>(frame) / kFps);
}

glm::vec3 CrowdFixture::trueGroundDirection(std::size_t agent)
{
    const glm::vec3 v = kWalkers[agent].velocity;
    return glm::normalize(glm::vec3(v.x, 0.0f, v.z));
}

CrowdFixture CrowdFixture::make()
{
    CrowdFixture fixture;
    sim::AgentType walker;
    walker.name = "walker";
    walker.radiusM = 0.3f;
    sim::AgentType runner;
    runner.name = "runner";
    runner.radiusM = 0.25f;
    runner.variation.tints = {{0.1f, 0.2f, 0.9f}};
    fixture.scene.agentTypes = {walker, runner};
    fixture.scene.settings.fps = kFps;

    std::vector<sim::AgentInfo> infos;
    for (const Walker& w : kWalkers)
        infos.push_back({w.id, w.type});
    fixture.cache.reset(infos, kFps);
    for (std::size_t f = 0; f < kFrames; ++f) {
        std::vector<sim::AgentFrame> frame;
        for (std::size_t i = 0; i < std::size(kWalkers); ++i) {
            const Walker& w = kWalkers[i];
            sim::AgentFrame a;
            a.position = truePosition(i, f);
            // Heading convention of AgentFrame: 0 faces +x, counter-clockwise seen from
            // above (y up, z south), so it faces (cos h, 0, -sin h).
            a.headingRad = std::atan2(-w.velocity.z, w.velocity.x);
            a.speed = glm::length(w.velocity);
            a.phase = std::fmod(0.05f * static_cast<float>(f), 1.0f);
            a.clip = w.clip;
            frame.push_back(a);
        }
        fixture.cache.append(frame);
    }
    return fixture;
}

CrowdFixture CrowdFixture::makeCrowd(std::size_t agents, std::size_t frames)
{
    CrowdFixture fixture;
    sim::AgentType walker;
    walker.name = "walker";
    walker.variation.looks = {"man", "woman", "tall_man", "child"};
    walker.variation.tints = {{0.8f, 0.25f, 0.2f}, {0.2f, 0.45f, 0.8f}, {0.9f, 0.75f, 0.3f}};
    walker.variation.heightScale = {0.92f, 1.08f};
    fixture.scene.agentTypes = {walker};
    fixture.scene.settings.fps = kFps;
    std::vector<sim::AgentInfo> infos;
    for (std::size_t i = 0; i < agents; ++i)
        infos.push_back({static_cast<sim::AgentId>(i + 1), 0});
    fixture.cache.reset(infos, kFps);
    const float paces[] = {0.0f, 0.8f, 1.3f, 2.4f, 3.6f};
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(agents))));
    std::vector<sim::AgentFrame> frame(agents);
    for (std::size_t f = 0; f < frames; ++f) {
        for (std::size_t i = 0; i < agents; ++i) {
            const float heading = 0.37f * static_cast<float>(i);
            const float pace = paces[i % std::size(paces)];
            const bool stops = i % 3 == 0 && f > frames / 2;
            const float t = static_cast<float>(stops ? frames / 2 : f) / kFps;
            sim::AgentFrame& a = frame[i];
            a.position = glm::vec3(2.0f * static_cast<float>(i % side), 0.0f, 2.0f * static_cast<float>(i / side)) +
                         pace * t * glm::vec3(std::cos(heading), 0.0f, -std::sin(heading));
            a.headingRad = heading;
            a.speed = stops ? 0.0f : pace;
        }
        fixture.cache.append(frame);
    }
    return fixture;
}

}  // namespace throng::test
