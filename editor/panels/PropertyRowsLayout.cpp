// A layout operation's rows (sim::LayoutOp): its name, kind, whether it is on, the agents
// it edits, its frames, and the amount of its kind (offset, angle, frames later and the
// held pose, the mirror's line, the factor). Each edit is one undoable step; a range
// running backwards is refused with why.
#include "editor/layout/LayoutText.h"
#include "editor/panels/PropertyForm.h"
#include "editor/panels/PropertyRows.h"

#include <QSignalBlocker>
#include <QSpinBox>

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return PropertyForm::tr(text);
}

constexpr int kMaxFrame = 10'000'000;

template <class Member>
PropertyForm::Locate<Member> opField(Member sim::LayoutOp::*member)
{
    return [member](sim::Scene& s, std::size_t i) -> Member& { return s.layout.ops[i].*member; };
}

PropertyForm::Shown isKind(sim::LayoutKind kind)
{
    return [kind](const sim::Scene& s, std::size_t i) { return s.layout.ops[i].kind == kind; };
}

// A whole-number row: `read` gives the first selected operation's value, `write` takes
// the typed one (refusing it or applying it to every selected operation). The lowest
// value shows `lowest` when not empty ("to the end").
QSpinBox* addWholeRow(PropertyForm& form, const QString& key, const QString& label, int min, int max,
                      const QString& lowest, std::function<int(const sim::LayoutOp&)> read,
                      std::function<void(QSpinBox*, int)> write, PropertyForm::Shown shown = {})
{
    auto* spin = new QSpinBox(form.owner());
    spin->setObjectName(key);
    spin->setRange(min, max);
    spin->setKeyboardTracking(false);
    spin->setSpecialValueText(lowest);
    QObject::connect(spin, &QSpinBox::valueChanged, &form, [spin, write](int v) { write(spin, v); });
    form.addRow(label, spin, [&form, spin, read, shown] {
        form.showRowFor(spin, shown);
        const std::vector<std::size_t> items = form.indices();
        if (items.empty())
            return;
        const QSignalBlocker block(spin);
        spin->setValue(read(form.scene().layout.ops[items.front()]));
    });
    return spin;
}

int lastShown(const sim::LayoutOp& op)
{
    return op.lastFrame == sim::kLastFrame ? -1 : int(std::min<std::size_t>(op.lastFrame, kMaxFrame));
}

// A swap's type ("(keep)" for its own), look and tint, numbered from 1 as elsewhere.
void addSwapRows(PropertyForm& form)
{
    const PropertyForm::Shown swap = isKind(sim::LayoutKind::Swap);
    form.addIndexChoice("type", tr("Show as type"), [&form] {
        QStringList names{tr("(keep)")};
        for (const sim::AgentType& t : form.scene().agentTypes)
            names << QString::fromStdString(t.name);
        return names;
    }, [&form]() -> std::optional<int> {
        const auto type = form.common(opField(&sim::LayoutOp::type));
        if (!type)
            return std::nullopt;
        const auto& types = form.scene().agentTypes;
        const auto it =
            std::find_if(types.begin(), types.end(), [&](const sim::AgentType& t) { return t.name == *type; });
        return it == types.end() ? 0 : int(it - types.begin()) + 1;
    }, [&form](int index) {
        const std::string name = index <= 0 ? std::string() : form.scene().agentTypes.at(std::size_t(index - 1)).name;
        form.apply<std::string>("type", tr("Show as type"), opField(&sim::LayoutOp::type), name);
    }, swap);
    const auto look = opField(&sim::LayoutOp::look);
    addWholeRow(form, "look", tr("Look"), 0, 255, tr("as drawn"), [](const sim::LayoutOp& op) { return op.look + 1; },
                [&form, look](QSpinBox*, int v) { form.apply<int>("look", tr("Look"), look, v - 1); }, swap);
    const auto tint = opField(&sim::LayoutOp::tint);
    auto* tints = addWholeRow(form, "tint", tr("Tint"), -1, 127, tr("as drawn"),
                              [](const sim::LayoutOp& op) { return op.tint + 1; },
                              [&form, tint](QSpinBox*, int v) { form.apply<int>("tint", tr("Tint"), tint, v - 1); },
                              swap);
    tints->setToolTip(tr("The tint to show, numbered from 1; 0 untinted"));
}

}  // namespace

