// The icon set and the dark theme as a user meets them: every tool and action has an icon
// that draws light, well-placed lines readable on the dark window, and a themed window's
// docks, lists, tool bars and tool tips are the viewport's dark with text at WCAG AAA.
// THRONG_ICON_SHEET=<png> also writes the icons' contact sheet (docs/images/icons.png).
#include "EditorTestSupport.h"
#include "TestRegistry.h"

#include "editor/DarkTheme.h"
#include "editor/Icons.h"
#include "editor/SceneDocument.h"
#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainScene.h"
#include "editor/tools/ToolManager.h"
#include "editor/viewport/ViewportPalette.h"

#include <QDockWidget>
#include <QListWidget>
#include <QMainWindow>
#include <QPainter>
#include <QSplitter>
#include <QStyle>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <QToolTip>

#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

struct IconGroup {
    QString title;
    QStringList keys;
};

// Every tool and action the editor shows, as the lead wires them in.
const QList<IconGroup> kExpected = {
    {"Tools",
     {"tool-select", "tool-crowd-brush", "tool-spawn-group", "tool-erase-brush", "tool-variation-brush",
      "tool-orient-brush", "tool-assign-brush", "tool-wall", "tool-path", "tool-obstacle", "tool-traffic-light",
      "tool-lane", "tool-flow-stroke", "tool-hero", "tool-goal",
      "tool-action-point", "tool-source", "tool-measure", "tool-layout-move"}},
    {"File and edit",
     {"action-new", "action-open", "action-save", "action-save-as", "action-export", "action-undo", "action-redo",
      "action-delete", "action-duplicate", "action-new-agent-type", "action-revert", "action-quit"}},
    {"View",
     {"action-top-view", "action-3d-view", "action-frame-all", "action-frame-selection", "action-reset-layout",
      "action-brains-workspace", "action-layout-workspace"}},
    {"Playback",
     {"action-play", "action-pause", "action-step-forward", "action-step-back", "action-first-frame",
      "action-last-frame", "action-loop", "action-simulate-to-end"}},
    {"Help", {"action-shortcuts", "action-user-guide", "action-about"}},
};

// WCAG 2 relative luminance and contrast ratio.
double luminance(const QColor& c)
{
    auto linear = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    return 0.2126 * linear(c.redF()) + 0.7152 * linear(c.greenF()) + 0.0722 * linear(c.blueF());
}
double contrast(const QColor& a, const QColor& b)
{
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

QColor toColour(glm::vec4 c)
{
    return QColor::fromRgbF(c.r, c.g, c.b);
}
QString name(const QColor& c)
{
    return QStringLiteral("rgb(%1, %2, %3)").arg(c.red()).arg(c.green()).arg(c.blue());
}
bool near(const QColor& a, const QColor& b, int tolerance)
{
    return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

// What a user sees of an icon: its pixmap at `sizePx` in `mode`, over a background.
struct Ink {
    int pixels = 0;          // pixels at least half covered
    int readable = 0;        // of those, pixels at 3:1 or more against the background (WCAG 1.4.11)
    int onEdge = 0;          // of those, pixels in the outermost ring
    QRect bounds;            // the drawing's extent
    double meanLuminance = 0.0;
};
// `background` is what the icon is drawn on: the window, or a selected row's highlight.
Ink inkOf(const QIcon& icon, int sizePx, const QColor& background, QIcon::Mode mode = QIcon::Normal)
{
    const QImage image = icon.pixmap(QSize(sizePx, sizePx), 1.0, mode).toImage().convertToFormat(QImage::Format_ARGB32);
    Ink ink;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.alpha() < 128)
                continue;
            const double a = c.alphaF();
            const QColor over = QColor::fromRgbF(a * c.redF() + (1 - a) * background.redF(),
                                                 a * c.greenF() + (1 - a) * background.greenF(),
                                                 a * c.blueF() + (1 - a) * background.blueF());
            ++ink.pixels;
            ink.readable += contrast(over, background) >= 3.0 ? 1 : 0;
            ink.onEdge += (x == 0 || y == 0 || x == image.width() - 1 || y == image.height() - 1) ? 1 : 0;
            ink.bounds |= QRect(x, y, 1, 1);
            ink.meanLuminance += luminance(over);
        }
    if (ink.pixels > 0)
        ink.meanLuminance /= ink.pixels;
    return ink;
}

