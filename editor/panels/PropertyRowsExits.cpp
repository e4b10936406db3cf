// The properties panel's row of exits that a group's or a source's agents choose among
// (ExitChoice.h), typed as a list of goal names and checked as the scene file checks them.
#include "editor/panels/PropertyRows.h"

#include "editor/panels/PropertyForm.h"

#include <QComboBox>
#include <QLineEdit>
#include <QSignalBlocker>

#include <algorithm>

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return PropertyForm::tr(text);
}

// Why `names` cannot be exits to choose among, or empty: at least two, each an exit goal,
// none twice (none at all gives the choice up).
QString exitsProblem(const sim::Scene& scene, const std::vector<std::string>& names)
{
    if (names.size() == 1)
        return tr("List at least two exits to choose among, or none; the exits stay as they were.");
    for (std::size_t k = 0; k < names.size(); ++k) {
        const sim::Goal* goal = scene.findGoal(names[k]);
        const QString name = QString::fromStdString(names[k]);
        if (!goal)
            return tr("There is no goal named \"%1\"; the exits stay as they were.").arg(name);
        if (!goal->exit)
            return tr("Goal \"%1\" is not an exit; the exits stay as they were.").arg(name);
        if (std::find(names.begin(), names.begin() + std::ptrdiff_t(k), names[k]) != names.begin() + std::ptrdiff_t(k))
            return tr("\"%1\" is listed twice; the exits stay as they were.").arg(name);
    }
    return QString();
}

QString shown(const std::vector<std::string>& names)
{
    QStringList out;
    for (const std::string& n : names)
        out << QString::fromStdString(n);
    return out.join(", ");
}

}  // namespace

void addExitsRow(PropertyForm& form, std::function<std::vector<std::string>&(sim::Scene&, std::size_t)> exits,
                 std::function<void(const std::vector<std::string>&)> apply, const QStringList& routeRows)
{
    using Names = std::vector<std::string>;
    std::vector<QWidget*> routes;
    for (const QString& key : routeRows)
        routes.push_back(form.owner()->findChildren<QComboBox*>(key).last());
    auto* edit = new QLineEdit(form.owner());
    edit->setObjectName("exits");
    edit->setPlaceholderText(tr("none: a goal or a path instead"));
    edit->setToolTip(tr("Exit goals the agents choose among, separated by commas: each takes the one it expects to "
                        "leave by soonest (its walk there, or the queue ahead of it)"));
    QObject::connect(edit, &QLineEdit::editingFinished, &form, [&form, edit, exits, apply] {
        const std::optional<Names> now = form.common<Names>(exits);
        if ((!now && edit->text() == tr("(mixed)")) || (now && edit->text() == shown(*now)))
            return;
        Names names;
        for (const QString& part : edit->text().split(',', Qt::SkipEmptyParts))
            if (!part.trimmed().isEmpty())
                names.push_back(part.trimmed().toStdString());
        if (const QString why = exitsProblem(form.scene(), names); !why.isEmpty()) {
            form.refuse(edit, why);
            return;
        }
        edit->setToolTip(QString());
        apply(names);
    });
    form.addRow(tr("Exits"), edit, [&form, edit, exits, routes] {
        const QSignalBlocker block(edit);
        const std::optional<Names> value = form.common<Names>(exits);
        edit->setText(value ? shown(*value) : tr("(mixed)"));
        auto& scene = const_cast<sim::Scene&>(form.scene());  // read only
        const std::vector<std::size_t> items = form.indices();
        const bool choosing = std::any_of(items.begin(), items.end(), [&](std::size_t i) {
            return !exits(scene, i).empty();
        });
        for (QWidget* row : routes)
            form.setRowShown(row, !choosing);
    });
}

}  // namespace throng::editor
