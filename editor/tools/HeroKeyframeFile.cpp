#include "editor/tools/HeroKeyframeFile.h"

#include <QCoreApplication>
#include <QFile>
#include <QRegularExpression>
#include <QTextStream>

#include <cmath>

namespace throng::editor {

KeyframeFileResult readKeyframeFile(const QString& path)
{
    KeyframeFileResult result;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        result.error = QCoreApplication::translate("HeroKeyframeFile", "%1: cannot open: %2").arg(path, file.errorString());
        return result;
    }
    QTextStream in(&file);
    static const QRegularExpression space(QStringLiteral("[ \t]+"));
    for (int lineNo = 1; !in.atEnd(); ++lineNo) {
        const QString raw = in.readLine();
        const QString line = raw.section('#', 0, 0);
        const QStringList tokens = line.split(space, Qt::SkipEmptyParts);
        if (tokens.isEmpty())
            continue;
        auto fail = [&](int column, const QString& why) {
            result.error = QStringLiteral("%1:%2:%3: %4").arg(path).arg(lineNo).arg(column).arg(why);
            result.positions.clear();
        };
        if (tokens.size() != 3) {
            fail(int(raw.indexOf(tokens.front())) + 1,
                 QCoreApplication::translate("HeroKeyframeFile", "expected 'x y z', got %n value(s)", nullptr,
                                             int(tokens.size())));
            return result;
        }
        glm::vec3 p;
        qsizetype from = 0;
        for (int c = 0; c < 3; ++c) {
            from = raw.indexOf(tokens[c], from);
            bool ok = false;
            p[c] = tokens[c].toFloat(&ok);
            if (!ok || !std::isfinite(p[c])) {
                fail(int(from) + 1, QCoreApplication::translate("HeroKeyframeFile", "'%1' is not a number").arg(tokens[c]));
                return result;
            }
            from += tokens[c].size();
        }
        result.positions.push_back(p);
    }
    if (result.positions.empty())
        result.error = QCoreApplication::translate("HeroKeyframeFile", "%1: no keyframes").arg(path);
    return result;
}

}  // namespace throng::editor
