#include "editor/panels/PropertyForm.h"

#include "editor/ComboTypeAhead.h"
#include "editor/commands/NameReferences.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSpinBox>

#include <algorithm>

namespace throng::editor {

namespace {

QString mixedText()
{
    return PropertyForm::tr("(mixed)");
}

// Shows `value` in a spin box, or "(mixed)" one step below its range when it is unset.
template <class Spin, class Value>
void showNumber(Spin* spin, std::optional<Value> value, double min)
{
    const QSignalBlocker block(spin);
    if (value) {
        spin->setSpecialValueText(QString());
        spin->setMinimum(min);
        spin->setValue(*value);
    } else {
        spin->setMinimum(min - spin->singleStep());
        spin->setSpecialValueText(mixedText());
        spin->setValue(spin->minimum());
    }
}

}  // namespace

PropertyForm::PropertyForm(SceneDocument& document, QFormLayout* layout, QWidget* owner)
    : QObject(owner), m_document(document), m_layout(layout), m_owner(owner)
{
}

ItemKind PropertyForm::kind() const
{
    const Selection& selection = m_document.selection();
    return selection.empty() ? ItemKind::Settings : selection.front().kind;
}

std::vector<std::size_t> PropertyForm::indices() const
{
    std::vector<std::size_t> out;
    const std::size_t count = itemCount(scene(), kind());
    for (const SceneItem& item : m_document.selection())
        if (item.kind == kind() && item.index < count)
            out.push_back(item.index);
    return out;
}

QString PropertyForm::mergeKey(const QString& key) const
{
    std::size_t hash = 0;
    for (std::size_t i : indices())
        hash = hash * 1000003u + i + 1;
    return QStringLiteral("property/%1/%2/%3").arg(int(kind())).arg(key).arg(qulonglong(hash));
}

void PropertyForm::refresh()
{
    if (m_applying)
        return;
    for (const auto& refresher : m_refreshers)
        refresher();
}

void PropertyForm::addRow(const QString& label, QWidget* widget, std::function<void()> refresh)
{
    m_layout->addRow(label, widget);
    m_refreshers.push_back(std::move(refresh));
}

void PropertyForm::setRowShown(QWidget* widget, bool shown)
{
    m_layout->setRowVisible(widget, shown);
}

void PropertyForm::addNumberFields()
{
    for (const PropertyField& field : propertyFields(kind()))
        addNumber(field);
}

void PropertyForm::addNumber(const PropertyField& field)
{
    auto* spin = new QDoubleSpinBox(m_owner);
    spin->setObjectName(field.key);
    spin->setRange(field.min, field.max);
    spin->setSingleStep(field.step);
    spin->setDecimals(field.decimals);
    spin->setKeyboardTracking(false);
    const Locate<float> locate = field.locate;
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this, spin, field, locate](double v) {
        if (!spin->specialValueText().isEmpty() && v == spin->minimum())
            return;  // still "(mixed)"
        if (field.refusal) {
            for (std::size_t i : indices())
                if (const QString why = field.refusal(scene(), i, float(v)); !why.isEmpty()) {
                    refuse(spin, why);
                    return;
                }
        }
        spin->setToolTip(QString());
        apply(field.key, field.label, locate, float(v));
    });
    addRow(field.label, spin, [this, spin, field, locate] {
        showRowFor(spin, field.shown);
        const std::optional<float> value = common(locate);
        showNumber(spin, value ? std::optional<double>(*value) : std::nullopt, field.min);
    });
}

void PropertyForm::refuse(QWidget* widget, const QString& why)
{
    widget->setToolTip(why);
    emit problem(why);
    refresh();  // shows the value that stayed
}

void PropertyForm::addIntegerRow(const QString& key, const QString& label, int min, int max,
                                 std::function<std::optional<long long>()> value, std::function<void(int)> apply)
{
    auto* spin = new QSpinBox(m_owner);
    spin->setObjectName(key);
    spin->setRange(min, max);
    spin->setKeyboardTracking(false);
    connect(spin, &QSpinBox::valueChanged, this, [spin, apply](int v) {
        if (!spin->specialValueText().isEmpty() && v == spin->minimum())
            return;
        apply(v);
    });
    addRow(label, spin, [spin, value, min, max] {
        const std::optional<long long> v = value();
        showNumber(spin, v ? std::optional<int>(int(std::clamp<long long>(*v, min, max))) : std::nullopt, min);
    });
}

void PropertyForm::showRowFor(QWidget* widget, const Shown& shown)
{
    if (!shown)
        return;
    const std::vector<std::size_t> items = indices();
    m_layout->setRowVisible(widget, std::any_of(items.begin(), items.end(),
                                                [&](std::size_t i) { return shown(scene(), i); }));
}

void PropertyForm::addCheck(const QString& key, const QString& label, Locate<bool> locate, Shown shown)
{
    auto* check = new QCheckBox(m_owner);
    check->setObjectName(key);
    connect(check, &QCheckBox::clicked, this, [this, check, key, label, locate] {
        // From "(mixed)" a click sets the value on every item.
        apply(key, label, locate, check->checkState() != Qt::Unchecked);
    });
    addRow(label, check, [this, check, locate, shown] {
        showRowFor(check, shown);
        const QSignalBlocker block(check);
        const std::optional<bool> value = common(locate);
        check->setTristate(!value);
        check->setCheckState(!value ? Qt::PartiallyChecked : *value ? Qt::Checked : Qt::Unchecked);
    });
}

