// Writes the scene's layout layer (`layout`): its operations in order.
#include "simcore/io/detail/YamlWriter.h"
#include "simcore/scene/Scene.h"

namespace throng::sim::detail {

namespace {

void writeSelector(YamlWriter& w, const AgentSelector& s)
{
    YAML::Emitter& o = w.out;
    w.key("agents");
    o << YAML::Flow << YAML::BeginMap;
    if (!s.ids.empty()) {
        w.key("ids");
        o << YAML::Flow << YAML::BeginSeq;
        for (const std::uint32_t id : s.ids)
            o << id;
        o << YAML::EndSeq;
    }
    auto names = [&](const char* key, const std::vector<std::string>& list) {
        if (list.empty())
            return;
        w.key(key);
        o << YAML::Flow << YAML::BeginSeq;
        for (const std::string& n : list)
            o << n;
        o << YAML::EndSeq;
    };
    names("groups", s.groups);
    names("types", s.types);
    if (!s.lasso.empty()) {
        w.key("lasso");
        w.polyline(s.lasso);
        w.key("lasso_frame");
        o << s.lassoFrame;
    }
    o << YAML::EndMap;
}

}  // namespace

void writeSceneLayout(YamlWriter& w, const Scene& s)
{
    if (s.layout.ops.empty())
        return;
    YAML::Emitter& o = w.out;
    w.key("layout");
    o << YAML::BeginSeq;
    for (const LayoutOp& op : s.layout.ops) {
        o << YAML::Flow << YAML::BeginMap;
        if (!op.name.empty())
            w.kv("name", op.name);
        w.kv("op", toString(op.kind));
        if (!op.enabled) {
            w.key("enabled");
            o << false;
        }
        if (op.kind != LayoutKind::Resolve || !(op.agents == AgentSelector{}))
            writeSelector(w, op.agents);
        if (op.firstFrame != 0 || op.lastFrame != kLastFrame) {
            w.key("frames");
            o << YAML::Flow << YAML::BeginSeq << op.firstFrame;
            if (op.lastFrame != kLastFrame)
                o << op.lastFrame;
            o << YAML::EndSeq;
        }
        switch (op.kind) {
        case LayoutKind::Translate:
            w.key("offset");
            w.vec2(op.offset);
            break;
        case LayoutKind::Rotate:
            w.kvf("angle", op.angleDeg);
            if (op.pivot) {
                w.key("pivot");
                w.vec2(*op.pivot);
            }
            break;
        case LayoutKind::TimeOffset:
            w.key("later");
            o << op.frames;
            if (!op.holdFirst) {
                w.key("hold_first");
                o << false;
            }
            break;
        case LayoutKind::Mirror:
            w.key("axis");
            w.polyline({op.axis[0], op.axis[1]});
            break;
        case LayoutKind::Delete:
            break;
        case LayoutKind::Expand:
            w.kvf("factor", op.factor);
            break;
        case LayoutKind::Duplicate:
            w.key("offset");
            w.vec2(op.offset);
            break;
        case LayoutKind::Swap:
            if (!op.type.empty())
                w.kv("type", op.type);
            if (op.look >= 0) {
                w.key("look");
                o << op.look;
            }
            if (op.tint == -1)
                w.kv("tint", "none");
            else if (op.tint >= 0) {
                w.key("tint");
                o << op.tint;
            }
            break;
        case LayoutKind::ReplaceClip:
            w.kv("clip", toString(op.clip));
            break;
        case LayoutKind::Resolve:
            break;
        }
        o << YAML::EndMap;
    }
    o << YAML::EndSeq;
}

}  // namespace throng::sim::detail
