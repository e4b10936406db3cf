// How a group's members keep together (Formations.h): its formation's shape, spacing and
// column width, or its companions' group sizes, typed as "2 to 4". A formation and
// companions exclude each other (setting one clears the other in the same step); both
// are for groups that go to one place (fliers: a formation only), and anything else is
// refused with why.
#include "editor/panels/PropertyRows.h"

#include "editor/panels/PropertyForm.h"

#include <QComboBox>
#include <QLineEdit>
#include <QRegularExpression>
#include <QSignalBlocker>

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return PropertyForm::tr(text);
}

const PropertyForm::Locate<sim::SpawnGroup> kGroup = [](sim::Scene& s, std::size_t i) -> sim::SpawnGroup& {
    return s.groups[i];
};

// Why group i cannot keep together, or empty: walkers may hold a formation or walk as
// companions, fliers only fly in formation.
QString keepTogetherProblem(const sim::Scene& s, std::size_t i, bool companions)
{
    const sim::SpawnGroup& g = s.groups[i];
    const sim::AgentType* type = s.findAgentType(g.type);
    if (type && type->kind == sim::AgentKind::Vehicle)
        return tr("%1: vehicles hold no formation; it stays as it is.").arg(QString::fromStdString(g.name));
    if (type && companions && type->kind != sim::AgentKind::Pedestrian)
        return tr("%1: only walkers walk as companions; it stays as it is.").arg(QString::fromStdString(g.name));
    if (!g.exits.empty())
        return tr("%1 chooses among exits: members that keep together walk to one place. Give it a goal or a path "
                  "first; it stays as it is.")
            .arg(QString::fromStdString(g.name));
    return QString();
}

QString companionsText(glm::uvec2 c)
{
    return c.y < 2 ? QString() : tr("%1 to %2").arg(c.x).arg(c.y);
}

}  // namespace

void addKeepTogetherRows(PropertyForm& form)
{
    const QStringList shapes{tr("None"), tr("Line"), tr("Column"), tr("Wedge")};
    form.addIndexChoice("formation", tr("Formation"), [shapes] { return shapes; }, [&form]() -> std::optional<int> {
        const auto shape = form.common<sim::FormationShape>([](sim::Scene& s, std::size_t i) -> auto& {
            return s.groups[i].formation.shape;
        });
        return shape ? std::optional<int>(int(*shape)) : std::nullopt;
    }, [&form](int index) {
        const auto shape = sim::FormationShape(index);
        if (shape != sim::FormationShape::None)
            for (std::size_t i : form.indices())
                if (const QString why = keepTogetherProblem(form.scene(), i, false); !why.isEmpty()) {
                    form.refuse(form.owner()->findChild<QComboBox*>("formation"), why);
                    return;
                }
        const sim::Scene& scene = form.scene();
        form.applyEach<sim::SpawnGroup>("formation", tr("Formation"), kGroup,
                                        [shape, &scene](const sim::SpawnGroup& now) {
            sim::SpawnGroup out = now;
            out.formation.shape = shape;
            if (shape != sim::FormationShape::None) {
                out.companions = glm::uvec2(0u);
                // Room for two bodies at least, as the file requires.
                if (const sim::AgentType* type = scene.findAgentType(now.type))
                    out.formation.spacingM = std::max(out.formation.spacingM, 2.0f * type->radiusM + 0.1f);
            }
            return out;
        });
    });
    form.addInteger<std::uint32_t>("formationWidth", tr("Column width (walkers)"), 1, 1000,
                                   [](sim::Scene& s, std::size_t i) -> auto& { return s.groups[i].formation.width; });

    auto* edit = new QLineEdit(form.owner());
    edit->setObjectName("companions");
    edit->setPlaceholderText(tr("none"));
    edit->setToolTip(tr("Walk in small groups of this many, such as \"2 to 4\": families and friends, abreast where "
                        "there is room; empty for none"));
    QObject::connect(edit, &QLineEdit::editingFinished, &form, [&form, edit] {
        const std::optional<glm::uvec2> now = form.common<glm::uvec2>([](sim::Scene& s, std::size_t i) -> auto& {
            return s.groups[i].companions;
        });
        if ((!now && edit->text() == tr("(mixed)")) || (now && edit->text() == companionsText(*now)))
            return;
        static const QRegularExpression number(R"([0-9]+)");
        std::vector<unsigned> sizes;
        for (auto it = number.globalMatch(edit->text()); it.hasNext();)
            sizes.push_back(it.next().captured(0).toUInt());
        const QString rest = QString(edit->text()).remove(number).remove(QRegularExpression(R"([\s,\-]|to)"));
        if (sizes.size() > 2 || !rest.isEmpty()) {
            form.refuse(edit, tr("Type two sizes, such as \"2 to 4\", or nothing for none; the companions stay as they "
                                 "were."));
            return;
        }
        const glm::uvec2 size = sizes.empty() ? glm::uvec2(0u) : glm::uvec2(sizes.front(), sizes.back());
        if (!sizes.empty() && (size.x < 1 || size.x > size.y || size.y < 2 || size.y > 8)) {
            form.refuse(edit, tr("Small groups of 1 to 8, the second size at least 2 and not below the first; the "
                                 "companions stay as they were."));
            return;
        }
        if (!sizes.empty())
            for (std::size_t i : form.indices())
                if (const QString why = keepTogetherProblem(form.scene(), i, true); !why.isEmpty()) {
                    form.refuse(edit, why);
                    return;
                }
        edit->setToolTip(QString());
        form.applyEach<sim::SpawnGroup>("companions", tr("Companions"), kGroup, [size](const sim::SpawnGroup& now) {
            sim::SpawnGroup out = now;
            out.companions = size;
            if (size.y >= 2)
                out.formation.shape = sim::FormationShape::None;
            return out;
        });
    });
    form.addRow(tr("Companions"), edit, [&form, edit] {
        const QSignalBlocker block(edit);
        const auto value = form.common<glm::uvec2>([](sim::Scene& s, std::size_t i) -> auto& {
            return s.groups[i].companions;
        });
        edit->setText(value ? companionsText(*value) : tr("(mixed)"));
    });
}

}  // namespace throng::editor
