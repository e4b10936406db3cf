// The USD export (issue 28), read by an independent reader: tinyusdz (tests/tools/usd-check)
// parses the .usda, composes its variants and references and converts it to its render
// scene. What it finds is held against the trajectories CSV of the same recording: one
// SkelRoot per agent, the shot's time codes and fps, every agent's root where the CSV puts
// it on every frame it is there and invisible on the frames it is not, a skeleton and an
// animation of the same joints, every mesh bound to a material, the set with its lamps.
// A scene at 10^6 m reads back at 10^6 m; --no-set leaves the set out; compact shares the
// looks' cycles in a clips layer at each agent's walking pace; bad paths fail with a
// message and leave nothing behind.
#include "CourtFixture.h"
#include "ExternalReader.h"
#include "TestRegistry.h"

#include "export/TrajectoryCsv.h"
#include "export/character/CharacterLibrary.h"
#include "export/UsdExporter.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using namespace throng;

namespace {

// A time-sampled value at time t: USD's linear interpolation, held before the first and after the last.
glm::dvec3 sampleAt(const QJsonArray& samples, double t)
{
    auto value = [&](int k) {
        const QJsonArray v = samples[k].toArray()[1].toArray();
        return glm::dvec3(v[0].toDouble(), v[1].toDouble(), v[2].toDouble());
    };
    if (t <= samples[0].toArray()[0].toDouble())
        return value(0);
    for (int k = 1; k < samples.size(); ++k) {
        const double t1 = samples[k].toArray()[0].toDouble();
        if (t <= t1) {
            const double t0 = samples[k - 1].toArray()[0].toDouble();
            return value(k - 1) + (value(k) - value(k - 1)) * ((t - t0) / (t1 - t0));
        }
    }
    return value(samples.size() - 1);
}

// The token in force at time t (held from its sample on); "inherited" before any.
QString tokenAt(const QJsonArray& samples, double t)
{
    QString token = "inherited";
    for (const QJsonValue& s : samples)
        if (s.toArray()[0].toDouble() <= t)
            token = s.toArray()[1].toString();
    return token;
}

struct Read {
    test::ExternalReaderRun run;
    QJsonObject stage;
};

Read readUsd(const QString& path, const QTemporaryDir& dir)
{
    Read r;
    const QString json = dir.filePath("usd-check.json");
    r.run = test::runExternalReader("usd-check", {"--json-out", json, path});
    QFile file(json);
    if (file.open(QIODevice::ReadOnly))
        r.stage = QJsonDocument::fromJson(file.readAll()).object();
    return r;
}

}  // namespace

