// Heroes as an animator checks them: the hero is exactly on every keyframe (inline or
// from a Maya-style "x y z" file at frame / fps), moves smoothly between them, faces
// where it goes, and walkers near it are moved out of its clearance without popping.
#include "TestRegistry.h"

#include "simcore/hero/HeroTrack.h"
#include "simcore/io/SceneIO.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

using namespace throng::sim;

namespace {
const Hero* findHero(const Scene& scene, const std::string& name)
{
    for (const Hero& h : scene.heroes)
        if (h.name == name)
            return &h;
    return nullptr;
}
std::vector<glm::vec3> readFrames(const std::string& path)
{
    std::ifstream in(path);
    std::vector<glm::vec3> out;
    std::string line;
    while (std::getline(in, line)) {
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#')
            continue;
        std::istringstream ss(line);
        glm::vec3 p;
        ss >> p.x >> p.y >> p.z;
        out.push_back(p);
    }
    return out;
}
}  // namespace

class TestHeroTrack : public QObject {
    Q_OBJECT
private slots:
    void passesExactlyThroughInlineKeyframes()
    {
        const LoadResult r = loadScene(THRONG_TEST_DATA_DIR "/scenes/every-key.yaml");
        QVERIFY(r.ok());
        const Hero* hero = findHero(r.scene, "lead_actor");
        QVERIFY(hero && hero->keyframes.size() == 3);
        for (HeroInterpolation mode : {HeroInterpolation::Linear, HeroInterpolation::CatmullRom}) {
            const HeroTrack track(*hero, mode);
            QCOMPARE(track.clearanceM(), 2.5f);
            for (const Keyframe& k : hero->keyframes) {
                const glm::vec3 p = track.positionAt(double(k.timeS));
                QCOMPARE(p.x, k.position.x);
                QCOMPARE(p.y, k.position.y);
                QCOMPARE(p.z, k.position.z);
            }
            // Before the first keyframe it waits there, after the last it stays.
            QVERIFY(track.positionAt(-3.0) == hero->keyframes.front().position);
            QVERIFY(track.positionAt(100.0) == hero->keyframes.back().position);
            QVERIFY(track.velocityAt(100.0) == glm::vec3(0.0f));
        }
        // Linear: halfway in time is halfway in space.
        const HeroTrack linear(*hero, HeroInterpolation::Linear);
        QVERIFY(glm::distance(linear.positionAt(2.0), glm::vec3(-12.5f, 0.0f, 10.0f)) < 1e-5f);
    }

    void keyframeFileIsKeyedAtFrameOverFps()
    {
        const LoadResult r = loadScene(THRONG_TEST_DATA_DIR "/scenes/brain-file.yaml");
        QVERIFY(r.ok());
        const Hero* hero = findHero(r.scene, "stunt_double");
        QVERIFY(hero);
        const std::vector<glm::vec3> frames = readFrames(THRONG_TEST_DATA_DIR "/scenes/hero-keyframes.txt");
        QVERIFY(frames.size() > 10);
        const float fps = r.scene.settings.fps;
        for (HeroInterpolation mode : {HeroInterpolation::Linear, HeroInterpolation::CatmullRom}) {
            const HeroTrack fromScene(*hero, mode);
            const HeroTrack fromFrames(HeroTrack::fromFrames(frames, fps), 2.0f, mode);
            for (std::size_t n = 0; n < frames.size(); ++n) {
                // Frame n at n / fps, whether the caller computes it in double or in float.
                QVERIFY(fromScene.positionAt(double(n) / double(fps)) == frames[n]);
                QVERIFY(fromScene.positionAt(double(float(n) * (1.0f / fps))) == frames[n]);
                QVERIFY(fromFrames.positionAt(double(n) / double(fps)) == frames[n]);
            }
            QCOMPARE(fromScene.endS(), double(float(double(frames.size() - 1) / double(fps))));
        }
    }

    void catmullRomIsSmoothAndKeepsSteadyMotion()
    {
        // Uneven keyframe times along a curve: velocity is continuous at every keyframe.
        const std::vector<Keyframe> keys{{0.0f, {0, 0, 0}}, {1.0f, {2, 0, 1}}, {3.5f, {5, 0, -2}}, {4.0f, {6, 0, -2}},
                                         {6.0f, {10, 0, 3}}};
        const HeroTrack cr(keys, 2.0f, HeroInterpolation::CatmullRom);
        for (std::size_t k = 1; k + 1 < keys.size(); ++k) {
            const double t = double(keys[k].timeS);
            const glm::vec3 before = cr.velocityAt(t - 1e-4), after = cr.velocityAt(t + 1e-4);
            QVERIFY2(glm::distance(before, after) < 5e-3f, "no velocity jump at a keyframe");
        }
        // The linear track's velocity does jump there.
        const HeroTrack lin(keys, 2.0f, HeroInterpolation::Linear);
        QVERIFY(glm::distance(lin.velocityAt(0.9999), lin.velocityAt(1.0001)) > 0.5f);
        // Evenly keyed straight motion stays straight and steady with Catmull-Rom.
        std::vector<glm::vec3> line;
        for (int n = 0; n < 10; ++n)
            line.push_back({0.5f * float(n), 0.0f, -0.25f * float(n)});
        const HeroTrack steady(HeroTrack::fromFrames(line, 24.0f), 2.0f);
        for (double t = 0.0; t < 9.0 / 24.0; t += 0.003) {
            const glm::vec3 p = steady.positionAt(t);
            QVERIFY(glm::distance(p, glm::vec3(12.0f * float(t), 0.0f, -6.0f * float(t))) < 1e-4f);
        }
    }

