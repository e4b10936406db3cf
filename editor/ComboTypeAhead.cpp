#include "editor/ComboTypeAhead.h"

#include <QComboBox>
#include <QEvent>
#include <QKeyEvent>

namespace throng::editor {

namespace {

class TypeAhead : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::ShortcutOverride) {
            const auto* key = static_cast<QKeyEvent*>(event);
            if (!key->text().isEmpty() && key->text().front().isPrint() &&
                !(key->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))) {
                event->accept();
                return true;
            }
        }
        return QObject::eventFilter(watched, event);
    }
};

}  // namespace

void keepTypedLetters(QComboBox* combo)
{
    combo->installEventFilter(new TypeAhead(combo));
}

}  // namespace throng::editor
