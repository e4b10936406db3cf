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

namespace throng::editor {

namespace {
const char* const kSuffix[] = {"glb", "gltf", "csv"};
constexpr int kProgressSteps = 1000;
}  // namespace

ExportDialog::ExportDialog(SceneDocument& document, SimulationController& simulation, QWidget* parent)
    : QDialog(parent), m_document(document), m_simulation(simulation)
{
    setObjectName("exportDialog");
    setWindowTitle(tr("Export"));
    auto* form = new QFormLayout;
    m_format = new QComboBox(this);
    m_format->setObjectName("exportFormat");
    m_format->addItems({tr("glTF binary (.glb)"), tr("glTF with .bin (.gltf)"), tr("Trajectories (.csv)")});
    m_format->setToolTip(tr("Animated glTF for Blender, Maya, Houdini or a game engine, or a CSV of every agent per frame"));
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
    m_pretty->setChecked(true);
    form->addRow(tr("Options"), m_pretty);

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

void ExportDialog::formatChanged()
{
    const int f = m_format->currentIndex();
    QFileInfo info(m_path->text());
    m_path->setText(info.absolutePath() + '/' + info.completeBaseName() + '.' + kSuffix[f]);
    m_pretty->setEnabled(ExportFormat(f) == ExportFormat::Gltf);
}

void ExportDialog::browse()
{
    const int f = m_format->currentIndex();
    const QString path = QFileDialog::getSaveFileName(this, tr("Export To"), m_path->text(),
                                                      QStringLiteral("*.%1").arg(kSuffix[f]));
    if (!path.isEmpty())
        m_path->setText(path);
}

ExportRequest ExportDialog::request() const
{
    ExportRequest r;
    r.format = ExportFormat(m_format->currentIndex());
    r.path = m_path->text().toStdString();
    r.firstFrame = std::size_t(std::min(m_first->value(), m_last->value()));
    r.lastFrame = std::size_t(std::max(m_first->value(), m_last->value()));
    r.prettyJson = m_pretty->isChecked();
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
    const ExportRequest r = request();
    if (m_waitingForFrames) {
        // The first half of the bar is the simulation, the second the writing.
        const double recorded = double(m_simulation.recordedFrames());
        m_progress->setValue(int(0.5 * kProgressSteps * std::min(1.0, recorded / double(r.lastFrame + 1))));
        if (m_simulation.recordedFrames() <= r.lastFrame)
            return;
        m_waitingForFrames = false;
        m_status->setText(tr("Writing %1...").arg(QString::fromStdString(r.path)));
        m_job = std::make_unique<ExportJob>(m_document.scene(), m_simulation.cache(), r);
        return;
    }
    if (!m_job)
        return;
    m_progress->setValue(int(kProgressSteps * (0.5 + 0.5 * double(m_job->progress()))));
    if (!m_job->isDone())
        return;
    const exporting::ExportResult result = m_job->result();
    m_job.reset();
    if (result.cancelled)
        finish(false, tr("Cancelled; no file was written."));
    else if (!result.ok())
        finish(false, QString::fromStdString(result.error));
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
