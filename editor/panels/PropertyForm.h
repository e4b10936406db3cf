#pragma once
// The rows of the properties panel for the current selection (items of one kind): builds
// a fitting widget per field (spin box, combo box, check box, line edit, label), shows
// the selection's common value or "(mixed)", and turns each edit into one
// ChangeValuesCommand over every selected item. Never writes the scene itself.

#include "editor/SceneDocument.h"
#include "editor/commands/ChangeValuesCommand.h"
#include "editor/panels/PropertyChange.h"
#include "editor/panels/PropertyFields.h"

#include <QObject>
#include <QStringList>
#include <QUndoStack>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QFormLayout;
class QWidget;

namespace throng::editor {

class PropertyForm : public QObject {
    Q_OBJECT

public:
    template <class T>
    using Locate = std::function<T&(sim::Scene&, std::size_t)>;
    // The names a combo box offers, in the scene's order.
    using Options = std::function<QStringList(const sim::Scene&)>;
    // Whether a row applies to item `index` (a vehicle type's car following, a flier's banking).
    using Shown = std::function<bool(const sim::Scene&, std::size_t index)>;

    PropertyForm(SceneDocument& document, QFormLayout* layout, QWidget* owner);

    const sim::Scene& scene() const { return m_document.scene(); }
    ItemKind kind() const;
    // The selected items' indices (those of the first item's kind).
    std::vector<std::size_t> indices() const;
    QWidget* owner() const { return m_owner; }

    void addNumber(const PropertyField& field);
    // A number row for each of the kind's fields (propertyFields), in their order.
    void addNumberFields();
    // A combo box of names; `none` adds "(none)" for an empty value; `editable` lets the
    // user type a new name (an agent's group).
    void addChoice(const QString& key, const QString& label, Options options, Locate<std::string> locate,
                   bool none, bool editable = false);
    // A combo box of an enum's values, `names` in the enum's order; with `shown`, the row
    // shows only while that holds for one of the selected items.
    template <class Enum>
    void addEnum(const QString& key, const QString& label, const QStringList& names, Locate<Enum> locate,
                 Shown shown = {})
    {
        addIndexChoice(key, label, [names] { return names; }, [this, locate]() -> std::optional<int> {
            const auto value = common(locate);
            return value ? std::optional<int>(int(*value)) : std::nullopt;
        }, [this, key, label, locate](int index) { apply(key, label, locate, Enum(index)); }, std::move(shown));
    }
    // A check box; with `shown`, the row shows only while that holds for one of the selected items.
    void addCheck(const QString& key, const QString& label, Locate<bool> locate, Shown shown = {});
    // A combo box of `names()` (read again on every refresh): `value` is the selection's
    // common index (empty = "(mixed)"), `apply` takes the picked one.
    void addIndexChoice(const QString& key, const QString& label, std::function<QStringList()> names,
                        std::function<std::optional<int>()> value, std::function<void(int)> apply, Shown shown = {});
    template <class Int>
    void addInteger(const QString& key, const QString& label, int min, int max, Locate<Int> locate)
    {
        addIntegerRow(key, label, min, max, [this, locate]() -> std::optional<long long> {
            const auto value = common(locate);
            return value ? std::optional<long long>((long long)(*value)) : std::nullopt;
        }, [this, key, label, locate](int v) { apply(key, label, locate, Int(v)); });
    }
    // The item's name; a rename also renames every reference to it, and an empty or
    // taken name is refused (problem()) with nothing changed.
    void addName();
    // Read-only text about the first selected item.
    void addInfo(const QString& key, const QString& label, std::function<QString(const sim::Scene&, std::size_t)> text);
    // Any other widget; `refresh` re-reads its values from the scene.
    void addRow(const QString& label, QWidget* widget, std::function<void()> refresh);
    // Shows or hides the row of a widget added with addRow (a row that applies to some
    // items only: a polygon group's points).
    void setRowShown(QWidget* widget, bool shown);
    // Shows the row of `widget` while `shown` holds for one of the selected items (always when empty).
    void showRowFor(QWidget* widget, const Shown& shown);

    // The value every selected item has, or nothing when they differ.
    template <class T>
    std::optional<T> common(const Locate<T>& locate) const
    {
        auto& s = const_cast<sim::Scene&>(scene());  // read only
        const std::vector<std::size_t> items = indices();
        if (items.empty())
            return std::nullopt;
        const T first = locate(s, items.front());
        for (std::size_t i : items)
            if (!(locate(s, i) == first))
                return std::nullopt;
        return first;
    }

    // Sets `locate` of every selected item to change(its current value), as one undo step.
    template <class T>
    void applyEach(const QString& key, const QString& label, Locate<T> locate, const std::function<T(const T&)>& change)
    {
        std::vector<typename ChangeValuesCommand<T>::Locate> locates;
        std::vector<T> values;
        auto& s = const_cast<sim::Scene&>(scene());  // read only
        for (std::size_t i : indices()) {
            locates.push_back([locate, i](sim::Scene& sc) -> T& { return locate(sc, i); });
            values.push_back(change(locate(s, i)));
        }
        push(new ChangeValuesCommand<T>(m_document, mergeKey(key), std::move(locates), std::move(values),
                                        tr("Change %1").arg(label), propertyChange(kind(), key, indices())));
    }
    template <class T>
    void apply(const QString& key, const QString& label, Locate<T> locate, T value)
    {
        applyEach<T>(key, label, std::move(locate), [value](const T&) { return value; });
    }

    // Re-reads every field from the scene (not while an edit of ours is being pushed).
    void refresh();
    // Refuses an edit: `why` goes to the widget's tooltip and the message log (problem()),
    // and the fields show the scene's values again.
    void refuse(QWidget* widget, const QString& why);

signals:
    // An edit was refused; the text says why and what stayed.
    void problem(const QString& text);

private:
    template <class T>
    void push(ChangeValuesCommand<T>* command)
    {
        if (command->changesNothing()) {
            delete command;
            return;
        }
        m_applying = true;
        m_document.undoStack()->push(command);
        m_applying = false;
        refresh();
    }
    QString mergeKey(const QString& key) const;
    void addIntegerRow(const QString& key, const QString& label, int min, int max,
                       std::function<std::optional<long long>()> value, std::function<void(int)> apply);
    void rename(const QString& text);

    SceneDocument& m_document;
    QFormLayout* m_layout;
    QWidget* m_owner;
    std::vector<std::function<void()>> m_refreshers;
    bool m_applying = false;
};

}  // namespace throng::editor
