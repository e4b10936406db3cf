#pragma once
// The assign brush: gives the placed agents under the brush an agent type, a brain of
// their own (in place of the type's), a group, a goal or a path, each left as it is
// unless chosen. One stroke is one undo step; it never edits the scene directly.

#include "editor/tools/AgentBrushTool.h"

#include <optional>
#include <string>

class QHBoxLayout;

namespace throng::editor {

struct AssignBrushSettings {
    std::optional<std::string> type;  // empty optional = keep
    std::optional<std::string> goal;  // "" = no goal
    std::optional<std::string> path;  // "" = no path
    std::optional<std::string> brain; // "" = the type's brain
    std::optional<std::string> group; // "" = no group; a new name makes a new group
};

class AssignBrushTool : public AgentBrushTool {
    Q_OBJECT

public:
    using AgentBrushTool::AgentBrushTool;

    QString name() const override { return tr("Assign Brush"); }
    QString toolTip() const override
    {
        return tr("Assign Brush (Shift+A): drag over agents to give them a type, a brain, a group, a goal or a path");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::SHIFT | Qt::Key_A); }
    QString objectKey() const override { return QStringLiteral("assignBrush"); }
    QWidget* createOptionsWidget(QWidget* parent) override;

    AssignBrushSettings& settings() { return m_settings; }

protected:
    bool editAgent(sim::Agent& agent, glm::vec2 centre, glm::vec2 direction, int strokeId) const override;
    QString verb() const override { return tr("Assign"); }
    QColor brushColour() const override { return QColor(250, 200, 80); }

private:
    void addGroupChoice(QWidget* box, QHBoxLayout* row);

    AssignBrushSettings m_settings;
};

}  // namespace throng::editor
