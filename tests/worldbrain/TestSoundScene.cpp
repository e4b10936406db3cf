// Sound in the scene file: sound_sources and an agent type's `emits` load, save and load
// again without loss, and bad values are errors at their file:line:col.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"

#include <QTest>

using namespace throng::sim;

namespace {

const char* kSound = R"(throng: 1
agent_types:
  - {name: ringer, emits: {channel: bell, strength: 0.8, radius: 12.5}}
  - {name: quiet}
sound_sources:
  - {name: church, channel: bell, position: [3.25, -7], strength: 1, radius: 50}
  - {name: ship, channel: horn, position: [0.1, 0.2]}
)";

const Diagnostic* find(const LoadResult& r, const std::string& key)
{
    for (const Diagnostic& d : r.diagnostics)
        if (d.key == key)
            return &d;
    return nullptr;
}

}  // namespace

class TestSoundScene : public QObject {
    Q_OBJECT
private slots:
    void loadsWhatTheFileSays()
    {
        const LoadResult r = parseScene(kSound, "s.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        const Scene& s = r.scene;
        QCOMPARE(QString::fromStdString(s.agentTypes[0].emits.channel), QString("bell"));
        QCOMPARE(s.agentTypes[0].emits.strength, 0.8f);
        QCOMPARE(s.agentTypes[0].emits.radiusM, 12.5f);
        QVERIFY(s.agentTypes[1].emits.channel.empty());
        QCOMPARE(s.soundSources.size(), std::size_t(2));
        QCOMPARE(QString::fromStdString(s.soundSources[0].name), QString("church"));
        QCOMPARE(s.soundSources[0].position.x, 3.25f);
        QCOMPARE(s.soundSources[0].position.y, -7.0f);
        QCOMPARE(s.soundSources[0].radiusM, 50.0f);
        // Defaults: strength 1, heard over 20 m.
        QCOMPARE(s.soundSources[1].strength, 1.0f);
        QCOMPARE(s.soundSources[1].radiusM, 20.0f);
    }

    void roundTripIsLossless()
    {
        const LoadResult a = parseScene(kSound, "s.yaml", "");
        QVERIFY(a.ok());
        const std::string text = sceneToYaml(a.scene);
        QVERIFY(text.find("sound_sources") != std::string::npos);
        QVERIFY(text.find("emits") != std::string::npos);
        const LoadResult b = parseScene(text, "again.yaml", "");
        QVERIFY2(b.ok(), b.ok() ? "" : b.diagnostics[0].format().c_str());
        QVERIFY(b.scene == a.scene);
        QCOMPARE(sceneToYaml(b.scene), text);
    }

    void badValuesAreErrorsAtTheirPlace()
    {
        const LoadResult r = parseScene(R"(throng: 1
agent_types:
  - {name: ringer, emits: {channel: bell, strength: 0}}
  - {name: shy, emits: {strength: 1}}
sound_sources:
  - {name: church, channel: bell, position: [0, 0], radius: -2}
  - {name: church, channel: bell, position: [1, 1]}
  - {name: mute, position: [1, 1]}
)", "bad.yaml", "");
        QVERIFY(!r.ok());
        const Diagnostic* strength = find(r, "agent_types[0].emits.strength");
        QVERIFY(strength);
        QCOMPARE(strength->line, 3);
        QCOMPARE(strength->column, 53);
        const Diagnostic* channel = find(r, "agent_types[1].emits.channel");
        QVERIFY(channel);
        QCOMPARE(channel->line, 4);
        const Diagnostic* radius = find(r, "sound_sources[0].radius");
        QVERIFY(radius);
        QVERIFY2(radius->format().starts_with("bad.yaml:6:61:"), radius->format().c_str());
        const Diagnostic* twice = find(r, "sound_sources[1].name");
        QVERIFY2(twice && twice->line == 7 && twice->message.find("church") != std::string::npos,
                 twice ? twice->format().c_str() : "no duplicate-name error");
        const Diagnostic* noChannel = find(r, "sound_sources[2].channel");
        QVERIFY(noChannel);
        QCOMPARE(noChannel->line, 8);
    }
};

THRONG_REGISTER_TEST(TestSoundScene)
#include "TestSoundScene.moc"
