#pragma once
// The height of the window's foot, the bottom row the timeline shares with the messages
// and, behind them, the analysis. The row is as low as the timeline needs, so the viewport
// keeps the height. Brought forward, the analysis takes the height its tabs and charts
// need, if the row is lower; when the messages come forward again, the row gives that
// height back, unless the user has set the row's height since.

#include <QObject>

class QDockWidget;
class QMainWindow;
class QWidget;

namespace throng::editor {

class FootHeight : public QObject {
    Q_OBJECT

public:
    // The docks must already share the bottom area: the analysis tabbed with the messages.
    // `analysisPanel` is the analysis dock's content (inside its scroll area).
    FootHeight(QMainWindow& window, QDockWidget& timeline, QDockWidget& messages, QDockWidget& analysis,
               QWidget& analysisPanel);

private:
    bool sharesTheRow(const QDockWidget& dock) const;
    void growForAnalysis();
    void giveBack();

    QMainWindow& m_window;
    QDockWidget& m_timeline;
    QDockWidget& m_messages;
    QDockWidget& m_analysis;
    QWidget& m_panel;
    int m_before = -1;  // the row's height before the analysis grew it; -1: it did not
    int m_grown = -1;   // the height it grew it to
};

}  // namespace throng::editor
