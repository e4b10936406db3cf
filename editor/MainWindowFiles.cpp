// MainWindow's File menu: new, open, save, revert, recent files, drops and the question
// before unsaved changes are lost.
#include "editor/MainWindow.h"

#include "editor/AgentTypePresets.h"
#include "editor/AutosaveRecovery.h"
#include "editor/Icons.h"
#include "editor/MessagesPanel.h"
#include "editor/RecentFiles.h"
#include "editor/WorkspaceLayout.h"
#include "editor/exporting/ExportDialog.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>

namespace throng::editor {

namespace {
constexpr int kStatusMessageMs = 5000;
const char* const kSceneFilter = "Throng scenes (*.yaml *.yml);;All files (*)";

bool isSceneFile(const QString& path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == "yaml" || suffix == "yml";
}
}  // namespace

bool MainWindow::openScene(const QString& path)
{
    const std::vector<sim::Diagnostic> diagnostics = m_document.load(path);
    const QString name = QFileInfo(path).fileName();
    if (sim::hasErrors(diagnostics)) {
        const QString failed = tr("Could not open %1; the current scene stays open.").arg(name);
        m_messages->showDiagnostics(failed, diagnostics);
        m_messagesDock->show();
        m_messagesDock->raise();
        statusBar()->showMessage(failed, kStatusMessageMs);
        return false;
    }
    m_messages->showDiagnostics(tr("Opened %1.").arg(m_document.filePath()), diagnostics);
    statusBar()->showMessage(tr("Opened %1").arg(name), kStatusMessageMs);
    m_recent->add(m_document.filePath());
    return true;
}

void MainWindow::setUnsavedChangesPrompt(std::function<QMessageBox::StandardButton()> prompt)
{
    m_prompt = std::move(prompt);
}

bool MainWindow::offerRecovery(std::function<bool()> ask)
{
    if (!m_autosave->hasRecovery())
        return false;
    const QString forFile = m_autosave->recoveredFor();
    const QString question = tr("Throng closed without saving the changes to %1. Recover them?")
                                 .arg(forFile.isEmpty() ? tr("an untitled scene") : QFileInfo(forFile).fileName());
    const bool yes = ask ? ask()
                         : QMessageBox::question(this, tr("Recover unsaved changes"), question,
                                                 QMessageBox::Yes | QMessageBox::No) == QMessageBox::Yes;
    if (!yes) {
        m_autosave->discard();
        return false;
    }
    if (!m_autosave->restore()) {
        m_messages->showNote(tr("The recovery file could not be read: %1").arg(AutosaveRecovery::recoveryPath()));
        return false;
    }
    m_messages->showNote(tr("Recovered unsaved changes to %1; save them to keep them.")
                             .arg(forFile.isEmpty() ? tr("an untitled scene") : forFile));
    return true;
}

bool MainWindow::maybeKeepChanges()
{
    if (!m_document.isModified())
        return true;
    const QMessageBox::StandardButton answer =
        m_prompt ? m_prompt()
                 : QMessageBox::warning(this, tr("Unsaved changes"),
                                        tr("The scene has changes that are not saved. Save them first?"),
                                        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                        QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::createFileMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&File"));
    auto add = [&](const QString& text, const char* icon, const QKeySequence& key, const QString& tip, auto slot) {
        QAction* a = menu->addAction(themeIcon(icon), text, this, slot);
        a->setShortcut(key);
        a->setToolTip(tip);
        return a;
    };
    add(tr("&New"), "action-new", QKeySequence::New, tr("Start an empty scene"), &MainWindow::newScene);
    add(tr("&Open..."), "action-open", QKeySequence::Open, tr("Open a scene file (.yaml)"), &MainWindow::openWithDialog);
    m_recent = new RecentFiles(menu->addMenu(tr("Open &Recent")), this);
    connect(m_recent, &RecentFiles::openRequested, this, &MainWindow::openAfterAsking);
    add(tr("&Save"), "action-save", QKeySequence::Save, tr("Save the scene to its file"), &MainWindow::save);
    // Spelled out: without a desktop's platform theme Qt gives SaveAs and Quit no keys.
    add(tr("Save &As..."), "action-save-as", QKeySequence(tr("Ctrl+Shift+S")), tr("Save the scene to a new file"), &MainWindow::saveAsWithDialog);
    add(tr("Re&vert"), "action-revert", QKeySequence(), tr("Throw away the changes and read the file again"), &MainWindow::revert);
    menu->addSeparator();
    add(tr("&Export..."), "action-export", QKeySequence(tr("Ctrl+Shift+E")),
        tr("Export the recorded run: glTF, USD, FBX, trajectories CSV, PedPy text, or per-agent caches (text, Maya)"),
        &MainWindow::showExportDialog);
    menu->addSeparator();
    add(tr("&Quit"), "action-quit", QKeySequence(tr("Ctrl+Q")), tr("Close Throng"), &QWidget::close);
    menu->setToolTipsVisible(true);
}

ExportDialog* MainWindow::showExportDialog()
{
    auto* dialog = new ExportDialog(m_document, *m_simulation, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
}

void MainWindow::newScene()
{
    if (!maybeKeepChanges())
        return;
    m_document.reset(newSceneTemplate());
    m_messages->showNote(tr("New scene with a pedestrian type. Draw a spawn group (S) or paint agents with the crowd "
                            "brush (B); walls (W) and goals (G) give them a place to go."));
}

void MainWindow::openWithDialog()
{
    if (!maybeKeepChanges())
        return;
    const QString dir = m_document.filePath().isEmpty() ? QString() : QFileInfo(m_document.filePath()).path();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Scene"), dir, tr(kSceneFilter));
    if (!path.isEmpty())
        openScene(path);
}

void MainWindow::openAfterAsking(const QString& path)
{
    if (maybeKeepChanges())
        openScene(path);
}

void MainWindow::revert()
{
    if (m_document.filePath().isEmpty())
        return;
    openScene(m_document.filePath());
}

bool MainWindow::save()
{
    if (m_document.filePath().isEmpty())
        return saveAsWithDialog();
    return reportSave(m_document.save());
}

bool MainWindow::saveAsWithDialog()
{
    QFileDialog dialog(this, tr("Save Scene As"), m_document.filePath(), tr(kSceneFilter));
    dialog.setObjectName("saveSceneDialog");
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setOption(QFileDialog::DontUseNativeDialog);  // the same dialog on every desktop, and tests can drive it
    dialog.setDefaultSuffix("yaml");
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return false;
    return reportSave(m_document.saveAs(dialog.selectedFiles().front()));
}

bool MainWindow::reportSave(const sim::SaveResult& result)
{
    if (!result.ok) {
        QMessageBox::warning(this, tr("Save failed"), QString::fromStdString(result.error));
        return false;
    }
    m_recent->add(m_document.filePath());
    m_autosave->discard();
    statusBar()->showMessage(tr("Saved %1").arg(m_document.filePath()), kStatusMessageMs);
    return true;
}

void MainWindow::updateTitle()
{
    const QString path = m_document.filePath();
    const QString name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    setWindowTitle(tr("%1[*] - Throng").arg(name));
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() == 1 && urls.front().isLocalFile() && isSceneFile(urls.front().toLocalFile()))
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() != 1 || !urls.front().isLocalFile())
        return;
    event->acceptProposedAction();
    openAfterAsking(urls.front().toLocalFile());
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maybeKeepChanges()) {
        event->ignore();
        return;
    }
    m_autosave->discard();
    m_workspace->save();
    QMainWindow::closeEvent(event);
}

}  // namespace throng::editor
