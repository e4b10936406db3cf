#pragma once
// The "add node" search popup (Tab, as in Houdini and Blender): a line to type in and
// the node types of the catalogue whose name, category or description match every typed
// word. Enter (or a double click) chooses. Knows nothing of graphs; never edits one.

#include <QFrame>

#include <string>
#include <vector>

class QLineEdit;
class QListWidget;
class QMenu;

namespace throng::editor {

class NodePalette : public QFrame {
    Q_OBJECT

public:
    explicit NodePalette(QWidget* parent);

    // Shows the palette at `pos` (parent coordinates) with an empty search, offering
    // only `allowed` types when that is not empty.
    void open(QPoint pos, std::vector<std::string> allowed = {});
    QLineEdit* search() const { return m_search; }
    QListWidget* list() const { return m_list; }
    // The types shown now, in order.
    QStringList shownTypes() const;

    // A menu of every node type, one submenu per category; triggering an action emits
    // `chosen` with its type.
    QMenu* categoryMenu(QWidget* parent);

signals:
    void chosen(const QString& type);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void refilter();
    void choose();

    QLineEdit* m_search;
    QListWidget* m_list;
    std::vector<std::string> m_allowed;
};

}  // namespace throng::editor
