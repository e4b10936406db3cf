// The properties panel's rows for an agent type's look, ages and collisions: the variation's
// looks (a comma list) and tints (a colour table), the character (a built-in name or a
// .glb/.gltf file), the walkers' age range (two numbers), the collision layer and the
// layers it avoids.
#include "editor/panels/PropertyRows.h"

#include "editor/ComboTypeAhead.h"
#include "editor/panels/PropertyForm.h"
#include "editor/panels/TintTable.h"

#include "simcore/scene/WalkingAge.h"

#include <QComboBox>
#include <QLineEdit>
#include <QRegularExpression>
#include <QSignalBlocker>

#include <algorithm>

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return PropertyForm::tr(text);
}

template <class T>
PropertyForm::Locate<T> typeField(T sim::AgentType::*member)
{
    return [member](sim::Scene& s, std::size_t i) -> T& { return s.agentTypes[i].*member; };
}

// A line edit whose text is `show(value)` of the selection's common value ("(mixed)"
// when they differ); Return applies `parse(text)`, whose empty refusal text accepts it.
template <class T>
void addTextRow(PropertyForm& form, const QString& key, const QString& label, PropertyForm::Locate<T> locate,
                std::function<QString(const T&)> show, std::function<QString(const QString&, T&)> parse)
{
    auto* edit = new QLineEdit(form.owner());
    edit->setObjectName(key);
    QObject::connect(edit, &QLineEdit::editingFinished, &form, [&form, edit, key, label, locate, show, parse] {
        const std::optional<T> now = form.common(locate);
        if (!now && edit->text() == tr("(mixed)"))
            return;
        if (now && edit->text() == show(*now))
            return;
        T value{};
        if (const QString why = parse(edit->text(), value); !why.isEmpty()) {
            form.refuse(edit, why);
            return;
        }
        edit->setToolTip(QString());
        form.apply<T>(key, label, locate, value);
    });
    form.addRow(label, edit, [&form, edit, locate, show] {
        const QSignalBlocker block(edit);
        const std::optional<T> value = form.common(locate);
        edit->setText(value ? show(*value) : tr("(mixed)"));
    });
}

// The highest look index placed agents of the selected types fixed (-1: none).
int highestLook(const PropertyForm& form)
{
    int highest = -1;
    for (std::size_t t : form.indices())
        for (const sim::Agent& a : form.scene().agents)
            if (a.type == form.scene().agentTypes[t].name)
                highest = std::max(highest, a.look);
    return highest;
}

}  // namespace

void addAgentTypeLookRows(PropertyForm& form)
{
    using Names = std::vector<std::string>;
    addTextRow<Names>(form, "looks", tr("Looks"), [](sim::Scene& s, std::size_t i) -> Names& {
        return s.agentTypes[i].variation.looks;
    }, [](const Names& looks) {
        QStringList out;
        for (const std::string& look : looks)
            out << QString::fromStdString(look);
        return out.join(", ");
    }, [&form](const QString& text, Names& out) {
        for (const QString& part : text.split(',', Qt::SkipEmptyParts))
            if (!part.trimmed().isEmpty())
                out.push_back(part.trimmed().toStdString());
        const int used = highestLook(form);
        if (used >= std::max<int>(1, int(out.size())))
            return tr("A placed agent uses look %1: keep at least %1 looks (the looks stay as they were).").arg(used + 1);
        return QString();
    });
    auto* tints = new TintTable(form, form.owner());
    form.addRow(tr("Tints"), tints, [tints] { tints->refresh(); });

    // The character: a built-in name or a character file.
    auto* character = new QComboBox(form.owner());
    character->setObjectName("character");
    character->setEditable(true);
    character->setInsertPolicy(QComboBox::NoInsert);
    keepTypedLetters(character);
    const PropertyForm::Locate<std::string> locate = typeField(&sim::AgentType::character);
    auto apply = [&form, character, locate](const QString& typed) {
        const QString text = typed.trimmed();
        if (text == tr("(mixed)"))
            return;
        const std::string name = text == tr("(none)") ? std::string() : text.toStdString();
        if (form.common(locate) == std::optional<std::string>(name))
            return;  // the shown value again (the combo box reports it after a refusal too)
        const auto& builtins = sim::builtinCharacters();
        const bool builtin = std::find(builtins.begin(), builtins.end(), name) != builtins.end();
        if (!name.empty() && !builtin && !name.ends_with(".glb") && !name.ends_with(".gltf")) {
            form.refuse(character, tr("\"%1\" is neither a built-in character nor a .glb or .gltf file; the "
                                      "character stays as it was.")
                                       .arg(text));
            return;
        }
        character->setToolTip(QString());
        form.apply<std::string>("character", tr("Character"), locate, name);
    };
    QObject::connect(character, &QComboBox::activated, &form,
                     [character, apply](int index) { apply(character->itemText(index)); });
    QObject::connect(character->lineEdit(), &QLineEdit::editingFinished, &form,
                     [character, apply] { apply(character->currentText()); });
    form.addRow(tr("Character"), character, [&form, character, locate] {
        const QSignalBlocker block(character);
        character->clear();
        character->addItem(tr("(none)"));
        for (const std::string& name : sim::builtinCharacters())
            character->addItem(QString::fromStdString(name));
        const std::optional<std::string> value = form.common(locate);
        character->setCurrentText(!value ? tr("(mixed)") : value->empty() ? tr("(none)") : QString::fromStdString(*value));
    });
}