    void headingFollowsTheDirectionOfTravel()
    {
        const std::vector<Keyframe> keys{{0.0f, {0, 0, 0}}, {2.0f, {10, 0, 0}}, {4.0f, {10, 0, -10}}};
        const HeroTrack track(keys, 2.0f, HeroInterpolation::Linear);
        QVERIFY(std::abs(track.headingDegAt(1.0) - 0.0f) < 1e-3f);   // east
        QVERIFY(std::abs(track.headingDegAt(3.0) - 90.0f) < 1e-3f);  // north (-z)
        QVERIFY(std::abs(track.headingDegAt(10.0) - 90.0f) < 1e-3f); // stopped: keeps its last heading
        QVERIFY(std::abs(track.headingDegAt(-1.0) - 0.0f) < 1e-3f);  // not started: faces its first move
    }

    void pushClearsTheRadiusAndOnlyMovesTheWalker()
    {
        std::mt19937 gen(9);
        std::uniform_real_distribution<float> u(-4.0f, 4.0f);
        const glm::vec2 hero{1.0f, -2.0f}, heroVel{1.2f, 0.0f};
        const float clearance = 2.5f, radius = 0.3f;
        int inside = 0;
        for (int k = 0; k < 2000; ++k) {
            const glm::vec2 p = hero + glm::vec2(u(gen), u(gen));
            const HeroPush push = heroPush(hero, heroVel, clearance, p, radius, std::uint32_t(k));
            const float d = glm::distance(p, hero);
            if (d >= clearance + radius) {
                QVERIFY(!push.inside && push.displacement == glm::vec2(0.0f));
                continue;
            }
            ++inside;
            QVERIFY(push.inside);
            QVERIFY2(glm::distance(p + push.displacement, hero) >= clearance + radius, "the walker ends outside");
            QVERIFY2(glm::length(push.displacement) <= clearance + radius - d + 1e-3f, "no further than needed");
            QVERIFY2(glm::dot(push.velocity, glm::vec2(-heroVel.y, heroVel.x)) * glm::dot(p - hero, glm::vec2(-heroVel.y, heroVel.x)) >= 0.0f,
                     "makes room on its own side of the hero's line");
        }
        QVERIFY(inside > 500);
        // Two walkers exactly at the hero's centre part to opposite sides.
        const HeroPush a = heroPush(hero, heroVel, clearance, hero, radius, 1);
        const HeroPush b = heroPush(hero, heroVel, clearance, hero, radius, 2);
        QVERIFY(glm::dot(a.displacement, b.displacement) < 0.0f);
        QVERIFY(glm::length(a.displacement) >= clearance + radius);
    }

    void aCrowdMakesRoomWithoutPopping()
    {
        // A hero walks 20 m through 300 standing walkers at 1.6 m/s; each frame every
        // walker takes its push. Nobody is left inside, and nobody moves more in a frame
        // than the hero does (plus a hair): the room opens ahead of the hero smoothly.
        const std::vector<Keyframe> keys{{0.0f, {-10, 0, 0}}, {12.5f, {10, 0, 0}}};
        const HeroTrack track(keys, 1.5f);
        std::mt19937 gen(4);
        std::uniform_real_distribution<float> ux(-8.0f, 8.0f), uz(-4.0f, 4.0f);
        std::vector<glm::vec2> walkers;
        while (walkers.size() < 300) {
            const glm::vec2 p{ux(gen), uz(gen)};
            if (glm::distance(p, glm::vec2(-10, 0)) > 1.8f + 0.3f)
                walkers.push_back(p);
        }
        const float dt = 1.0f / 24.0f;
        float worstStep = 0.0f, closest = 1e9f;
        for (int f = 0; f <= 12 * 24 + 12; ++f) {
            const double t = double(f) * double(dt);
            const glm::vec3 h = track.positionAt(t), v = track.velocityAt(t);
            for (std::size_t i = 0; i < walkers.size(); ++i) {
                const HeroPush push =
                    heroPush({h.x, h.z}, {v.x, v.z}, track.clearanceM(), walkers[i], 0.3f, std::uint32_t(i));
                walkers[i] += push.displacement;
                worstStep = std::max(worstStep, glm::length(push.displacement));
                closest = std::min(closest, glm::distance(walkers[i], glm::vec2(h.x, h.z)));
            }
        }
        qInfo("hero through 300 walkers: closest walker %.3f m (clearance + radius 1.8 m), largest push in a frame %.3f m "
              "(hero moves %.3f m)",
              double(closest), double(worstStep), 1.6 * double(dt));
        QVERIFY(closest >= 1.8f - 1e-4f);
        QVERIFY(worstStep <= 1.6f * dt + 1e-3f);
    }
};

THRONG_REGISTER_TEST(TestHeroTrack)
#include "TestHeroTrack.moc"
