// The layout layer (`layout`): edits to the recorded crowd, applied after the simulation
// (LayoutLayer.h); they change nothing in the simulation itself.
#include "simcore/io/detail/LayoutReader.h"

#include "simcore/scene/GroundPolygon.h"

#include <algorithm>
#include <cmath>

namespace throng::sim::detail {

void LayoutReader::readAgents(const YAML::Node& item, const std::string& key, const Scene& scene,
                              AgentSelector& s)
{
    const YAML::Node agents = item["agents"];
    const std::string at = key + ".agents";
    if (!agents.IsDefined()) {
        m_f.error(item.Mark(), key, "give the operation's 'agents': {ids: [...], groups: [...], types: [...], "
                                    "lasso: [[x, z], ...], lasso_frame: N}");
        return;
    }
    if (!m_f.expectMap(agents, at))
        return;
    m_f.checkKeys(agents, at, {"ids", "groups", "types", "lasso", "lasso_frame"});
    if (const YAML::Node ids = agents["ids"]; ids.IsDefined() && m_f.expectSequence(ids, at + ".ids"))
        for (std::size_t k = 0; k < ids.size(); ++k) {
            std::uint32_t id = 0;
            YAML::Node holder;
            holder["id"] = ids[k];
            if (m_f.readU32(holder, "id", indexKey(at + ".ids", k), id, true))
                s.ids.push_back(id);
        }
    m_f.readStringList(agents, "groups", at, s.groups, false);
    m_f.readStringList(agents, "types", at, s.types, false);
    for (const std::string& t : s.types)
        if (!scene.findAgentType(t))
            m_f.error(agents["types"].Mark(), at + ".types", "no agent type named '" + t + "'");
    if (agents["lasso"].IsDefined() && m_f.readPolyline(agents, "lasso", at, s.lasso, true, 3) &&
        polygonSelfCrossing(s.lasso))
        m_f.error(agents["lasso"].Mark(), at + ".lasso", "the lasso's outline crosses itself");
    std::uint64_t frame = 0;
    if (m_f.readUInt(agents, "lasso_frame", at, frame, false, 100'000'000))
        s.lassoFrame = std::size_t(frame);
    if (s.ids.empty() && s.groups.empty() && s.types.empty() && s.lasso.empty())
        m_f.error(agents.Mark(), at, "select some agents: ids, groups, types or a lasso");
}

void LayoutReader::readSwap(const YAML::Node& item, const std::string& key, const Scene& scene, LayoutOp& op)
{
    if (item["frames"].IsDefined())
        m_f.error(item["frames"].Mark(), key + ".frames",
                  "a swap shows the agents so on every frame: leave out 'frames'");
    const AgentType* type = nullptr;
    if (m_f.readString(item, "type", key, op.type, false) && !op.type.empty()) {
        type = scene.findAgentType(op.type);
        if (!type)
            m_f.error(item["type"].Mark(), key + ".type", "no agent type named '" + op.type + "'");
    }
    // Out of range for the type it shows (when the file says which): as for a placed agent.
    const std::string known = type ? op.type : std::string();
    m_f.readIndexOfType(item, "look", key, op.look, type ? std::max<std::size_t>(1, type->variation.looks.size()) : 0,
                        known);
    if (const YAML::Node tint = item["tint"]; tint.IsDefined()) {
        if (tint.IsScalar() && tint.Scalar() == "none")
            op.tint = -1;
        else
            m_f.readIndexOfType(item, "tint", key, op.tint, type ? type->variation.tints.size() : 0, known);
    }
    if (op.type.empty() && op.look < 0 && op.tint == LayoutOp::kKeepTint && !item["look"].IsDefined() &&
        !item["tint"].IsDefined())
        m_f.error(item.Mark(), key, "a swap gives a 'look', a 'tint' (or none) or a 'type'");
}

void LayoutReader::read(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "layout"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("layout", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "op", "enabled", "agents", "frames", "offset", "angle", "pivot",
                                  "later", "hold_first", "axis", "factor", "look", "tint", "type", "clip"});
        LayoutOp op;
        if (m_f.readName(item, "name", key, op.name, false) && !op.name.empty() && !m_names.insert(op.name).second)
            m_f.error(item["name"].Mark(), key + ".name",
                      "another layout operation is already named '" + op.name + "'");
        std::string kind;
        if (!m_f.readString(item, "op", key, kind, true))
            continue;
        if (!layoutKindFromName(kind, op.kind)) {
            m_f.error(item["op"].Mark(), key + ".op",
                      "unknown layout operation '" + kind +
                          "' (translate, rotate, time_offset, mirror, delete, expand, duplicate, swap, "
                          "replace_clip or resolve)");
            continue;
        }
        m_f.readBool(item, "enabled", key, op.enabled, false);
        // A resolve without agents resolves every agent the operations before it moved.
        if (op.kind != LayoutKind::Resolve || item["agents"].IsDefined())
            readAgents(item, key, scene, op.agents);
        if (const YAML::Node frames = item["frames"]; frames.IsDefined()) {
            // [first, last] inclusive, or [first] for "from this frame on".
            std::vector<float> range;
            if (m_f.readFloatList(item, "frames", key, range, true)) {
                const bool whole = std::all_of(range.begin(), range.end(),
                                               [](float v) { return v >= 0.0f && v == float(std::size_t(v)); });
                if (range.empty() || range.size() > 2 || !whole || (range.size() == 2 && range[1] < range[0]))
                    m_f.error(frames.Mark(), key + ".frames", "give [first, last] frames (whole, first <= last) "
                                                              "or [first] for every frame from first on");
                else {
                    op.firstFrame = std::size_t(range[0]);
                    op.lastFrame = range.size() == 2 ? std::size_t(range[1]) : kLastFrame;
                }
            }
        }
        switch (op.kind) {
        case LayoutKind::Translate:
            m_f.readVec2(item, "offset", key, op.offset, true);
            break;
        case LayoutKind::Rotate: {
            m_f.readFloat(item, "angle", key, op.angleDeg, true);
            glm::vec2 pivot;
            if (item["pivot"].IsDefined() && m_f.readVec2(item, "pivot", key, pivot, true))
                op.pivot = pivot;
            break;
        }
        case LayoutKind::TimeOffset: {
            float later = 0.0f;
            if (m_f.readFloat(item, "later", key, later, true)) {
                if (later != float(int(later)) || std::abs(later) > 1e7f)
                    m_f.error(item["later"].Mark(), key + ".later", "a whole number of frames");
                else
                    op.frames = int(later);
            }
            m_f.readBool(item, "hold_first", key, op.holdFirst, false);
            break;
        }
        case LayoutKind::Mirror: {
            std::vector<glm::vec2> axis;
            if (m_f.readPolyline(item, "axis", key, axis, true, 2)) {
                if (axis.size() != 2 || axis[0] == axis[1])
                    m_f.error(item["axis"].Mark(), key + ".axis",
                              "the mirror's line: two different points [[x, z], [x, z]]");
                else {
                    op.axis[0] = axis[0];
                    op.axis[1] = axis[1];
                }
            }
            break;
        }
        case LayoutKind::Delete:
            break;
        case LayoutKind::Expand:
            if (m_f.readFloat(item, "factor", key, op.factor, true) && !(op.factor > 0.0f && op.factor <= 100.0f))
                m_f.error(item["factor"].Mark(), key + ".factor", "the factor is above 0 and at most 100");
            break;
        case LayoutKind::Duplicate:
            m_f.readVec2(item, "offset", key, op.offset, true);
            break;
        case LayoutKind::Swap:
            readSwap(item, key, scene, op);
            break;
        case LayoutKind::Resolve:
            break;
        case LayoutKind::ReplaceClip: {
            std::string clip;
            if (m_f.readString(item, "clip", key, clip, true)) {
                if (const std::optional<Clip> c = clipFromName(clip))
                    op.clip = *c;
                else
                    m_f.error(item["clip"].Mark(), key + ".clip",
                              "unknown clip '" + clip + "' (idle, walk, run, or an action such as wave or sit)");
            }
            break;
        }
        }
        scene.layout.ops.push_back(std::move(op));
    }
}

}  // namespace throng::sim::detail
