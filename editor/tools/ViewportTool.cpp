#include "editor/tools/ViewportTool.h"

namespace throng::editor {

ViewportTool::ViewportTool(SceneDocument& document, Viewport& viewport, QObject* parent)
    : QObject(parent), m_document(document), m_viewport(viewport)
{
}

}  // namespace throng::editor
