// brain_editor_figures: how fluid the brain editor stays on a big graph. Builds a
// 300-node brain (inputs, fuzz sets, rules, math, outputs, ~400 links), shows it in the
// real Brains panel and times repaints while panning and zooming. Prints JSON; not a
// test (timings depend on the machine). Run: xvfb-run -a brain_editor_figures [nodes]
#include "editor/SceneDocument.h"
#include "editor/brain/BrainEditorPanel.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/BrainView.h"
#include "editor/simulation/SimulationController.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QScrollBar>
#include <QTest>
#include <QUndoCommand>

#include <algorithm>
#include <cstdio>
#include <vector>

using namespace throng;
using namespace throng::editor;

namespace {

sim::BrainGraph bigGraph(int nodes)
{
    // Columns of five kinds; each node reads from one or two nodes of the column before.
    const char* kinds[] = {"input", "fuzz.triangle", "rule.and", "math.add", "output"};
    sim::BrainGraph g;
    g.name = "big";
    const int perColumn = nodes / 5;
    for (int c = 0; c < 5; ++c)
        for (int r = 0; r < perColumn; ++r) {
            sim::BrainNode n;
            n.id = sim::NodeId(c * perColumn + r + 1);
            n.type = kinds[c];
            n.position = {float(c) * 280.0f, float(r) * 160.0f};
            if (c == 0)
                n.params = {{"sensor", "speed", {}}};
            if (c == 1)
                n.params = {{"points", {}, {0.0f, 0.5f, 1.0f}}};
            if (c == 4)
                n.params = {{"channel", "weight", {}}, {"behaviour", "seek", {}}};
            g.nodes.push_back(n);
            if (c == 0)
                continue;
            const sim::NodeId prev = sim::NodeId((c - 1) * perColumn + 1);
            g.links.push_back({prev + sim::NodeId(r), 0, n.id, 0});
            if (c == 2 || c == 3)
                g.links.push_back({prev + sim::NodeId((r + 1) % perColumn), 0, n.id, 1});
        }
    return g;
}

struct Timing {
    double meanMs = 0, p95Ms = 0, maxMs = 0;
};

template <typename Step>
Timing timeRepaints(QWidget* viewport, int frames, Step step)
{
    std::vector<double> ms;
    QElapsedTimer t;
    for (int i = 0; i < frames; ++i) {
        step(i);
        t.start();
        viewport->repaint();
        ms.push_back(double(t.nsecsElapsed()) / 1e6);
    }
    std::sort(ms.begin(), ms.end());
    Timing out;
    for (double v : ms)
        out.meanMs += v / double(ms.size());
    out.p95Ms = ms[std::size_t(double(ms.size() - 1) * 0.95)];
    out.maxMs = ms.back();
    return out;
}

class SetBrain : public QUndoCommand {
public:
    SetBrain(SceneDocument& d, sim::BrainGraph g) : m_doc(d), m_graph(std::move(g)) {}
    void redo() override { m_doc.modify(brains(), [&](sim::Scene& s) { s.brains = {m_graph}; }); }
    void undo() override { m_doc.modify(brains(), [](sim::Scene& s) { s.brains.clear(); }); }

private:
    // The brain list as a whole.
    static SceneChange brains() { return SceneChange::ofAll(ItemKind::Brain, SceneField::Items); }

    SceneDocument& m_doc;
    sim::BrainGraph m_graph;
};

}  // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    const int nodes = argc > 1 ? std::max(5, std::atoi(argv[1])) : 300;
    SceneDocument document;
    SimulationController simulation;
    const sim::BrainGraph graph = bigGraph(nodes);
    document.undoStack()->push(new SetBrain(document, graph));
    BrainEditorPanel panel(document, simulation, nullptr);
    panel.resize(1600, 1000);
    panel.show();
    if (!QTest::qWaitForWindowExposed(&panel))
        return 1;
    QElapsedTimer t;
    t.start();
    panel.view().frameAll();
    panel.view().viewport()->repaint();
    const double frameAllMs = double(t.nsecsElapsed()) / 1e6;
    QWidget* vp = panel.view().viewport();
    const double fitZoom = panel.view().zoom();
    const Timing panFit = timeRepaints(vp, 120, [&](int i) {
        panel.view().horizontalScrollBar()->setValue(panel.view().horizontalScrollBar()->value() + (i % 40 < 20 ? 15 : -15));
    });
    panel.view().zoomBy(1.0 / fitZoom);  // 1:1, text drawn
    const Timing pan1 = timeRepaints(vp, 120, [&](int i) {
        panel.view().verticalScrollBar()->setValue(panel.view().verticalScrollBar()->value() + (i % 40 < 20 ? 15 : -15));
    });
    const Timing zoom = timeRepaints(vp, 120, [&](int i) { panel.view().zoomBy(i % 30 < 15 ? 1.1 : 1.0 / 1.1); });
    std::printf("{\"nodes\": %zu, \"links\": %zu, \"view_px\": [%d, %d], \"frame_all_ms\": %.2f, \"fit_zoom\": %.3f,\n"
                " \"pan_all_visible\": {\"mean_ms\": %.2f, \"p95_ms\": %.2f, \"max_ms\": %.2f},\n"
                " \"pan_zoom_1\": {\"mean_ms\": %.2f, \"p95_ms\": %.2f, \"max_ms\": %.2f},\n"
                " \"zoom_steps\": {\"mean_ms\": %.2f, \"p95_ms\": %.2f, \"max_ms\": %.2f}}\n",
                graph.nodes.size(), graph.links.size(), vp->width(), vp->height(), frameAllMs, fitZoom, panFit.meanMs,
                panFit.p95Ms, panFit.maxMs, pan1.meanMs, pan1.p95Ms, pan1.maxMs, zoom.meanMs, zoom.p95Ms, zoom.maxMs);
    return 0;
}
