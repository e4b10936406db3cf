#include "editor/ShortcutToolTips.h"

#include <QAction>
#include <QWidget>

namespace throng::editor {

void nameShortcutsInToolTips(QWidget& root)
{
    for (QAction* action : root.findChildren<QAction*>()) {
        if (action->shortcut().isEmpty())
            continue;
        const QString keys = action->shortcut().toString(QKeySequence::NativeText);
        QString tip = action->toolTip();
        if (tip.contains(keys))
            continue;
        // Qt's default tooltip is the text without its mnemonic.
        if (tip.isEmpty())
            tip = action->text().remove('&');
        action->setToolTip(QStringLiteral("%1 (%2)").arg(tip, keys));
    }
}

}  // namespace throng::editor
