#pragma once
// The Analysis dock: the recorded run as a researcher reads it — its figures, the
// trajectories and the density heatmap over the set, speed against density in the
// measurement areas, flow over the measurement lines and out of the exits, and the agents
// in the scene over time (report/), with Analyse to read the frames recorded so far and
// Save Report to write them as one HTML file. Reads the document and the frame cache;
// never edits the scene and never simulates.

#include "simcore/analysis/RunAnalysis.h"

#include <QPointer>
#include <QWidget>

#include <cstdint>
#include <memory>
#include <optional>

class QChartView;
class QDoubleSpinBox;
class QSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTabWidget;
class QTimer;
class QTreeWidget;

namespace throng::editor {

class AnalysisJob;
class SceneDocument;
class SimulationController;

class AnalysisPanel : public QWidget {
    Q_OBJECT

public:
    AnalysisPanel(SceneDocument& document, SimulationController& controller, QWidget* parent = nullptr);
    ~AnalysisPanel() override;

    // Analyses the frames recorded so far on a thread of its own, with progress and Stop,
    // and shows them when done (10,000 walkers over 2,400 frames take about 0.6 s). The
    // recording holds still meanwhile; an edit that changes it stops the analysis first.
    void analyse();
    // Stops an analysis under way; the last one shown stays.
    void stopAnalysis();
    bool analysing() const { return m_job != nullptr; }
    // Writes the shown analysis as an HTML report; false (with `error` set) when it could not.
    bool saveReport(const QString& path, QString& error);

    // No taller than the Messages it shares the bottom with: the docks' default heights
    // come from their size hints.
    QSize sizeHint() const override { return {480, 120}; }

    const std::optional<sim::RunAnalysis>& analysis() const { return m_analysis; }
    QTreeWidget* figures() const { return m_figures; }
    QTabWidget* tabs() const { return m_tabs; }

signals:
    // Something the user should read (a report written, or why not).
    void message(const QString& text);

private:
    // The job's progress, and once it is done its result.
    void poll();
    void showAnalysis();
    void updateStatus();
    void saveReportAs();

    SceneDocument& m_document;
    SimulationController& m_controller;
    QPointer<SimulationController> m_controllerAlive;  // the controller may go first
    std::shared_ptr<AnalysisJob> m_job;                 // the analysis under way, if any
    std::size_t m_jobFrames = 0;                        // the frames it reads
    QTimer* m_poll = nullptr;
    std::optional<sim::RunAnalysis> m_analysis;
    std::size_t m_analysedFrames = 0;
    std::uint64_t m_analysedRevision = 0;
    QLabel* m_status = nullptr;
    QPushButton* m_analyse = nullptr;
    QPushButton* m_save = nullptr;
    QPushButton* m_stop = nullptr;
    QProgressBar* m_progress = nullptr;
    QTabWidget* m_tabs = nullptr;
    QTreeWidget* m_figures = nullptr;
    QLabel* m_trajectories = nullptr;
    QSpinBox* m_drawn = nullptr;        // the next analysis: walkers drawn at most
    QDoubleSpinBox* m_cell = nullptr;   // the next analysis: the heatmap's cell
    QLabel* m_density = nullptr;
    QChartView* m_speedDensity = nullptr;
    QChartView* m_flow = nullptr;
    QChartView* m_occupancy = nullptr;
};

}  // namespace throng::editor
