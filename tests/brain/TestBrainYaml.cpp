// Brains survive YAML without loss (inline in a scene and as .brain.yaml files), errors
// in a brain file point into that file, and docs/brains.md matches the catalogue.
#include "RandomBrain.h"
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"

#include <QTemporaryDir>
#include <QTest>

#include <fstream>
#include <sstream>

using namespace throng;
using namespace throng::test;

namespace {

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Loads a brain file through a scene that references it.
sim::LoadResult loadBrainFile(const std::string& dir, const std::string& file)
{
    return sim::parseScene("throng: 1\nbrains:\n  - {name: b, file: " + file + "}\n", "scene.yaml", dir);
}

}  // namespace

class TestBrainYaml : public QObject {
    Q_OBJECT
private slots:
    void shippedBrainFilesRoundTrip()
    {
        QTemporaryDir tmp;
        for (const char* name : {"pedestrian", "boid", "rider", "car"}) {
            const sim::LoadResult a = loadBrainFile(THRONG_SOURCE_DIR "/resources/brains", std::string(name) + ".brain.yaml");
            QVERIFY(a.ok());
            const std::string path = tmp.path().toStdString() + "/" + name + ".brain.yaml";
            QVERIFY(sim::writeFileAtomically(path, sim::brainToYaml(a.scene.brains[0])).ok);
            const sim::LoadResult b = loadBrainFile(tmp.path().toStdString(), std::string(name) + ".brain.yaml");
            QVERIFY(b.ok());
            sim::BrainGraph ga = a.scene.brains[0], gb = b.scene.brains[0];
            ga.file = gb.file;
            QVERIFY2(ga == gb, name);
        }
    }

    void randomInlineBrainsRoundTrip()
    {
        std::mt19937 gen(99);
        for (int round = 0; round < 200; ++round) {
            sim::Scene scene;
            for (int b = 0; b < 3; ++b) {
                sim::BrainGraph g = randomBrain(gen, "brain" + std::to_string(b), {"brain0"});
                std::vector<sim::BrainLink> kept;
                for (const sim::BrainLink& l : g.links)
                    if (g.findNode(l.fromNode) && g.findNode(l.toNode))
                        kept.push_back(l);
                g.links = kept;
                scene.brains.push_back(g);
            }
            const std::string text = sim::sceneToYaml(scene);
            const sim::LoadResult back = sim::parseScene(text, "round.yaml", ".");
            QVERIFY2(back.ok(), back.diagnostics.empty() ? text.c_str() : back.diagnostics[0].format().c_str());
            QVERIFY2(back.scene.brains == scene.brains, text.c_str());
            QCOMPARE(sim::sceneToYaml(back.scene), text);
        }
    }

    void errorsInABrainFilePointIntoIt()
    {
        QTemporaryDir tmp;
        const std::string path = tmp.path().toStdString() + "/bad.brain.yaml";
        QVERIFY(sim::writeFileAtomically(path, "throng_brain: 1\n"
                                               "nodes:\n"
                                               "  - {id: 1, type: input, params: {sensor: speed}}\n"
                                               "  - {id: 2, type: fuzz.triangle, params: {points: [3, 2, 1]}}\n"
                                               "links:\n"
                                               "  - {from: [1, 0], to: [2, 0]}\n")
                    .ok);
        const sim::LoadResult r = loadBrainFile(tmp.path().toStdString(), "bad.brain.yaml");
        QVERIFY(r.ok());
        const sim::BrainCompileResult c = sim::compileBrain(r.scene.brains[0]);
        QCOMPARE(c.errors.size(), std::size_t(1));
        QCOMPARE(c.errors[0].node, sim::NodeId(2));
        QCOMPARE(c.errors[0].format(),
                 path + ":4:5: error: node 2 (fuzz.triangle): parameter 'points' must be in ascending order");
    }

    void docsMatchTheCatalogue()
    {
        const std::string doc = readText(THRONG_SOURCE_DIR "/docs/brains.md");
        const std::string begin = "<!-- catalogue: generated from simcore/brain/NodeCatalogue.cpp -->\n";
        const std::string end = "<!-- end of catalogue -->";
        const std::size_t b = doc.find(begin), e = doc.find(end);
        QVERIFY2(b != std::string::npos && e != std::string::npos, "docs/brains.md lacks the catalogue markers");
        const std::string have = doc.substr(b + begin.size(), e - b - begin.size());
        const std::string want = sim::brainCatalogueMarkdown();
        if (have != want) {
            const std::string out = QDir::tempPath().toStdString() + "/brains-catalogue.md";
            sim::writeFileAtomically(out, want);
            QFAIL(qPrintable(QString::fromStdString("docs/brains.md is out of date; the generated section is in " + out)));
        }
    }
};

THRONG_REGISTER_TEST(TestBrainYaml)
#include "TestBrainYaml.moc"