void addAgentTypeAgeRow(PropertyForm& form)
{
    addTextRow<glm::vec2>(form, "ages", tr("Ages (years)"), [](sim::Scene& s, std::size_t i) -> glm::vec2& {
        return s.agentTypes[i].variation.ageYears;
    }, [](const glm::vec2& ages) {
        return sim::hasAge(ages) ? tr("%1 to %2").arg(double(ages.x)).arg(double(ages.y)) : QString();
    }, [](const QString& text, glm::vec2& out) {
        static const QRegularExpression number(R"([0-9]+(\.[0-9]+)?)");
        std::vector<float> years;
        for (auto it = number.globalMatch(text); it.hasNext();)
            years.push_back(it.next().captured(0).toFloat());
        const QString rest = QString(text).remove(number).remove(QRegularExpression(R"([\s,\-]|to)"));
        if (years.size() > 2 || !rest.isEmpty())
            return tr("Type two ages, such as \"20 to 80\", or nothing for none; the ages stay as they were.");
        out = years.empty() ? glm::vec2(0.0f) : glm::vec2(years.front(), years.back());
        if (!years.empty() && (out.x < sim::kWalkingAgeMinYears || out.y > sim::kWalkingAgeMaxYears))
            return tr("Ages lie within 10 to 80 years, where Weidmann's walking speeds are known; the ages stay as "
                      "they were.");
        if (out.x > out.y)
            return tr("The first age is above the second; the ages stay as they were.");
        return QString();
    });
}

void addAgentTypeCollisionRows(PropertyForm& form)
{
    form.addInteger<std::uint32_t>("layer", tr("Collision layer"), 0, 31, typeField(&sim::AgentType::layer));
    addTextRow<std::uint32_t>(form, "collidesWith", tr("Avoids layers"), typeField(&sim::AgentType::collidesWith),
        [](const std::uint32_t& mask) {
            if (mask == 0xffffffffu)
                return tr("all");
            QStringList layers;
            for (int k = 0; k < 32; ++k)
                if (mask & (1u << k))
                    layers << QString::number(k);
            return layers.isEmpty() ? tr("none") : layers.join(", ");
        },
        [](const QString& text, std::uint32_t& mask) {
            const QString t = text.trimmed();
            if (t == tr("all")) {
                mask = 0xffffffffu;
                return QString();
            }
            mask = 0;
            if (t == tr("none") || t.isEmpty())
                return QString();
            for (const QString& part : t.split(',', Qt::SkipEmptyParts)) {
                bool ok = false;
                const int layer = part.trimmed().toInt(&ok);
                if (!ok || layer < 0 || layer > 31)
                    return tr("\"%1\" is not a layer from 0 to 31 (give \"all\", \"none\" or a list such as 0, 2); "
                              "nothing changed.")
                        .arg(part.trimmed());
                mask |= 1u << layer;
            }
            return QString();
        });
}

}  // namespace throng::editor
