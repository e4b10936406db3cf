#include "export/UsdExporter.h"

#include "export/character/AgentVariation.h"
#include "export/character/CharacterLibrary.h"
#include "export/detail/AgentBake.h"
#include "export/detail/CrowdSetup.h"
#include "export/detail/ExportCancel.h"
#include "export/detail/TextFields.h"
#include "export/detail/UsdAnimation.h"
#include "export/detail/UsdCharacter.h"
#include "export/detail/UsdMaterials.h"
#include "export/detail/UsdSet.h"
#include "export/detail/UsdText.h"
#include "export/detail/StagingDirectory.h"
#include "simcore/base/ThreadTeam.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <filesystem>
#include <set>

namespace throng::exporting {

namespace {

using detail::appendUsdFloat;
using detail::appendUsdQuat;
using detail::appendUsdVec3;
using detail::indent;
using detail::usdQuoted;

constexpr float kUsdDegToRad = 3.14159265358979f / 180.0f;
const std::string kCrowd = "/Crowd";
const std::string kCharacters = kCrowd + "/Characters";
const std::string kMaterials = kCrowd + "/Materials";

// The clips layer's file name beside the stage: its stem and ".clips.usda", keeping only
// [A-Za-z0-9._~-] (the stage names it in an asset path).
std::string usdClipsFileName(const std::string& stagePath)
{
    std::string name = std::filesystem::path(stagePath).stem().string() + ".clips.usda";
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '~' && c != '-')
            c = '_';
    return name;
}

// Writes the agents, remembering which looks and materials they use.
class AgentWriter {
public:
    AgentWriter(const sim::Scene& scene, const sim::FrameCache& cache, const CharacterLibrary& library,
                std::uint64_t seed, const detail::JointClock& jointClock, detail::UsdMaterials& materials)
        : m_scene(scene), m_cache(cache), m_library(library), m_seed(seed), m_jointClock(jointClock),
          m_materials(materials)
    {
        std::set<std::string> taken;
        for (std::size_t c = 0; c < library.characterCount(); ++c) {
            std::string base = detail::usdIdentifier(library.character(c).name), name = base;
            for (int k = 1; taken.count(name); ++k)
                name = base + "_" + std::to_string(k);
            taken.insert(name);
            m_looks.push_back(detail::usdLookOf(library.character(c), name));
        }
        m_used.assign(library.characterCount(), false);
    }

    // compact: the agents' animations read shared cycles from this clips layer ("./x.clips.usda").
    void shareCycles(const std::string& clipsAsset)
    {
        m_cycles = std::make_unique<detail::UsdSharedCycles>(m_library, clipsAsset, m_cache.fps());
    }
    void write(std::string& out, std::size_t i, const detail::AgentWork& w);
    void writeClipsLayer(std::string& out) const { m_cycles->writeClipsLayer(out, m_looks); }
    // The looks some agent's variant set names, as class prims.
    void writeCharacters(std::string& out, int depth);

private:
    std::string tintMaterial(std::size_t typeIndex, int tint);
    std::string slotMaterial(MaterialSlot slot, std::size_t colour);
    void writeLookVariant(std::string& out, int depth, std::size_t character, std::uint32_t id,
                          const AgentVariation& v, const std::string& untinted);

    const sim::Scene& m_scene;
    const sim::FrameCache& m_cache;
    const CharacterLibrary& m_library;
    std::uint64_t m_seed;
    const detail::JointClock& m_jointClock;
    detail::UsdMaterials& m_materials;
    std::vector<detail::UsdLook> m_looks;
    std::vector<bool> m_used;
    std::unique_ptr<detail::UsdSharedCycles> m_cycles;  // compact; none: each agent's joints baked
};

std::string AgentWriter::tintMaterial(std::size_t typeIndex, int tint)
{
    const sim::AgentType& type = m_scene.agentTypes[typeIndex];
    if (tint < 0)
        return m_materials.path(type.name + "_colour", glm::vec3(untintedColour(typeIndex)));
    const glm::vec3 rgb = glm::clamp(type.variation.tints[static_cast<std::size_t>(tint)], 0.0f, 1.0f);
    return m_materials.path(type.name + "_tint" + std::to_string(tint), rgb);
}

std::string AgentWriter::slotMaterial(MaterialSlot slot, std::size_t colour)
{
    return m_materials.path(std::string(toString(slot)) + "_" + std::to_string(colour), slotPalette(slot)[colour],
                            slot == MaterialSlot::Skin ? 0.55f : 0.8f);
}

void AgentWriter::writeLookVariant(std::string& out, int depth, std::size_t character, std::uint32_t id,
                                   const AgentVariation& v, const std::string& untinted)
{
    const Character& c = m_library.character(character);
    const detail::UsdLook& look = m_looks[character];
    m_used[character] = true;
    indent(out, depth);
    out += usdQuoted(look.prim) + " {\n";
    indent(out, depth + 1);
    out += "over \"Character\" (\n";
    indent(out, depth + 2);
    out += "prepend references = <" + kCharacters + "/" + look.prim + ">\n";
    indent(out, depth + 1);
    out += ")\n";
    indent(out, depth + 1);
    out += "{\n";
    const std::vector<MeshPart> parts = partsOf(c.mesh);
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const MeshPart& part = parts[p];
        const bool worn = wearsPart(part, m_seed, id);
        const bool tinted = slotPalette(part.slot).empty();
        if (worn && tinted && untinted.empty())
            continue;  // the tint's variant binds it
        indent(out, depth + 2);
        out += "over " + usdQuoted(look.partNames[p]) + "\n";
        indent(out, depth + 2);
        out += "{\n";
        indent(out, depth + 3);
        if (!worn)
            out += "token visibility = \"invisible\"\n";
        else
            out += "rel material:binding = <" +
                   (tinted ? untinted
                           : slotMaterial(part.slot, v.colour[static_cast<std::size_t>(part.slot)])) +
                   ">\n";
        indent(out, depth + 2);
        out += "}\n";
    }
    indent(out, depth + 1);
    out += "}\n";
    indent(out, depth);
    out += "}\n";
}

