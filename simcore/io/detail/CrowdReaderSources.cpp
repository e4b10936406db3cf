// Sources (`sources`): streams of agents that enter the scene during the run (Scene.h,
// Source).
#include "simcore/io/detail/CrowdReader.h"

namespace throng::sim::detail {

namespace {

constexpr double kMaxSourceAgents = 10'000'000;

}  // namespace

void CrowdReader::readSources(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "sources"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("sources", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "type", "types", "line", "rect", "rate", "arrivals", "windows", "goal",
                                  "path", "cap", "heading", "exits"});
        Source s;
        if (m_f.readName(item, "name", key, s.name, true))
            m_names.claim(item, key, s.name, "source");
        readSourceTypes(item, key, s);
        readSourcePlace(item, key, s);
        m_f.readFloat(item, "rate", key, s.rate, true, Range::Positive);
        if (const YAML::Node a = item["arrivals"]; a.IsDefined()) {
            const std::string word = a.IsScalar() ? a.Scalar() : std::string();
            if (word == "steady" || word == "poisson")
                s.arrivals = word == "poisson" ? Arrivals::Poisson : Arrivals::Steady;
            else
                m_f.error(a.Mark(), key + ".arrivals", "must be 'steady' or 'poisson'");
        }
        readSourceWindows(item, key, s);
        if (m_f.readName(item, "goal", key, s.goal, false) && !s.goal.empty())
            m_names.checkKnown(item, "goal", key, s.goal, "goal");
        if (m_f.readName(item, "path", key, s.path, false) && !s.path.empty())
            m_names.checkKnown(item, "path", key, s.path, "path");
        if (!s.goal.empty() && !s.path.empty())
            m_f.error(item.Mark(), key, "give a goal or a path, not both");
        readExits(item, key, s.exits, !s.goal.empty() || !s.path.empty(), "goal or path", scene);
        for (const SourceType& t : s.types)
            if (!s.exits.empty() && scene.brainPicksGoals(t.type))
                m_f.warning(item["exits"].Mark(), key + ".exits", "the brain of type '" + t.type +
                                                                  "' picks its agents' goals: they do not choose "
                                                                  "among exits");
        m_f.readU32(item, "cap", key, s.cap, false);
        if (double(s.cap) > kMaxSourceAgents)
            m_f.error(item["cap"].Mark(), key + ".cap", "at most 10,000,000 agents per source");
        else if (s.cap == 0 && double(s.rate) * double(scene.settings.durationS) > kMaxSourceAgents)
            m_f.error(item["rate"].Mark(), key + ".rate",
                      "lets in more than 10,000,000 agents over the run's duration; lower it or set a 'cap'");
        if (s.goal.empty() && s.path.empty() && s.exits.empty())
            m_f.warning(item.Mark(), key, "has no goal, path or exits: its agents stand where they enter");
        if (item["heading"].IsDefined() && m_f.readFloat(item, "heading", key, s.headingDeg, false))
            s.headed = true;
        scene.sources.push_back(std::move(s));
    }
}

// `type: NAME`, or `types: {NAME: weight, ...}` for a mix.
void CrowdReader::readSourceTypes(const YAML::Node& item, const std::string& key, Source& s)
{
    const YAML::Node one = item["type"], mix = item["types"];
    if (one.IsDefined() == mix.IsDefined()) {
        m_f.error(item.Mark(), key, "give the agents' 'type', or a mix as 'types: {name: weight, ...}'");
        return;
    }
    if (one.IsDefined()) {
        SourceType t;
        if (m_f.readName(item, "type", key, t.type, true) &&
            m_names.checkKnown(item, "type", key, t.type, "agent type"))
            s.types.push_back(std::move(t));
        return;
    }
    if (!mix.IsMap() || mix.size() == 0) {
        m_f.error(mix.Mark(), key + ".types", "must be a map of agent type names to weights, e.g. {walker: 3}");
        return;
    }
    m_f.checkDuplicateKeys(mix, key + ".types");
    for (auto it = mix.begin(); it != mix.end(); ++it) {
        SourceType t;
        t.type = it->first.Scalar();
        const std::string tk = key + ".types." + t.type;
        if (!m_names.known("agent type", t.type)) {
            m_f.error(it->first.Mark(), tk, "no agent type named '" + t.type + "'");
            continue;
        }
        if (m_f.toFloat(it->second, tk, t.weight, Range::Positive))
            s.types.push_back(std::move(t));
    }
}

// `line: [[x, z], [x, z]]` or `rect: {min: [x, z], max: [x, z]}`.
void CrowdReader::readSourcePlace(const YAML::Node& item, const std::string& key, Source& s)
{
    const YAML::Node line = item["line"], rect = item["rect"];
    if (line.IsDefined() == rect.IsDefined()) {
        m_f.error(item.Mark(), key, "give where agents enter: 'line: [[x, z], [x, z]]' or 'rect: {min, max}'");
        return;
    }
    if (line.IsDefined()) {
        std::vector<glm::vec2> points;
        if (!m_f.readPolyline(item, "line", key, points, true, 2))
            return;
        if (points.size() != 2) {
            m_f.error(line.Mark(), key + ".line", "a source's line has two points, its ends");
            return;
        }
        s.shape = SourceShape::Line;
        s.from = points[0];
        s.to = points[1];
        return;
    }
    if (!m_f.expectMap(rect, key + ".rect"))
        return;
    s.shape = SourceShape::Rect;
    readRect(rect, key + ".rect", s.min, s.max);
}

// `windows: [[start, end], ...]` in seconds, in order, each start before its end.
void CrowdReader::readSourceWindows(const YAML::Node& item, const std::string& key, Source& s)
{
    const YAML::Node windows = item["windows"];
    if (!windows.IsDefined())
        return;
    if (!m_f.expectSequence(windows, key + ".windows"))
        return;
    float end = 0.0f;
    for (std::size_t w = 0; w < windows.size(); ++w) {
        const std::string wk = indexKey(key + ".windows", w);
        glm::vec2 window(0.0f);
        if (!m_f.toVec2(windows[w], wk, window, Range::NonNegative))
            continue;
        if (window.x >= window.y)
            m_f.error(windows[w].Mark(), wk, "a window's start must come before its end, in seconds");
        else if (window.x < end)
            m_f.error(windows[w].Mark(), wk, "windows must be in order and must not overlap");
        else
            s.windows.push_back(window);
        end = std::max(end, window.y);
    }
}

}  // namespace throng::sim::detail
