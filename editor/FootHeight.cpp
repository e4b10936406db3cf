#include "editor/FootHeight.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QTimer>

#include <algorithm>

namespace throng::editor {

FootHeight::FootHeight(QMainWindow& window, QDockWidget& timeline, QDockWidget& messages, QDockWidget& analysis,
                       QWidget& analysisPanel)
    : QObject(&window), m_window(window), m_timeline(timeline), m_messages(messages), m_analysis(analysis),
      m_panel(analysisPanel)
{
    // After the tab switch has laid the docks out: the sizes are then the new ones.
    connect(&m_analysis, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible && sharesTheRow(m_analysis))
            QTimer::singleShot(0, this, &FootHeight::growForAnalysis);
    });
    connect(&m_messages, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible && sharesTheRow(m_messages))
            QTimer::singleShot(0, this, &FootHeight::giveBack);
    });
}

bool FootHeight::sharesTheRow(const QDockWidget& dock) const
{
    // (A tabbed dock cannot be resized itself: the timeline beside it sets the row's height.)
    return !dock.isFloating() && !m_timeline.isFloating() && m_timeline.isVisible() &&
           m_window.dockWidgetArea(&m_timeline) == m_window.dockWidgetArea(const_cast<QDockWidget*>(&dock));
}

void FootHeight::growForAnalysis()
{
    if (!m_analysis.isVisible())
        return;
    // As the scroll area measures it: its wrapped status line needs more height the
    // narrower it is.
    const int width = m_analysis.widget()->width();
    const int panel =
        std::max(m_panel.minimumSizeHint().height(), m_panel.hasHeightForWidth() ? m_panel.heightForWidth(width) : 0);
    const int wanted = panel + m_analysis.height() - m_analysis.widget()->height();
    if (m_analysis.height() >= wanted)
        return;
    const int before = m_timeline.height();
    m_window.resizeDocks({&m_timeline}, {before + wanted - m_analysis.height()}, Qt::Vertical);
    if (m_before < 0)
        m_before = before;
    // The docks take their new sizes when the window lays them out, after this.
    m_grown = -1;
    QTimer::singleShot(0, this, [this] {
        if (m_before >= 0)
            m_grown = m_timeline.height();
    });
}

void FootHeight::giveBack()
{
    if (m_before < 0 || !m_messages.isVisible())
        return;
    // Set by hand since the analysis grew it: the user's height stays.
    if (m_timeline.height() == m_grown)
        m_window.resizeDocks({&m_timeline}, {m_before}, Qt::Vertical);
    m_before = m_grown = -1;
}

}  // namespace throng::editor
