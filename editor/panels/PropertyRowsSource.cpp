// The properties panel's rows for sources: the type (or its mix, read only), where agents
// come in, how often, where they go, how many and which way they face.
#include "editor/panels/PropertyRows.h"

#include "editor/commands/NameReferences.h"
#include "editor/panels/PropertyForm.h"

#include <glm/common.hpp>

#include <QLabel>

#include <algorithm>

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return PropertyForm::tr(text);
}

QStringList sourceRowNames(const std::vector<std::string>& names)
{
    QStringList out;
    for (const std::string& n : names)
        out << QString::fromStdString(n);
    return out;
}

// "commuter 3, tourist 1": a source's mix of types with their weights.
QString sourceMixText(const sim::Source& source)
{
    QStringList parts;
    for (const sim::SourceType& t : source.types)
        parts << QStringLiteral("%1 %2").arg(QString::fromStdString(t.type)).arg(double(t.weight));
    return parts.join(", ");
}

// "the whole run" or "0–60 s, 120–180 s".
QString sourceWindowsText(const sim::Source& source)
{
    if (source.windows.empty())
        return tr("the whole run");
    QStringList parts;
    for (glm::vec2 w : source.windows)
        parts << QStringLiteral("%1–%2 s").arg(double(w.x)).arg(double(w.y));
    return parts.join(", ");
}

// The source with its shape switched, carried over so it stays where it was: the rectangle
// round the line, or the line across the rectangle's middle along its longer side.
sim::Source withSourceShape(const sim::Source& now, sim::SourceShape shape)
{
    sim::Source next = now;
    next.shape = shape;
    if (shape == now.shape)
        return next;
    if (shape == sim::SourceShape::Rect) {
        next.min = glm::min(now.from, now.to);
        next.max = glm::max(now.from, now.to);
    } else {
        const glm::vec2 middle = 0.5f * (now.min + now.max), half = 0.5f * (now.max - now.min);
        const glm::vec2 along = half.x >= half.y ? glm::vec2(half.x, 0.0f) : glm::vec2(0.0f, half.y);
        next.from = middle - along;
        next.to = middle + along;
    }
    return next;
}

// A combo box of "(none)" and the names of `kind` (goals or paths) for the source's
// `field`. A source walks to a goal or along a path, never both: picking one clears the
// other in the same step.
void addSourceRoute(PropertyForm& form, const QString& key, const QString& label, ItemKind kind,
                    std::string sim::Source::*field, std::string sim::Source::*other)
{
    const PropertyForm::Locate<sim::Source> source = [](sim::Scene& s, std::size_t i) -> auto& { return s.sources[i]; };
    const auto names = [&form, kind] {
        return QStringList{PropertyForm::tr("(none)")} + sourceRowNames(namesOf(form.scene(), kind));
    };
    form.addIndexChoice(key, label, names, [&form, kind, field]() -> std::optional<int> {
        const auto value = form.common<std::string>([field](sim::Scene& s, std::size_t i) -> auto& {
            return s.sources[i].*field;
        });
        if (!value)
            return std::nullopt;
        const std::vector<std::string> all = namesOf(form.scene(), kind);
        const auto at = std::find(all.begin(), all.end(), *value);
        return at == all.end() ? 0 : int(at - all.begin()) + 1;
    }, [&form, key, label, kind, source, field, other](int index) {
        const std::vector<std::string> all = namesOf(form.scene(), kind);
        const std::string name = index <= 0 || index > int(all.size()) ? std::string() : all[std::size_t(index - 1)];
        form.applyEach<sim::Source>(key, label, source, [name, field, other](const sim::Source& now) {
            sim::Source next = now;
            next.*field = name;
            if (!name.empty())
                next.*other = std::string();
            return next;
        });
    });
}

}  // namespace

