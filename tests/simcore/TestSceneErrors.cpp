// Broken scene files: each gives the right verdict and names file:line:col and the key,
// and nothing crashes (tests/data/broken/EXPECTED.tsv lists the hand-written cases).
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <chrono>
#include <fstream>
#include <random>

using namespace throng::sim;

class TestSceneErrors : public QObject {
    Q_OBJECT

    static QString brokenDir() { return QStringLiteral(THRONG_TEST_DATA_DIR "/broken"); }

    static const Diagnostic* firstOf(const LoadResult& r, Severity s)
    {
        for (const Diagnostic& d : r.diagnostics)
            if (d.severity == s)
                return &d;
        return nullptr;
    }

    static void writeFile(const QString& path, const std::string& bytes)
    {
        std::ofstream out(path.toStdString(), std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size()));
    }

private slots:
    void brokenFile_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("fragment");
        QFile manifest(brokenDir() + "/EXPECTED.tsv");
        QVERIFY(manifest.open(QIODevice::ReadOnly | QIODevice::Text));
        while (!manifest.atEnd()) {
            const QString line = QString::fromUtf8(manifest.readLine()).trimmed();
            if (line.isEmpty() || line.startsWith('#'))
                continue;
            const QStringList f = line.split('\t');
            QCOMPARE(f.size(), 5);
            const QStringList lc = f[2].split(':');
            QTest::newRow(qPrintable(f[0])) << f[0] << (f[1] == "valid") << lc[0].toInt() << lc[1].toInt()
                                            << (f[3] == "-" ? QString() : f[3]) << f[4];
        }
    }

    void brokenFile()
    {
        QFETCH(QString, file);
        QFETCH(bool, valid);
        QFETCH(int, line);
        QFETCH(int, column);
        QFETCH(QString, key);
        QFETCH(QString, fragment);
        const std::string path = (brokenDir() + "/" + file).toStdString();
        const LoadResult r = loadScene(path);
        QCOMPARE(r.ok(), valid);
        const Diagnostic* d = firstOf(r, valid ? Severity::Warning : Severity::Error);
        QVERIFY2(d, "expected a diagnostic");
        QCOMPARE(QString::fromStdString(d->file), QString::fromStdString(path));
        QCOMPARE(d->line, line);
        QCOMPARE(d->column, column);
        QCOMPARE(QString::fromStdString(d->key), key);
        QVERIFY2(QString::fromStdString(d->message).contains(fragment), d->format().c_str());
        if (!valid)
            QVERIFY2(r.scene == Scene{}, "a failed load must not return a half-loaded scene");
    }

    void everyBrokenFileIsListed()
    {
        QFile manifest(brokenDir() + "/EXPECTED.tsv");
        QVERIFY(manifest.open(QIODevice::ReadOnly | QIODevice::Text));
        const QString text = QString::fromUtf8(manifest.readAll());
        const QStringList files = QDir(brokenDir()).entryList({"*.yaml"}, QDir::Files);
        QVERIFY(files.size() >= 15);
        for (const QString& f : files)
            QVERIFY2(text.contains(f + '\t'), qPrintable(f + " has no row in EXPECTED.tsv"));
    }

    void emptyAndBlankFiles()
    {
        QTemporaryDir dir;
        for (const std::string& content : {std::string(), std::string("\n\n   \n"), std::string("# only a comment\n")}) {
            const QString path = dir.filePath("empty.yaml");
            writeFile(path, content);
            const LoadResult r = loadScene(path.toStdString());
            QVERIFY(!r.ok());
            QVERIFY(!r.diagnostics.empty());
            QVERIFY2(r.diagnostics[0].message.find("empty") != std::string::npos ||
                         r.diagnostics[0].message.find("map of sections") != std::string::npos,
                     r.diagnostics[0].format().c_str());
        }
    }

    void binaryGarbage()
    {
        QTemporaryDir dir;
        std::mt19937 gen(7);
        std::string bytes(4096, '\0');
        for (char& c : bytes)
            c = char(gen() & 0xff);
        bytes.replace(0, 10, "throng: 1\n");
        const QString path = dir.filePath("garbage.yaml");
        writeFile(path, bytes);
        const LoadResult r = loadScene(path.toStdString());
        QVERIFY(!r.ok());
        QVERIFY(r.diagnostics[0].message.find("not UTF-8 text") != std::string::npos);
        QVERIFY(r.diagnostics[0].line >= 1);
    }

    void deepNestingDoesNotCrash()
    {
        const std::string text = "throng: 1\nsettings: " + std::string(100000, '[') + std::string(100000, ']') + "\n";
        const LoadResult r = parseScene(text, "deep.yaml", "");
        QVERIFY(!r.ok());
    }

    void missingFileAndDirectory()
    {
        QTemporaryDir dir;
        const LoadResult missing = loadScene(dir.filePath("nope.yaml").toStdString());
        QVERIFY(!missing.ok());
        QCOMPARE(missing.diagnostics[0].message, std::string("no such file"));
        const LoadResult directory = loadScene(dir.path().toStdString());
        QVERIFY(!directory.ok());
        QVERIFY(directory.diagnostics[0].message.find("directory") != std::string::npos);
    }

    // A 50 MB painted crowd in the table form loads, and is fast about it.
    void fiftyMegabyteSceneLoads()
    {
        QTemporaryDir dir;
        std::string text = "throng: 1\nagent_types:\n  - {name: walker}\nagents:\n  columns: [id, type, x, y, z, heading]\n"
                           "  rows: |\n";
        std::uint32_t id = 1;
        while (text.size() < 50u * 1024 * 1024) {
            const float x = float(id % 1000) * 0.75f, z = float(id / 1000) * 0.75f;
            text += "    " + std::to_string(id) + " walker " + std::to_string(x) + " 0 " + std::to_string(z) +
                    " 90.5\n";
            ++id;
        }
        const QString path = dir.filePath("big.yaml");
        writeFile(path, text);
        const auto start = std::chrono::steady_clock::now();
        const LoadResult r = loadScene(path.toStdString());
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        QVERIFY2(r.ok(), r.diagnostics.empty() ? "" : r.diagnostics[0].format().c_str());
        QCOMPARE(r.scene.agents.size(), std::size_t(id - 1));
        QCOMPARE(r.scene.agents.back().position.x, float((id - 1) % 1000) * 0.75f);
        qInfo("50 MB scene with %u agents loaded in %.2f s", id - 1, seconds);
    }

    // 50 MB of text that is not a scene gives one clear error, not a crash or a hang.
    void fiftyMegabytesOfNonsense()
    {
        QTemporaryDir dir;
        std::string text;
        text.reserve(50u * 1024 * 1024 + 64);
        std::mt19937 gen(3);
        while (text.size() < 50u * 1024 * 1024) {
            text += "lorem: [ipsum, {dolor: sit}, amet]\n- ";
            text += char('a' + gen() % 26);
            text += '\n';
        }
        const QString path = dir.filePath("nonsense.yaml");
        writeFile(path, text);
        const LoadResult r = loadScene(path.toStdString());
        QVERIFY(!r.ok());
        QVERIFY(r.diagnostics[0].line >= 1);
    }

    void tooLargeIsRefusedBeforeReading()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("huge.yaml");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        QVERIFY(f.resize(qint64(kMaxSceneFileBytes) + 1));  // sparse: no disk used
        f.close();
        const LoadResult r = loadScene(path.toStdString());
        QVERIFY(!r.ok());
        QVERIFY(r.diagnostics[0].message.find("limited to") != std::string::npos);
    }

    void everyErrorIsReportedNotJustTheFirst()
    {
        const std::string text = "throng: 1\nagent_types:\n  - {name: a, radius: -1, mass: 0}\n  - {name: b, max_speed: x}\n";
        const LoadResult r = parseScene(text, "many.yaml", "");
        int errors = 0;
        for (const Diagnostic& d : r.diagnostics)
            errors += d.severity == Severity::Error;
        QCOMPARE(errors, 3);
    }
};

THRONG_REGISTER_TEST(TestSceneErrors)
#include "TestSceneErrors.moc"
