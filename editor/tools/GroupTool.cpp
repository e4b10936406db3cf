#include "editor/tools/GroupTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/BrushOverlay.h"
#include "editor/tools/UniqueName.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPolygonF>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStackedWidget>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {
constexpr float kClickM = 0.3f;          // a drag shorter than this is a click
constexpr float kClickSquareM = 10.0f;   // the side of the square a click places
constexpr float kClickCircleM = 5.0f;    // the radius of the circle a click places
const QColor kPreview(120, 230, 140);
}  // namespace

QString GroupTool::toolTip() const
{
    return tr("Spawn Group (S): drag a rectangle (or a circle: centre, then radius) to fill with agents of the "
              "chosen type, by count or density; a click places a 10 m square");
}

QString GroupTool::statusText() const
{
    if (document().scene().agentTypes.empty())
        return tr("Spawn Group: the scene has no agent type yet; click to create one");
    if (state() != State::Dragging)
        return toolTip();
    const sim::SpawnGroup g = previewGroup();
    return tr("Spawn Group: %1 agents of %2").arg(g.count).arg(QString::fromStdString(g.type));
}

void GroupTool::mousePressed(const ToolMouse& mouse)
{
    if (document().scene().agentTypes.empty()) {
        emit agentTypeNeeded();
        return;
    }
    if (!mouse.ground)
        return;
    m_start = m_end = {mouse.ground->x, mouse.ground->z};
    setState(State::Dragging);
    emit overlayChanged();
}

void GroupTool::mouseMoved(const ToolMouse& mouse)
{
    if (state() != State::Dragging || !mouse.ground)
        return;
    m_end = {mouse.ground->x, mouse.ground->z};
    emit overlayChanged();
}

void GroupTool::mouseReleased(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    mouseMoved(mouse);
    setState(State::Idle);
    sim::SpawnGroup group = previewGroup();
    const QString text = tr("Add spawn group %1 (%2 agents)").arg(QString::fromStdString(group.name)).arg(group.count);
    document().undoStack()->push(
        new AddSceneItemCommand<sim::SpawnGroup>(document(), &sim::Scene::groups, std::move(group), text));
    document().setSelection({{ItemKind::Group, document().scene().groups.size() - 1}});
    emit overlayChanged();
}

sim::SpawnGroup GroupTool::previewGroup() const
{
    const sim::Scene& scene = document().scene();
    sim::SpawnGroup g;
    g.name = uniqueName(scene.groups, "group");
    const bool known = std::any_of(scene.agentTypes.begin(), scene.agentTypes.end(),
                                   [&](const sim::AgentType& t) { return t.name == m_settings.type; });
    g.type = known ? m_settings.type : scene.agentTypes.empty() ? std::string() : scene.agentTypes.front().name;
    g.shape = m_settings.shape;
    const bool click = glm::length(m_end - m_start) < kClickM;
    if (g.shape == sim::AreaShape::Rect) {
        const glm::vec2 end = click ? m_start + glm::vec2(kClickSquareM) : m_end;
        g.min = glm::min(m_start, end);
        g.max = glm::max(m_start, end);
    } else {
        g.center = m_start;
        g.radiusM = click ? kClickCircleM : glm::length(m_end - m_start);
    }
    g.count = countFor(g);
    return g;
}

std::uint32_t GroupTool::countFor(const sim::SpawnGroup& g) const
{
    if (m_settings.amount == Amount::Count)
        return std::uint32_t(std::max(1, m_settings.count));
    const double area = g.shape == sim::AreaShape::Rect ? double(g.max.x - g.min.x) * double(g.max.y - g.min.y)
                                                        : 3.14159265358979 * double(g.radiusM) * double(g.radiusM);
    return std::uint32_t(std::max(1.0, std::round(area * m_settings.densityPerM2)));
}

