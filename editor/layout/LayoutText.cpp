#include "editor/layout/LayoutText.h"

#include <QCoreApplication>
#include <QStringList>

namespace throng::editor {

namespace {

QString tr(const char* text, int n = -1)
{
    return QCoreApplication::translate("LayoutText", text, nullptr, n);
}

constexpr int kIdsShown = 6;  // ids listed before "and N more"

QString names(const std::vector<std::string>& list)
{
    QStringList out;
    for (const std::string& name : list)
        out << QString::fromStdString(name);
    return out.join(", ");
}

QString point(glm::vec2 p)
{
    return QStringLiteral("(%1, %2)").arg(double(p.x), 0, 'f', 2).arg(double(p.y), 0, 'f', 2);
}

}  // namespace

QString selectorText(const sim::AgentSelector& agents)
{
    QStringList parts;
    if (!agents.ids.empty()) {
        QStringList ids;
        for (std::size_t k = 0; k < agents.ids.size() && k < kIdsShown; ++k)
            ids << QString::number(agents.ids[k]);
        QString text = (agents.ids.size() == 1 ? tr("agent %1") : tr("agents %1")).arg(ids.join(", "));
        if (agents.ids.size() > kIdsShown)
            text += tr(" and %n more", int(agents.ids.size() - kIdsShown));
        parts << text;
    }
    if (!agents.groups.empty())
        parts << (agents.groups.size() == 1 ? tr("group %1") : tr("groups %1")).arg(names(agents.groups));
    if (!agents.types.empty())
        parts << (agents.types.size() == 1 ? tr("type %1") : tr("types %1")).arg(names(agents.types));
    if (!agents.lasso.empty())
        parts << tr("a lasso on frame %1").arg(agents.lassoFrame);
    return parts.isEmpty() ? tr("nobody") : parts.join("; ");
}

QString framesText(const sim::LayoutOp& op)
{
    if (op.lastFrame == sim::kLastFrame)
        return op.firstFrame == 0 ? tr("every frame") : tr("from frame %1 on").arg(op.firstFrame);
    if (op.firstFrame == op.lastFrame)
        return tr("frame %1").arg(op.firstFrame);
    return tr("frames %1 to %2").arg(op.firstFrame).arg(op.lastFrame);
}

QString effectText(const sim::LayoutOp& op)
{
    switch (op.kind) {
    case sim::LayoutKind::Translate: return tr("by %1 m").arg(point(op.offset));
    case sim::LayoutKind::Rotate:
        return op.pivot ? tr("by %1° about %2").arg(double(op.angleDeg), 0, 'f', 1).arg(point(*op.pivot))
                        : tr("by %1° about their centre").arg(double(op.angleDeg), 0, 'f', 1);
    case sim::LayoutKind::TimeOffset: {
        const QString shift =
            op.frames >= 0 ? tr("%n frame(s) later", op.frames) : tr("%n frame(s) earlier", -op.frames);
        return op.holdFirst ? tr("%1, holding the first pose").arg(shift) : tr("%1, absent before").arg(shift);
    }
    case sim::LayoutKind::Mirror: return tr("across %1 to %2").arg(point(op.axis[0]), point(op.axis[1]));
    case sim::LayoutKind::Delete: return tr("removed");
    case sim::LayoutKind::Expand: return tr("spread ×%1").arg(double(op.factor), 0, 'f', 2);
    case sim::LayoutKind::Duplicate: return tr("copied %1 m away").arg(point(op.offset));
    case sim::LayoutKind::Swap: {
        QStringList what;
        if (!op.type.empty())
            what << tr("as %1").arg(QString::fromStdString(op.type));
        if (op.look >= 0)
            what << tr("look %1").arg(op.look + 1);
        if (op.tint == -1)
            what << tr("untinted");
        else if (op.tint >= 0)
            what << tr("tint %1").arg(op.tint + 1);
        return what.isEmpty() ? tr("shown as drawn") : what.join(", ");
    }
    case sim::LayoutKind::ReplaceClip: return tr("playing %1").arg(QString::fromLatin1(sim::toString(op.clip)));
    case sim::LayoutKind::Resolve: return tr("nudged apart where the edits above made bodies overlap");
    }
    return {};
}

QString layoutSummary(const sim::LayoutOp& op)
{
    if (op.kind == sim::LayoutKind::Resolve && op.agents == sim::AgentSelector{})
        return QStringLiteral("%1 · %2 · %3").arg(tr("every edited agent"), effectText(op), framesText(op));
    return QStringLiteral("%1 · %2 · %3").arg(selectorText(op.agents), effectText(op), framesText(op));
}

}  // namespace throng::editor