void addSourceRows(PropertyForm& form)
{
    form.addName();
    const PropertyForm::Locate<std::vector<sim::SourceType>> types = [](sim::Scene& s, std::size_t i) -> auto& {
        return s.sources[i].types;
    };
    // One type: a combo box of the scene's types. A mix is shown (read only) instead.
    const auto single = [](const sim::Scene& s, std::size_t i) { return s.sources[i].types.size() <= 1; };
    const auto typeNames = [&form] { return sourceRowNames(namesOf(form.scene(), ItemKind::AgentType)); };
    form.addIndexChoice("type", tr("Type"), typeNames,
                        [&form, types]() -> std::optional<int> {
                            const auto value = form.common(types);
                            if (!value || value->size() != 1)
                                return std::nullopt;
                            const std::vector<std::string> all = namesOf(form.scene(), ItemKind::AgentType);
                            const auto at = std::find(all.begin(), all.end(), value->front().type);
                            return at == all.end() ? std::nullopt : std::optional<int>(int(at - all.begin()));
                        },
                        [&form, types](int index) {
                            const std::vector<std::string> all = namesOf(form.scene(), ItemKind::AgentType);
                            if (index < 0 || index >= int(all.size()))
                                return;
                            form.apply("type", tr("Type"), types,
                                       std::vector<sim::SourceType>{{all[std::size_t(index)], 1.0f}});
                        },
                        single);
    auto* mix = new QLabel(form.owner());
    mix->setObjectName("types");
    mix->setWordWrap(true);
    form.addRow(tr("Types"), mix, [&form, mix] {
        const std::vector<std::size_t> items = form.indices();
        const bool mixed = std::any_of(items.begin(), items.end(), [&](std::size_t i) {
            return form.scene().sources[i].types.size() > 1;
        });
        form.setRowShown(mix, mixed);
        if (mixed && !items.empty())
            mix->setText(sourceMixText(form.scene().sources[items.front()]));
    });

    const PropertyForm::Locate<sim::Source> source = [](sim::Scene& s, std::size_t i) -> auto& { return s.sources[i]; };
    form.addIndexChoice("shape", tr("Enters on"), [] { return QStringList{tr("Line"), tr("Rectangle")}; }, [&form] {
        const auto shape = form.common<sim::SourceShape>([](sim::Scene& s, std::size_t i) -> auto& {
            return s.sources[i].shape;
        });
        return shape ? std::optional<int>(int(*shape)) : std::nullopt;
    }, [&form, source](int index) {
        form.applyEach<sim::Source>("shape", tr("Enters on"), source, [index](const sim::Source& now) {
            return withSourceShape(now, sim::SourceShape(index));
        });
    });
    form.addEnum<sim::Arrivals>("arrivals", tr("Arrivals"), {tr("Steady"), tr("Poisson")},
                                [](sim::Scene& s, std::size_t i) -> auto& { return s.sources[i].arrivals; });
    addSourceRoute(form, "goal", tr("Goal"), ItemKind::Goal, &sim::Source::goal, &sim::Source::path);
    addSourceRoute(form, "path", tr("Path"), ItemKind::Path, &sim::Source::path, &sim::Source::goal);
    // A source's agents choose their exit or have a goal or a path: exits clear those.
    addExitsRow(form, [](sim::Scene& s, std::size_t i) -> auto& { return s.sources[i].exits; },
                [&form, source](const std::vector<std::string>& names) {
                    form.applyEach<sim::Source>("exits", tr("Exits"), source, [names](const sim::Source& now) {
                        sim::Source out = now;
                        out.exits = names;
                        if (!names.empty()) {
                            out.goal.clear();
                            out.path.clear();
                        }
                        return out;
                    });
                },
                {"goal", "path"});
    form.addInteger<std::uint32_t>("cap", tr("Cap (0 = none)"), 0, 10000000,
                                   [](sim::Scene& s, std::size_t i) -> auto& { return s.sources[i].cap; });
    form.addCheck("headed", tr("Sets heading"),
                  [](sim::Scene& s, std::size_t i) -> auto& { return s.sources[i].headed; });
    form.addNumberFields();  // the line's ends or the rectangle's corners, rate, heading
    form.addInfo("windows", tr("Windows"),
                 [](const sim::Scene& s, std::size_t i) { return sourceWindowsText(s.sources[i]); });
}

}  // namespace throng::editor
