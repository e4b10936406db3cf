#pragma once
// A small fixed-capacity list of steering requests (force + weight) that the combiners read.
// Lives on the stack: never allocates; a request beyond capacity is refused, not grown into.

#include "simcore/steering/UninitialisedArray.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace throng::sim {

struct SteeringRequest {
    glm::vec3 force{0.0f};  // N
    float weight = 1.0f;    // >= 0
};

class SteeringRequestList {
public:
    static constexpr std::size_t kCapacity = 16;

    // Appends in priority order (first = most urgent). False, and nothing added, when full.
    bool add(glm::vec3 force, float weight = 1.0f)
    {
        if (m_size == kCapacity)
            return false;
        m_requests[m_size++] = SteeringRequest{force, weight};
        return true;
    }
    void clear() { m_size = 0; }
    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    std::span<const SteeringRequest> requests() const { return {m_requests.data(), m_size}; }
    operator std::span<const SteeringRequest>() const { return requests(); }

private:
    // Uninitialised: requests() reads only the first m_size, each written by add().
    UninitialisedArray<SteeringRequest, kCapacity> m_requests;
    std::size_t m_size = 0;
};

}  // namespace throng::sim
