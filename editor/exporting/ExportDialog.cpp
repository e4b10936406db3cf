#include "editor/exporting/ExportDialog.h"

#include "editor/SceneDocument.h"
#include "editor/simulation/SimulationController.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace throng::editor {

namespace {
constexpr int kProgressSteps = 1000;

// "glTF 2.0 ... (*.glb *.gltf)" for the file chooser.
QString fileFilter(const exporting::ExportFormat& format)
{
    QStringList patterns;
    for (const std::string& suffix : format.suffixes)
        patterns << '*' + QString::fromStdString(suffix);
    return QStringLiteral("%1 (%2)").arg(QString::fromStdString(format.label), patterns.join(' '));
}
}  // namespace

ExportDialog::ExportDialog(SceneDocument& document, SimulationController& simulation, QWidget* parent)
    : QDialog(parent), m_document(document), m_simulation(simulation)
{
    setObjectName("exportDialog");
    setWindowTitle(tr("Export"));
    auto* form = new QFormLayout;
    m_format = new QComboBox(this);
    m_format->setObjectName("exportFormat");
    for (const exporting::ExportFormat& f : exporting::exportFormats())
        m_format->addItem(QString::fromStdString(f.label), QString::fromStdString(f.key));
    m_format->setToolTip(tr("The formats throng-cli run --export writes: animated glTF for Blender, Maya, Houdini "
                            "or a game engine, USD for film pipelines, FBX for games and older pipelines, a CSV "
                            "of every agent per frame, the walkers for PedPy, or a text "
                            "file per agent (for Maya with a manifest that resources/maya/throngCrowd.mel reads)"));
    form->addRow(tr("Format"), m_format);

    auto* pathRow = new QHBoxLayout;
    m_path = new QLineEdit(this);
    m_path->setObjectName("exportPath");
    const QString scenePath = m_document.filePath();
    const QFileInfo info(scenePath.isEmpty() ? QStringLiteral("untitled.yaml") : scenePath);
    m_path->setText(info.absolutePath() + '/' + info.completeBaseName() + ".glb");
    auto* browse = new QPushButton(tr("Browse..."), this);
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);
    form->addRow(tr("File"), pathRow);

    const int lastFrame = int(m_simulation.totalFrames()) - 1;
    m_first = new QSpinBox(this);
    m_first->setObjectName("exportFirstFrame");
    m_first->setRange(0, lastFrame);
    m_last = new QSpinBox(this);
    m_last->setObjectName("exportLastFrame");
    m_last->setRange(0, lastFrame);
    m_last->setValue(lastFrame);
    auto* range = new QHBoxLayout;
    range->addWidget(m_first);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_last);
    form->addRow(tr("Frames"), range);
    m_pretty = new QCheckBox(tr("Indented JSON (.gltf)"), this);
    m_pretty->setObjectName("exportIndented");
    m_pretty->setChecked(true);
    m_pretty->setToolTip(tr("Write a .gltf's JSON indented, one value a line, for reading and diffing; clear it for "
                            "a smaller file. A .glb is binary and has no text to indent"));
    m_set = new QCheckBox(tr("The set: ground, lanes, crosswalks, walls, obstacles, lights"), this);
    m_set->setObjectName("exportSet");
    m_set->setChecked(true);
    m_set->setToolTip(tr("Write the set with the crowd, as the 3D view stands it up, each traffic light's lamps lit "
                         "with its phase; clear it for the crowd alone (throng-cli --no-set)"));
    auto* options = new QVBoxLayout;
    options->addWidget(m_pretty);
    options->addWidget(m_set);
    form->addRow(tr("Options"), options);

    m_bake = new QComboBox(this);
    m_bake->setObjectName("exportJoints");
    m_bake->addItem(tr("Baked per agent"), int(exporting::JointBake::Exact));
    m_bake->addItem(tr("Compact: each look's cycles shared"), int(exporting::JointBake::Compact));
    m_bake->setToolTip(tr("Baked: every agent's joints, frame by frame, feet planted. Compact: each look's walk and "
                          "run cycle stored once, each agent reading it at its own pace; several times smaller "
                          "(throng-cli --export-mode)"));
    form->addRow(tr("Joints"), m_bake);
    m_lod = new QComboBox(this);
    m_lod->setObjectName("exportDetail");
    m_lod->addItem(tr("Near (about 6,600 triangles a body)"), int(exporting::Lod::Near));
    m_lod->addItem(tr("Mid (2,300)"), int(exporting::Lod::Mid));
    m_lod->addItem(tr("Far (1,000)"), int(exporting::Lod::Far));
    m_lod->setToolTip(tr("How fine the built-in characters' bodies are: near for close-ups, far for the back of a "
                         "crowd or a large FBX (throng-cli --export-lod)"));
    form->addRow(tr("Detail"), m_lod);

    m_progress = new QProgressBar(this);
    m_progress->setObjectName("exportProgress");
    m_progress->setRange(0, kProgressSteps);
    m_progress->setValue(0);
    m_status = new QLabel(this);
    m_status->setObjectName("exportStatus");
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* buttons = new QDialogButtonBox(this);
    m_export = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    m_export->setObjectName("exportButton");
    m_cancel = buttons->addButton(QDialogButtonBox::Cancel);
    m_cancel->setObjectName("cancelButton");
    auto* column = new QVBoxLayout(this);
    column->addLayout(form);
    column->addWidget(m_progress);
    column->addWidget(m_status);
    column->addWidget(buttons);

    m_poll = new QTimer(this);
    m_poll->setInterval(30);
    connect(m_poll, &QTimer::timeout, this, &ExportDialog::poll);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportDialog::formatChanged);
    connect(m_path, &QLineEdit::textChanged, this, &ExportDialog::updateOptions);
    connect(browse, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(m_export, &QPushButton::clicked, this, &ExportDialog::start);
    connect(m_cancel, &QPushButton::clicked, this, &ExportDialog::cancelOrClose);
    formatChanged();
}