void addLayoutOpRows(PropertyForm& form)
{
    form.addName();
    QStringList kinds;
    for (int k = 0; k < sim::kLayoutKindCount; ++k)
        kinds << layoutKindTitle(sim::LayoutKind(k));
    form.addEnum<sim::LayoutKind>("op", tr("Operation"), kinds, opField(&sim::LayoutOp::kind));
    form.addCheck("enabled", tr("On"), opField(&sim::LayoutOp::enabled));
    form.addInfo("agents", tr("Agents"), [](const sim::Scene& s, std::size_t i) {
        const sim::LayoutOp& op = s.layout.ops[i];
        if (op.kind == sim::LayoutKind::Resolve && op.agents == sim::AgentSelector{})
            return tr("every edited agent");
        return selectorText(op.agents);
    });
    const auto first = opField(&sim::LayoutOp::firstFrame);
    const auto last = opField(&sim::LayoutOp::lastFrame);
    addWholeRow(form, "firstFrame", tr("From frame"), 0, kMaxFrame, {},
                [](const sim::LayoutOp& op) { return int(std::min<std::size_t>(op.firstFrame, kMaxFrame)); },
                [&form, first](QSpinBox* spin, int v) {
                    for (std::size_t i : form.indices())
                        if (form.scene().layout.ops[i].lastFrame < std::size_t(v))
                            return form.refuse(spin, tr("%1 ends on frame %2: it cannot start after that; it stays as "
                                                        "it is.")
                                                         .arg(itemLabel(form.scene(), {ItemKind::LayoutOp, i}))
                                                         .arg(form.scene().layout.ops[i].lastFrame));
                    form.apply<std::size_t>("firstFrame", tr("From frame"), first, std::size_t(v));
                });
    addWholeRow(form, "lastFrame", tr("To frame"), -1, kMaxFrame, tr("the end"), lastShown,
                [&form, last](QSpinBox* spin, int v) {
                    const std::size_t to = v < 0 ? sim::kLastFrame : std::size_t(v);
                    for (std::size_t i : form.indices())
                        if (form.scene().layout.ops[i].firstFrame > to)
                            return form.refuse(spin, tr("%1 starts on frame %2: it cannot end before that; it stays as "
                                                        "it is.")
                                                         .arg(itemLabel(form.scene(), {ItemKind::LayoutOp, i}))
                                                         .arg(form.scene().layout.ops[i].firstFrame));
                    form.apply<std::size_t>("lastFrame", tr("To frame"), last, to);
                });
    form.addNumberFields();
    const auto later = opField(&sim::LayoutOp::frames);
    addWholeRow(form, "later", tr("Frames later"), -kMaxFrame, kMaxFrame, {},
                [](const sim::LayoutOp& op) { return op.frames; },
                [&form, later](QSpinBox*, int v) { form.apply<int>("later", tr("Frames later"), later, v); },
                isKind(sim::LayoutKind::TimeOffset));
    form.addCheck("holdFirst", tr("Hold first pose"), opField(&sim::LayoutOp::holdFirst),
                  isKind(sim::LayoutKind::TimeOffset));
    addSwapRows(form);
    QStringList clips;
    for (int c = 0; c < sim::kClipCount; ++c)
        clips << QString::fromLatin1(sim::toString(sim::Clip(c)));
    form.addEnum<sim::Clip>("clip", tr("Clip"), clips, opField(&sim::LayoutOp::clip),
                            isKind(sim::LayoutKind::ReplaceClip));
}

}  // namespace throng::editor
