#pragma once
// Owns the viewport tools (THRONG_EDITOR_TOOLS in editor/CMakeLists.txt lists them) and the
// exclusive QActionGroup that picks one; shows the active tool's options in the tool options
// bar. Routes nothing itself: the viewport forwards input to the tool it is given.

#include "editor/tools/ViewportTool.h"

#include <QObject>

#include <vector>

class QAction;
class QActionGroup;
class QToolBar;

namespace throng::editor {

class SceneDocument;
class Viewport;

class ToolManager : public QObject {
    Q_OBJECT

public:
    ToolManager(SceneDocument& document, Viewport& viewport, QObject* parent = nullptr);

    const std::vector<ViewportTool*>& tools() const { return m_tools; }
    // The tool with this objectKey() ("crowdBrush"), or null.
    ViewportTool* tool(const QString& key) const;
    template <class T>
    T* tool() const
    {
        for (ViewportTool* t : m_tools)
            if (auto* found = qobject_cast<T*>(t))
                return found;
        return nullptr;
    }
    ViewportTool* activeTool() const { return m_active; }
    void activate(ViewportTool* tool);

    QActionGroup* actions() const { return m_group; }
    // Fills `tools` with one checkable button per tool and `options` with the active
    // tool's settings; `options` gets the height of the tallest tool's settings, for good.
    void populate(QToolBar* tools, QToolBar* options);

signals:
    void activeToolChanged(ViewportTool* tool);

private:
    void showOptions();
    void fillOptions(ViewportTool* tool);

    Viewport& m_viewport;
    std::vector<ViewportTool*> m_tools;
    ViewportTool* m_active = nullptr;
    QActionGroup* m_group = nullptr;
    QToolBar* m_optionsBar = nullptr;
};

}  // namespace throng::editor