// How much an icon stands out of the window: the sum over its pixels of the luminance it
// adds to the window's.
double inkWeight(const QIcon& icon, int sizePx, const QColor& window, QIcon::Mode mode)
{
    const QImage image = icon.pixmap(QSize(sizePx, sizePx), 1.0, mode).toImage().convertToFormat(QImage::Format_ARGB32);
    double weight = 0.0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            weight += c.alphaF() * std::max(0.0, luminance(c) - luminance(window));
        }
    return weight;
}

// The contact sheet: each group under its title, each icon at 24 and 16 px over its key.
// `placed` receives where each key's 24 px icon went.
QImage contactSheet(const QColor& window, const QColor& text, QHash<QString, QRect>& placed)
{
    const int columns = 8, cellW = 164, cellH = 72, titleH = 34, margin = 16;
    int height = margin;
    for (const IconGroup& group : kExpected)
        height += titleH + int((group.keys.size() + columns - 1) / columns) * cellH;
    QImage sheet(margin * 2 + columns * cellW, height + margin, QImage::Format_RGB32);
    sheet.fill(window);
    QPainter painter(&sheet);
    QFont titleFont;
    titleFont.setPixelSize(15);
    titleFont.setBold(true);
    QFont keyFont;
    keyFont.setPixelSize(11);
    int y = margin;
    for (const IconGroup& group : kExpected) {
        painter.setPen(text);
        painter.setFont(titleFont);
        painter.drawText(QRect(margin, y, columns * cellW, titleH), Qt::AlignLeft | Qt::AlignVCenter, group.title);
        y += titleH;
        painter.setFont(keyFont);
        for (int i = 0; i < group.keys.size(); ++i) {
            const QPoint cell(margin + (i % columns) * cellW, y + (i / columns) * cellH);
            const QIcon icon = themeIcon(group.keys[i]);
            placed[group.keys[i]] = QRect(cell + QPoint(cellW / 2 - 26, 8), QSize(24, 24));
            painter.drawPixmap(placed[group.keys[i]].topLeft(), icon.pixmap(24, 24));
            painter.drawPixmap(cell + QPoint(cellW / 2 + 10, 16), icon.pixmap(16, 16));
            painter.drawText(QRect(cell.x(), cell.y() + 40, cellW, 30), Qt::AlignHCenter | Qt::AlignTop,
                             group.keys[i]);
        }
        y += int((group.keys.size() + columns - 1) / columns) * cellH;
    }
    return sheet;
}

}  // namespace

class TestIconsAndTheme : public QObject {
    Q_OBJECT

private:
    QPalette m_palette;
    QString m_styleName;
    QString m_styleSheet;

private slots:
    void initTestCase()
    {
        m_palette = QApplication::palette();
        m_styleName = QApplication::style()->objectName();
        m_styleSheet = qApp->styleSheet();
        applyDarkTheme(*qApp);
    }

    void cleanupTestCase()
    {
        // Other test classes may share this process: leave the application as it was.
        qApp->setStyleSheet(m_styleSheet);
        if (!m_styleName.isEmpty())
            QApplication::setStyle(m_styleName);
        QApplication::setPalette(m_palette);
    }

    void everyToolAndActionHasAnIcon()
    {
        const QStringList keys = iconKeys();
        for (const IconGroup& group : kExpected)
            for (const QString& key : group.keys) {
                QVERIFY2(keys.contains(key), qPrintable(key + " is missing from the icon set"));
                QVERIFY2(!themeIcon(key).isNull(), qPrintable(key));
            }
        QTest::ignoreMessage(QtWarningMsg, QRegularExpression("no icon named \"tool-teleport\""));
        QVERIFY(themeIcon("tool-teleport").isNull());
    }