void AgentWriter::write(std::string& out, std::size_t i, const detail::AgentWork& w)
{
    const sim::AgentInfo& info = m_cache.agents()[i];
    const sim::AgentType& type = m_scene.agentTypes[info.typeIndex];
    const Character& look = m_library.character(w.character);
    const std::string name = "agent_" + std::to_string(info.id) + "_" + detail::usdIdentifier(type.name);
    const std::string path = kCrowd + "/Agents/" + name;
    const bool tints = !type.variation.tints.empty();
    const std::size_t frames = m_cache.frameCount();
    constexpr int d = 2;

    indent(out, d);
    out += "def SkelRoot " + usdQuoted(name) + " (\n";
    indent(out, d + 1);
    out += "prepend apiSchemas = [\"SkelBindingAPI\"]\n";
    indent(out, d + 1);
    out += "customData = {\n";
    indent(out, d + 2);
    out += "int agentId = " + std::to_string(info.id) + "\n";
    indent(out, d + 2);
    out += "string type = " + usdQuoted(type.name) + "\n";
    indent(out, d + 2);
    out += "string character = " + usdQuoted(look.name) + "\n";
    indent(out, d + 2);
    out += "int tint = " + std::to_string(w.variation.tint) + "\n";
    indent(out, d + 2);
    out += "float speedFactor = ";
    detail::appendUsdRounded(out, w.variation.speedFactor, 5);
    out += "\n";
    indent(out, d + 2);
    out += "float phaseOffset = ";
    detail::appendUsdRounded(out, w.variation.phaseOffset, 5);
    out += "\n";
    indent(out, d + 1);
    out += "}\n";
    indent(out, d + 1);
    out += "variants = {\n";
    indent(out, d + 2);
    out += "string look = " + usdQuoted(m_looks[w.character].prim) + "\n";
    if (tints) {
        indent(out, d + 2);
        out += "string tint = \"tint" + std::to_string(std::max(w.variation.tint, 0)) + "\"\n";
    }
    indent(out, d + 1);
    out += "}\n";
    indent(out, d + 1);
    out += tints ? "prepend variantSets = [\"look\", \"tint\"]\n" : "prepend variantSets = \"look\"\n";
    indent(out, d);
    out += ")\n";
    indent(out, d);
    out += "{\n";
    indent(out, d + 1);
    out += "rel skel:animationSource = <" + path + "/Anim>\n";
    // Time samples of `declaration` at the kept frames.
    auto samples = [&](const char* declaration, const std::vector<std::uint32_t>& kept, auto append) {
        out += declaration;
        out += ".timeSamples = {\n";
        for (const std::uint32_t f : kept) {
            indent(out, d + 2);
            out += std::to_string(f) + ": ";
            append(f);
            out += ",\n";
        }
        indent(out, d + 1);
        out += "}\n";
    };
    indent(out, d + 1);
    samples("double3 xformOp:translate", w.positionKept, [&](std::uint32_t f) { appendUsdVec3(out, w.positions[f]); });
    indent(out, d + 1);
    samples("quatf xformOp:orient", w.yawKept, [&](std::uint32_t f) { appendUsdQuat(out, w.yaw[f]); });
    indent(out, d + 1);
    out += "float3 xformOp:scale = ";
    appendUsdVec3(out, glm::vec3(w.variation.heightScale));
    out += '\n';
    indent(out, d + 1);
    out += "uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:orient\", \"xformOp:scale\"]\n";
    if (std::find(w.hidden.begin(), w.hidden.end(), 1) != w.hidden.end()) {
        indent(out, d + 1);
        out += "token visibility.timeSamples = {\n";
        for (std::size_t f = 0; f < frames; ++f) {
            if (f > 0 && w.hidden[f] == w.hidden[f - 1])
                continue;
            indent(out, d + 2);
            out += std::to_string(f) + (w.hidden[f] ? ": \"invisible\",\n" : ": \"inherited\",\n");
        }
        indent(out, d + 1);
        out += "}\n";
    }
    if (m_cycles)
        m_cycles->writeAnimation(out, d + 1, w, m_looks[w.character]);
    else
        detail::writeBakedAnimation(out, d + 1, look, m_looks[w.character], m_jointClock, w.joints);
    indent(out, d + 1);
    out += "def Xform \"Character\"\n";
    indent(out, d + 1);
    out += "{\n";
    indent(out, d + 1);
    out += "}\n";

    const std::string untinted = tints ? std::string() : tintMaterial(info.typeIndex, -1);
    indent(out, d + 1);
    out += "variantSet \"look\" = {\n";
    for (const std::size_t character : m_library.looksOf(info.typeIndex))
        writeLookVariant(out, d + 2, character, info.id, w.variation, untinted);
    indent(out, d + 1);
    out += "}\n";
    if (tints) {
        indent(out, d + 1);
        out += "variantSet \"tint\" = {\n";
        for (std::size_t t = 0; t < type.variation.tints.size(); ++t) {
            const std::string material = tintMaterial(info.typeIndex, static_cast<int>(t));
            indent(out, d + 2);
            out += "\"tint" + std::to_string(t) + "\" {\n";
            indent(out, d + 3);
            out += "over \"Character\"\n";
            indent(out, d + 3);
            out += "{\n";
            // Every look's tinted parts: whichever look the other set chooses.
            std::set<std::string> parts;
            for (const std::size_t character : m_library.looksOf(info.typeIndex)) {
                const std::vector<MeshPart> meshParts = partsOf(m_library.character(character).mesh);
                for (std::size_t p = 0; p < meshParts.size(); ++p)
                    if (slotPalette(meshParts[p].slot).empty() && wearsPart(meshParts[p], m_seed, info.id))
                        parts.insert(m_looks[character].partNames[p]);
            }
            for (const std::string& part : parts) {
                indent(out, d + 4);
                out += "over " + usdQuoted(part) + "\n";
                indent(out, d + 4);
                out += "{\n";
                indent(out, d + 5);
                out += "rel material:binding = <" + material + ">\n";
                indent(out, d + 4);
                out += "}\n";
            }
            indent(out, d + 3);
            out += "}\n";
            indent(out, d + 2);
            out += "}\n";
        }
        indent(out, d + 1);
        out += "}\n";
    }
    indent(out, d);
    out += "}\n";
}

