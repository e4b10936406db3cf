#pragma once
// The Analysis dock: the recorded run as a researcher reads it — its figures, the
// trajectories and the density heatmap over the set, speed against density in the
// measurement areas, flow over the measurement lines and out of the exits, and the agents
// in the scene over time (report/), with Analyse to read the frames recorded so far and
// Save Report to write them as one HTML file. Reads the document and the frame cache;
// never edits the scene and never simulates.

#include "simcore/analysis/RunAnalysis.h"

#include <QWidget>

#include <cstdint>
#include <memory>
#include <optional>

class QChartView;
class QLabel;
class QPushButton;
class QTabWidget;
class QTreeWidget;

namespace throng::editor {

class SceneDocument;
class SimulationController;

class AnalysisPanel : public QWidget {
    Q_OBJECT

public:
    AnalysisPanel(SceneDocument& document, SimulationController& controller, QWidget* parent = nullptr);

    // Analyses the frames recorded so far and shows them (a run of a few thousand agents
    // over a few thousand frames takes well under a second, on the GUI thread).
    void analyse();
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
    void showAnalysis();
    void updateStatus();
    void saveReportAs();

    SceneDocument& m_document;
    SimulationController& m_controller;
    std::optional<sim::RunAnalysis> m_analysis;
    std::size_t m_analysedFrames = 0;
    std::uint64_t m_analysedRevision = 0;
    QLabel* m_status = nullptr;
    QPushButton* m_analyse = nullptr;
    QPushButton* m_save = nullptr;
    QTabWidget* m_tabs = nullptr;
    QTreeWidget* m_figures = nullptr;
    QLabel* m_trajectories = nullptr;
    QLabel* m_density = nullptr;
    QChartView* m_speedDensity = nullptr;
    QChartView* m_flow = nullptr;
    QChartView* m_occupancy = nullptr;
};

}  // namespace throng::editor