void PropertyForm::addIndexChoice(const QString& key, const QString& label, std::function<QStringList()> names,
                                  std::function<std::optional<int>()> value, std::function<void(int)> apply,
                                  Shown shown)
{
    auto* combo = new QComboBox(m_owner);
    combo->setObjectName(key);
    keepTypedLetters(combo);
    connect(combo, &QComboBox::activated, this, [combo, apply](int index) {
        const QVariant data = combo->itemData(index);
        if (data.isValid())
            apply(data.toInt());
    });
    addRow(label, combo, [this, combo, names, value, shown] {
        if (shown) {
            const std::vector<std::size_t> items = indices();
            const bool any = std::any_of(items.begin(), items.end(), [&](std::size_t i) { return shown(scene(), i); });
            setRowShown(combo, any);
            if (!any)
                return;
        }
        const QSignalBlocker block(combo);
        combo->clear();
        const QStringList list = names();
        for (int i = 0; i < list.size(); ++i)
            combo->addItem(list[i], i);
        const std::optional<int> v = value();
        if (!v)
            combo->insertItem(0, mixedText());
        combo->setCurrentIndex(v ? *v : 0);
    });
}

void PropertyForm::addChoice(const QString& key, const QString& label, Options options, Locate<std::string> locate,
                             bool none, bool editable)
{
    auto* combo = new QComboBox(m_owner);
    combo->setObjectName(key);
    keepTypedLetters(combo);
    combo->setEditable(editable);
    if (editable)
        combo->setInsertPolicy(QComboBox::NoInsert);
    connect(combo, &QComboBox::activated, this, [this, combo, key, label, locate](int index) {
        const QVariant data = combo->itemData(index);
        if (data.isValid())  // not "(mixed)"
            apply(key, label, locate, data.toString().toStdString());
    });
    if (editable) {
        // A typed name: QComboBox::NoInsert emits nothing for it, so take it from the edit.
        connect(combo->lineEdit(), &QLineEdit::editingFinished, this, [this, combo, key, label, locate] {
            const QString text = combo->currentText().trimmed();
            if (text == mixedText())
                return;
            apply(key, label, locate, text == tr("(none)") ? std::string() : text.toStdString());
        });
    }
    addRow(label, combo, [this, combo, options, locate, none] {
        const QSignalBlocker block(combo);
        combo->clear();
        if (none)
            combo->addItem(tr("(none)"), QString());
        for (const QString& name : options(scene()))
            combo->addItem(name, name);
        const std::optional<std::string> value = common(locate);
        if (!value) {
            combo->insertItem(0, mixedText());
            combo->setCurrentIndex(0);
            return;
        }
        const QString current = QString::fromStdString(*value);
        int at = combo->findData(current);
        if (at < 0) {  // a name the scene does not define: show it as it is
            combo->addItem(current, current);
            at = combo->count() - 1;
        }
        combo->setCurrentIndex(at);
    });
}

void PropertyForm::addInfo(const QString& key, const QString& label,
                           std::function<QString(const sim::Scene&, std::size_t)> text)
{
    auto* info = new QLabel(m_owner);
    info->setObjectName(key);
    info->setWordWrap(true);
    info->setTextInteractionFlags(Qt::TextSelectableByMouse);
    addRow(label, info, [this, info, text] {
        const std::vector<std::size_t> items = indices();
        if (items.empty())
            return;
        const QString first = text(scene(), items.front());
        const bool same = std::all_of(items.begin(), items.end(), [&](std::size_t i) { return text(scene(), i) == first; });
        info->setText(same ? first : mixedText());
    });
}

void PropertyForm::addName()
{
    auto* edit = new QLineEdit(m_owner);
    edit->setObjectName("name");
    connect(edit, &QLineEdit::editingFinished, this, [this, edit] { rename(edit->text()); });
    addRow(tr("Name"), edit, [this, edit] {
        const QSignalBlocker block(edit);
        const std::vector<std::size_t> items = indices();
        edit->setEnabled(items.size() == 1);
        edit->setText(items.size() == 1 ? QString::fromStdString(nameOf(scene(), {kind(), items.front()})) : QString());
        edit->setPlaceholderText(items.size() == 1 ? QString() : tr("(one name per item)"));
    });
}

void PropertyForm::rename(const QString& text)
{
    const std::vector<std::size_t> items = indices();
    if (items.size() != 1)
        return;
    const SceneItem item{kind(), items.front()};
    const std::string before = nameOf(scene(), item);
    const std::string after = text.trimmed().toStdString();
    if (after == before)
        return;
    auto* edit = m_owner->findChild<QLineEdit*>("name");
    QString refusal;
    if (after.empty())
        refusal = tr("A name cannot be empty: %1 keeps its name.").arg(QString::fromStdString(before));
    else if (std::ranges::count(namesOf(scene(), item.kind), after) > 0)
        refusal = tr("Another of the %1 is already named \"%2\": %3 keeps its name.")
                      .arg(kindTitle(item.kind).toLower(), QString::fromStdString(after), QString::fromStdString(before));
    if (!refusal.isEmpty()) {
        if (edit) {
            const QSignalBlocker block(edit);
            edit->setText(QString::fromStdString(before));
            edit->setToolTip(refusal);
        }
        emit problem(refusal);
        return;
    }
    if (edit)
        edit->setToolTip(QString());
    // The references follow the new name, so a group still follows its renamed path.
    std::vector<ChangeValuesCommand<std::string>::Locate> locates{nameLocate(item)};
    const std::vector<NameUse> uses = nameUses(scene(), item.kind, before);
    for (const NameUse& use : uses)
        locates.push_back(use.locate);
    std::vector<std::string> values(locates.size(), after);
    push(new ChangeValuesCommand<std::string>(
        m_document, QString(), std::move(locates), std::move(values),
        tr("Rename %1 to %2").arg(QString::fromStdString(before), QString::fromStdString(after)),
        renameChange(item, uses)));
}

}  // namespace throng::editor