void GroupTool::drawOverlay(QPainter& painter) const
{
    if (state() != State::Dragging)
        return;
    const sim::SpawnGroup g = previewGroup();
    if (g.shape == sim::AreaShape::Circle) {
        drawBrushCircle(painter, viewport(), {g.center.x, 0.0f, g.center.y}, g.radiusM, kPreview);
    } else {
        QPolygonF corners;
        for (glm::vec2 c : {g.min, glm::vec2(g.max.x, g.min.y), g.max, glm::vec2(g.min.x, g.max.y)})
            corners << viewport().worldToPixel({c.x, 0.0f, c.y});
        painter.setPen(QPen(kPreview, 2.0));
        painter.setBrush(QColor(kPreview.red(), kPreview.green(), kPreview.blue(), 40));
        painter.drawPolygon(corners);
    }
    painter.setPen(kPreview);
    const QPointF at = viewport().worldToPixel({m_end.x, 0.0f, m_end.y}) + QPointF(12, -12);
    painter.drawText(at, tr("%1 × %2").arg(g.count).arg(QString::fromStdString(g.type)));
}

QWidget* GroupTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto* shape = new QComboBox(box);
    shape->setObjectName("groupShape");
    shape->addItems({tr("Rectangle"), tr("Circle")});
    shape->setCurrentIndex(m_settings.shape == sim::AreaShape::Rect ? 0 : 1);
    shape->setToolTip(tr("The area's shape: a rectangle dragged corner to corner, or a circle from its centre"));
    connect(shape, &QComboBox::currentIndexChanged, this,
            [this](int i) { m_settings.shape = i == 0 ? sim::AreaShape::Rect : sim::AreaShape::Circle; });
    auto* type = new QComboBox(box);
    type->setObjectName("groupType");
    type->setToolTip(tr("The agent type of the group's members"));
    type->setMinimumContentsLength(10);
    // Types made or renamed while the tool is active show up at once.
    auto fillTypes = [this, type] {
        const QSignalBlocker block(type);
        type->clear();
        for (const sim::AgentType& t : document().scene().agentTypes)
            type->addItem(QString::fromStdString(t.name));
        const int at = type->findText(QString::fromStdString(m_settings.type));
        type->setCurrentIndex(std::max(0, at));
    };
    fillTypes();
    connect(&document(), &SceneDocument::sceneChanged, type, fillTypes);
    connect(&document(), &SceneDocument::sceneReset, type, fillTypes);
    connect(type, &QComboBox::currentTextChanged, this, [this](const QString& t) { m_settings.type = t.toStdString(); });
    auto* amount = new QComboBox(box);
    amount->setObjectName("groupAmount");
    amount->addItems({tr("Count"), tr("Density")});
    amount->setCurrentIndex(int(m_settings.amount));
    amount->setToolTip(tr("Give the number of members, or agents per square metre of the area"));
    auto* values = new QStackedWidget(box);
    auto* count = new QSpinBox(values);
    count->setObjectName("groupCount");
    count->setRange(1, 10'000'000);
    count->setValue(m_settings.count);
    count->setToolTip(tr("How many agents the group spawns"));
    connect(count, &QSpinBox::valueChanged, this, [this](int v) { m_settings.count = v; });
    auto* density = new QDoubleSpinBox(values);
    density->setObjectName("groupDensity");
    density->setRange(0.01, 6.0);
    density->setSingleStep(0.1);
    density->setValue(m_settings.densityPerM2);
    density->setSuffix(tr(" /m²"));
    density->setToolTip(tr("Agents per square metre of the area (1 is a busy platform, 4 a packed crowd)"));
    connect(density, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_settings.densityPerM2 = v; });
    values->setMaximumWidth(130);  // a number, not the rest of the bar
    values->addWidget(count);
    values->addWidget(density);
    values->setCurrentIndex(int(m_settings.amount));
    connect(amount, &QComboBox::currentIndexChanged, this, [this, values](int i) {
        m_settings.amount = Amount(i);
        values->setCurrentIndex(i);
    });
    for (auto [label, widget] : {std::pair<QString, QWidget*>{tr("Shape"), shape}, {tr("Type"), type},
                                 {tr("By"), amount}, {QString(), values}}) {
        if (!label.isEmpty())
            row->addWidget(new QLabel(label, box));
        row->addWidget(widget);
    }
    row->addStretch(1);
    return box;
}

}  // namespace throng::editor
