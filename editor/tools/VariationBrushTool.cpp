#include "editor/tools/VariationBrushTool.h"

#include "editor/SceneDocument.h"
#include "simcore/base/Rng.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSpinBox>

#include <algorithm>

namespace throng::editor {

namespace {
// Streams of the brush's own draws, keyed by (stroke, agent id).
constexpr std::uint64_t kTintStream = 1, kLookStream = 2, kHeightStream = 3;

int drawIndex(int strokeId, std::uint32_t agentId, std::uint64_t stream, std::size_t count)
{
    const auto i = std::size_t(sim::rngUniform(std::uint64_t(strokeId), agentId, 0, stream) * float(count));
    return int(std::min(i, count - 1));
}
}  // namespace

bool VariationBrushTool::editAgent(sim::Agent& agent, glm::vec2, glm::vec2, int strokeId) const
{
    const sim::AgentType* type = document().scene().findAgentType(agent.type);
    if (!type)
        return false;
    const sim::Agent before = agent;
    const std::size_t tints = type->variation.tints.size();
    const std::size_t looks = std::max<std::size_t>(1, type->variation.looks.size());
    const VariationBrushSettings& s = m_settings;
    if (s.setTint && tints > 0)
        agent.tint = s.tint >= 0 ? std::min(s.tint, int(tints) - 1) : drawIndex(strokeId, agent.id, kTintStream, tints);
    if (s.setLook)
        agent.look = s.look >= 0 ? std::min(s.look, int(looks) - 1) : drawIndex(strokeId, agent.id, kLookStream, looks);
    if (s.setHeight)
        agent.heightScale = sim::rngRange(std::uint64_t(strokeId), agent.id, 0, kHeightStream, s.heightMin,
                                          std::max(s.heightMin, s.heightMax));
    return !(agent == before);
}

QWidget* VariationBrushTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    addRadiusOption(box, row, objectKey() + "Radius");
    auto addIndex = [&](const QString& label, const QString& key, bool& on, int& value, const QString& tip) {
        auto* check = new QCheckBox(label, box);
        check->setObjectName(key + "Check");
        check->setChecked(on);
        connect(check, &QCheckBox::toggled, this, [&on](bool v) { on = v; });
        // Numbered from 1 as Properties shows them (0 = random); the settings keep indices.
        auto* spin = new QSpinBox(box);
        spin->setObjectName(key + "Index");
        spin->setRange(0, 64);
        spin->setSpecialValueText(tr("random"));
        spin->setValue(value + 1);
        spin->setToolTip(tip);
        connect(spin, &QSpinBox::valueChanged, this, [&value](int v) { value = v - 1; });
        row->addWidget(check);
        row->addWidget(spin);
    };
    addIndex(tr("Tint"), "variationTint", m_settings.setTint, m_settings.tint,
             tr("Tint of the type's palette, 1 = the first as in Properties, or random per agent"));
    addIndex(tr("Look"), "variationLook", m_settings.setLook, m_settings.look,
             tr("Look of the type, 1 = the first as in Properties, or random per agent"));
    auto* height = new QCheckBox(tr("Height"), box);
    height->setObjectName("variationHeightCheck");
    height->setChecked(m_settings.setHeight);
    connect(height, &QCheckBox::toggled, this, [this](bool v) { m_settings.setHeight = v; });
    row->addWidget(height);
    for (float* field : {&m_settings.heightMin, &m_settings.heightMax}) {
        auto* spin = new QDoubleSpinBox(box);
        spin->setObjectName(field == &m_settings.heightMin ? "variationHeightMin" : "variationHeightMax");
        spin->setRange(0.2, 3.0);
        spin->setSingleStep(0.05);
        spin->setValue(double(*field));
        spin->setToolTip(tr("Height scale range drawn per agent"));
        connect(spin, &QDoubleSpinBox::valueChanged, this, [field](double v) { *field = float(v); });
        row->addWidget(spin);
    }
    return box;
}

}  // namespace throng::editor
