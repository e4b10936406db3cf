#include "editor/tools/HeroTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/HeroKeyframeFile.h"
#include "editor/tools/TerrainHeight.h"
#include "editor/tools/UniqueName.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

#include <algorithm>

namespace throng::editor {

sim::Hero HeroTool::newHero() const
{
    const sim::Scene& scene = document().scene();
    sim::Hero hero;
    hero.id = document().nextAgentId();
    hero.name = uniqueName(scene.heroes, "hero");
    hero.type = m_type;
    if (hero.type.empty() || !scene.findAgentType(hero.type)) {
        hero.type.clear();
        for (const sim::AgentType& t : scene.agentTypes)
            if (t.name == "hero" || (hero.type.empty() && t.kind == sim::AgentKind::Pedestrian))
                hero.type = t.name;
    }
    return hero;
}

void HeroTool::add(const std::vector<glm::vec2>& points)
{
    sim::Hero hero = newHero();
    const sim::Terrain& terrain = document().scene().terrain;
    float timeS = 0.0f;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i > 0)
            timeS += glm::length(points[i] - points[i - 1]) / m_speed;
        const glm::vec2 p = points[i];
        hero.keyframes.push_back({timeS, {p.x, terrainHeight(terrain, p.x, p.y), p.y}});
    }
    const QString text = tr("Add hero %1").arg(QString::fromStdString(hero.name));
    addAndSelect(document(), &sim::Scene::heroes, std::move(hero), text);
}

QString HeroTool::importFile(const QString& path)
{
    const KeyframeFileResult read = readKeyframeFile(path);
    if (!read.error.isEmpty())
        return read.error;
    sim::Hero hero = newHero();
    const float fps = document().scene().settings.fps;
    for (std::size_t f = 0; f < read.positions.size(); ++f)
        hero.keyframes.push_back({float(double(f) / double(fps)), read.positions[f]});
    // Saved beside the scene, the file is named relative to it (the format's rule).
    const QString sceneDir = QFileInfo(document().filePath()).absolutePath();
    hero.keyframesFile = (document().filePath().isEmpty() ? QFileInfo(path).absoluteFilePath()
                                                           : QDir(sceneDir).relativeFilePath(path))
                             .toStdString();
    const QString text = tr("Import hero %1").arg(QString::fromStdString(hero.name));
    addAndSelect(document(), &sim::Scene::heroes, std::move(hero), text);
    return {};
}

void HeroTool::showImportDialog(QWidget* parent)
{
    QWidget* window = parent->window();
    auto* dialog = new QFileDialog(window, tr("Import Hero Keyframes"),
                                   QFileInfo(document().filePath()).absolutePath(),
                                   tr("Keyframe files (*.txt *.xyz *.dat);;All files (*)"));
    dialog->setObjectName("heroImportDialog");
    dialog->setOption(QFileDialog::DontUseNativeDialog);
    dialog->setFileMode(QFileDialog::ExistingFile);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QFileDialog::fileSelected, this, [this, window](const QString& file) {
        const QString error = importFile(file);
        if (error.isEmpty())
            return;
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Import Hero Keyframes"), error, QMessageBox::Ok, window);
        box->setObjectName("heroImportError");
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
    dialog->open();
}

QWidget* HeroTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto* type = new QComboBox(box);
    type->setObjectName("heroType");
    type->addItem(tr("(default)"), QString());
    for (const sim::AgentType& t : document().scene().agentTypes)
        if (t.kind != sim::AgentKind::Vehicle)
            type->addItem(QString::fromStdString(t.name), QString::fromStdString(t.name));
    type->setCurrentIndex(std::max(0, type->findData(QString::fromStdString(m_type))));
    connect(type, &QComboBox::currentIndexChanged, this,
            [this, type](int) { m_type = type->currentData().toString().toStdString(); });
    row->addWidget(new QLabel(tr("Type"), box));
    row->addWidget(type);
    auto* speed = new QDoubleSpinBox(box);
    speed->setObjectName("heroSpeed");
    speed->setRange(0.1, 50.0);
    speed->setValue(double(m_speed));
    speed->setToolTip(tr("Speed along the clicked way in m/s: it times the keyframes"));
    connect(speed, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_speed = float(v); });
    row->addWidget(new QLabel(tr("Speed"), box));
    row->addWidget(speed);
    auto* import = new QPushButton(tr("Import Keyframes..."), box);
    import->setObjectName("heroImportButton");
    import->setToolTip(tr("Add a hero from a text file of \"x y z\" lines, one per frame"));
    connect(import, &QPushButton::clicked, this, [this, box] { showImportDialog(box); });
    row->addWidget(import);
    return box;
}

}  // namespace throng::editor
