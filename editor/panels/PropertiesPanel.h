#pragma once
// The properties panel: the fields of the selected items (all of one kind) with fitting
// widgets, built per kind by PropertyRows; with several selected, a field shows the
// common value or "(mixed)" and an edit applies to each, as one undo step. Every change
// is a command on the document's stack; the panel never writes the scene.

#include <QWidget>

class QFormLayout;
class QLabel;

namespace throng::editor {

class PropertyForm;
class SceneDocument;

class PropertiesPanel : public QWidget {
    Q_OBJECT

public:
    explicit PropertiesPanel(SceneDocument& document, QWidget* parent = nullptr);

signals:
    // An edit was refused (an empty or taken name, a bad parameter): why, for the log.
    void problem(const QString& text);

private:
    void rebuild();
    void refreshValues();

    SceneDocument& m_document;
    QLabel* m_title = nullptr;
    QWidget* m_fields = nullptr;
    QFormLayout* m_form = nullptr;
    PropertyForm* m_rows = nullptr;
};

}  // namespace throng::editor
