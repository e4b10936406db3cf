#include "editor/tools/CrowdBrushTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/PaintAgentsCommand.h"
#include "editor/tools/TypeMixButton.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>

namespace throng::editor {

namespace {
// A new dab every quarter radius keeps the density even along fast strokes.
constexpr float kCrowdDabSpacingRadii = 0.25f;
int g_nextStrokeId = 1;
}  // namespace

CrowdBrushTool::CrowdBrushTool(SceneDocument& document, Viewport& viewport, QObject* parent)
    : BrushTool(document, viewport, CrowdBrushSettings{}.radiusM, parent)
{
}

QString CrowdBrushTool::toolTip() const
{
    return tr("Crowd Brush (B): drag on the ground to paint agents at the chosen density, "
              "never inside walls or obstacles; [ and ] or Ctrl+drag size the brush");
}

bool CrowdBrushTool::strokeAllowed()
{
    if (!document().scene().agentTypes.empty())
        return true;
    emit agentTypeNeeded();  // nothing to paint with: the main window offers a type
    return false;
}

void CrowdBrushTool::strokeBegan(glm::vec2 point)
{
    m_strokeId = g_nextStrokeId++;
    m_dabIndex = 0;
    m_strokeAgents = 0;
    m_lastDab = point;
    dab(point, glm::vec2(0.0f));
}

void CrowdBrushTool::strokeMoved(glm::vec2 point)
{
    const float step = std::max(0.05f, radiusM() * kCrowdDabSpacingRadii);
    // Dabs at even spacing along the segment, so a fast move leaves no gaps.
    while (glm::length(point - m_lastDab) >= step) {
        const glm::vec2 dir = glm::normalize(point - m_lastDab);
        m_lastDab += dir * step;
        dab(m_lastDab, dir);
    }
}

void CrowdBrushTool::dab(glm::vec2 centre, glm::vec2 direction)
{
    CrowdBrushSettings settings = m_settings;
    settings.radiusM = radiusM();
    const std::uint64_t seed = (std::uint64_t(m_strokeId) << 32) ^ std::uint64_t(m_dabIndex++);
    std::vector<sim::Agent> agents = placeDab(document().scene(), {}, centre, direction, settings, seed);
    if (agents.empty())
        return;
    std::uint32_t id = document().nextAgentId();
    for (sim::Agent& a : agents)
        a.id = id++;
    m_strokeAgents += agents.size();
    document().undoStack()->push(new PaintAgentsCommand(document(), std::move(agents), m_strokeId));
}

QWidget* CrowdBrushTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    addRadiusOption(box, row, "brushRadius");
    auto addSpin = [&](const QString& label, const QString& key, double lo, double hi, double step, float& field,
                       const QString& tip) {
        auto* spin = new QDoubleSpinBox(box);
        spin->setObjectName(key);
        spin->setRange(lo, hi);
        spin->setSingleStep(step);
        spin->setDecimals(2);
        spin->setValue(double(field));
        spin->setToolTip(tip);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [&field](double v) { field = float(v); });
        row->addWidget(new QLabel(label, box));
        row->addWidget(spin);
    };
    addSpin(tr("Density"), "brushDensity", 0.01, 10.0, 0.05, m_settings.densityPerM2,
            tr("Agents per square metre inside the brush"));
    addSpin(tr("Spacing"), "brushSpacing", 0.0, 20.0, 0.1, m_settings.minSpacingM,
            tr("Least distance between agents in metres (Poisson-disc)"));
    auto* heading = new QComboBox(box);
    heading->setObjectName("brushHeading");
    heading->addItems({tr("Random"), tr("Along stroke"), tr("Toward point")});
    heading->setCurrentIndex(int(m_settings.heading));
    heading->setToolTip(tr("Which way new agents face"));
    connect(heading, &QComboBox::currentIndexChanged, this,
            [this](int i) { m_settings.heading = HeadingMode(i); });
    row->addWidget(new QLabel(tr("Heading"), box));
    row->addWidget(heading);
    auto* mix = new TypeMixButton(
        m_settings.mix,
        [this] {
            std::vector<std::string> names;
            for (const sim::AgentType& t : document().scene().agentTypes)
                if (t.kind != sim::AgentKind::Vehicle)
                    names.push_back(t.name);
            return names;
        },
        [this] { return defaultBrushType(document().scene()); }, box);
    connect(mix, &TypeMixButton::mixChanged, this, [this](const std::vector<TypeShare>& m) { m_settings.mix = m; });
    row->addWidget(new QLabel(tr("Mix"), box));
    row->addWidget(mix);
    return box;
}

}  // namespace throng::editor
