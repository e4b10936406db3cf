// The Help menu driven like a user: F1 opens the user guide, Ctrl+/ the sheet of every
// shortcut (each action's keys, each tool's key), and every action's tooltip names its
// shortcut.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/tools/ToolManager.h"

#include <QAction>
#include <QActionGroup>
#include <QDialog>
#include <QMap>
#include <QMenu>
#include <QMenuBar>
#include <QToolButton>

#include <functional>
#include <QTableWidget>
#include <QTest>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>

#include <vector>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

class TestHelpMenuUi : public QObject {
    Q_OBJECT

private slots:
    void f1OpensTheUserGuide()
    {
        MainWindow window;
        showNewWindow(window);
        QTest::keyClick(&window.viewport(), Qt::Key_F1);
        auto* guide = window.findChild<QDialog*>("userGuideDialog");
        QVERIFY(guide);
        QTRY_VERIFY(guide->isVisible());
        const QString text = guide->findChild<QTextBrowser*>("userGuideBrowser")->toPlainText();
        QVERIFY2(text.contains("The Throng editor"), qPrintable(text.left(200)));
        QVERIFY2(text.size() > 2000, qPrintable(QString::number(text.size())));
        // Its screenshots fit the reader's width, as the window is made narrower too: no
        // picture hides behind a sideways scroll bar.
        auto* browser = guide->findChild<QTextBrowser*>("userGuideBrowser");
        auto pictures = [&] {
            std::vector<double> widths;
            for (QTextBlock b = browser->document()->begin(); b.isValid(); b = b.next())
                for (QTextBlock::iterator it = b.begin(); !it.atEnd(); ++it)
                    if (it.fragment().charFormat().isImageFormat())
                        widths.push_back(it.fragment().charFormat().toImageFormat().width());
            return widths;
        };
        for (const int width : {900, 560}) {
            guide->resize(width, 700);
            QTRY_COMPARE(guide->width(), width);
            QCoreApplication::processEvents();
            const std::vector<double> widths = pictures();
            QVERIFY2(widths.size() >= 8, qPrintable(QString::number(widths.size())));
            for (const double w : widths)
                QVERIFY2(w > 0.0 && w <= browser->viewport()->width(),
                         qPrintable(QString("%1 in %2").arg(w).arg(browser->viewport()->width())));
            QCOMPARE(browser->horizontalScrollBar()->maximum(), 0);
        }
    }

    void theShortcutSheetListsEveryActionAndTool()
    {
        MainWindow window;
        showNewWindow(window);
        QTest::keyClick(&window.viewport(), Qt::Key_Slash, Qt::ControlModifier);
        auto* sheet = window.findChild<QDialog*>("shortcutsDialog");
        QVERIFY(sheet);
        QTRY_VERIFY(sheet->isVisible());
        auto* table = sheet->findChild<QTableWidget*>("shortcutsTable");
        QStringList rows;
        for (int r = 0; r < table->rowCount(); ++r)
            rows << table->item(r, 1)->text() + " | " + table->item(r, 2)->text();
        auto listed = [&](const QString& keys, const QString& what) {
            for (const QString& row : rows)
                if (row.startsWith(keys + " |") && row.contains(what))
                    return true;
            return false;
        };
        for (QAction* tool : window.tools().actions()->actions())
            QVERIFY2(listed(tool->shortcut().toString(QKeySequence::NativeText), tool->text()), qPrintable(tool->text()));
        QVERIFY(listed("Ctrl+N", "New"));
        QVERIFY(listed("Ctrl+B", "Brains Workspace"));
        QVERIFY(listed("Ctrl+T", "New Agent Type"));
        QVERIFY(listed("Space", "Play"));
        QVERIFY(listed("F1", "User Guide"));
        QVERIFY(listed("Alt + left drag", "Orbit"));
        // Each description says a thing once, whole: not its keys again (they have their
        // column), not its name twice ("Select - Select (Q): ..."), and on as many lines as
        // it needs instead of cut short.
        for (int r = 0; r < table->rowCount(); ++r) {
            const QString keys = table->item(r, 1)->text(), what = table->item(r, 2)->text();
            for (const QString& k : keys.split(", "))
                QVERIFY2(!what.contains("(" + k + ")"), qPrintable(keys + " | " + what));
            const QString name = what.section(" - ", 0, 0);
            QVERIFY2(!what.contains(" - ") || !what.section(" - ", 1).startsWith(name), qPrintable(what));
            // (The item's text margins: 3 pixels a side in Qt's styles.)
            const int needs = table->fontMetrics()
                                  .boundingRect(QRect(0, 0, table->columnWidth(2) - 6, 100000), Qt::TextWordWrap, what)
                                  .height();
            QVERIFY2(table->rowHeight(r) >= needs,
                     qPrintable(QString("%1 < %2: %3").arg(table->rowHeight(r)).arg(needs).arg(what)));
        }
    }

