#include "editor/tools/ToolManager.h"

#include "ToolList.h"  // generated from THRONG_EDITOR_TOOLS in editor/CMakeLists.txt

#include "editor/Icons.h"
#include "editor/viewport/Viewport.h"

#include <QAction>
#include <QActionGroup>
#include <QLabel>
#include <QToolBar>

#include <algorithm>

namespace throng::editor {

ToolManager::ToolManager(SceneDocument& document, Viewport& viewport, QObject* parent)
    : QObject(parent), m_viewport(viewport)
{
    m_tools = createListedTools(document, viewport, this);
    m_group = new QActionGroup(this);
    m_group->setExclusive(true);
    for (ViewportTool* t : m_tools) {
        QAction* action = m_group->addAction(t->name());
        action->setObjectName(t->objectKey() + "Action");
        action->setCheckable(true);
        action->setIcon(themeIcon(t->iconKey()));
        action->setShortcut(t->shortcut());
        action->setToolTip(t->toolTip());
        action->setStatusTip(t->toolTip());
        connect(action, &QAction::triggered, this, [this, t] { activate(t); });
    }
    activate(m_tools.front());
}

ViewportTool* ToolManager::tool(const QString& key) const
{
    for (ViewportTool* t : m_tools)
        if (t->objectKey() == key)
            return t;
    return nullptr;
}

void ToolManager::activate(ViewportTool* tool)
{
    if (tool == m_active)
        return;
    m_active = tool;
    m_viewport.setTool(tool);
    for (QAction* a : m_group->actions())
        if (a->objectName() == tool->objectKey() + "Action")
            a->setChecked(true);
    showOptions();
    emit activeToolChanged(tool);
}

void ToolManager::populate(QToolBar* tools, QToolBar* options)
{
    tools->addActions(m_group->actions());
    for (QAction* a : m_group->actions())
        if (QWidget* button = tools->widgetForAction(a))
            button->setObjectName(a->objectName().chopped(6) + "Button");
    m_optionsBar = options;
    // One height for every tool's options, so the viewport below never jumps on a switch;
    // only along the top or bottom, where that height is the bar's thickness.
    options->setAllowedAreas(Qt::TopToolBarArea | Qt::BottomToolBarArea);
    int tallest = 0;
    for (ViewportTool* t : m_tools) {
        fillOptions(t);
        tallest = std::max(tallest, options->sizeHint().height());
    }
    options->setFixedHeight(tallest);
    showOptions();
}

void ToolManager::showOptions()
{
    if (m_optionsBar)
        fillOptions(m_active);
}

void ToolManager::fillOptions(ViewportTool* tool)
{
    // clear() only hides the widgets; deleting their actions deletes them, so a switch
    // leaves one set of option widgets behind, not one per visit.
    const QList<QAction*> old = m_optionsBar->actions();
    m_optionsBar->clear();
    qDeleteAll(old);
    m_optionsBar->addWidget(new QLabel(tool->name() + "  ", m_optionsBar));
    if (QWidget* widget = tool->createOptionsWidget(m_optionsBar))
        m_optionsBar->addWidget(widget);
}

}  // namespace throng::editor