    // The tools bar shows kExpected's tools, in its order and with their icons, and starts on
    // the first: the order comes from THRONG_EDITOR_TOOLS (editor/CMakeLists.txt), so a tool
    // listed there and not here, or listed out of order, fails.
    void toolsBarShowsTheExpectedToolsInOrder()
    {
        MainWindow window;
        showNewWindow(window);
        auto* bar = window.findChild<QToolBar*>("toolsToolBar");
        QVERIFY(bar);
        QStringList shown;
        for (QAction* action : bar->actions()) {
            const ViewportTool* tool = window.tools().tool(action->objectName().chopped(6));
            QVERIFY2(tool, qPrintable(action->objectName()));
            shown << tool->iconKey();
            auto* button = qobject_cast<QToolButton*>(bar->widgetForAction(action));
            QVERIFY2(button, qPrintable(action->objectName()));
            const QImage drawn = button->icon().pixmap(24, 24).toImage();
            QVERIFY2(!drawn.isNull() && drawn == themeIcon(tool->iconKey()).pixmap(24, 24).toImage(),
                     qPrintable(tool->iconKey() + " is not the icon its button shows"));
        }
        QCOMPARE(shown, kExpected.front().keys);
        QVERIFY(bar->actions().front()->isChecked());
        QCOMPARE(window.tools().activeTool(), window.tools().tools().front());
        QCOMPARE(window.viewport().tool(), window.tools().tools().front());
    }

    void everyIconDrawsLightLinesInsideItsBox_data()
    {
        QTest::addColumn<QString>("key");
        for (const QString& key : iconKeys())
            QTest::newRow(qPrintable(key)) << key;
        QVERIFY(iconKeys().size() >= 43);
    }
    void everyIconDrawsLightLinesInsideItsBox()
    {
        QFETCH(QString, key);
        const QIcon icon = themeIcon(key);
        QVERIFY(!icon.isNull());
        const QColor window = QApplication::palette().color(QPalette::Window);
        for (int sizePx : {16, 24}) {
            const Ink ink = inkOf(icon, sizePx, window);
            const QString at = QStringLiteral("%1 at %2 px: ").arg(key).arg(sizePx);
            // Lines, not a blob and not a speck.
            const double coverage = double(ink.pixels) / (sizePx * sizePx);
            QVERIFY2(coverage > 0.08 && coverage < 0.5, qPrintable(at + QString::number(coverage) + " covered"));
            // At 16 px a 2 px line is 1.33 px wide: more of its pixels are half covered.
            QVERIFY2(ink.readable >= (sizePx == 16 ? 0.9 : 0.95) * ink.pixels,
                     qPrintable(at + QStringLiteral("%1 of %2 pixels under 3:1").arg(ink.pixels - ink.readable)
                                         .arg(ink.pixels)));
            QVERIFY2(ink.meanLuminance > 0.25, qPrintable(at + "mean luminance " + QString::number(ink.meanLuminance)));
            QVERIFY2(ink.onEdge == 0, qPrintable(at + QString::number(ink.onEdge) + " pixels on the edge"));
        }
        // The set's icons fill the same box (Material's keylines: 16 to 20 of 24 px).
        const QRect bounds = inkOf(icon, 24, window).bounds;
        QVERIFY2(std::max(bounds.width(), bounds.height()) >= 16,
                 qPrintable(key + QStringLiteral(" drawn in %1 x %2").arg(bounds.width()).arg(bounds.height())));
        // A disabled tool's icon is visibly fainter, yet still there.
        const double normal = inkWeight(icon, 24, window, QIcon::Normal);
        const double disabled = inkWeight(icon, 24, window, QIcon::Disabled);
        QVERIFY2(disabled > 0.2 * normal && disabled < 0.6 * normal,
                 qPrintable(key + QStringLiteral(": disabled %1, normal %2").arg(disabled).arg(normal)));
        // On a selected row's yellow the icon takes the selection's dark text colour.
        const QColor highlight = QApplication::palette().color(QPalette::Highlight);
        const Ink selected = inkOf(icon, 24, highlight, QIcon::Selected);
        QVERIFY2(selected.pixels > 0 && selected.readable >= 0.95 * selected.pixels,
                 qPrintable(key + QStringLiteral(": %1 of %2 pixels under 3:1 on the selection")
                                      .arg(selected.pixels - selected.readable).arg(selected.pixels)));
    }

