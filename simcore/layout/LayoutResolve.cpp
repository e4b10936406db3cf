#include "simcore/layout/LayoutResolve.h"

#include "simcore/layout/LayoutGrid.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace throng::sim {

namespace {

constexpr int kRounds = 8;            // relaxation rounds (each visits every pair once, in order)
constexpr float kSettledM = 1e-4f;    // a round that pushes no body further than this ends them

bool standsInShot(const AgentFrame& a) { return a.present && !a.out; }

glm::vec2 xzOf(const AgentFrame& a) { return {a.position.x, a.position.z}; }

// A fixed direction per agent, for two bodies on one spot: the golden angle apart.
glm::vec2 fallbackDirection(std::size_t i)
{
    const float angle = 2.39996323f * float(i + 1);
    return {std::cos(angle), std::sin(angle)};
}

}  // namespace

void resolveFrame(const ResolveFrame& frame, float toleranceM)
{
    std::span<AgentFrame> laid = frame.laid;
    const std::size_t n = laid.size(), recordedCount = frame.recorded.size();
    std::vector<std::uint32_t> moving;
    for (std::size_t i = 0; i < n; ++i)
        if (frame.movable[i] && standsInShot(laid[i]))
            moving.push_back(std::uint32_t(i));
    if (moving.empty())
        return;
    float largest = 0.0f;
    for (const float r : frame.radius)
        largest = std::max(largest, r);
    const float cell = std::max(2.0f * largest, 0.1f);
    // The bodies that stay, near enough to the moving ones to touch them (a move of up to
    // a body's width each round included): found once per frame.
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const std::uint32_t i : moving) {
        lo = glm::min(lo, xzOf(laid[i]));
        hi = glm::max(hi, xzOf(laid[i]));
    }
    const float reach = float(kRounds + 1) * cell;
    lo -= glm::vec2(reach);
    hi += glm::vec2(reach);
    std::vector<std::uint32_t> staying;
    staying.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (frame.movable[i] || !standsInShot(laid[i]))
            continue;
        const glm::vec2 p = xzOf(laid[i]);
        if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y)
            staying.push_back(std::uint32_t(i));
    }
    layout::CellGrid still = layout::CellGrid::fitting(lo, hi, cell, n);
    layout::CellGrid moved = still;
    still.build(laid, staying);
    // Whether the recording had the pair overlapping: then it is the simulation's, not ours.
    auto recordedOverlap = [&](std::size_t i, std::size_t j) {
        if (i >= recordedCount || j >= recordedCount || !standsInShot(frame.recorded[i]) ||
            !standsInShot(frame.recorded[j]))
            return false;
        return glm::length(xzOf(frame.recorded[i]) - xzOf(frame.recorded[j])) <
               frame.radius[i] + frame.radius[j] - toleranceM;
    };
    auto move = [&](std::size_t i, glm::vec2 by) {
        laid[i].position.x += by.x;
        laid[i].position.z += by.y;
    };
    for (int round = 0; round < kRounds; ++round) {
        moved.build(laid, moving);
        float largestPush = 0.0f;
        for (const std::uint32_t i : moving) {
            auto separate = [&](std::size_t j) {
                if (j == i || (frame.movable[j] && j < i))  // a moving pair once, from its lower index
                    return;
                const float need = frame.radius[i] + frame.radius[j] - 0.5f * toleranceM;
                const glm::vec2 d = xzOf(laid[i]) - xzOf(laid[j]);
                const float gap = glm::length(d);
                if (gap >= need || recordedOverlap(i, j))
                    return;
                const glm::vec2 away = gap > 1e-6f ? d / gap : fallbackDirection(i);
                const float push = need - gap;
                largestPush = std::max(largestPush, push);
                if (frame.movable[j]) {
                    move(i, 0.5f * push * away);
                    move(j, -0.5f * push * away);
                } else {
                    move(i, push * away);
                }
            };
            still.forNear(xzOf(laid[i]), separate);
            moved.forNear(xzOf(laid[i]), separate);
        }
        if (largestPush < kSettledM)
            break;
    }
    // Off the walls: a moving body a radius clear of every segment, on the side it stands.
    for (const std::uint32_t i : moving)
        for (const auto& [a, b] : frame.walls) {
            const glm::vec2 p = xzOf(laid[i]), ab = b - a;
            const float len2 = glm::dot(ab, ab);
            const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
            const glm::vec2 d = p - (a + t * ab);
            const float gap = glm::length(d);
            if (gap >= frame.radius[i] || gap < 1e-6f)
                continue;
            move(i, d / gap * (frame.radius[i] - gap));
        }
}

}  // namespace throng::sim
