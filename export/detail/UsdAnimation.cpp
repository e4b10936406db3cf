#include "export/detail/UsdAnimation.h"

#include "export/detail/UsdText.h"

#include <cmath>

namespace throng::exporting::detail {

namespace {

void appendPoseArrays(std::string& out, int depth, const Character& c, const Pose& pose, const char* suffix)
{
    indent(out, depth);
    out += std::string("float3[] translations") + suffix + "[";
    for (std::size_t j = 0; j < c.joints.size(); ++j) {
        if (j)
            out += ", ";
        appendUsdVec3(out, j == 0 ? pose.rootTranslation : c.joints[j].restTranslation);
    }
    out += "]\n";
    indent(out, depth);
    out += std::string("quatf[] rotations") + suffix + "[";
    for (std::size_t j = 0; j < c.joints.size(); ++j) {
        if (j)
            out += ", ";
        appendUsdQuat(out, pose.rotations[j]);
    }
    out += "]\n";
}

void appendScales(std::string& out, int depth, const Character& c)
{
    indent(out, depth);
    out += "half3[] scales = [";
    for (std::size_t j = 0; j < c.joints.size(); ++j) {
        if (j)
            out += ", ";
        appendUsdVec3(out, c.joints[j].restScale);
    }
    out += "]\n";
}

// The pairs (stage time code, clip time code) of a window: each sample at its time,
// dropping those the line through their kept neighbours reaches within the tolerance.
std::vector<std::pair<double, double>> clipTimes(const CompactPlan& p, float fps)
{
    std::vector<std::pair<double, double>> all;
    for (std::size_t k = 0; k < p.times.size(); ++k)
        all.emplace_back(double(p.times[k]) * double(fps), double(p.first + k));
    std::vector<std::pair<double, double>> kept{all.front()};
    std::size_t from = 0;
    for (std::size_t to = 2; to < all.size(); ++to) {
        const auto [t0, c0] = all[from];
        const auto [t1, c1] = all[to];
        bool fits = true;
        for (std::size_t k = from + 1; k < to && fits; ++k) {
            const double expected = c0 + (c1 - c0) * (all[k].first - t0) / (t1 - t0);
            fits = std::abs(expected - all[k].second) <= UsdSharedCycles::kTimeToleranceSamples;
        }
        if (!fits) {
            from = to - 1;
            kept.push_back(all[from]);
        }
    }
    if (all.size() > 1)
        kept.push_back(all.back());
    return kept;
}

}  // namespace

void writeBakedAnimation(std::string& out, int depth, const Character& c, const UsdLook& look,
                         const JointClock& jointClock, const BakedJoints& b)
{
    const std::size_t keys = jointClock.frames.size(), joints = c.joints.size();
    indent(out, depth);
    out += "def SkelAnimation \"Anim\"\n";
    indent(out, depth);
    out += "{\n";
    indent(out, depth + 1);
    out += "uniform token[] joints = ";
    appendUsdJointTokens(out, look);
    out += '\n';
    // Joint 0 moves (the hips bob); the others keep their rest translation.
    indent(out, depth + 1);
    out += "float3[] translations.timeSamples = {\n";
    for (const std::uint32_t k : b.rootKept) {
        indent(out, depth + 2);
        out += std::to_string(jointClock.frames[k]) + ": [";
        for (std::size_t j = 0; j < joints; ++j) {
            if (j)
                out += ", ";
            appendUsdVec3(out, j == 0 ? b.rootTranslation[k] : c.joints[j].restTranslation);
        }
        out += "],\n";
    }
    indent(out, depth + 1);
    out += "}\n";
    // A sample holds every joint: the keys any joint keeps.
    std::vector<std::uint8_t> kept(keys, 0);
    for (const std::vector<std::uint32_t>& joint : b.kept)
        for (const std::uint32_t k : joint)
            kept[k] = 1;
    indent(out, depth + 1);
    out += "quatf[] rotations.timeSamples = {\n";
    for (std::size_t k = 0; k < keys; ++k) {
        if (!kept[k])
            continue;
        indent(out, depth + 2);
        out += std::to_string(jointClock.frames[k]) + ": [";
        for (std::size_t j = 0; j < joints; ++j) {
            if (j)
                out += ", ";
            appendUsdQuat(out, b.rotations[j * keys + k]);
        }
        out += "],\n";
    }
    indent(out, depth + 1);
    out += "}\n";
    appendScales(out, depth + 1, c);
    indent(out, depth);
    out += "}\n";
}

UsdSharedCycles::UsdSharedCycles(const CharacterLibrary& library, std::string clipsAsset, float fps)
    : m_library(library), m_clipsAsset(std::move(clipsAsset)), m_fps(fps), m_planner(library)
{
}

std::string UsdSharedCycles::bankName(const UsdLook& look, std::size_t character, int clip) const
{
    const CycleClip& cycle = m_planner.clipOf(character, clip);
    return look.prim + "_" + std::to_string(clip) + "_" + usdIdentifier(cycle.name);
}

void UsdSharedCycles::writeAnimation(std::string& out, int depth, const AgentWork& w, const UsdLook& look)
{
    const Character& c = m_library.character(w.character);
    const CompactPlan plan = m_planner.plan(w.character, w.positions, w.gait, w.variation, m_fps);
    indent(out, depth);
    out += "def SkelAnimation \"Anim\"";
    if (plan.clip >= 0) {
        out += " (\n";
        indent(out, depth + 1);
        out += "clips = {\n";
        indent(out, depth + 2);
        out += "dictionary default = {\n";
        indent(out, depth + 3);
        out += "double2[] active = [(0, 0)]\n";
        indent(out, depth + 3);
        out += "asset[] assetPaths = [@" + m_clipsAsset + "@]\n";
        indent(out, depth + 3);
        out += "string primPath = " + usdQuoted("/Clips/" + bankName(look, w.character, plan.clip)) + "\n";
        indent(out, depth + 3);
        out += "double2[] times = [";
        bool first = true;
        for (const auto& [stage, clip] : clipTimes(plan, m_fps)) {
            out += first ? "(" : ", (";
            first = false;
            appendUsdDouble(out, std::round(stage * 1e4) / 1e4);
            out += ", ";
            appendUsdDouble(out, clip);
            out += ')';
        }
        out += "]\n";
        indent(out, depth + 2);
        out += "}\n";
        indent(out, depth + 1);
        out += "}\n";
        indent(out, depth);
        out += ")";
    }
    out += "\n";
    indent(out, depth);
    out += "{\n";
    indent(out, depth + 1);
    out += "uniform token[] joints = ";
    appendUsdJointTokens(out, look);
    out += '\n';
    if (plan.clip < 0) {  // never walks: the still pose, at every time
        appendPoseArrays(out, depth + 1, c, m_planner.stillPose(w.character), " = ");
        appendScales(out, depth + 1, c);
    }
    indent(out, depth);
    out += "}\n";
}

void UsdSharedCycles::writeClipsLayer(std::string& out, const std::vector<UsdLook>& looks) const
{
    std::size_t longest = 1;
    for (const auto& [key, length] : m_planner.bankLengths())
        longest = std::max(longest, length);
    out += "#usda 1.0\n(\n";
    out += "    doc = \"Throng's shared cycles: each agent's animation reads a window of one (value clips)\"\n";
    out += "    startTimeCode = 0\n";
    out += "    endTimeCode = " + std::to_string(longest - 1) + "\n";
    out += "    timeCodesPerSecond = ";
    appendUsdFloat(out, m_fps);
    out += "\n)\n\ndef Scope \"Clips\"\n{\n";
    for (const auto& [key, length] : m_planner.bankLengths()) {
        const auto [character, clip] = key;
        const Character& c = m_library.character(character);
        const CycleClip& cycle = m_planner.clipOf(character, clip);
        const std::size_t samples = cycle.samples.size();
        out += "    def SkelAnimation " + usdQuoted(bankName(looks[character], character, clip)) + "\n    {\n";
        out += "        uniform token[] joints = ";
        appendUsdJointTokens(out, looks[character]);
        out += "\n        float3[] translations.timeSamples = {\n";
        for (std::size_t s = 0; s < length; ++s) {
            out += "            " + std::to_string(s) + ": [";
            for (std::size_t j = 0; j < c.joints.size(); ++j) {
                if (j)
                    out += ", ";
                appendUsdVec3(out, j == 0 ? cycle.samples[s % samples].rootTranslation : c.joints[j].restTranslation);
            }
            out += "],\n";
        }
        out += "        }\n        quatf[] rotations.timeSamples = {\n";
        std::vector<glm::quat> previous(c.joints.size());
        for (std::size_t s = 0; s < length; ++s) {
            out += "            " + std::to_string(s) + ": [";
            for (std::size_t j = 0; j < c.joints.size(); ++j) {
                glm::quat q = cycle.samples[s % samples].rotations[j];
                if (s > 0 && glm::dot(q, previous[j]) < 0.0f)  // the short way from the sample before
                    q = -q;
                previous[j] = q;
                if (j)
                    out += ", ";
                appendUsdQuat(out, q);
            }
            out += "],\n";
        }
        out += "        }\n";
        appendScales(out, 2, c);
        out += "    }\n";
    }
    out += "}\n";
}

}  // namespace throng::exporting::detail
