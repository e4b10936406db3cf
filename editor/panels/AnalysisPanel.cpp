#include "editor/panels/AnalysisPanel.h"

#include "editor/Icons.h"
#include "editor/SceneDocument.h"
#include "editor/panels/AnalysisJob.h"
#include "editor/simulation/SimulationController.h"
#include "report/AnalysisCharts.h"
#include "report/GroundPlot.h"
#include "report/HtmlReport.h"
#include "report/ReportFigures.h"

#include <QtCharts/QAbstractAxis>
#include <QtCharts/QChartView>

#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QDoubleSpinBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTabWidget>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace throng::editor {

namespace {

QChartView* chartView(QWidget* parent, const QString& name)
{
    auto* view = new QChartView(parent);
    view->setObjectName(name);
    view->setRenderHint(QPainter::Antialiasing);
    // Small enough not to widen the window or deepen the bottom docks it shares.
    view->setMinimumSize(160, 90);
    return view;
}

// A tab of a painted plan, under a row holding `option` (what the next Analyse draws).
QLabel* imageLabel(QTabWidget* tabs, const QString& name, const QString& title, const QString& before,
                   QWidget* option, const QString& after)
{
    auto* page = new QWidget(tabs);
    auto* column = new QVBoxLayout(page);
    column->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(before, page));
    option->setParent(page);
    row->addWidget(option);
    row->addWidget(new QLabel(after, page));
    row->addStretch(1);
    column->addLayout(row);
    auto* label = new QLabel(page);
    label->setObjectName(name);
    label->setAlignment(Qt::AlignCenter);
    label->setBackgroundRole(QPalette::Base);
    auto* scroll = new QScrollArea(page);
    scroll->setWidget(label);
    scroll->setWidgetResizable(true);
    column->addWidget(scroll, 1);
    tabs->addTab(page, title);
    return label;
}

}  // namespace

