#include "editor/panels/TimelinePanel.h"

#include "editor/simulation/SimulationController.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

namespace throng::editor {

namespace {

QToolButton* makeButton(QWidget* parent, const QString& name, const QString& text, const QString& tip,
                        QStyle::StandardPixmap icon)
{
    auto* button = new QToolButton(parent);
    button->setObjectName(name);
    button->setText(text);
    button->setToolTip(tip);
    button->setIcon(parent->style()->standardIcon(icon));
    button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    return button;
}

}  // namespace

TimelinePanel::TimelinePanel(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller)
{
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(4, 2, 4, 2);
    QToolButton* restart = makeButton(this, "restartButton", tr("Restart"), tr("Back to frame 0 (Home)"),
                                      QStyle::SP_MediaSkipBackward);
    QToolButton* step = makeButton(this, "stepButton", tr("Step"), tr("Advance one frame (.)"),
                                   QStyle::SP_MediaSeekForward);
    m_play = makeButton(this, "playButton", tr("Play"), tr("Play or pause the simulation (Space)"),
                        QStyle::SP_MediaPlay);
    QToolButton* loop = makeButton(this, "loopButton", tr("Loop"), tr("Start again at the end"),
                                   QStyle::SP_BrowserReload);
    loop->setCheckable(true);
    m_scrub = new QSlider(Qt::Horizontal, this);
    m_scrub->setObjectName("scrubBar");
    m_scrub->setToolTip(tr("Scrub the recorded frames"));
    m_scrub->setRange(0, 0);
    m_frameLabel = new QLabel(this);
    m_frameLabel->setObjectName("timelineFrameLabel");
    m_frameLabel->setMinimumWidth(120);
    for (QWidget* w : {static_cast<QWidget*>(restart), static_cast<QWidget*>(step), static_cast<QWidget*>(m_play),
                       static_cast<QWidget*>(loop)})
        row->addWidget(w);
    row->addWidget(m_scrub, 1);
    row->addWidget(m_frameLabel);

    connect(restart, &QToolButton::clicked, &m_controller, &SimulationController::restart);
    connect(step, &QToolButton::clicked, &m_controller, &SimulationController::stepForward);
    connect(m_play, &QToolButton::clicked, &m_controller, &SimulationController::togglePlay);
    connect(loop, &QToolButton::toggled, &m_controller, &SimulationController::setLoop);
    connect(m_scrub, &QSlider::valueChanged, this, [this](int v) {
        m_controller.pause();
        m_controller.seek(std::size_t(std::max(0, v)));
    });
    connect(&m_controller, &SimulationController::frameChanged, this, &TimelinePanel::refresh);
    connect(&m_controller, &SimulationController::recordedChanged, this, &TimelinePanel::refresh);
    connect(&m_controller, &SimulationController::playingChanged, this, [this](bool playing) {
        m_play->setText(playing ? tr("Pause") : tr("Play"));
        m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });
    refresh();
}

void TimelinePanel::refresh()
{
    const QSignalBlocker block(m_scrub);
    const std::size_t recorded = m_controller.recordedFrames();
    m_scrub->setRange(0, int(recorded > 0 ? recorded - 1 : 0));
    m_scrub->setValue(int(m_controller.currentFrame()));
    m_frameLabel->setText(tr("Frame %1 / %2").arg(m_controller.currentFrame()).arg(m_controller.totalFrames() - 1));
}

}  // namespace throng::editor
