// The built-in car (wheels are joints that roll by distance) and bird (wing joints that
// flap, or hold still to glide; a smooth body and wings).
#include "export/character/BuiltinCharacters.h"
#include "export/character/PoseMaths.h"
#include "export/character/MeshBuilder.h"
#include "export/character/SurfaceBuilder.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace throng::exporting {

namespace {

glm::quat about(float a, glm::vec3 axis) { return glm::angleAxis(a, axis); }

void addJoint(Character& c, const char* name, int parent, glm::vec3 offset)
{
    Joint j;
    j.name = name;
    j.parent = parent;
    j.restTranslation = offset;
    c.joints.push_back(j);
}

CycleClip cycle(const Character& c, const char* name, float strideM, int samples, auto&& posed)
{
    CycleClip clip;
    clip.name = name;
    clip.strideM = strideM;
    for (int k = 0; k < samples; ++k) {
        Pose p;
        p.rotations.assign(c.joints.size(), glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
        p.rootTranslation = c.joints[0].restTranslation;
        posed(p, static_cast<float>(k) / static_cast<float>(samples));
        clip.samples.push_back(p);
    }
    return clip;
}

}  // namespace

Character makeCar()
{
    constexpr float kWheelR = 0.33f;
    Character c;
    c.name = "car";
    addJoint(c, "body", -1, {0.0f, kWheelR, 0.0f});
    const glm::vec3 wheelAt[4] = {{1.35f, 0.0f, -0.78f}, {1.35f, 0.0f, 0.78f}, {-1.3f, 0.0f, -0.78f}, {-1.3f, 0.0f, 0.78f}};
    const char* names[4] = {"wheel_fl", "wheel_fr", "wheel_rl", "wheel_rr"};
    for (int w = 0; w < 4; ++w)
        addJoint(c, names[w], 0, wheelAt[w]);
    MeshBuilder mb(c.mesh);
    const float y0 = kWheelR;
    mb.box(0, {-2.1f, y0 - 0.15f, -0.88f}, {2.1f, y0 + 0.45f, 0.88f});             // chassis
    mb.box(0, {-1.2f, y0 + 0.45f, -0.8f}, {0.9f, y0 + 1.05f, 0.8f}, {0.8f, 0.9f});  // cabin
    for (int w = 0; w < 4; ++w)
        mb.prism(w + 1, wheelAt[w] + glm::vec3(0.0f, y0, 0.0f), 2, kWheelR, 0.11f, 10);
    c.mesh.inverseBindMatrices = restInverseBindMatrices(c.joints);

    // One wheel turn per 2 pi r of road; a positive turn about +Z would roll backward.
    const float stride = 2.0f * kPi * kWheelR;
    c.walk = cycle(c, "roll", stride, 16, [](Pose& p, float phase) {
        for (int w = 1; w <= 4; ++w)
            p.rotations[w] = about(-2.0f * kPi * phase, {0.0f, 0.0f, 1.0f});
    });
    c.run = c.walk;
    c.idle = c.walk;
    c.hasIdle = false;
    c.idleSpeed = 0.0f;
    c.walkSpeed = 0.0f;
    c.runStartSpeed = c.runSpeed = 1e9f;
    return c;
}

Character makeBird(Lod lod)
{
    Character c;
    c.name = "bird";
    addJoint(c, "body", -1, {0.0f, 0.0f, 0.0f});
    addJoint(c, "head", 0, {0.11f, 0.04f, 0.0f});
    addJoint(c, "tail", 0, {-0.1f, 0.0f, 0.0f});
    addJoint(c, "wing_l", 0, {0.02f, 0.03f, -0.05f});
    addJoint(c, "wingtip_l", 3, {0.0f, 0.0f, -0.15f});
    addJoint(c, "wing_r", 0, {0.02f, 0.03f, 0.05f});
    addJoint(c, "wingtip_r", 5, {0.0f, 0.0f, 0.15f});
    // Tail to beak one smooth tube (tail, body and head joints), and each wing a thin one
    // from the shoulder to the tip (wing and wingtip joints): chord along x, thin in y.
    SurfaceBuilder sb(c.mesh, lod);
    const glm::vec3 up(0.0f, 1.0f, 0.0f), ahead(1.0f, 0.0f, 0.0f);
    Tube body;
    body.sections = {{{-0.2f, 0.0f, 0.0f}, 0.003f, 0.045f, MaterialSlot::Body},
                     {{-0.13f, 0.0f, 0.0f}, 0.008f, 0.028f, MaterialSlot::Body},
                     {{-0.07f, 0.0f, 0.0f}, 0.04f, 0.042f, MaterialSlot::Body},
                     {{0.02f, 0.003f, 0.0f}, 0.05f, 0.05f, MaterialSlot::Body},
                     {{0.09f, 0.03f, 0.0f}, 0.03f, 0.028f, MaterialSlot::Body},
                     {{0.12f, 0.045f, 0.0f}, 0.034f, 0.03f, MaterialSlot::Body},
                     {{0.155f, 0.045f, 0.0f}, 0.016f, 0.014f, MaterialSlot::Body},
                     {{0.19f, 0.042f, 0.0f}, 0.004f, 0.004f, MaterialSlot::Body}};
    body.forward = up;
    body.bones = {{2, 0.0f}, {0, 1.6f}, {1, 4.3f}};
    body.blendM = 0.02f;
    body.startCapM = 0.0f;
    body.endCapM = 0.004f;
    sb.tube(body);
    for (int side = 0; side < 2; ++side) {
        const float s = side == 0 ? -1.0f : 1.0f;
        const int wing = side == 0 ? 3 : 5;
        Tube t;
        t.sections = {{{0.02f, 0.03f, s * 0.03f}, 0.06f, 0.014f, MaterialSlot::Body},
                      {{0.01f, 0.032f, s * 0.12f}, 0.06f, 0.01f, MaterialSlot::Body},
                      {{-0.005f, 0.032f, s * 0.24f}, 0.045f, 0.006f, MaterialSlot::Body},
                      {{-0.015f, 0.03f, s * 0.34f}, 0.02f, 0.004f, MaterialSlot::Body}};
        t.forward = ahead;
        t.bones = {{wing, 0.0f}, {wing + 1, 1.67f}};
        t.blendM = 0.03f;
        t.startCapM = 0.02f;
        t.endCapM = 0.02f;
        sb.tube(t);
    }
    sb.finish();
    c.mesh.inverseBindMatrices = restInverseBindMatrices(c.joints);

    // Positive turns about +X lift the left wing (along -Z) and lower the right one.
    const glm::vec3 x(1.0f, 0.0f, 0.0f), z(0.0f, 0.0f, 1.0f);
    const float stride = 1.2f;  // m per wing beat
    c.walk = cycle(c, "flap", stride, 24, [&](Pose& p, float phase) {
        const float a = 0.75f * std::sin(2.0f * kPi * phase), tip = 0.4f * std::sin(2.0f * kPi * phase - 0.8f);
        p.rotations[3] = about(a, x);
        p.rotations[4] = about(tip, x);
        p.rotations[5] = about(-a, x);
        p.rotations[6] = about(-tip, x);
        p.rotations[1] = about(0.08f * std::sin(2.0f * kPi * phase + 1.0f), z);
        p.rootTranslation.y = -0.02f * std::sin(2.0f * kPi * phase);
    });
    c.run = cycle(c, "glide", stride, 1, [&](Pose& p, float) {
        p.rotations[3] = about(0.1f, x);
        p.rotations[4] = about(0.05f, x);
        p.rotations[5] = about(-0.1f, x);
        p.rotations[6] = about(-0.05f, x);
    });
    c.idle = c.run;
    c.idle.name = "glide";
    c.hasIdle = false;
    c.idleSpeed = 0.0f;
    c.walkSpeed = 0.0f;
    c.runStartSpeed = 4.5f;
    c.runSpeed = 6.5f;
    return c;
}

}  // namespace throng::exporting