void AgentWriter::writeCharacters(std::string& out, int depth)
{
    indent(out, depth);
    out += "class Scope \"Characters\"\n";
    indent(out, depth);
    out += "{\n";
    for (std::size_t c = 0; c < m_looks.size(); ++c) {
        if (!m_used[c])
            continue;
        // Until an agent's variant binds its own: the first colour of each palette, grey tops.
        std::vector<std::string> materials;
        for (const MeshPart& part : partsOf(m_library.character(c).mesh))
            materials.push_back(slotPalette(part.slot).empty()
                                    ? m_materials.path("untinted", glm::vec3(0.6f))
                                    : slotMaterial(part.slot, 0));
        detail::writeUsdCharacter(out, depth + 1, m_library.character(c), m_looks[c],
                                  kCharacters + "/" + m_looks[c].prim, materials);
    }
    indent(out, depth);
    out += "}\n";
}

void writeHeader(std::string& out, const sim::FrameCache& cache, std::uint64_t seed, const UsdOptions& options)
{
    out += "#usda 1.0\n(\n";
    out += "    defaultPrim = \"Crowd\"\n";
    out += "    doc = \"A crowd written by Throng\"\n";
    out += "    metersPerUnit = 1\n";
    out += "    upAxis = \"Y\"\n";
    out += "    startTimeCode = 0\n";
    out += "    endTimeCode = " + std::to_string(cache.frameCount() - 1) + "\n";
    out += "    timeCodesPerSecond = ";
    appendUsdFloat(out, cache.fps());
    out += "\n    framesPerSecond = ";
    appendUsdFloat(out, cache.fps());
    out += "\n    customLayerData = {\n";
    out += "        string generator = \"Throng\"\n";
    out += "        int agentCount = " + std::to_string(cache.agentCount()) + "\n";
    out += "        int frameCount = " + std::to_string(cache.frameCount()) + "\n";
    out += "        string seed = \"" + std::to_string(seed) + "\"\n";
    out += "        int jointFrameStep = " + std::to_string(options.jointFrameStep) + "\n";
    out += std::string("        string mode = \"") + (options.compact ? "compact" : "exact") + "\"\n";
    out += std::string("        bool set = ") + (options.includeSet ? "1" : "0") + "\n";
    out += "    }\n)\n\n";
    out += "def Xform \"Crowd\" (\n    kind = \"assembly\"\n)\n{\n";
    const glm::dvec3 origin = cache.origin();
    if (origin != glm::dvec3(0.0)) {
        out += "    double3 xformOp:translate = (";
        detail::appendUsdDouble(out, origin.x);
        out += ", ";
        detail::appendUsdDouble(out, origin.y);
        out += ", ";
        detail::appendUsdDouble(out, origin.z);
        out += ")\n    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n";
    }
}

}  // namespace