ExportDialog::~ExportDialog() = default;

QString ExportDialog::outcome() const
{
    return m_status->text();
}

const exporting::ExportFormat& ExportDialog::format() const
{
    const exporting::ExportFormat* f = exporting::formatByKey(m_format->currentData().toString().toStdString());
    return f ? *f : exporting::exportFormats().front();
}

void ExportDialog::formatChanged()
{
    const exporting::ExportFormat& f = format();
    QString path = m_path->text();
    while (path.size() > 1 && path.endsWith('/'))
        path.chop(1);
    const QFileInfo info(path);
    const QString stem = info.absolutePath() + '/' + info.completeBaseName();
    const std::string suffix = '.' + info.suffix().toLower().toStdString();
    if (f.writesDirectory)
        m_path->setText(stem);
    else if (std::find(f.suffixes.begin(), f.suffixes.end(), suffix) == f.suffixes.end())
        m_path->setText(stem + QString::fromStdString(f.suffixes.front()));
    updateOptions();
}

void ExportDialog::updateOptions()
{
    const exporting::ExportFormat& f = format();
    m_pretty->setEnabled(exporting::indentsText(f, m_path->text().trimmed().toStdString()));
    m_set->setEnabled(f.writesSet);
    m_bake->setEnabled(f.sharesCycles);
    m_lod->setEnabled(f.writesCharacters);
}

void ExportDialog::browse()
{
    const exporting::ExportFormat& f = format();
    const QString path = f.writesDirectory
                             ? QFileDialog::getExistingDirectory(this, tr("Export Into"), m_path->text())
                             : QFileDialog::getSaveFileName(this, tr("Export To"), m_path->text(), fileFilter(f));
    if (!path.isEmpty())
        m_path->setText(path);
}

ExportJobRequest ExportDialog::request() const
{
    ExportJobRequest r;
    r.format = &format();
    r.output.path = m_path->text().toStdString();
    // Character files named relative to the scene resolve as the viewport resolves them.
    if (!m_document.filePath().isEmpty())
        r.output.sceneDirectory = QFileInfo(m_document.filePath()).absolutePath().toStdString();
    r.output.indentedText = m_pretty->isChecked();
    r.output.includeSet = m_set->isChecked();
    r.output.jointBake = exporting::JointBake(m_bake->currentData().toInt());
    r.output.lod = exporting::Lod(m_lod->currentData().toInt());
    r.firstFrame = std::size_t(std::min(m_first->value(), m_last->value()));
    r.lastFrame = std::size_t(std::max(m_first->value(), m_last->value()));
    r.output.firstFrame = r.firstFrame;  // the lights keep the recording's time
    return r;
}

void ExportDialog::start()
{
    if (isBusy())
        return;
    if (m_path->text().trimmed().isEmpty()) {
        finish(false, tr("Choose a file to export to."));
        return;
    }
    m_export->setEnabled(false);
    m_status->setText(tr("Simulating..."));
    m_progress->setValue(0);
    m_waitingForFrames = true;
    m_simulation.requestFrames(request().lastFrame + 1);
    m_poll->start();
}

void ExportDialog::poll()
{
    const ExportJobRequest r = request();
    if (m_waitingForFrames) {
        // The first half of the bar is the simulation, the second the writing.
        const double recorded = double(m_simulation.recordedFrames());
        m_progress->setValue(int(0.5 * kProgressSteps * std::min(1.0, recorded / double(r.lastFrame + 1))));
        if (m_simulation.recordedFrames() <= r.lastFrame)
            return;
        m_waitingForFrames = false;
        m_status->setText(tr("Writing %1...").arg(QString::fromStdString(r.output.path)));
        m_job = std::make_unique<ExportJob>(m_document.scene(), m_simulation.cache(), r);
        return;
    }
    if (!m_job)
        return;
    m_progress->setValue(int(kProgressSteps * (0.5 + 0.5 * double(m_job->progress()))));
    if (!m_job->isDone())
        return;
    const exporting::ExportResult result = m_job->result();
    const bool directory = m_job->format().writesDirectory;
    m_job.reset();
    if (result.cancelled)
        finish(false, tr("Cancelled; no file was written."));
    else if (!result.ok())
        finish(false, QString::fromStdString(result.error));
    else if (directory || result.writtenPaths.empty())
        finish(true, tr("Wrote %1 files into %2")
                         .arg(result.writtenPaths.size())
                         .arg(QString::fromStdString(r.output.path)));
    else
        finish(true, tr("Wrote %1").arg(QString::fromStdString(result.writtenPaths.front())));
}

void ExportDialog::cancelOrClose()
{
    if (m_job) {
        m_job->cancel();
        return;
    }
    if (m_waitingForFrames) {
        finish(false, tr("Cancelled; no file was written."));
        return;
    }
    reject();
}

void ExportDialog::finish(bool ok, const QString& message)
{
    m_poll->stop();
    m_waitingForFrames = false;
    m_export->setEnabled(true);
    m_status->setText(message);
    m_progress->setValue(ok ? kProgressSteps : 0);
    emit exportFinished(ok);
}

}  // namespace throng::editor
