#pragma once
// The File > Recent list: the last opened or saved scene paths, remembered in QSettings,
// newest first. Keeps the menu in step; opens nothing itself.

#include <QObject>
#include <QStringList>

class QMenu;

namespace throng::editor {

class RecentFiles : public QObject {
    Q_OBJECT

public:
    static constexpr int kMaxEntries = 8;

    RecentFiles(QMenu* menu, QObject* parent = nullptr);
    void add(const QString& path);
    QStringList paths() const;

signals:
    void openRequested(const QString& path);

private:
    void rebuildMenu();

    QMenu* m_menu;
};

}  // namespace throng::editor
