#pragma once
// Path following (Reynolds 1999): keep the agent's predicted position inside a path of some
// radius around a polyline spine, moving along it in one direction. Pure; returns exactly
// zero while the agent is on the path and progressing, and never allocates.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/SteeringGeometry.h"

#include <glm/vec3.hpp>

#include <array>
#include <string_view>

namespace throng::sim {

struct PathFollowParams {
    float predictionS = 1.0f;       // s, >= 0: the future position is position + velocity * this
    float aheadM = 1.5f;            // m, >= 0: distance along the spine, past the agent's projection, to seek
    bool reverse = false;           // true: travel against the order of the points
    float cruiseFraction = 0.9f;    // [0, 1]: moving along the path slower than this share of
                                    // maxSpeed counts as not progressing, so the follower speeds up
    float responseTimeS = 0.25f;    // s, > 0: time to reach the desired velocity
};

// Steers only when the predicted position lies outside the radius, when the agent is not moving
// along the path in its direction at cruiseFraction * maxSpeed (for instance standing still), or
// when the prediction has reached the end of an open path. Then it seeks the spine point aheadM
// beyond the agent's own projection; when that point is the end of an open path it arrives there
// (slowing distance max(aheadM, maxSpeed * 1 s)) and stops.
glm::vec3 followPath(const SteeringAgent& agent, const SteeringPath& path, const PathFollowParams& params = {});

// The same for a follower that remembers how far along the spine it has come
// (progressM, m from the first point, as advancePathProgress keeps it): its projections
// are sought only from there on, within pathReachM, so on a path that turns back on
// itself (a hairpin) the nearest point of a leg already walked never draws it back.
glm::vec3 followPath(const SteeringAgent& agent, const SteeringPath& path, const PathFollowParams& params,
                     float progressM);

// How far along the spine a follower's projection may move in one step (m): its step at
// maxSpeed, the width of the path (cutting the inside of a corner jumps the projection
// across it) and the seek distance ahead.
float pathReachM(const SteeringPath& path, const PathFollowParams& params, float maxSpeed, float dtS);

// The follower's progress after it moved to p: the distance along of its nearest spine
// point within reachM past progressM (before it when params.reverse), never back. On a
// closed path the distance wraps round. Start from startProgressM.
float advancePathProgress(const SteeringPath& path, glm::vec3 p, float progressM, float reachM, bool reverse);
// Where a follower at p starts: the distance along of its nearest spine point.
float startPathProgress(const SteeringPath& path, glm::vec3 p);

// The nearest point on the spine and its distance along the spine from the first point (m).
struct PathProjection {
    glm::vec3 point{0.0f};
    float distanceAlongM = 0.0f;
    glm::vec3 tangent{0.0f};  // unit direction of the spine there, in point order; zero for a point path
};
PathProjection projectOntoPath(const SteeringPath& path, glm::vec3 p);
// The nearest point among the spine points whose distance along lies in [fromM, toM]
// (clamped to the spine on an open path; on a closed one the window may wrap past the
// first point, and the distance returned lies in [0, length)).
PathProjection projectOntoPathWithin(const SteeringPath& path, glm::vec3 p, float fromM, float toM);

// The spine point at a distance along it: wrapped on closed paths, clamped on open ones.
glm::vec3 pointAlongPath(const SteeringPath& path, float distanceAlongM);

// Total spine length in metres, including the closing segment of a closed path.
float pathLength(const SteeringPath& path);

// Path following's entry in the behaviour list (BehaviourTable.h): asks of an agent on a
// path. Paths lie on the ground; a flier follows one in the horizontal at its own height.
struct PathFollowingBehaviour {
    static constexpr std::string_view kName = "path_following";
    struct Slot {
        PathFollowParams path;
    };
    static constexpr auto kParams = &Slot::path;
    using P = PathFollowParams;
    static constexpr std::array kKeys{
        ParamKey<P>{.key = "prediction", .meaning = "s, >= 0: look-ahead of the future position",
                    .number = &P::predictionS},
        ParamKey<P>{.key = "ahead", .meaning = "m, >= 0: how far along the spine to aim", .number = &P::aheadM},
        ParamKey<P>{.key = "response_time", .meaning = "s, > 0", .lo = 1e-3f, .number = &P::responseTimeS},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const PathFollowParams& p, Emit&& emit)
    {
        if (!step.onPath())
            return;
        SteeringAgent flat = step.self;
        if (step.flying)
            flat.position.y = flat.velocity.y = 0.0f;
        emit(followPath(flat, step.path(), p, step.pathProgressM()));
    }
};

}  // namespace throng::sim