ExportResult exportUsd(const sim::Scene& scene, const sim::FrameCache& cache, const UsdOptions& options,
                       const ProgressFn& progress)
{
    detail::CrowdStart start;
    if (std::optional<ExportResult> ended = detail::startCrowd(
            detail::checkCrowdInput(scene, cache, options.path, {".usda"}, options.jointFrameStep,
                                    {options.positionToleranceM, options.rotationToleranceDeg,
                                     options.rootRotationToleranceDeg}),
            scene, cache, options, progress, start))
        return *ended;
    ExportResult result;
    const std::uint64_t seed = start.seed;
    const std::size_t frames = cache.frameCount(), agents = cache.agentCount();
    const detail::AgentBaker baker(scene, cache, start.library, seed, start.times, start.jointClock,
                                   {.compact = options.compact,
                                    .positionToleranceM = options.positionToleranceM,
                                    .rotationToleranceRad = options.rotationToleranceDeg * kUsdDegToRad,
                                    .rootRotationToleranceRad = options.rootRotationToleranceDeg * kUsdDegToRad});

    // The stage, and in compact mode the clips layer beside it, are written in full in a
    // staging folder beside the target, then renamed in: the clips first.
    detail::StagingDirectory staging(options.path);
    if (!staging.create()) {
        result.error = staging.error();
        return result;
    }
    const std::string clipsName = usdClipsFileName(options.path);
    std::ofstream file(staging.filePath("stage.usda"), std::ios::binary);
    auto flush = [&](std::string& text, bool always) {
        if (always || text.size() >= detail::kFlushBytes) {
            file.write(text.data(), static_cast<std::streamsize>(text.size()));
            text.clear();
        }
    };
    std::string text;
    writeHeader(text, cache, seed, options);
    detail::UsdMaterials materials(kMaterials);
    AgentWriter writer(scene, cache, start.library, seed, start.jointClock, materials);
    if (options.compact)
        writer.shareCycles("./" + clipsName);
    text += "    def Xform \"Agents\"\n    {\n";

    if (!detail::bakeInOrder(baker, agents, true, sim::ThreadTeam(options.threads), progress, 0.0f, 0.95f,
                             [&](std::size_t i, const detail::AgentWork& w) {
                                 writer.write(text, i, w);
                                 flush(text, false);
                             }))
        return detail::cancelledExport(options.path);
    text += "    }\n";
    writer.writeCharacters(text, 1);
    if (options.includeSet)
        detail::writeUsdSet(text, 1, kCrowd + "/Set", scene, glm::dvec2(cache.origin().x, cache.origin().z), frames,
                            cache.fps(), options.firstFrame, materials);
    if (!materials.empty())
        materials.write(text, 1);
    text += "}\n";
    flush(text, true);
    file.close();
    std::string clipsPath;
    if (options.compact) {
        std::string clips;
        writer.writeClipsLayer(clips);
        std::ofstream out(staging.filePath("clips.usda"), std::ios::binary);
        out.write(clips.data(), static_cast<std::streamsize>(clips.size()));
        if (!out.flush()) {
            result.error = "cannot write '" + options.path + "': " + std::strerror(errno);
            return result;
        }
        clipsPath = (std::filesystem::path(options.path).parent_path() / clipsName).string();
    }
    if (!file) {
        result.error = "cannot write '" + options.path + "': " + std::strerror(errno);
        return result;
    }
    if (!staging.syncToDisk() || (options.compact && !staging.publish("clips.usda", clipsPath)) ||
        !staging.publish("stage.usda", options.path)) {
        result.error = staging.error();
        return result;
    }
    if (options.compact)
        result.writtenPaths.push_back(clipsPath);
    result.writtenPaths.push_back(options.path);
    if (progress)
        progress(1.0f);
    return result;
}

}  // namespace throng::exporting
