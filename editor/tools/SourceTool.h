#pragma once
// Draws a source, a line where agents come in during the run: press where it starts, drag
// and release where it ends (a click draws a 2 m line running east-west across the click).
// The new source lets in the scene's first pedestrian type at the rate and arrivals of the
// tool options, with no goal yet (the properties panel picks one). The preview stays in the
// tool; the release pushes one AddSource step, Escape drops it. Never edits the scene itself.

#include "editor/tools/ViewportTool.h"

#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string>

namespace throng::editor {

class SourceTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Source"); }
    QString toolTip() const override
    {
        return tr("Source (R): drag a line where agents come in during the run, at the rate of the tool options; "
                  "a click draws a 2 m line. Pick their goal or path in Properties");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_R); }
    QString objectKey() const override { return QStringLiteral("source"); }
    QString statusText() const override;

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;
    QWidget* createOptionsWidget(QWidget* parent) override;

    // A drag shorter than this is a click, m.
    static constexpr float kClickM = 0.3f;
    // The length of the line a click draws, m.
    static constexpr float kClickLineM = 2.0f;

private:
    // The type a new source lets in: the first pedestrian type, else the first type; empty
    // when the scene has none.
    std::string sourceType() const;
    void place(glm::vec2 from, glm::vec2 to);

    glm::vec2 m_from{0.0f}, m_to{0.0f};
    float m_rate = 1.0f;  // agents a second, > 0
    sim::Arrivals m_arrivals = sim::Arrivals::Steady;
};

}  // namespace throng::editor
