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

}  // namespace

void addLayoutOpRows(PropertyForm& form)
{
    form.addName();
    form.addEnum<sim::LayoutKind>("op", tr("Operation"),
                                  {layoutKindTitle(sim::LayoutKind::Translate), layoutKindTitle(sim::LayoutKind::Rotate),
                                   layoutKindTitle(sim::LayoutKind::TimeOffset), layoutKindTitle(sim::LayoutKind::Mirror),
                                   layoutKindTitle(sim::LayoutKind::Delete), layoutKindTitle(sim::LayoutKind::Expand)},
                                  opField(&sim::LayoutOp::kind));
    form.addCheck("enabled", tr("On"), opField(&sim::LayoutOp::enabled));
    form.addInfo("agents", tr("Agents"), [](const sim::Scene& s, std::size_t i) {
        return selectorText(s.layout.ops[i].agents);
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
}

}  // namespace throng::editor
