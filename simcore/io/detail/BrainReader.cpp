#include "simcore/io/detail/SceneReader.h"

#include <charconv>
#include <set>

namespace throng::sim::detail {

namespace {

bool readPort(YamlFields& f, const YAML::Node& link, const char* name, const std::string& key, NodeId& node,
              std::uint32_t& port)
{
    const YAML::Node v = link[name];
    const std::string k = childKey(key, name);
    if (!v.IsDefined()) {
        f.error(link.Mark(), k, std::string("missing required key '") + name + "' ([node id, port])");
        return false;
    }
    if (!v.IsSequence() || v.size() != 2 || !v[0].IsScalar() || !v[1].IsScalar()) {
        f.error(v.Mark(), k, "must be [node id, port]");
        return false;
    }
    std::uint64_t n = 0, p = 0;
    const std::string& ns = v[0].Scalar();
    const std::string& ps = v[1].Scalar();
    auto [e1, ec1] = std::from_chars(ns.data(), ns.data() + ns.size(), n);
    auto [e2, ec2] = std::from_chars(ps.data(), ps.data() + ps.size(), p);
    if (ec1 != std::errc() || ec2 != std::errc() || e1 != ns.data() + ns.size() || e2 != ps.data() + ps.size() ||
        n == 0 || n > 0xffffffffull || p > 0xffffull) {
        f.error(v.Mark(), k, "must be [node id >= 1, port >= 0] as whole numbers");
        return false;
    }
    node = NodeId(n);
    port = std::uint32_t(p);
    return true;
}

void readParams(YamlFields& f, const YAML::Node& params, const std::string& key, BrainNode& node)
{
    if (!f.expectMap(params, key))
        return;
    f.checkDuplicateKeys(params, key);
    std::set<std::string> seen;
    for (auto it = params.begin(); it != params.end(); ++it) {
        BrainParam p;
        p.key = it->first.Scalar();
        if (!seen.insert(p.key).second)
            continue;  // reported as a duplicate key
        const std::string pk = key + "." + p.key;
        const YAML::Node v = it->second;
        if (v.IsSequence()) {
            p.numbers.resize(v.size());
            bool ok = true;
            for (std::size_t i = 0; ok && i < v.size(); ++i)
                ok = f.toFloat(v[i], indexKey(pk, i), p.numbers[i], Range::Any);
            if (!ok)
                continue;
        } else if (v.IsScalar() && v.Tag() == "!") {
            p.text = v.Scalar();  // quoted: always text, even "3"
        } else if (v.IsScalar()) {
            float number = 0.0f;
            std::string why;
            if (parseFiniteFloat(v.Scalar(), number, why))
                p.numbers = {number};
            else if (why.find("finite") != std::string::npos || why.find("range") != std::string::npos) {
                f.error(v.Mark(), pk, why);
                continue;
            } else
                p.text = v.Scalar();
        } else {
            f.error(v.Mark(), pk, "a parameter is a number, a list of numbers or text");
            continue;
        }
        node.params.push_back(std::move(p));
    }
}

}  // namespace

void readBrainGraph(YamlFields& f, const YAML::Node& node, const std::string& key, BrainGraph& brain, bool isFile)
{
    if (!f.expectMap(node, key))
        return;
    if (isFile) {
        f.checkKeys(node, key, {"throng_brain", "nodes", "links"});
        std::uint64_t version = 0;
        if (f.readUInt(node, "throng_brain", key, version, true, 1'000'000) && version != 1)
            f.error(node["throng_brain"].Mark(), "throng_brain",
                    "unsupported brain format version " + std::to_string(version) + " (this Throng reads version 1)");
    } else {
        f.checkKeys(node, key, {"name", "nodes", "links"});
    }
    std::set<NodeId> ids;
    brain.source.file = f.file();
    const auto at = [](const YAML::Node& n) { return BrainSourcePos{n.Mark().line + 1, n.Mark().column + 1}; };
    if (const YAML::Node nodes = node["nodes"]; nodes.IsDefined() && f.expectSequence(nodes, childKey(key, "nodes"))) {
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            const std::string nk = indexKey(childKey(key, "nodes"), i);
            const YAML::Node item = nodes[i];
            if (!f.expectMap(item, nk))
                continue;
            f.checkKeys(item, nk, {"id", "type", "label", "position", "params"});
            BrainNode n;
            if (!f.readU32(item, "id", nk, n.id, true) || !f.readName(item, "type", nk, n.type, true))
                continue;
            if (n.id == 0) {
                f.error(item["id"].Mark(), nk + ".id", "node ids start at 1");
                continue;
            }
            if (!ids.insert(n.id).second) {
                f.error(item["id"].Mark(), nk + ".id", "node id " + std::to_string(n.id) + " is used twice");
                continue;
            }
            f.readString(item, "label", nk, n.label, false);
            f.readVec2(item, "position", nk, n.position, false);
            if (const YAML::Node params = item["params"]; params.IsDefined())
                readParams(f, params, nk + ".params", n);
            brain.source.nodes.emplace_back(n.id, at(item));
            brain.nodes.push_back(std::move(n));
        }
    }
    if (const YAML::Node links = node["links"]; links.IsDefined() && f.expectSequence(links, childKey(key, "links"))) {
        for (std::size_t i = 0; i < links.size(); ++i) {
            const std::string lk = indexKey(childKey(key, "links"), i);
            const YAML::Node item = links[i];
            if (!f.expectMap(item, lk))
                continue;
            f.checkKeys(item, lk, {"from", "to"});
            BrainLink l;
            if (!readPort(f, item, "from", lk, l.fromNode, l.fromPort) ||
                !readPort(f, item, "to", lk, l.toNode, l.toPort))
                continue;
            bool ok = true;
            for (auto [id, end] : {std::pair{l.fromNode, "from"}, std::pair{l.toNode, "to"}})
                if (!ids.count(id)) {
                    f.error(item[end].Mark(), lk + "." + end,
                            "no node with id " + std::to_string(id) + " in this brain");
                    ok = false;
                }
            if (ok) {
                brain.links.push_back(l);
                brain.source.links.push_back(at(item));
            }
        }
    }
}

}  // namespace throng::sim::detail
