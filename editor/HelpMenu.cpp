#include "editor/HelpMenu.h"

#include "editor/GuideBrowser.h"
#include "editor/Icons.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QHeaderView>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <map>

namespace throng::editor {

namespace {

// Keys and mouse gestures that belong to no action: the viewport's and the brain editor's.
struct GestureRow {
    const char* where;
    const char* keys;
    const char* what;
};
constexpr GestureRow kGestures[] = {
    {"Viewport", "Alt + left drag", "Orbit the 3D view"},
    {"Viewport", "Alt + middle drag, middle drag", "Pan"},
    {"Viewport", "Alt + right drag, wheel", "Zoom (the wheel zooms toward the cursor)"},
    {"Viewport", "Right drag", "Orbit (3D) or pan (top view)"},
    {"Viewport", "[  ]", "Shrink or grow the brush"},
    {"Viewport", "Ctrl + drag", "Resize the brush"},
    {"Viewport", "Escape", "Cancel the drag or drawing in progress"},
    {"Viewport", "Shift + click", "Add to the selection"},
    {"Viewport", "Double click on a line", "Insert a point (select tool)"},
    {"Brain editor", "Tab", "Node palette: type a node's name"},
    {"Brain editor", "F / Shift+F", "Frame all nodes / the selected nodes"},
    {"Brain editor", "Ctrl+C, Ctrl+V, Ctrl+D", "Copy, paste, duplicate nodes"},
    {"Brain editor", "Ctrl+G / Ctrl+Shift+G", "Group nodes into a macro / ungroup"},
};

QString plainText(QString text)
{
    return text.remove('&');
}

// What an action does, for the sheet: its name, then its tooltip without what the sheet
// shows already (the keys, in their column; the name, where the tooltip starts with it).
QString sheetText(const QAction& action, const QStringList& keys)
{
    const QString name = plainText(action.text());
    QString tip = action.toolTip();
    for (const QString& k : keys)
        tip.remove(" (" + k + ")");
    tip = tip.trimmed();
    if (tip.isEmpty() || tip == name)
        return name;
    return tip.startsWith(name) ? tip : name + " - " + tip;
}

}  // namespace

HelpMenu::HelpMenu(QMainWindow& window) : QObject(&window), m_window(window)
{
    QMenu* menu = window.menuBar()->addMenu(tr("&Help"));
    menu->setObjectName("helpMenu");
    menu->setToolTipsVisible(true);
    QAction* guide = menu->addAction(themeIcon("action-user-guide"), tr("&User Guide"), this, &HelpMenu::showGuide);
    guide->setObjectName("userGuideAction");
    guide->setShortcut(QKeySequence::HelpContents);
    guide->setToolTip(tr("How to build a crowd scene in Throng (F1)"));
    QAction* keys = menu->addAction(themeIcon("action-shortcuts"), tr("&Keyboard Shortcuts"), this, &HelpMenu::showShortcuts);
    keys->setObjectName("shortcutsAction");
    keys->setShortcut(QKeySequence(tr("Ctrl+/")));
    keys->setToolTip(tr("Every shortcut and mouse gesture on one sheet (Ctrl+/)"));
    menu->addSeparator();
    QAction* about = menu->addAction(themeIcon("action-about"), tr("&About Throng"), this, [this] {
        QMessageBox::about(&m_window, tr("About Throng"),
                           tr("<h3>Throng</h3><p>An open-source authoring tool for crowd scenes: brushes, brains, "
                              "steering, navigation and traffic, with glTF, CSV and cache export.</p>"
                              "<p>Built with Qt %1.</p>")
                               .arg(QString::fromLatin1(qVersion())));
    });
    about->setObjectName("aboutAction");
    about->setToolTip(tr("What Throng is and what it is built with"));
    QAction* aboutQt = menu->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
    aboutQt->setObjectName("aboutQtAction");
}

QDialog* HelpMenu::showShortcuts()
{
    if (!m_shortcuts) {
        m_shortcuts = new QDialog(&m_window);
        m_shortcuts->setObjectName("shortcutsDialog");
        m_shortcuts->setWindowTitle(tr("Keyboard Shortcuts"));
        m_shortcuts->resize(720, 640);
        auto* table = new QTableWidget(0, 3, m_shortcuts);
        table->setObjectName("shortcutsTable");
        table->setHorizontalHeaderLabels({tr("Where"), tr("Keys"), tr("What it does")});
        table->horizontalHeader()->setStretchLastSection(true);
        table->verticalHeader()->hide();
        // Each description whole, on as many lines as the width leaves it, as the sheet is resized.
        table->setWordWrap(true);
        table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
        table->setEditTriggers(QAbstractItemView::NoEditTriggers);
        table->setSortingEnabled(false);
        auto* layout = new QVBoxLayout(m_shortcuts);
        layout->addWidget(table);
    }
    auto* table = m_shortcuts->findChild<QTableWidget*>("shortcutsTable");
    table->setRowCount(0);
    auto addRow = [table](const QString& where, const QString& keys, const QString& what) {
        const int row = table->rowCount();
        table->insertRow(row);
        table->setItem(row, 0, new QTableWidgetItem(where));
        table->setItem(row, 1, new QTableWidgetItem(keys));
        table->setItem(row, 2, new QTableWidgetItem(what));
    };
    // The menus' actions as they are now, menu by menu, in menu order.
    std::function<void(QMenu*, const QString&)> walk = [&](QMenu* menu, const QString& where) {
        for (QAction* a : menu->actions()) {
            // An action with a menu (New Agent Type and its presets) may have keys of its own.
            if (a->menu())
                walk(a->menu(), where);
            if (a->isSeparator() || a->shortcut().isEmpty())
                continue;
            QStringList keys;
            for (const QKeySequence& k : a->shortcuts())
                keys << k.toString(QKeySequence::NativeText);
            addRow(where, keys.join(", "), sheetText(*a, keys));
        }
    };
    for (QAction* top : m_window.menuBar()->actions())
        if (top->menu())
            walk(top->menu(), plainText(top->text()));
    for (const GestureRow& g : kGestures)
        addRow(tr(g.where), tr(g.keys), tr(g.what));
    table->resizeColumnToContents(0);
    table->resizeColumnToContents(1);  // the descriptions take the rest, wrapped
    m_shortcuts->show();
    m_shortcuts->raise();
    return m_shortcuts;
}

QDialog* HelpMenu::showGuide()
{
    if (!m_guide) {
        m_guide = new QDialog(&m_window);
        m_guide->setObjectName("userGuideDialog");
        m_guide->setWindowTitle(tr("Throng User Guide"));
        m_guide->resize(900, 760);
        auto* browser = new GuideBrowser(m_guide);
        browser->setObjectName("userGuideBrowser");
        browser->setOpenExternalLinks(false);
        browser->setSource(QUrl("qrc:/guide/editor.md"), QTextDocument::MarkdownResource);
        auto* layout = new QVBoxLayout(m_guide);
        layout->addWidget(browser);
    }
    m_guide->show();
    m_guide->raise();
    return m_guide;
}

}  // namespace throng::editor
