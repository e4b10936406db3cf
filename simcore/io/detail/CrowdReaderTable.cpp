// The compact form of `agents` for painted crowds: one text row per agent inside a
// literal block, parsed here without building a YAML node per value.
#include "simcore/io/detail/CrowdReader.h"

#include <algorithm>
#include <array>
#include <charconv>

namespace throng::sim::detail {

namespace {

enum Column { kId, kType, kX, kY, kZ, kHeading, kGoal, kPath, kLeader, kLook, kTint, kHeight, kBrain, kGroup,
              kColumnCount };
const std::array<const char*, kColumnCount> kColumnNames{
    "id", "type", "x", "y", "z", "heading", "goal", "path", "leader", "look", "tint", "height", "brain", "group"};

// Finds a 0-based line of the source text.
struct LineIndex {
    std::string_view text;
    std::string_view line(int line0) const
    {
        std::size_t pos = 0;
        for (int i = 0; i < line0 && pos != std::string_view::npos; ++i) {
            pos = text.find('\n', pos);
            if (pos != std::string_view::npos)
                ++pos;
        }
        if (pos == std::string_view::npos || pos >= text.size())
            return {};
        std::size_t end = text.find('\n', pos);
        return text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
    }
};

}  // namespace

void CrowdReader::readAgentTable(const YAML::Node& node, const std::string& key, Scene& scene)
{
    m_f.checkKeys(node, key, {"columns", "rows"});
    std::vector<std::string> columns;
    if (!m_f.readStringList(node, "columns", key, columns, true))
        return;
    std::array<int, kColumnCount> at;
    at.fill(-1);
    for (std::size_t i = 0; i < columns.size(); ++i) {
        int found = -1;
        for (int c = 0; c < kColumnCount; ++c)
            if (columns[i] == kColumnNames[c])
                found = c;
        const std::string ck = indexKey(key + ".columns", i);
        if (found < 0) {
            m_f.error(
                node["columns"][i].Mark(), ck,
                "unknown column '" + columns[i] +
                    "' (known: id, type, x, y, z, heading, goal, path, leader, look, tint, height, brain, group)");
            return;
        }
        if (at[found] >= 0) {
            m_f.error(node["columns"][i].Mark(), ck, "column '" + columns[i] + "' appears twice");
            return;
        }
        at[found] = int(i);
    }
    for (int required : {kType, kX, kZ})
        if (at[required] < 0) {
            m_f.error(node["columns"].Mark(), key + ".columns",
                      std::string("missing required column '") + kColumnNames[required] + "'");
            return;
        }
    std::string rows;
    if (!m_f.readString(node, "rows", key, rows, true))
        return;

    // A literal block's first row is on the line after the "|" indicator.
    const int firstLine0 = node["rows"].Mark().line + 1;
    LineIndex index{m_source};
    std::string_view body(rows);
    std::vector<std::string_view> tok;
    std::size_t pos = 0;
    int row = -1;
    std::string_view firstRawLine = index.line(firstLine0);
    const int indent = int(firstRawLine.find_first_not_of(' ') == std::string_view::npos
                               ? 0 : firstRawLine.find_first_not_of(' '));
    while (pos < body.size()) {
        ++row;
        std::size_t end = body.find('\n', pos);
        if (end == std::string_view::npos)
            end = body.size();
        std::string_view line = body.substr(pos, end - pos);
        // A '#' starts a comment, on its own line or after a row's values.
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        pos = end + 1;
        tok.clear();
        std::vector<std::size_t> offsets;
        for (std::size_t i = 0; i < line.size();) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
                ++i;
            if (i >= line.size())
                break;
            std::size_t j = i;
            while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r')
                ++j;
            tok.push_back(line.substr(i, j - i));
            offsets.push_back(i);
            i = j;
        }
        if (tok.empty())
            continue;
        const int line1 = firstLine0 + row + 1;
        const std::string rk = indexKey(key + ".rows", std::size_t(row));
        if (tok.size() != columns.size()) {
            m_f.errorAtLine(line1, indent + 1, rk, "expected " + std::to_string(columns.size()) + " values, got " +
                                                       std::to_string(tok.size()));
            if (m_f.errorCount() > 200)
                return;
            continue;
        }
        auto col1 = [&](int c) { return indent + int(offsets[std::size_t(at[c])]) + 1; };
        Agent a;
        bool ok = true;
        auto number = [&](int c, float& out) {
            if (at[c] < 0 || !ok)
                return;
            std::string why;
            if (!parseFiniteFloat(std::string(tok[std::size_t(at[c])]), out, why)) {
                m_f.errorAtLine(line1, col1(c), rk + "." + kColumnNames[c], why);
                ok = false;
            }
        };
        auto name = [&](int c, std::string& out, bool exists, const char* what) {
            if (at[c] < 0 || !ok)
                return;
            std::string_view t = tok[std::size_t(at[c])];
            if (t == "-" && c != kType)
                return;
            out = std::string(t);
            if (!exists) {
                m_f.errorAtLine(line1, col1(c), rk + "." + kColumnNames[c],
                                std::string("no ") + what + " named '" + out + "'");
                ok = false;
            }
        };
        if (at[kId] >= 0) {
            std::string_view t = tok[std::size_t(at[kId])];
            auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), a.id);
            if (ec != std::errc() || p != t.data() + t.size() || a.id == 0) {
                m_f.errorAtLine(line1, col1(kId), rk + ".id",
                                "must be a whole number >= 1, got '" + std::string(t) + "'");
                ok = false;
            } else if (!m_names.takeId(a.id)) {
                m_f.errorAtLine(line1, col1(kId), rk + ".id",
                                "id " + std::to_string(a.id) + " is already used by another agent, vehicle or hero");
                ok = false;
            }
        }
        std::string_view typeTok = tok[std::size_t(at[kType])];
        name(kType, a.type, m_names.known("agent type", std::string(typeTok)), "agent type");
        number(kX, a.position.x);
        number(kY, a.position.y);
        number(kZ, a.position.z);
        number(kHeading, a.headingDeg);
        if (at[kGoal] >= 0)
            name(kGoal, a.goal, m_names.known("goal", std::string(tok[std::size_t(at[kGoal])])), "goal");
        if (at[kPath] >= 0)
            name(kPath, a.path, m_names.known("path", std::string(tok[std::size_t(at[kPath])])), "path");
        if (at[kBrain] >= 0)
            name(kBrain, a.brain, m_names.known("brain", std::string(tok[std::size_t(at[kBrain])])), "brain");
        if (at[kGroup] >= 0)
            name(kGroup, a.group, true, "group");
        if (at[kLeader] >= 0 && ok) {
            std::string_view t = tok[std::size_t(at[kLeader])];
            if (t != "-") {
                auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), a.leader);
                if (ec != std::errc() || p != t.data() + t.size() || a.leader == 0) {
                    m_f.errorAtLine(line1, col1(kLeader), rk + ".leader",
                                    "must be an agent id >= 1 or '-', got '" + std::string(t) + "'");
                    ok = false;
                } else {
                    YAML::Mark place;
                    place.line = line1 - 1;
                    place.column = col1(kLeader) - 1;
                    m_names.leads(place, rk + ".leader", a.leader);
                }
            }
        }
        // Hand-set variation: '-' leaves it drawn from the type's ranges.
        const AgentType* type = ok ? scene.findAgentType(a.type) : nullptr;
        auto index = [&](int c, int& out, std::size_t count) {
            if (at[c] < 0 || !ok || tok[std::size_t(at[c])] == "-")
                return;
            std::string_view t = tok[std::size_t(at[c])];
            unsigned v = 0;
            auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
            if (ec != std::errc() || p != t.data() + t.size() || (type && v >= count)) {
                m_f.errorAtLine(line1, col1(c), rk + "." + kColumnNames[c],
                                "must be an index below " + std::to_string(count) + " or '-', got '" + std::string(t) +
                                    "'");
                ok = false;
                return;
            }
            out = int(v);
        };
        index(kLook, a.look, type ? std::max<std::size_t>(1, type->variation.looks.size()) : 0);
        index(kTint, a.tint, type ? type->variation.tints.size() : 0);
        if (at[kHeight] >= 0 && ok && tok[std::size_t(at[kHeight])] != "-") {
            number(kHeight, a.heightScale);
            if (ok && !(a.heightScale > 0.0f)) {
                m_f.errorAtLine(line1, col1(kHeight), rk + ".height", "must be > 0 or '-'");
                ok = false;
            }
        }
        if (ok)
            scene.agents.push_back(std::move(a));
        if (m_f.errorCount() > 200)
            return;
    }
}

}  // namespace throng::sim::detail
