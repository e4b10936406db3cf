#include "editor/tools/AssignBrushTool.h"

#include "editor/SceneDocument.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>

#include <algorithm>
#include <set>

namespace throng::editor {

bool AssignBrushTool::editAgent(sim::Agent& agent, glm::vec2, glm::vec2, int) const
{
    const sim::Agent before = agent;
    if (m_settings.type)
        agent.type = *m_settings.type;
    if (m_settings.goal)
        agent.goal = *m_settings.goal;
    if (m_settings.path)
        agent.path = *m_settings.path;
    if (m_settings.brain)
        agent.brain = *m_settings.brain;
    if (m_settings.group)
        agent.group = *m_settings.group;
    return !(agent == before);
}

QWidget* AssignBrushTool::createOptionsWidget(QWidget* parent)
{
    const sim::Scene& scene = document().scene();
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    addRadiusOption(box, row, objectKey() + "Radius");
    // Each combo: "(keep)" first, then "(none)" where none is allowed, then the names. The
    // item data holds the name, or nothing for keep.
    auto addChoice = [&](const QString& label, const QString& key, std::optional<std::string>& field,
                         const std::vector<std::string>& names, bool noneAllowed) {
        auto* combo = new QComboBox(box);
        combo->setObjectName(key);
        combo->addItem(tr("(keep)"));
        if (noneAllowed)
            combo->addItem(tr("(none)"), QString());
        for (const std::string& n : names)
            combo->addItem(QString::fromStdString(n), QString::fromStdString(n));
        if (field)
            combo->setCurrentIndex(std::max(0, combo->findData(QString::fromStdString(*field))));
        connect(combo, &QComboBox::currentIndexChanged, this, [combo, &field](int) {
            const QVariant data = combo->currentData();
            field = data.isValid() ? std::optional(data.toString().toStdString()) : std::nullopt;
        });
        row->addWidget(new QLabel(label, box));
        row->addWidget(combo);
    };
    std::vector<std::string> types, goals, paths;
    for (const sim::AgentType& t : scene.agentTypes)
        if (t.kind != sim::AgentKind::Vehicle)
            types.push_back(t.name);
    for (const sim::Goal& g : scene.goals)
        goals.push_back(g.name);
    for (const sim::Path& p : scene.paths)
        paths.push_back(p.name);
    addChoice(tr("Type"), "assignType", m_settings.type, types, false);
    addChoice(tr("Goal"), "assignGoal", m_settings.goal, goals, true);
    addChoice(tr("Path"), "assignPath", m_settings.path, paths, true);
    std::vector<std::string> brains;
    for (const sim::BrainGraph& b : scene.brains)
        brains.push_back(b.name);
    addChoice(tr("Brain"), "assignBrain", m_settings.brain, brains, true);
    if (auto* brain = box->findChild<QComboBox*>("assignBrain"))
        brain->setItemText(1, tr("(type's)"));
    addGroupChoice(box, row);
    return box;
}

// The group combo is editable: typing a name not listed yet starts a new group.
void AssignBrushTool::addGroupChoice(QWidget* box, QHBoxLayout* row)
{
    std::set<std::string> groups;
    for (const sim::Agent& a : document().scene().agents)
        if (!a.group.empty())
            groups.insert(a.group);
    auto* combo = new QComboBox(box);
    combo->setObjectName("assignGroup");
    combo->setEditable(true);
    combo->setInsertPolicy(QComboBox::NoInsert);
    combo->setToolTip(tr("The group to put the agents in; type a name for a new group"));
    const QString keep = tr("(keep)"), none = tr("(none)");
    combo->addItem(keep);
    combo->addItem(none);
    for (const std::string& g : groups)
        combo->addItem(QString::fromStdString(g));
    combo->setCurrentText(m_settings.group ? (m_settings.group->empty() ? none : QString::fromStdString(*m_settings.group))
                                           : keep);
    connect(combo, &QComboBox::currentTextChanged, this, [this, keep, none](const QString& text) {
        const QString name = text.trimmed();
        m_settings.group = name == keep || name.isEmpty() ? std::nullopt
                           : name == none                 ? std::optional(std::string())
                                                          : std::optional(name.toStdString());
    });
    row->addWidget(new QLabel(tr("Group"), box));
    row->addWidget(combo);
}

}  // namespace throng::editor