    void paletteIsTheCanvasesDarkWithAaaText()
    {
        const QPalette p = QApplication::palette();
        const QColor viewport = toColour(palette::kBackground);
        QVERIFY2(near(p.color(QPalette::Window), viewport, 2),
                 qPrintable(name(p.color(QPalette::Window)) + " against the viewport's " + name(viewport)));
        SceneDocument document;
        BrainGraphModel model(document);
        BrainScene brainCanvas(model);
        const QColor canvas = brainCanvas.backgroundBrush().color();
        QVERIFY2(near(p.color(QPalette::Base), canvas, 2),
                 qPrintable(name(p.color(QPalette::Base)) + " against the brain canvas " + name(canvas)));
        for (QPalette::ColorRole role : {QPalette::Window, QPalette::Base, QPalette::Button, QPalette::ToolTipBase})
            QVERIFY2(luminance(p.color(role)) < 0.05, qPrintable(name(p.color(role))));

        const QList<std::pair<QPalette::ColorRole, QPalette::ColorRole>> pairs = {
            {QPalette::WindowText, QPalette::Window}, {QPalette::Text, QPalette::Base},
            {QPalette::ButtonText, QPalette::Button}, {QPalette::ToolTipText, QPalette::ToolTipBase},
            {QPalette::HighlightedText, QPalette::Highlight}};
        for (auto [fore, back] : pairs)
            QVERIFY2(contrast(p.color(fore), p.color(back)) >= 7.0,
                     qPrintable(name(p.color(fore)) + " on " + name(p.color(back)) + ": " +
                                QString::number(contrast(p.color(fore), p.color(back)))));
        QVERIFY2(contrast(QToolTip::palette().color(QPalette::ToolTipText), QToolTip::palette().color(QPalette::ToolTipBase)) >= 7.0,
                 "tool tips keep a palette of their own");

        // Selection is the viewport's yellow; disabled text is dimmer but still legible.
        const QColor selection = toColour(palette::kSelection);
        QVERIFY2(std::abs(p.color(QPalette::Highlight).hue() - selection.hue()) <= 6,
                 qPrintable(name(p.color(QPalette::Highlight))));
        const double disabled = contrast(p.color(QPalette::Disabled, QPalette::WindowText), p.color(QPalette::Window));
        QVERIFY2(disabled >= 3.0 && disabled < 0.6 * contrast(p.color(QPalette::WindowText), p.color(QPalette::Window)),
                 qPrintable(QString::number(disabled)));
    }

