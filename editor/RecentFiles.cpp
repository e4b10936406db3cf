#include "editor/RecentFiles.h"

#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace throng::editor {

namespace {
const char* const kKey = "files/recent";
}

RecentFiles::RecentFiles(QMenu* menu, QObject* parent) : QObject(parent), m_menu(menu)
{
    rebuildMenu();
}

QStringList RecentFiles::paths() const
{
    return QSettings().value(kKey).toStringList();
}

void RecentFiles::add(const QString& path)
{
    QStringList list = paths();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    list.removeAll(absolute);
    list.prepend(absolute);
    while (list.size() > kMaxEntries)
        list.removeLast();
    QSettings().setValue(kKey, list);
    rebuildMenu();
}

void RecentFiles::rebuildMenu()
{
    m_menu->clear();
    const QStringList list = paths();
    for (int i = 0; i < list.size(); ++i) {
        QAction* a = m_menu->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(list[i]).fileName()));
        a->setToolTip(list[i]);
        connect(a, &QAction::triggered, this, [this, path = list[i]] { emit openRequested(path); });
    }
    m_menu->setEnabled(!list.isEmpty());
}

}  // namespace throng::editor
