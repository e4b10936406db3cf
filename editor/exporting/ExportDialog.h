#pragma once
// File > Export: a format from exporting::exportFormats(), its file or directory, frame
// range and options; simulates the missing frames, then exports on a worker thread with a
// progress bar and Cancel. Reads the document and the recording; never edits the scene.

#include "editor/exporting/ExportJob.h"

#include <QDialog>

#include <memory>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTimer;

namespace throng::editor {

class SceneDocument;
class SimulationController;

class ExportDialog : public QDialog {
    Q_OBJECT

public:
    ExportDialog(SceneDocument& document, SimulationController& simulation, QWidget* parent = nullptr);
    ~ExportDialog() override;

    bool isBusy() const { return m_waitingForFrames || m_job; }
    // What the last export said ("Wrote ...", the error, or "Cancelled").
    QString outcome() const;

    // Starts the export as the Export button does.
    void start();

signals:
    void exportFinished(bool ok);

private:
    void formatChanged();
    // Greys out the options the format, or the file's suffix, does not use.
    void updateOptions();
    void browse();
    void poll();
    void cancelOrClose();
    void finish(bool ok, const QString& message);
    // The table's row the format list shows.
    const exporting::ExportFormat& format() const;
    ExportJobRequest request() const;

    SceneDocument& m_document;
    SimulationController& m_simulation;
    QComboBox* m_format = nullptr;
    QLineEdit* m_path = nullptr;
    QSpinBox* m_first = nullptr;
    QSpinBox* m_last = nullptr;
    QCheckBox* m_pretty = nullptr;
    QCheckBox* m_set = nullptr;
    QComboBox* m_bake = nullptr;
    QComboBox* m_lod = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QPushButton* m_export = nullptr;
    QPushButton* m_cancel = nullptr;
    QTimer* m_poll = nullptr;
    bool m_waitingForFrames = false;
    std::unique_ptr<ExportJob> m_job;
};

}  // namespace throng::editor
