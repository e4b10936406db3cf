#pragma once
// Places an action point: press at its centre and drag out its radius toward where the
// walkers who stop there will face (a click gives the radius of the tool options and
// keeps the heading they come with). The action and how long they play it come from the
// tool options. The release pushes one AddActionPoint step.

#include "editor/tools/CircleDragTool.h"

#include <string>

namespace throng::editor {

class ActionPointTool : public CircleDragTool {
    Q_OBJECT

public:
    using CircleDragTool::CircleDragTool;

    QString name() const override { return tr("Action Point"); }
    QString toolTip() const override
    {
        return tr("Action point (I): press where walkers stop and drag toward where they face; they play the "
                  "action for the duration, then go on. A click uses the default radius");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_I); }
    QString objectKey() const override { return QStringLiteral("actionPoint"); }
    QWidget* createOptionsWidget(QWidget* parent) override;

protected:
    float defaultRadiusM() const override { return m_defaultRadiusM; }
    float clickRadiusM() const override { return 0.3f; }
    QColor previewColour() const override { return QColor(245, 122, 204); }
    void place(glm::vec2 centre, float radiusM) override;

private:
    float m_defaultRadiusM = 1.0f;
    float m_durationS = 4.0f;
    std::string m_action = "look_around";
};

}  // namespace throng::editor
