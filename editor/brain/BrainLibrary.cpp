#include "editor/brain/BrainLibrary.h"

#include "editor/brain/AutoLayout.h"
#include "simcore/io/SceneIO.h"

#include <QFileInfo>

namespace throng::editor::brainlib {

State current(const sim::Scene& scene)
{
    State s{scene.brains, scene.agentTypes, {}};
    for (std::size_t i = 0; i < scene.agents.size(); ++i)
        if (!scene.agents[i].brain.empty())
            s.agentBrains.emplace_back(i, scene.agents[i].brain);
    return s;
}

std::string uniqueName(const sim::Scene& scene, const std::string& base)
{
    std::string name = base;
    for (int n = 2; scene.findBrain(name); ++n)
        name = base + " " + std::to_string(n);
    return name;
}

State added(const sim::Scene& scene, const std::string& base)
{
    State s = current(scene);
    sim::BrainGraph g;
    g.name = uniqueName(scene, base);
    s.brains.push_back(g);
    return s;
}

std::optional<State> renamed(const sim::Scene& scene, std::size_t brain, const std::string& name, QString* problem)
{
    if (brain >= scene.brains.size())
        return std::nullopt;
    const std::string old = scene.brains[brain].name;
    if (name.empty() || (name != old && scene.findBrain(name))) {
        if (problem)
            *problem = name.empty() ? QObject::tr("A brain needs a name")
                                    : QObject::tr("The scene already has a brain named '%1'").arg(QString::fromStdString(name));
        return std::nullopt;
    }
    State s = current(scene);
    s.brains[brain].name = name;
    for (sim::AgentType& t : s.agentTypes)
        if (t.brain == old)
            t.brain = name;
    for (auto& [agent, brain] : s.agentBrains)
        if (brain == old)
            brain = name;
    for (sim::BrainGraph& g : s.brains)
        for (sim::BrainNode& n : g.nodes)
            if (n.type == "macro")
                for (sim::BrainParam& p : n.params)
                    if (p.key == "brain" && p.text == old)
                        p.text = name;
    return s;
}

State duplicated(const sim::Scene& scene, std::size_t brain)
{
    State s = current(scene);
    if (brain >= scene.brains.size())
        return s;
    sim::BrainGraph copy = scene.brains[brain];
    copy.name = uniqueName(scene, copy.name + " copy");
    copy.file.clear();
    copy.source = {};
    s.brains.push_back(copy);
    return s;
}

State removed(const sim::Scene& scene, std::size_t brain)
{
    State s = current(scene);
    if (brain >= scene.brains.size())
        return s;
    const std::string name = s.brains[brain].name;
    s.brains.erase(s.brains.begin() + std::ptrdiff_t(brain));
    for (sim::AgentType& t : s.agentTypes)
        if (t.brain == name)
            t.brain.clear();
    for (auto& [agent, brain] : s.agentBrains)
        if (brain == name)
            brain.clear();
    return s;
}

State assigned(const sim::Scene& scene, std::size_t agentType, const std::string& brainName)
{
    State s = current(scene);
    if (agentType < s.agentTypes.size())
        s.agentTypes[agentType].brain = brainName;
    return s;
}

std::optional<State> imported(const sim::Scene& scene, const QString& path, QString* problem)
{
    const QFileInfo info(path);
    // The scene reader is the one place that reads brain files: let it read this one as a
    // scene's brain reference, so errors carry the brain file's line and column.
    const std::string yaml = "throng: 1\nbrains: [{name: imported, file: \"" +
                             info.fileName().toStdString() + "\"}]\n";
    const sim::LoadResult r = sim::parseScene(yaml, "import.yaml", info.absolutePath().toStdString());
    if (!r.ok() || r.scene.brains.empty()) {
        if (problem) {
            QStringList lines;
            for (const sim::Diagnostic& d : r.diagnostics)
                lines << QString::fromStdString(d.format());
            *problem = lines.join('\n');
        }
        return std::nullopt;
    }
    sim::BrainGraph g = r.scene.brains.front();
    QString base = info.fileName();
    base.chop(base.endsWith(".brain.yaml") ? 11 : int(info.suffix().size() + 1));
    g.name = uniqueName(scene, base.toStdString());
    g.file.clear();
    g.source = {};
    if (needsLayout(g))
        autoLayout(g);
    State s = current(scene);
    s.brains.push_back(std::move(g));
    return s;
}

bool exportBrain(const sim::Scene& scene, std::size_t brain, const QString& path, QString* problem)
{
    if (brain >= scene.brains.size())
        return false;
    const sim::SaveResult r = sim::writeFileAtomically(path.toStdString(), sim::brainToYaml(scene.brains[brain]));
    if (!r.ok && problem)
        *problem = QString::fromStdString(r.error);
    return r.ok;
}

}  // namespace throng::editor::brainlib