AnalysisPanel::AnalysisPanel(SceneDocument& document, SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_document(document), m_controller(controller), m_controllerAlive(&controller)
{
    setObjectName("analysisPanel");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* bar = new QHBoxLayout;
    m_analyse = new QPushButton(themeIcon("action-analyse"), tr("&Analyse"), this);
    m_analyse->setObjectName("analyseButton");
    m_analyse->setToolTip(tr("Measure the frames recorded so far: flows over the measurement lines, density and speed "
                             "in the areas, agents in the scene and out (Ctrl+Shift+A)"));
    m_analyse->setShortcut(QKeySequence(tr("Ctrl+Shift+A")));
    m_save = new QPushButton(themeIcon("action-export"), tr("Save &Report..."), this);
    m_save->setObjectName("saveReportButton");
    m_save->setToolTip(tr("Write this analysis as one HTML file: the figures, every plot and the data behind them"));
    m_save->setEnabled(false);
    m_stop = new QPushButton(tr("S&top"), this);
    m_stop->setObjectName("stopAnalysisButton");
    m_stop->setToolTip(tr("Stop measuring; the analysis shown before stays"));
    m_stop->setVisible(false);
    m_progress = new QProgressBar(this);
    m_progress->setObjectName("analysisProgress");
    m_progress->setRange(0, 100);
    m_progress->setMaximumWidth(160);
    m_progress->setVisible(false);
    m_status = new QLabel(this);
    m_status->setObjectName("analysisStatus");
    m_status->setWordWrap(true);
    bar->addWidget(m_analyse);
    bar->addWidget(m_save);
    bar->addWidget(m_progress);
    bar->addWidget(m_stop);
    bar->addWidget(m_status, 1);
    layout->addLayout(bar);

    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName("analysisTabs");
    m_figures = new QTreeWidget(m_tabs);
    m_figures->setObjectName("analysisFigures");
    m_figures->setColumnCount(2);
    m_figures->setHeaderLabels({tr("Figure"), tr("Value")});
    m_figures->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_tabs->addTab(m_figures, tr("Figures"));
    m_drawn = new QSpinBox;
    m_drawn->setObjectName("analysisDrawn");
    m_drawn->setRange(1, 1'000'000);
    m_drawn->setValue(int(sim::AnalysisOptions{}.maxTrajectories));
    m_drawn->setToolTip(tr("How many walkers' paths the plan draws at most, picked evenly; the next Analyse "
                           "draws them (throng-cli --report-trajectories)"));
    m_trajectories = imageLabel(m_tabs, "analysisTrajectories", tr("Trajectories"), tr("At most"), m_drawn,
                                tr("walkers"));
    m_cell = new QDoubleSpinBox;
    m_cell->setObjectName("analysisCell");
    m_cell->setRange(0.1, 100.0);
    m_cell->setSingleStep(0.25);
    m_cell->setDecimals(2);
    m_cell->setValue(sim::AnalysisOptions{}.densityCellM);
    m_cell->setToolTip(tr("The heatmap's cells, in metres, for the next Analyse; very fine cells over large "
                          "bounds are made coarser (throng-cli --report-cell)"));
    m_density = imageLabel(m_tabs, "analysisDensity", tr("Density"), tr("Cells of"), m_cell, tr("m"));
    m_speedDensity = chartView(m_tabs, "analysisSpeedDensity");
    m_tabs->addTab(m_speedDensity, tr("Speed-Density"));
    m_flow = chartView(m_tabs, "analysisFlow");
    m_tabs->addTab(m_flow, tr("Flow"));
    m_occupancy = chartView(m_tabs, "analysisOccupancy");
    m_tabs->addTab(m_occupancy, tr("In and Out"));
    layout->addWidget(m_tabs, 1);

    m_poll = new QTimer(this);
    m_poll->setInterval(50);
    connect(m_poll, &QTimer::timeout, this, &AnalysisPanel::poll);
    connect(m_analyse, &QPushButton::clicked, this, &AnalysisPanel::analyse);
    connect(m_stop, &QPushButton::clicked, this, &AnalysisPanel::stopAnalysis);
    connect(m_save, &QPushButton::clicked, this, &AnalysisPanel::saveReportAs);
    connect(&m_controller, &SimulationController::recordedChanged, this, &AnalysisPanel::updateStatus);
    // Another scene: what was measured belongs to the last one.
    connect(&m_document, &SceneDocument::sceneReset, this, [this] {
        m_analysis.reset();
        m_trajectories->clear();
        m_density->clear();
        for (QChartView* view : {m_speedDensity, m_flow, m_occupancy}) {
            QChart* old = view->chart();
            view->setChart(new QChart);
            delete old;
        }
        showAnalysis();
        updateStatus();
    });
    updateStatus();
}

AnalysisPanel::~AnalysisPanel()
{
    if (m_job)
        m_job->stop();
    if (m_controllerAlive)
        m_controllerAlive->clearCacheReader();
}

void AnalysisPanel::analyse()
{
    if (m_job)
        return;
    m_jobFrames = m_controller.cache().frameCount();
    sim::AnalysisOptions options;
    options.densityCellM = m_cell->value();
    options.maxTrajectories = std::size_t(m_drawn->value());
    m_job = std::make_shared<AnalysisJob>(m_document.scene(), m_controller.cache(), options);
    // An edit that changes the recording stops the job first (it reads the cache in place).
    m_controller.setCacheReader([job = std::weak_ptr<AnalysisJob>(m_job)] {
        if (const std::shared_ptr<AnalysisJob> j = job.lock())
            j->stop();
    });
    m_analyse->setEnabled(false);
    m_progress->setValue(0);
    m_progress->setVisible(true);
    m_stop->setVisible(true);
    m_status->setText(tr("Measuring %1 frames...").arg(m_jobFrames));
    m_poll->start();
}

void AnalysisPanel::stopAnalysis()
{
    if (m_job)
        m_job->stop();
    poll();
}

void AnalysisPanel::poll()
{
    if (!m_job)
        return;
    m_progress->setValue(int(m_job->progress() * 100.0 + 0.5));
    if (!m_job->isDone())
        return;
    m_poll->stop();
    const std::shared_ptr<AnalysisJob> job = std::exchange(m_job, nullptr);
    m_controller.clearCacheReader();
    m_analyse->setEnabled(true);
    m_progress->setVisible(false);
    m_stop->setVisible(false);
    if (!job->result().complete) {
        updateStatus();
        m_status->setText(m_status->text() + " " + tr("(The analysis was stopped before it finished.)"));
        return;
    }
    m_analysis = job->result();
    m_analysedFrames = m_jobFrames;
    m_analysedRevision = m_controller.cache().revision();
    showAnalysis();
    updateStatus();
}

void AnalysisPanel::showAnalysis()
{
    m_figures->clear();
    m_save->setEnabled(m_analysis.has_value());
    if (!m_analysis)
        return;
    const sim::RunAnalysis& a = *m_analysis;
    for (const report::FigureSection& section : report::reportFigures(a)) {
        auto* top = new QTreeWidgetItem(m_figures, {QString::fromStdString(section.title)});
        for (const report::FigureRow& row : section.rows)
            new QTreeWidgetItem(top, {QString::fromStdString(row.label), QString::fromStdString(row.value)});
        top->setExpanded(true);
    }
    const sim::Scene& scene = m_document.scene();
    m_trajectories->setPixmap(
        QPixmap::fromImage(report::paintGround(scene, a, report::GroundLayer::Trajectories, QSize(900, 620))));
    m_density->setPixmap(
        QPixmap::fromImage(report::paintGround(scene, a, report::GroundLayer::Density, QSize(900, 620))));
    // QChartView takes the charts; the one it showed before is deleted with it.
    auto replace = [](QChartView* view, std::unique_ptr<QChart> chart) {
        // A dock is small: the tab names the chart (a title that says what is missing
        // stays), the legend goes beside it, the axes' text shrinks.
        if (!chart->title().contains(QChar(0x2014)))
            chart->setTitle(QString());
        chart->setMargins(QMargins(2, 2, 2, 2));
        chart->legend()->setAlignment(Qt::AlignRight);
        QFont small = chart->font();
        small.setPointSizeF(std::max(6.0, small.pointSizeF() - 1.0));
        for (QAbstractAxis* axis : chart->axes()) {
            axis->setLabelsFont(small);
            axis->setTitleFont(small);
        }
        chart->legend()->setFont(small);
        QChart* old = view->chart();
        view->setChart(chart.release());
        delete old;
    };
    replace(m_speedDensity, report::speedDensityChart(a));
    replace(m_flow, report::flowChart(a));
    replace(m_occupancy, report::occupancyChart(a));
}

void AnalysisPanel::updateStatus()
{
    const sim::FrameCache& cache = m_controller.cache();
    const std::size_t frames = cache.frameCount();
    if (!m_analysis) {
        m_status->setText(frames > 1 ? tr("%1 frames recorded: press Analyse to measure them.").arg(frames)
                                     : tr("Play or simulate to the end, then press Analyse."));
        return;
    }
    const bool stale = cache.revision() != m_analysedRevision || frames != m_analysedFrames;
    const QString measured =
        tr("Measured %1 frames (%2 s).").arg(m_analysedFrames).arg(m_analysis->durationS, 0, 'f', 1);
    m_status->setText(stale ? measured + " " + tr("The recording has changed since: press Analyse again.") : measured);
}

bool AnalysisPanel::saveReport(const QString& path, QString& error)
{
    if (!m_analysis) {
        error = tr("Nothing analysed yet: press Analyse first.");
        return false;
    }
    const QString file =
        m_document.filePath().isEmpty() ? tr("untitled scene") : QFileInfo(m_document.filePath()).fileName();
    const sim::SaveResult r = report::writeReport(path.toStdString(), m_document.scene(), *m_analysis,
                                                  {file.toStdString(), m_document.scene().settings.seed});
    if (!r.ok)
        error = QString::fromStdString(r.error);
    return r.ok;
}

void AnalysisPanel::saveReportAs()
{
    const QString base = m_document.filePath().isEmpty()
                             ? QStringLiteral("report")
                             : QFileInfo(m_document.filePath()).completeBaseName() + "-report";
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Report"), base + ".html", tr("HTML (*.html)"));
    if (path.isEmpty())
        return;
    QString error;
    if (saveReport(path, error))
        emit message(tr("Report written to %1").arg(path));
    else
        emit message(tr("The report was not written: %1").arg(error));
}

}  // namespace throng::editor