    void everyTooltipNamesItsShortcut()
    {
        MainWindow window;
        showNewWindow(window);
        int named = 0;
        for (QAction* a : window.findChildren<QAction*>()) {
            if (a->shortcut().isEmpty())
                continue;
            const QString keys = a->shortcut().toString(QKeySequence::NativeText);
            QVERIFY2(a->toolTip().contains(keys), qPrintable(a->text() + ": " + a->toolTip()));
            ++named;
        }
        QVERIFY2(named >= 30, qPrintable(QString::number(named)));
    }

    // Every command in the menus and every tool button shows an icon (a choice between
    // modes, a dock's toggle, a recent file and Qt's About are text).
    void everyCommandAndToolHasAnIcon()
    {
        MainWindow window;
        showNewWindow(window);
        int checked = 0;
        std::function<void(QMenu*)> walk = [&](QMenu* menu) {
            if (menu->objectName() == "recentFilesMenu" || menu->title().remove('&') == "Open Recent")
                return;
            for (QAction* a : menu->actions()) {
                if (a->menu() && a->menu() != menu)
                    walk(a->menu());
                if (a->isSeparator() || a->isCheckable() || a->objectName() == "aboutQtAction" || a->menu())
                    continue;
                QVERIFY2(!a->icon().isNull(), qPrintable(menu->title() + " > " + a->text()));
                ++checked;
            }
        };
        for (QAction* top : window.menuBar()->actions())
            if (top->menu())
                walk(top->menu());
        QVERIFY2(checked >= 25, qPrintable(QString::number(checked)));
        for (QAction* tool : window.tools().actions()->actions()) {
            auto* button = window.findChild<QToolButton*>(tool->objectName().chopped(6) + "Button");
            QVERIFY2(button && !button->icon().isNull(), qPrintable(tool->text()));
            QCOMPARE(button->toolButtonStyle(), Qt::ToolButtonIconOnly);
        }
    }

    // Two actions on one key both do nothing (Qt calls it ambiguous); every file action
    // has its key on any desktop.
    void noTwoActionsShareAKey()
    {
        MainWindow window;
        showNewWindow(window);
        QMap<QString, QString> owner;
        for (QAction* a : window.findChildren<QAction*>()) {
            if (a->shortcutContext() == Qt::WidgetShortcut)
                continue;
            for (const QKeySequence& k : a->shortcuts()) {
                const QString keys = k.toString(QKeySequence::PortableText);
                QVERIFY2(!owner.contains(keys) || owner[keys] == a->text(),
                         qPrintable(keys + ": " + owner.value(keys) + " and " + a->text()));
                owner[keys] = a->text();
            }
        }
        for (const char* keys : {"Ctrl+N", "Ctrl+O", "Ctrl+S", "Ctrl+Shift+S", "Ctrl+Q", "Ctrl+Z"})
            QVERIFY2(owner.contains(keys), keys);
    }
};

THRONG_REGISTER_TEST(TestHelpMenuUi)
#include "TestHelpMenuUi.moc"
