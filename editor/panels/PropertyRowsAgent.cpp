// The properties panel's rows for what an agent carries besides its type and goals: the
// leader it follows (agents and groups), and its look, tint and height scale (variation
// set by hand; "(drawn)" leaves them to the type's variation).
#include "editor/panels/PropertyRows.h"

#include "editor/ComboTypeAhead.h"
#include "editor/panels/PropertyForm.h"

#include <QColor>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalBlocker>

#include <algorithm>

namespace throng::editor {

namespace {

constexpr std::size_t kMaxLeaders = 1000;  // listed in the combo box; the current one always

QString tr(const char* text)
{
    return PropertyForm::tr(text);
}

// The height scale: 0 shows "drawn" (the type's range decides), below 0 "(mixed)".
class HeightSpinBox : public QDoubleSpinBox {
public:
    using QDoubleSpinBox::QDoubleSpinBox;

protected:
    QString textFromValue(double value) const override
    {
        return value < 0.0 ? tr("(mixed)") : value == 0.0 ? tr("drawn") : QDoubleSpinBox::textFromValue(value);
    }
    double valueFromText(const QString& text) const override
    {
        return text == tr("drawn") ? 0.0 : text == tr("(mixed)") ? -1.0 : QDoubleSpinBox::valueFromText(text);
    }
    QValidator::State validate(QString& text, int& pos) const override
    {
        if (tr("drawn").startsWith(text) || tr("(mixed)").startsWith(text))
            return text == tr("drawn") || text == tr("(mixed)") ? QValidator::Acceptable : QValidator::Intermediate;
        return QDoubleSpinBox::validate(text, pos);
    }
};

// Who may lead: every placed agent, and the vehicles and heroes with an id, as
// (id, "3: agent walker").
std::vector<std::pair<std::uint32_t, QString>> leaders(const sim::Scene& s)
{
    std::vector<std::pair<std::uint32_t, QString>> out;
    for (const sim::Agent& a : s.agents)
        out.emplace_back(a.id, tr("%1: agent %2").arg(a.id).arg(QString::fromStdString(a.type)));
    for (const sim::Vehicle& v : s.vehicles)
        if (v.id != 0)
            out.emplace_back(v.id, tr("%1: vehicle %2").arg(v.id).arg(QString::fromStdString(v.type)));
    for (const sim::Hero& h : s.heroes)
        if (h.id != 0)
            out.emplace_back(h.id, tr("%1: hero %2").arg(h.id).arg(QString::fromStdString(h.name)));
    return out;
}

// The variation of the first selected agent's type (the lists the look and tint offer).
const sim::Variation* variationOf(const PropertyForm& form)
{
    const std::vector<std::size_t> items = form.indices();
    if (items.empty())
        return nullptr;
    const sim::AgentType* type = form.scene().findAgentType(form.scene().agents[items.front()].type);
    return type ? &type->variation : nullptr;
}

// An index into the type's looks or tints, "(drawn)" first (-1). `count` says how many
// an agent's type offers; a pick past that for any selected agent is refused.
void addVariationIndex(PropertyForm& form, const QString& key, const QString& label,
                       std::function<QStringList(const sim::Variation&)> names, std::function<int(const sim::Variation*)> count,
                       int sim::Agent::*member)
{
    const PropertyForm::Locate<int> locate = [member](sim::Scene& s, std::size_t i) -> int& { return s.agents[i].*member; };
    form.addIndexChoice(key, label, [&form, names] {
        QStringList list{tr("(drawn)")};
        if (const sim::Variation* v = variationOf(form))
            list << names(*v);
        return list;
    }, [&form, locate] {
        const std::optional<int> v = form.common(locate);
        return v ? std::optional<int>(*v + 1) : std::nullopt;
    }, [&form, key, label, count, locate](int index) {
        const int value = index - 1;
        for (std::size_t i : form.indices()) {
            const sim::Agent& a = form.scene().agents[i];
            const sim::AgentType* type = form.scene().findAgentType(a.type);
            if (value >= count(type ? &type->variation : nullptr)) {
                form.refuse(form.owner()->findChild<QComboBox*>(key),
                            tr("Agent %1's type %2 has no %3 %4; nothing changed.")
                                .arg(a.id)
                                .arg(QString::fromStdString(a.type), label.toLower())
                                .arg(value + 1));
                return;
            }
        }
        form.apply<int>(key, label, locate, value);
    });
}

}  // namespace

void addLeaderRow(PropertyForm& form, PropertyForm::Locate<std::uint32_t> locate, bool agents)
{
    auto* combo = new QComboBox(form.owner());
    combo->setObjectName("leader");
    keepTypedLetters(combo);
    QObject::connect(combo, &QComboBox::activated, &form, [&form, combo, locate, agents](int index) {
        const QVariant data = combo->itemData(index);
        if (!data.isValid())
            return;  // "(mixed)"
        const std::uint32_t id = data.toUInt();
        if (agents && id != 0)
            for (std::size_t i : form.indices())
                if (form.scene().agents[i].id == id) {
                    form.refuse(combo, tr("Agent %1 cannot lead itself; its leader stays as it was.").arg(id));
                    return;
                }
        combo->setToolTip(QString());
        form.apply<std::uint32_t>("leader", tr("Leader"), locate, id);
    });
    form.addRow(tr("Leader"), combo, [&form, combo, locate] {
        const QSignalBlocker block(combo);
        combo->clear();
        combo->addItem(tr("(none)"), 0u);
        const std::optional<std::uint32_t> value = form.common(locate);
        std::size_t listed = 0;
        for (const auto& [id, text] : leaders(form.scene()))
            if (++listed <= kMaxLeaders || (value && id == *value))
                combo->addItem(text, id);
        if (!value) {
            combo->insertItem(0, tr("(mixed)"));
            combo->setCurrentIndex(0);
            return;
        }
        int at = combo->findData(*value);
        if (at < 0) {  // an id nothing in the scene has
            combo->addItem(tr("%1: unknown").arg(*value), *value);
            at = combo->count() - 1;
        }
        combo->setCurrentIndex(at);
    });
}

void addAgentVariationRows(PropertyForm& form)
{
    addVariationIndex(form, "look", tr("Look"), [](const sim::Variation& v) {
        QStringList out;
        for (const std::string& look : v.looks)
            out << QString::fromStdString(look);
        if (out.isEmpty())
            out << tr("default look");
        return out;
    }, [](const sim::Variation* v) { return v ? std::max(1, int(v->looks.size())) : 0; }, &sim::Agent::look);
    addVariationIndex(form, "tint", tr("Tint"), [](const sim::Variation& v) {
        QStringList out;
        for (const glm::vec3& c : v.tints)
            out << QColor::fromRgbF(c.r, c.g, c.b).name();
        return out;
    }, [](const sim::Variation* v) { return v ? int(v->tints.size()) : 0; }, &sim::Agent::tint);

    auto* spin = new HeightSpinBox(form.owner());
    spin->setObjectName("heightScale");
    spin->setRange(0.0, 10.0);
    spin->setSingleStep(0.05);
    spin->setDecimals(2);
    spin->setKeyboardTracking(false);
    spin->setToolTip(tr("The agent's height scale; \"drawn\" (0) takes it from the type's range"));
    const PropertyForm::Locate<float> locate = [](sim::Scene& s, std::size_t i) -> float& { return s.agents[i].heightScale; };
    QObject::connect(spin, &QDoubleSpinBox::valueChanged, &form, [&form, locate](double v) {
        if (v >= 0.0)
            form.apply<float>("heightScale", tr("Height scale"), locate, float(v));
    });
    form.addRow(tr("Height scale"), spin, [&form, spin, locate] {
        const QSignalBlocker block(spin);
        const std::optional<float> value = form.common(locate);
        spin->setMinimum(value ? 0.0 : -1.0);
        spin->setValue(value ? double(*value) : -1.0);
    });
}

}  // namespace throng::editor