class TestUsdExport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        if (!QFile::exists(test::externalReaderPath("usd-check")))
            QFAIL("tests/tools/usd-check is missing");
    }

    void tinyusdzReadsTheCrowdWhereTheCsvHasIt_data()
    {
        QTest::addColumn<double>("shift");
        QTest::newRow("at the origin") << 0.0;
        QTest::newRow("at 10^6 m") << 1.0e6;
    }
    void tinyusdzReadsTheCrowdWhereTheCsvHasIt()
    {
        QFETCH(double, shift);
        QTemporaryDir dir;
        const test::CourtShot rec = test::recordCourt(shift);
        const std::string csv = dir.filePath("court.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(rec.cache, csv).ok());
        exporting::UsdOptions options;
        options.path = dir.filePath("court.usda").toStdString();
        const exporting::ExportResult result = exporting::exportUsd(rec.scene, rec.cache, options);
        QVERIFY2(result.ok(), result.error.c_str());

        const Read read = readUsd(QString::fromStdString(options.path), dir);
        QVERIFY2(read.run.started && read.run.exitCode == 0, qPrintable(read.run.output.right(3000)));
        const QJsonObject& s = read.stage;
        QCOMPARE(s["agents"].toInt(), int(rec.cache.agentCount()));
        QCOMPARE(s["startTimeCode"].toDouble(), 0.0);
        QCOMPARE(s["endTimeCode"].toDouble(), double(rec.cache.frameCount() - 1));
        QCOMPARE(s["timeCodesPerSecond"].toDouble(), 12.0);
        QCOMPARE(s["framesPerSecond"].toDouble(), 12.0);
        QCOMPARE(s["metersPerUnit"].toDouble(), 1.0);
        QCOMPARE(s["upAxis"].toString(), QString("Y"));
        QCOMPARE(s["defaultPrim"].toString(), QString("Crowd"));
        // Every agent mesh wears a material; the set is there, a lamp per colour of the light.
        QVERIFY(s["agentMeshes"].toInt() >= int(rec.cache.agentCount()));
        QCOMPARE(s["unboundAgentMeshes"].toInt(), 0);
        QVERIFY(s["setMeshes"].toInt() >= 6);
        QCOMPARE(s["lamps"].toInt(), 3);
        const QJsonArray origin = s["origin"].toArray();
        QCOMPARE(origin[0].toDouble(), rec.cache.origin().x);
        QCOMPARE(origin[2].toDouble(), rec.cache.origin().z);

        const auto rows = test::readTrajectoryRows(csv);
        const glm::dvec3 o(origin[0].toDouble(), origin[1].toDouble(), origin[2].toDouble());
        int left = 0, compared = 0;
        double worst = 0.0;
        for (const QJsonValue& v : s["agentList"].toArray()) {
            const QJsonObject a = v.toObject();
            const int id = a["name"].toString().section('_', 1, 1).toInt();
            QVERIFY2(rows.count(id), qPrintable(a["name"].toString()));
            const auto& frames = rows.at(id);
            QCOMPARE(a["animJoints"].toInt(), a["skelJoints"].toInt());
            QVERIFY(a["animJoints"].toInt() > 10);
            // The render scene's evaluated root: the first frame's place.
            const QJsonArray first = a["first"].toArray();
            const glm::dvec3 at0(first[0].toDouble(), first[1].toDouble(), first[2].toDouble());
            QVERIFY2(glm::length(at0 - frames.at(0)) < 1e-3,
                     qPrintable(QString("%1 at frame 0: %2 %3").arg(a["name"].toString()).arg(at0.x).arg(at0.z)));
            // Every frame: where the CSV has it, visible; out of the shot, invisible.
            const QJsonArray translate = a["translate"].toArray(), visibility = a["visibility"].toArray();
            bool gone = false;
            for (std::size_t f = 0; f < rec.cache.frameCount(); ++f) {
                const auto row = frames.find(int(f));
                const QString shown = tokenAt(visibility, double(f));
                if (row == frames.end()) {
                    QCOMPARE(shown, QString("invisible"));
                    gone = true;
                    continue;
                }
                const QByteArray samples = QJsonDocument(visibility).toJson(QJsonDocument::Compact);
                QVERIFY2(shown == "inherited",
                         qPrintable(QString("%1 frame %2: %3").arg(a["name"].toString()).arg(f).arg(samples.constData())));
                const double error = glm::length(o + sampleAt(translate, double(f)) - row->second);
                worst = std::max(worst, error);
                ++compared;
            }
            left += gone ? 1 : 0;
        }
        QVERIFY2(worst < 1e-3, qPrintable(QString("worst root %1 m from the CSV").arg(worst)));
        QVERIFY2(left >= 4, qPrintable(QString("%1 agents left through the door").arg(left)));
        // Each agent faces where the CSV says: every orient sample, a turn about +Y by its heading.
        const auto headings = test::readTrajectoryHeadings(csv);
        double worstTurn = 0.0;
        int turns = 0;
        for (const QJsonValue& v : s["agentList"].toArray()) {
            const QJsonObject a = v.toObject();
            const auto& byFrame = headings.at(a["name"].toString().section('_', 1, 1).toInt());
            for (const QJsonValue& sample : a["orient"].toArray()) {
                const int f = int(sample.toArray()[0].toDouble());
                const QJsonArray q = sample.toArray()[1].toArray();  // (w, x, y, z)
                QVERIFY(std::abs(q[1].toDouble()) < 1e-6 && std::abs(q[3].toDouble()) < 1e-6);
                const auto row = byFrame.find(f);
                if (row == byFrame.end())
                    continue;
                const double yaw = 2.0 * std::atan2(q[2].toDouble(), q[0].toDouble());
                worstTurn = std::max(worstTurn, std::abs(std::remainder(yaw - row->second, 2.0 * 3.14159265358979)));
                ++turns;
            }
        }
        QVERIFY2(worstTurn < 2e-3, qPrintable(QString("worst heading %1 rad from the CSV").arg(worstTurn)));
        QVERIFY(turns > 100);
        QVERIFY(compared > 1000);
        qInfo("%d agent-frames within %.2g m of the CSV; %d agents left the shot", compared, worst, left);
    }

    void withoutTheSetTheCrowdStaysAsItWas()
    {
        QTemporaryDir dir;
        const test::CourtShot rec = test::recordCourt(0.0);
        exporting::UsdOptions options;
        options.path = dir.filePath("bare.usda").toStdString();
        options.includeSet = false;
        QVERIFY(exporting::exportUsd(rec.scene, rec.cache, options).ok());
        const Read read = readUsd(QString::fromStdString(options.path), dir);
        QVERIFY2(read.run.started && read.run.exitCode == 0, qPrintable(read.run.output.right(3000)));
        QCOMPARE(read.stage["setMeshes"].toInt(), 0);
        QCOMPARE(read.stage["lamps"].toInt(), 0);
        QCOMPARE(read.stage["agents"].toInt(), int(rec.cache.agentCount()));
    }

    void eachAgentWearsItsLookAndTint()
    {
        QTemporaryDir dir;
        const test::CourtShot rec = test::recordCourt(0.0);
        exporting::UsdOptions options;
        options.path = dir.filePath("looks.usda").toStdString();
        QVERIFY(exporting::exportUsd(rec.scene, rec.cache, options).ok());
        QFile file(QString::fromStdString(options.path));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        // Visitors have tints: a variant set of both, the drawn one selected; walkers none.
        int visitors = 0;
        for (const sim::AgentInfo& info : rec.cache.agents()) {
            const QString name = QString("agent_%1_%2").arg(info.id).arg(info.typeIndex ? "visitor" : "walker");
            const qsizetype at = text.indexOf("def SkelRoot \"" + name + "\"");
            QVERIFY2(at >= 0, qPrintable(name));
            const QString agent = text.mid(at, text.indexOf("def SkelRoot", at + 10) - at);
            QVERIFY(agent.contains("variantSet \"look\""));
            if (info.typeIndex == 0) {
                QVERIFY(!agent.contains("variantSet \"tint\""));
                continue;
            }
            ++visitors;
            QVERIFY(agent.contains("\"tint0\" {") && agent.contains("\"tint1\" {"));
            QVERIFY(agent.contains("</Crowd/Materials/visitor_tint0>") &&
                    agent.contains("</Crowd/Materials/visitor_tint1>"));
        }
        QCOMPARE(visitors, 4);
        QVERIFY(text.contains("def Material \"visitor_tint1\""));
        QVERIFY(text.contains("string mode = \"exact\""));
        QVERIFY(text.contains("color3f inputs:diffuseColor = (0.1, 0.2, 0.9)"));
    }

    // Compact: each look's walk stored once in a clips layer beside the stage, each agent a
    // value clip into it whose times advance one sample per 1/N of a stride walked (N
    // samples a cycle): its feet keep to the ground as in the exact bake.
    void compactAgentsReadSharedCyclesAtTheirWalkingPace()
    {
        QTemporaryDir dir;
        const test::CourtShot rec = test::recordCourt(0.0);
        const std::string csv = dir.filePath("court.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(rec.cache, csv).ok());
        exporting::UsdOptions options;
        options.path = dir.filePath("court.usda").toStdString();
        options.compact = true;
        const exporting::ExportResult result = exporting::exportUsd(rec.scene, rec.cache, options);
        QVERIFY2(result.ok(), result.error.c_str());
        QCOMPARE(result.writtenPaths.size(), std::size_t(2));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 3);  // the CSV, the stage, its clips
        QVERIFY(QFile::exists(dir.filePath("court.clips.usda")));
        QFile stageFile(QString::fromStdString(options.path));
        QVERIFY(stageFile.open(QIODevice::ReadOnly) && stageFile.readAll().contains("string mode = \"compact\""));

        const Read read = readUsd(QString::fromStdString(options.path), dir);
        QVERIFY2(read.run.started && read.run.exitCode == 0, qPrintable(read.run.output.right(3000)));
        const QJsonObject& s = read.stage;
        QCOMPARE(s["agents"].toInt(), int(rec.cache.agentCount()));
        QCOMPARE(s["clippedAgents"].toInt(), int(rec.cache.agentCount()));  // every one walks

        std::vector<bool> used(rec.scene.agentTypes.size(), true);
        exporting::CharacterLibrary library;
        QVERIFY(library.resolve(rec.scene, "", used).empty());
        const auto rows = test::readTrajectoryRows(csv);
        int checked = 0;
        double worst = 0.0;
        for (const QJsonValue& v : s["agentList"].toArray()) {
            const QJsonObject a = v.toObject();
            const QJsonObject clip = a["clip"].toObject();
            const QString bank = clip["primPath"].toString().section('/', 2);  // <look>_<clip>_<name>
            QVERIFY2(bank.section('_', 1, 1) == "0", qPrintable(bank));       // walkers walk
            const exporting::Character* look = nullptr;
            for (std::size_t c = 0; c < library.characterCount(); ++c)
                if (QString::fromStdString(library.character(c).name) == bank.section('_', 0, 0))
                    look = &library.character(c);
            QVERIFY2(look, qPrintable(bank));
            QCOMPARE(clip["joints"].toInt(), int(look->joints.size()));
            const double perMetre =
                double(look->walk.samples.size()) / (double(look->walk.strideM) * a["scale"].toDouble());
            // The clip's time at each frame, against the distance the CSV says it walked.
            const QJsonArray times = clip["times"].toArray();
            auto clipAt = [&](double frame) {
                QJsonArray held;
                for (const QJsonValue& t : times)
                    held.append(QJsonArray{t.toArray()[0], QJsonArray{t.toArray()[1], 0, 0}});
                return sampleAt(held, frame).x;
            };
            const double lo = times.first().toArray()[1].toDouble() + 1.0;
            const double hi = times.last().toArray()[1].toDouble() - 1.0;
            const auto& frames = rows.at(a["name"].toString().section('_', 1, 1).toInt());
            // Clip time less distance walked (in samples) is constant where feet do not slide.
            std::vector<double> drift;
            double walked = 0.0;
            glm::dvec3 last = frames.begin()->second;
            for (const auto& [f, at] : frames) {
                walked += glm::length(at - last);
                last = at;
                const double c = clipAt(f);
                if (c > lo && c < hi)
                    drift.push_back(c - walked * perMetre);
            }
            QVERIFY2(drift.size() > 20, qPrintable(a["name"].toString()));
            std::vector<double> sorted = drift;
            std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
            const double median = sorted[sorted.size() / 2];
            for (const double d : drift)
                worst = std::max(worst, std::abs(d - median));
            checked += int(drift.size());
        }
        // Between two samples the clip runs at one pace: where the walker speeds up or slows
        // down within a sample (a 24th of a stride), it leads or lags by a part of a sample.
        QVERIFY2(worst < 0.35, qPrintable(QString("the clip strays %1 samples from the distance walked").arg(worst)));
        QVERIFY(checked > 500);

        // Smaller than the exact bake even for twelve agents, whose banks are as long as the
        // longest walk (the crossroads' 227 agents over 240 frames: 8.4 MB against 50.7 MB).
        exporting::UsdOptions exact = options;
        exact.path = dir.filePath("exact.usda").toStdString();
        exact.compact = false;
        QVERIFY(exporting::exportUsd(rec.scene, rec.cache, exact).ok());
        const double compactBytes = double(QFileInfo(QString::fromStdString(options.path)).size() +
                                           QFileInfo(dir.filePath("court.clips.usda")).size());
        const double exactBytes = double(QFileInfo(QString::fromStdString(exact.path)).size());
        QVERIFY2(compactBytes < 0.7 * exactBytes,
                 qPrintable(QString("%1 vs %2 bytes").arg(compactBytes).arg(exactBytes)));
        qInfo("compact: %d agent-frames within %.3f samples of the distance walked; %.0f bytes, exact %.0f", checked,
              worst, compactBytes, exactBytes);
    }

    void badPathsFailWithAMessageAndLeaveNothing()
    {
        QTemporaryDir dir;
        const test::CourtShot rec = test::recordCourt(0.0);
        exporting::UsdOptions options;
        options.path = dir.filePath("crowd.usd").toStdString();
        exporting::ExportResult r = exporting::exportUsd(rec.scene, rec.cache, options);
        QVERIFY(!r.ok());
        QVERIFY2(r.error.find("crowd.usd") != std::string::npos && r.error.find(".usda") != std::string::npos,
                 r.error.c_str());
        options.path = dir.filePath("no/such/dir/crowd.usda").toStdString();
        r = exporting::exportUsd(rec.scene, rec.cache, options);
        QVERIFY(!r.ok());
        QVERIFY2(r.error.find("crowd.usda") != std::string::npos, r.error.c_str());
        QCOMPARE(QDir(dir.path()).entryList(QDir::NoDotAndDotDot | QDir::AllEntries).size(), 0);
    }
};

THRONG_REGISTER_TEST(TestUsdExport)
#include "TestUsdExport.moc"
