#include "editor/brain/ParamText.h"

#include <QRegularExpression>
#include <QStringList>

namespace throng::editor {

QString parseParamText(const sim::ParamSpec& spec, const QString& text, sim::BrainParam& param)
{
    param = {spec.key, {}, {}};
    const QString key = QString::fromStdString(spec.key);
    const QString trimmed = text.trimmed();
    switch (spec.type) {
    case sim::ParamType::Text:
        if (trimmed.isEmpty())
            return QObject::tr("%1: type a name").arg(key);
        param.text = trimmed.toStdString();
        return {};
    case sim::ParamType::Choice:
        for (const std::string& c : spec.choices)
            if (trimmed.toStdString() == c) {
                param.text = c;
                return {};
            }
        return QObject::tr("%1: '%2' is not one of the choices").arg(key, trimmed);
    case sim::ParamType::Number:
    case sim::ParamType::Numbers:
        break;
    }
    const QStringList parts = trimmed.split(QRegularExpression("[\\s,;\\[\\]]+"), Qt::SkipEmptyParts);
    for (const QString& part : parts) {
        bool ok = false;
        const float v = part.toFloat(&ok);
        if (!ok)
            return QObject::tr("%1: '%2' is not a number").arg(key, part);
        if (v < spec.min || v > spec.max)
            return QObject::tr("%1: %2 is outside [%3, %4]").arg(key).arg(double(v)).arg(double(spec.min)).arg(double(spec.max));
        param.numbers.push_back(v);
    }
    if (spec.type == sim::ParamType::Number && param.numbers.size() != 1)
        return QObject::tr("%1: type one number").arg(key);
    if (spec.type == sim::ParamType::Numbers && spec.count > 0 && param.numbers.size() != spec.count)
        return QObject::tr("%1: type %2 numbers").arg(key).arg(spec.count);
    if (param.numbers.empty())
        return QObject::tr("%1: type a number").arg(key);
    return {};
}

}  // namespace throng::editor