    void themedWindowShowsDarkDocksToolBarAndToolTips()
    {
        const DarkThemeColours& colours = darkThemeColours();
        QMainWindow window;
        QToolBar* tools = window.addToolBar("Tools");
        QAction* play = tools->addAction(themeIcon("action-play"), "Play");
        play->setToolTip("Play the simulation");
        QAction* separator = tools->addSeparator();
        tools->addAction(themeIcon("tool-select"), "Select");
        auto* split = new QSplitter(Qt::Horizontal);
        split->addWidget(new QWidget);
        split->addWidget(new QWidget);
        window.setCentralWidget(split);
        auto* dock = new QDockWidget("Outliner");
        auto* list = new QListWidget;
        list->addItems({"walkers", "runners"});
        dock->setWidget(list);
        window.addDockWidget(Qt::LeftDockWidgetArea, dock);
        window.resize(640, 400);
        window.show();
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        const QImage shot = window.grab().toImage();
        auto pixel = [&](QWidget* w, QPoint p) { return shot.pixelColor(w->mapTo(&window, p)); };
        auto expect = [](const QColor& seen, const QColor& wanted, const char* where) {
            QVERIFY2(near(seen, wanted, 3), qPrintable(QString(where) + ": " + name(seen) + ", expected " + name(wanted)));
        };

        expect(pixel(split->widget(0), {20, 20}), colours.window, "the window");
        expect(pixel(dock, {dock->width() / 2, 3}), colours.panel, "the dock's title bar");
        expect(pixel(list, {list->width() / 2, list->height() - 10}), colours.base, "the list");
        QWidget* handle = split->handle(1);
        expect(pixel(handle, {handle->width() / 2, handle->height() / 2}), colours.base, "the splitter handle");
        QWidget* rule = tools->widgetForAction(separator);
        QVERIFY(rule);
        bool ruleDrawn = false;
        for (int x = 0; x < rule->width(); ++x)
            ruleDrawn = ruleDrawn || near(pixel(rule, {x, rule->height() / 2}), colours.separator, 3);
        QVERIFY2(ruleDrawn, "no separator line in the tool bar");

        // The list's text is the theme's text: its glyphs reach AAA contrast on the list.
        const QRect item = list->visualItemRect(list->item(0));
        double best = 0.0;
        for (int y = item.top(); y <= item.bottom(); ++y)
            for (int x = item.left(); x <= item.right(); ++x)
                best = std::max(best, contrast(pixel(list->viewport(), {x, y}), colours.base));
        QVERIFY2(best >= 7.0, qPrintable(QString::number(best)));

        // The play button shows its green triangle.
        QWidget* playButton = tools->widgetForAction(play);
        const QImage button = playButton->grab().toImage();
        int green = 0;
        for (int y = 0; y < button.height(); ++y)
            for (int x = 0; x < button.width(); ++x)
                green += near(button.pixelColor(x, y), QColor("#4cd67a"), 12) ? 1 : 0;
        QVERIFY2(green > 40, qPrintable(QString::number(green)));

        // Resting the pointer on it shows a dark tool tip with readable text.
        QTest::mouseMove(playButton, playButton->rect().center());
        QTest::mouseMove(playButton, playButton->rect().center() + QPoint(1, 1));
        QTRY_VERIFY_WITH_TIMEOUT(QToolTip::isVisible(), 5000);
        QCOMPARE(QToolTip::text(), QStringLiteral("Play the simulation"));
        QWidget* tip = nullptr;
        for (QWidget* w : QApplication::topLevelWidgets())
            if (w->inherits("QTipLabel") && w->isVisible())
                tip = w;
        QVERIFY(tip);
        const QImage tipShot = tip->grab().toImage();
        expect(tipShot.pixelColor(tipShot.width() - 3, tipShot.height() / 2), colours.panel, "the tool tip");
        double tipBest = 0.0;
        for (int y = 0; y < tipShot.height(); ++y)
            for (int x = 0; x < tipShot.width(); ++x)
                tipBest = std::max(tipBest, contrast(tipShot.pixelColor(x, y), colours.panel));
        QVERIFY2(tipBest >= 7.0, qPrintable(QString::number(tipBest)));
        QToolTip::hideText();
    }

    void contactSheetShowsEveryIcon()
    {
        const DarkThemeColours& colours = darkThemeColours();
        QHash<QString, QRect> placed;
        const QImage sheet = contactSheet(colours.window, colours.text, placed);
        for (const IconGroup& group : kExpected)
            for (const QString& key : group.keys) {
                int drawn = 0;
                const QRect cell = placed.value(key);
                for (int y = cell.top(); y <= cell.bottom(); ++y)
                    for (int x = cell.left(); x <= cell.right(); ++x)
                        drawn += contrast(sheet.pixelColor(x, y), colours.window) >= 3.0 ? 1 : 0;
                QVERIFY2(drawn > 40, qPrintable(key + QStringLiteral(": %1 pixels drawn").arg(drawn)));
            }
        if (const QString out = qEnvironmentVariable("THRONG_ICON_SHEET"); !out.isEmpty())
            QVERIFY2(sheet.save(out), qPrintable(out));
    }
};

THRONG_REGISTER_TEST(TestIconsAndTheme)
#include "TestIconsAndTheme.moc"
