#include "editor/tools/GroupTool.h"

#include "editor/SceneDocument.h"
#include "editor/SpawnPolygonCheck.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/BrushOverlay.h"
#include "editor/tools/UniqueName.h"
#include "editor/viewport/Viewport.h"
#include "simcore/scene/GroundPolygon.h"
#include "simcore/scene/SpawnArea.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QKeyEvent>
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
const QColor kRefused(255, 110, 90);
}  // namespace

QString GroupTool::toolTip() const
{
    return tr("Spawn Group (S): drag a rectangle (or a circle: centre, then radius) to fill with agents of the "
              "chosen type, by count or density; a click places a 10 m square; a polygon takes a click per corner "
              "and closes on a double-click or Enter");
}

QString GroupTool::statusText() const
{
    if (document().scene().agentTypes.empty())
        return tr("Spawn Group: the scene has no agent type yet; click to create one");
    if (!m_refusal.isEmpty())
        return tr("Spawn Group: %1").arg(m_refusal);
    if (m_settings.shape == sim::AreaShape::Polygon && !m_corners.empty())
        return tr("Spawn Group: %n corner(s), %1 agents of %2; click to add a corner, double-click or Enter closes, "
                  "Backspace drops the last, Escape cancels",
                  nullptr, int(m_corners.size()))
            .arg(m_corners.size() >= 3 ? previewGroup().count : 0)
            .arg(QString::fromStdString(previewGroup().type));
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
    if (m_settings.shape == sim::AreaShape::Polygon) {
        m_refusal.clear();
        // The second press of a double-click lands on the corner just added.
        if (m_corners.empty() || glm::length(m_corners.back() - m_start) >= 1e-4f)
            m_corners.push_back(m_start);
        m_cursor = m_start;
    }
    setState(State::Dragging);
    emit overlayChanged();
}

void GroupTool::mouseMoved(const ToolMouse& mouse)
{
    if (m_settings.shape == sim::AreaShape::Polygon) {
        m_cursor = mouse.ground ? std::optional<glm::vec2>(glm::vec2(mouse.ground->x, mouse.ground->z)) : std::nullopt;
        if (!m_corners.empty())
            emit overlayChanged();
        return;
    }
    if (state() != State::Dragging || !mouse.ground)
        return;
    m_end = {mouse.ground->x, mouse.ground->z};
    emit overlayChanged();
}

void GroupTool::mouseReleased(const ToolMouse& mouse)
{
    // A polygon's corners stay in the tool until it is closed.
    if (state() != State::Dragging || m_settings.shape == sim::AreaShape::Polygon)
        return;
    mouseMoved(mouse);
    setState(State::Idle);
    pushGroup(previewGroup());
}

void GroupTool::mouseDoubleClicked(const ToolMouse&)
{
    if (m_settings.shape == sim::AreaShape::Polygon && !m_corners.empty())
        closePolygon();
}

bool GroupTool::keyPressed(QKeyEvent* event)
{
    if (m_settings.shape != sim::AreaShape::Polygon || m_corners.empty())
        return ViewportTool::keyPressed(event);
    switch (event->key()) {
    case Qt::Key_Return:
    case Qt::Key_Enter: closePolygon(); return true;
    case Qt::Key_Escape: cancel(); return true;
    case Qt::Key_Backspace:
        m_corners.pop_back();
        m_refusal.clear();
        if (m_corners.empty())
            setState(State::Idle);
        emit overlayChanged();
        return true;
    default: return false;
    }
}

void GroupTool::cancel()
{
    m_corners.clear();
    m_refusal.clear();
    ViewportTool::cancel();
}

void GroupTool::closePolygon()
{
    if (document().scene().agentTypes.empty())
        return;
    // Closing on the first corner repeats it; the outline closes by itself.
    while (m_corners.size() > 3 && glm::length(m_corners.back() - m_corners.front()) < 1e-4f)
        m_corners.pop_back();
    m_refusal = spawnPolygonProblem(m_corners);
    if (!m_refusal.isEmpty()) {
        emit overlayChanged();
        return;
    }
    sim::SpawnGroup group = previewGroup();
    m_corners.clear();
    setState(State::Idle);
    pushGroup(std::move(group));
}

void GroupTool::pushGroup(sim::SpawnGroup group)
{
    const QString text = tr("Add spawn group %1 (%2 agents)").arg(QString::fromStdString(group.name)).arg(group.count);
    addAndSelect(document(), &sim::Scene::groups, std::move(group), text);
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
    if (g.shape == sim::AreaShape::Polygon) {
        g.points = m_corners;
    } else if (g.shape == sim::AreaShape::Rect) {
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
    const double area = sim::spawnAreaM2(g);
    return std::uint32_t(std::max(1.0, std::round(area * m_settings.densityPerM2)));
}

void GroupTool::drawOverlay(QPainter& painter) const
{
    if (m_settings.shape == sim::AreaShape::Polygon) {
        drawPolygonOverlay(painter);
        return;
    }
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

// The corners so far, the edge to the mouse and the closing edge back to the first
// corner, filled while they make a valid polygon; red with the reason when closing was
// refused or the outline crosses itself.
void GroupTool::drawPolygonOverlay(QPainter& painter) const
{
    if (m_corners.empty())
        return;
    std::vector<glm::vec2> outline = m_corners;
    if (m_cursor && glm::length(*m_cursor - m_corners.back()) >= 1e-4f)
        outline.push_back(*m_cursor);
    const bool crossing = outline.size() >= 3 && sim::polygonSelfCrossing(outline).has_value();
    const QColor colour = crossing || !m_refusal.isEmpty() ? kRefused : kPreview;
    QPolygonF pixels;
    for (glm::vec2 p : outline)
        pixels << viewport().worldToPixel({p.x, 0.0f, p.y});
    painter.setPen(QPen(colour, 2.0));
    painter.setBrush(outline.size() >= 3 && !crossing ? QColor(colour.red(), colour.green(), colour.blue(), 40)
                                                      : QColor(Qt::transparent));
    painter.drawPolygon(pixels);
    painter.setBrush(colour);
    for (int i = 0; i < int(m_corners.size()); ++i)
        painter.drawEllipse(pixels[i], 3.0, 3.0);
    painter.setPen(colour);
    const QPointF at = pixels.back() + QPointF(12, -12);
    if (!m_refusal.isEmpty()) {
        painter.drawText(at, m_refusal);
        return;
    }
    const sim::SpawnGroup g = previewGroup();
    const QString count = m_corners.size() >= 3 ? tr("%1 × %2").arg(g.count).arg(QString::fromStdString(g.type))
                                                : tr("%n more corner(s)", nullptr, int(3 - m_corners.size()));
    painter.drawText(at, crossing ? tr("crosses itself") : count);
}

QWidget* GroupTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto* shape = new QComboBox(box);
    shape->setObjectName("groupShape");
    shape->addItems({tr("Rectangle"), tr("Circle"), tr("Polygon")});
    shape->setCurrentIndex(int(m_settings.shape));
    shape->setToolTip(tr("The area's shape: a rectangle dragged corner to corner, a circle from its centre, or a "
                         "polygon clicked corner by corner (double-click or Enter closes it)"));
    connect(shape, &QComboBox::currentIndexChanged, this, [this](int i) {
        cancel();  // corners of a polygon half drawn do not carry over to another shape
        m_settings.shape = sim::AreaShape(i);
    });
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
    connect(&document(), &SceneDocument::sceneChanged, type, [fillTypes](const SceneChange& change) {
        if (change.touches(ItemKind::AgentType))
            fillTypes();
    });
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
