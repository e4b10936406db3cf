#include "editor/DarkTheme.h"

#include "editor/viewport/ViewportPalette.h"

#include <QApplication>
#include <QPalette>
#include <QStyleFactory>
#include <QToolTip>

#include <cmath>

namespace throng::editor {

namespace {

QColor fromLinear(const glm::vec4& c)
{
    // The viewport writes these numbers to the framebuffer as they are (no sRGB
    // conversion), so 8-bit values are the same numbers scaled.
    auto byte = [](float v) { return int(std::lround(v * 255.0f)); };
    return QColor(byte(c.r), byte(c.g), byte(c.b));
}

DarkThemeColours makeColours()
{
    DarkThemeColours c;
    c.window = fromLinear(palette::kBackground);
    c.base = QColor(34, 36, 40);  // BrainScene's background brush
    c.panel = fromLinear(palette::kGround);
    c.text = QColor(0xd8, 0xdc, 0xe2);
    c.disabledText = QColor(122, 127, 134);
    c.highlight = fromLinear(palette::kSelection);
    c.highlightedText = QColor(27, 28, 30);
    c.link = fromLinear(palette::kPathLine);
    c.separator = QColor(72, 76, 82);
    return c;
}

QPalette makePalette(const DarkThemeColours& c)
{
    QPalette p;
    p.setColor(QPalette::Window, c.window);
    p.setColor(QPalette::WindowText, c.text);
    p.setColor(QPalette::Base, c.base);
    p.setColor(QPalette::AlternateBase, QColor(42, 44, 48));
    p.setColor(QPalette::ToolTipBase, c.panel);
    p.setColor(QPalette::ToolTipText, c.text);
    p.setColor(QPalette::PlaceholderText, QColor(128, 133, 140));
    p.setColor(QPalette::Text, c.text);
    p.setColor(QPalette::Button, c.panel);
    p.setColor(QPalette::ButtonText, c.text);
    p.setColor(QPalette::BrightText, QColor(255, 110, 110));
    // Fusion draws bevels and frames from these; kept close to the window so edges stay quiet.
    p.setColor(QPalette::Light, QColor(78, 82, 88));
    p.setColor(QPalette::Midlight, QColor(64, 67, 72));
    p.setColor(QPalette::Mid, QColor(44, 46, 50));
    p.setColor(QPalette::Dark, QColor(24, 25, 28));
    p.setColor(QPalette::Shadow, QColor(8, 8, 10));
    p.setColor(QPalette::Highlight, c.highlight);
    p.setColor(QPalette::HighlightedText, c.highlightedText);
    p.setColor(QPalette::Link, c.link);
    p.setColor(QPalette::LinkVisited, fromLinear(palette::kFlowArrow));

    for (QPalette::ColorRole role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
        p.setColor(QPalette::Disabled, role, c.disabledText);
    p.setColor(QPalette::Disabled, QPalette::Button, c.window);
    p.setColor(QPalette::Disabled, QPalette::Base, c.window);
    p.setColor(QPalette::Disabled, QPalette::Highlight, c.separator);
    p.setColor(QPalette::Disabled, QPalette::HighlightedText, c.text);
    return p;
}

QString makeStyleSheet(const DarkThemeColours& c)
{
    // Only what the palette cannot say: a dock title bar in a shade of its own, and the
    // dock separators, splitter handles and tool bar rules as solid bars (Fusion draws
    // them as faint marks that vanish on a dark window).
    return QStringLiteral(
               "QDockWidget::title { background: %1; padding: 4px 6px; }"
               "QMainWindow::separator { background: %2; width: 4px; height: 4px; }"
               "QMainWindow::separator:hover, QSplitter::handle:hover { background: %3; }"
               "QSplitter::handle { background: %2; }"
               "QSplitter::handle:horizontal { width: 4px; }"
               "QSplitter::handle:vertical { height: 4px; }"
               "QToolBar { background: %4; border: none; spacing: 2px; padding: 2px; }"
               "QToolBar::separator { background: %3; }"
               "QToolBar::separator:horizontal { width: 1px; margin: 4px 4px; }"
               "QToolBar::separator:vertical { height: 1px; margin: 4px 4px; }"
               "QToolTip { color: %5; background-color: %1; border: 1px solid %3; padding: 3px; }")
        .arg(c.panel.name(), c.base.name(), c.separator.name(), c.window.name(), c.text.name());
}

}  // namespace

const DarkThemeColours& darkThemeColours()
{
    static const DarkThemeColours kColours = makeColours();
    return kColours;
}

void applyDarkTheme(QApplication& app)
{
    const DarkThemeColours& colours = darkThemeColours();
    app.setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    const QPalette palette = makePalette(colours);
    QApplication::setPalette(palette);
    QToolTip::setPalette(palette);
    app.setStyleSheet(makeStyleSheet(colours));
}

}  // namespace throng::editor
