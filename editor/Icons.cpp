#include "editor/Icons.h"

#include "editor/SvgIconEngine.h"

#include <QDir>
#include <QFile>
#include <QtGlobal>

// Q_INIT_RESOURCE must be called outside any namespace. The editor is a static library:
// without a call that names the resource, the linker drops the compiled icons.
static void initIconResources()
{
    Q_INIT_RESOURCE(icons);
}

namespace throng::editor {

namespace {

const QString kIconFolder = QStringLiteral(":/icons/");

void ensureResources()
{
    static const bool kLoaded = (initIconResources(), true);
    Q_UNUSED(kLoaded);
}

}  // namespace

QIcon themeIcon(const QString& key)
{
    ensureResources();
    const QString path = kIconFolder + key + QStringLiteral(".svg");
    if (!QFile::exists(path)) {
        qWarning("themeIcon: no icon named \"%s\" in %s", qPrintable(key), qPrintable(kIconFolder));
        return {};
    }
    return QIcon(new SvgIconEngine(path));
}

QStringList iconKeys()
{
    ensureResources();
    QStringList keys;
    const QStringList files = QDir(kIconFolder).entryList({QStringLiteral("*.svg")}, QDir::Files, QDir::Name);
    for (const QString& file : files)
        keys << file.chopped(4);
    return keys;
}

}  // namespace throng::editor
