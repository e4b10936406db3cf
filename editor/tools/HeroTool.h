#pragma once
// Adds a hero, a hand-animated agent the crowd makes room for: click the points of its
// way (timed by the walking speed of the options), finish with Enter or a double-click;
// or import a keyframe file of "x y z" lines (one per frame). One AddHero step each.

#include "editor/tools/PolylineTool.h"
#include "simcore/scene/Scene.h"

#include <string>

namespace throng::editor {

class HeroTool : public PolylineTool {
    Q_OBJECT

public:
    using PolylineTool::PolylineTool;

    QString name() const override { return tr("Hero"); }
    QString toolTip() const override
    {
        return tr("Hero (H): click the hero's way (timed by its speed), Enter to finish; or import keyframes");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_H); }
    QString objectKey() const override { return QStringLiteral("hero"); }
    QWidget* createOptionsWidget(QWidget* parent) override;

    // Adds a hero keyed by the file's lines, frame n at n / fps. On a bad file, nothing is
    // added and the returned text says where (file:line:col); empty on success.
    QString importFile(const QString& path);

protected:
    void add(const std::vector<glm::vec2>& points) override;
    QColor previewColour() const override { return QColor(255, 120, 60); }

private:
    sim::Hero newHero() const;
    void showImportDialog(QWidget* parent);

    float m_speed = 1.4f;  // m/s along the clicked way, > 0
    std::string m_type;    // empty = a type named "hero", else the first walking type
};

}  // namespace throng::editor
