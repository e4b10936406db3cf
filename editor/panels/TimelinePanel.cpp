#include "editor/panels/TimelinePanel.h"

#include "editor/Icons.h"
#include "editor/Timecode.h"

#include "editor/panels/TimelineRuler.h"
#include "editor/simulation/SimulationController.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {

const char* const kModeKey = "timeline/playbackMode";

QToolButton* makeButton(QWidget* parent, const QString& name, const QString& text, const QString& tip,
                        const QString& icon)
{
    auto* button = new QToolButton(parent);
    button->setObjectName(name);
    button->setText(text);
    button->setToolTip(tip);
    button->setIcon(themeIcon(icon));
    // Icons only, as DCC playbars have them: the dock keeps to the window's narrowest width.
    button->setToolButtonStyle(Qt::ToolButtonIconOnly);
    return button;
}

}  // namespace

TimelinePanel::TimelinePanel(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller)
{
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 2, 4, 2);
    column->setSpacing(2);
    m_scrub = new TimelineRuler(this);
    m_scrub->setObjectName("scrubBar");
    m_scrub->setToolTip(tr("Click or drag to a frame: frames not computed yet are computed up to it.\n"
                           "Left / Right: previous / next frame, Home: frame 0, End: last computed frame\n"
                           "With a layout time offset selected: Shift+drag to shift its agents by the frames dragged"));
    column->addWidget(m_scrub);
    column->addWidget(makeControls());
    // A dock taller than the panel (beside a taller one in the bottom row) keeps the
    // controls right under the ruler, not at the bottom of an empty strip.
    column->addStretch(1);

    auto goTo = [this](int frame) {
        m_controller.pause();
        m_controller.seek(std::size_t(std::max(0, frame)));
    };
    connect(m_scrub, &QSlider::valueChanged, this, goTo);
    connect(m_frameField, &QSpinBox::valueChanged, this, goTo);
    connect(&m_controller, &SimulationController::frameChanged, this, &TimelinePanel::refresh);
    connect(&m_controller, &SimulationController::recordedChanged, this, &TimelinePanel::refresh);
    connect(&m_controller, &SimulationController::playingChanged, this, [this](bool playing) {
        m_play->setText(playing ? tr("Pause") : tr("Play"));
        m_play->setIcon(themeIcon(playing ? "action-pause" : "action-play"));
    });
    refresh();
}

QWidget* TimelinePanel::makeControls()
{
    auto* controls = new QWidget(this);
    auto* row = new QHBoxLayout(controls);
    row->setContentsMargins(0, 0, 0, 0);
    QToolButton* restart = makeButton(controls, "restartButton", tr("Restart"), tr("Back to frame 0 (Home)"),
                                      "action-first-frame");
    QToolButton* step = makeButton(controls, "stepButton", tr("Step"), tr("Advance one frame (Right or .)"),
                                   "action-step-forward");
    m_play = makeButton(controls, "playButton", tr("Play"), tr("Play or pause the simulation (Space)"),
                        "action-play");
    QToolButton* loop = makeButton(controls, "loopButton", tr("Loop"), tr("Start again at the end"),
                                   "action-loop");
    loop->setCheckable(true);
    m_frameField = new QSpinBox(controls);
    m_frameField->setObjectName("frameField");
    m_frameField->setToolTip(tr("Type a frame and press Enter to go there: frames not computed yet are computed first"));
    m_frameField->setKeyboardTracking(false);
    m_frameField->setAccelerated(true);
    m_timecodeLabel = new QLabel(controls);
    m_timecodeLabel->setObjectName("timecodeLabel");
    m_timecodeLabel->setToolTip(tr("Timecode (hours:minutes:seconds:frames) at the scene's frame rate, and seconds"));
    m_frameLabel = new QLabel(controls);
    m_frameLabel->setObjectName("timelineFrameLabel");
    // Fixed widths: a longer number must not widen the dock (and the window) while it plays.
    m_timecodeLabel->setMinimumWidth(m_timecodeLabel->fontMetrics().horizontalAdvance("00:00:00:00  0000.00 s"));
    m_frameLabel->setMinimumWidth(m_frameLabel->fontMetrics().horizontalAdvance("Frame 00000 / 00000"));
    m_modeBox = new QComboBox(controls);
    m_modeBox->setObjectName("playbackModeBox");
    m_modeBox->addItem(tr("Real time"), "realTime");
    m_modeBox->addItem(tr("Play every frame"), "everyFrame");
    m_modeBox->setToolTip(tr("Real time: keep the shot's frame rate, skipping frames the viewport cannot draw in time.\n"
                             "Play every frame: show each frame, at most at the shot's rate."));
    for (QWidget* w : std::initializer_list<QWidget*>{restart, step, m_play, loop, m_frameField, m_timecodeLabel,
                                                      m_frameLabel})
        row->addWidget(w);
    row->addStretch(1);
    row->addWidget(m_modeBox);

    connect(restart, &QToolButton::clicked, &m_controller, &SimulationController::restart);
    connect(step, &QToolButton::clicked, &m_controller, &SimulationController::stepForward);
    connect(m_play, &QToolButton::clicked, &m_controller, &SimulationController::togglePlay);
    connect(loop, &QToolButton::toggled, &m_controller, &SimulationController::setLoop);
    m_modeBox->setCurrentIndex(std::max(0, m_modeBox->findData(QSettings().value(kModeKey, "realTime"))));
    pickPlaybackMode(m_modeBox->currentIndex());
    connect(m_modeBox, &QComboBox::currentIndexChanged, this, [this](int index) {
        pickPlaybackMode(index);
        QSettings().setValue(kModeKey, m_modeBox->itemData(index));
    });
    return controls;
}

void TimelinePanel::pickPlaybackMode(int index)
{
    m_controller.setPlaybackMode(m_modeBox->itemData(index).toString() == "everyFrame"
                                     ? SimulationController::PlaybackMode::EveryFrame
                                     : SimulationController::PlaybackMode::RealTime);
}

void TimelinePanel::refresh()
{
    const std::size_t current = m_controller.currentFrame();
    const int last = int(std::max<std::size_t>(1, m_controller.totalFrames()) - 1);
    {
        const QSignalBlocker block(m_scrub);
        m_scrub->setRange(0, last);
        m_scrub->setValue(int(current));
        m_scrub->setCachedFrames(m_controller.recordedFrames());
    }
    {
        const QSignalBlocker block(m_frameField);
        m_frameField->setRange(0, last);
        // A number being typed stays until Enter takes it.
        if (!m_frameField->hasFocus() || m_frameField->cleanText() == QString::number(m_frameField->value()))
            m_frameField->setValue(int(current));
    }
    const double fps = m_controller.fps();
    m_timecodeLabel->setText(
        tr("%1  %2 s").arg(timecode(current, fps)).arg(double(current) / fps, 0, 'f', 2));
    m_frameLabel->setText(tr("Frame %1 / %2").arg(current).arg(last));
    const std::optional<std::size_t> target = m_controller.seekTarget();
    m_scrub->setTargetFrame(target ? int(*target) : -1);
}

}  // namespace throng::editor
