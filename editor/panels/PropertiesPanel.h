#pragma once
// The properties panel: number fields of the selected items (all of one kind; with
// several selected, a change applies to each, as one undo step). Every change is a
// ChangeValueCommand on the document's stack; the panel never writes the scene.

#include <QWidget>

class QFormLayout;
class QLabel;

namespace throng::editor {

class SceneDocument;

class PropertiesPanel : public QWidget {
    Q_OBJECT

public:
    explicit PropertiesPanel(SceneDocument& document, QWidget* parent = nullptr);

private:
    void rebuild();
    void refreshValues();
    void apply(std::size_t field, double value);

    SceneDocument& m_document;
    QLabel* m_title = nullptr;
    QFormLayout* m_form = nullptr;
    bool m_applying = false;
};

}  // namespace throng::editor
