#include "export/detail/FbxFraming.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace throng::exporting::detail {

namespace {

constexpr char kMagic[] = "Kaydara FBX Binary  ";  // then 0x00, 0x1a, 0x00, the u32 version
constexpr std::size_t kHeaderBytes = 27;
// The footer's fixed parts (what every writer, Autodesk's and Blender's, puts there).
constexpr unsigned char kFooterId[16] = {0xfa, 0xbc, 0xab, 0x09, 0xd0, 0xc8, 0xd4, 0x66,
                                         0xb1, 0x76, 0xfb, 0x83, 0x1c, 0xf7, 0x26, 0x7e};
constexpr unsigned char kFooterMagic[16] = {0xf8, 0x5a, 0x8c, 0x6a, 0xde, 0xf5, 0xd9, 0x7e,
                                            0xec, 0xe9, 0x0c, 0xe3, 0x75, 0x8f, 0x29, 0x0b};

struct Record {
    std::size_t nameAt = 0, nameBytes = 0;    // in the source
    std::size_t propsAt = 0, propsBytes = 0;  // in the source
    std::uint64_t propCount = 0;
    std::vector<Record> children;
    std::vector<unsigned char> newProps;  // when not empty: written instead of the source's
};

class Reader {
public:
    Reader(std::span<const unsigned char> b, bool wide, bool sentinels)
        : m_b(b), m_wide(wide), m_sentinels(sentinels)
    {
    }

    // The records in [pos, limit): until a null record (consumed) or `limit`.
    bool readList(std::size_t& pos, std::size_t limit, std::vector<Record>& out, bool topLevel)
    {
        while (pos < limit) {
            if (topLevel && limit - pos >= 16 && std::memcmp(&m_b[pos], kFooterId, 16) == 0)
                return true;  // the footer, no null record before it
            std::uint64_t end = 0, count = 0, length = 0;
            if (!word(pos, end) || !word(pos + offsetBytes(), count) || !word(pos + 2 * offsetBytes(), length))
                return false;
            const std::size_t nameAt = pos + 3 * offsetBytes() + 1;
            if (end == 0) {  // a null record: the list ends
                if (!allZero(pos, sentinelBytes()))
                    return false;
                pos += sentinelBytes();
                return true;
            }
            if (nameAt > m_b.size())
                return false;
            Record r;
            r.nameAt = nameAt;
            r.nameBytes = m_b[nameAt - 1];
            r.propsAt = nameAt + r.nameBytes;
            r.propsBytes = length;
            r.propCount = count;
            const std::size_t childrenAt = r.propsAt + r.propsBytes;
            if (end <= pos || end > limit || childrenAt > end)
                return false;
            std::size_t childEnd = end;
            if (childrenAt < end && m_sentinels) {
                if (end - childrenAt < sentinelBytes() || !allZero(end - sentinelBytes(), sentinelBytes()))
                    return false;
                childEnd = end - sentinelBytes();
            }
            std::size_t at = childrenAt;
            if (!readList(at, childEnd, r.children, false) || at != childEnd)
                return false;
            out.push_back(std::move(r));
            ++m_records;
            pos = end;
        }
        return pos == limit;
    }

    std::size_t offsetBytes() const { return m_wide ? 8 : 4; }
    std::size_t sentinelBytes() const { return 3 * offsetBytes() + 1; }
    // The records read, at every depth.
    std::size_t records() const { return m_records; }

private:
    bool word(std::size_t at, std::uint64_t& value) const
    {
        if (at + offsetBytes() > m_b.size())
            return false;
        value = 0;
        for (std::size_t k = 0; k < offsetBytes(); ++k)
            value |= std::uint64_t(m_b[at + k]) << (8 * k);
        return true;
    }
    bool allZero(std::size_t at, std::size_t n) const
    {
        return at + n <= m_b.size() && std::all_of(m_b.begin() + long(at), m_b.begin() + long(at + n),
                                                   [](unsigned char c) { return c == 0; });
    }

    std::span<const unsigned char> m_b;
    bool m_wide, m_sentinels;
    std::size_t m_records = 0;
};

// FBX's TimeMode for a frame rate: its own for the common ones, else "custom" (14) with
// CustomFrameRate.
int timeModeFor(double fps)
{
    constexpr std::pair<double, int> kModes[] = {{120, 1}, {100, 2}, {60, 3}, {50, 4}, {48, 5},
                                                 {30, 6}, {25, 10}, {24, 11}, {96, 15}, {72, 16}};
    for (const auto& [rate, mode] : kModes)
        if (fps == rate)
            return mode;
    return 14;
}

// Sets the last value of the Properties70 entry `name` (a P record: name, type, label,
// flags, value) when it holds one of type `type` ('I', 'D' or 'L').
void setProperty(std::span<unsigned char> b, const Record& p, const char* name, char type, const void* value)
{
    std::size_t at = p.propsAt;
    const std::size_t end = p.propsAt + p.propsBytes;
    for (std::uint64_t k = 0; k < p.propCount && at < end; ++k) {
        const char t = char(b[at]);
        if (t == 'S' || t == 'R') {
            std::uint32_t n = 0;
            std::memcpy(&n, &b[at + 1], 4);
            if (k == 0 && std::string(reinterpret_cast<const char*>(&b[at + 5]), n) != name)
                return;
            at += 5 + n;
        } else if (k == p.propCount - 1 && t == type) {
            std::memcpy(&b[at + 1], value, type == 'I' ? 4 : 8);
            return;
        } else {
            at += 1 + (t == 'I' || t == 'F' ? 4 : t == 'Y' ? 2 : t == 'C' ? 1 : 8);
        }
    }
}

void setShotTime(std::span<unsigned char> b, const std::vector<Record>& top, const FbxShotTime& time)
{
    const std::int32_t mode = timeModeFor(time.fps);
    const double rate = time.fps;
    const std::int64_t stop = std::int64_t(time.durationS * 46186158000.0 + 0.5);  // FBX's ticks a second
    auto named = [&](const Record& r, const char* name) {
        return r.nameBytes == std::strlen(name) && std::memcmp(&b[r.nameAt], name, r.nameBytes) == 0;
    };
    auto properties = [&](const Record& r, auto set) {
        for (const Record& props : r.children)
            if (named(props, "Properties70"))
                for (const Record& p : props.children)
                    set(p);
    };
    for (const Record& r : top) {
        if (named(r, "GlobalSettings"))
            properties(r, [&](const Record& p) {
                setProperty(b, p, "TimeMode", 'I', &mode);
                setProperty(b, p, "CustomFrameRate", 'D', &rate);
                setProperty(b, p, "TimeSpanStop", 'L', &stop);
            });
        if (named(r, "Objects"))  // assimp writes the stack's end in whole seconds
            for (const Record& object : r.children)
                if (named(object, "AnimationStack"))
                    properties(object, [&](const Record& p) {
                        setProperty(b, p, "LocalStop", 'L', &stop);
                        setProperty(b, p, "ReferenceStop", 'L', &stop);
                    });
    }
}

// assimp connects scale curves to "Lcl Scale", a property no model has: readers then drop
// every scale animation. The property is "Lcl Scaling".
void renameScaleConnections(std::span<const unsigned char> b, std::vector<Record>& top)
{
    static const std::string kWrong = "Lcl Scale", kRight = "Lcl Scaling";
    for (Record& r : top) {
        if (std::string_view(reinterpret_cast<const char*>(&b[r.nameAt]), r.nameBytes) != "Connections")
            continue;
        for (Record& c : r.children) {
            const std::size_t end = c.propsAt + c.propsBytes;
            const std::size_t tail = 1 + 4 + kWrong.size();  // 'S', length, text
            if (c.propsBytes < tail || b[end - tail] != 'S' ||
                std::memcmp(&b[end - kWrong.size()], kWrong.data(), kWrong.size()) != 0)
                continue;
            std::uint32_t n = 0;
            std::memcpy(&n, &b[end - tail + 1], 4);
            if (n != kWrong.size())
                continue;
            c.newProps.assign(b.begin() + long(c.propsAt), b.begin() + long(end - tail));
            c.newProps.push_back('S');
            const std::uint32_t length = static_cast<std::uint32_t>(kRight.size());
            for (int k = 0; k < 4; ++k)
                c.newProps.push_back(static_cast<unsigned char>(length >> (8 * k)));
            c.newProps.insert(c.newProps.end(), kRight.begin(), kRight.end());
        }
    }
}

class Writer {
public:
    Writer(std::span<const unsigned char> source, bool wide) : m_src(source), m_wide(wide) {}

    // `scoped`: each record gets a list of children, empty or not (what assimp's reader asks
    // of the objects: an AnimationLayer without one is refused).
    void list(const std::vector<Record>& records, bool scoped = false)
    {
        for (const Record& r : records)
            record(r, scoped);
    }
    void nullRecord() { out.insert(out.end(), 3 * bytes() + 1, 0); }

    std::vector<unsigned char> out;

private:
    std::size_t bytes() const { return m_wide ? 8 : 4; }
    void put(std::size_t at, std::uint64_t value)
    {
        for (std::size_t k = 0; k < bytes(); ++k)
            out[at + k] = static_cast<unsigned char>(value >> (8 * k));
    }
    void record(const Record& r, bool scoped)
    {
        const std::size_t start = out.size();
        out.insert(out.end(), 3 * bytes(), 0);
        put(start + bytes(), r.propCount);
        put(start + 2 * bytes(), r.newProps.empty() ? r.propsBytes : r.newProps.size());
        out.push_back(static_cast<unsigned char>(r.nameBytes));
        out.insert(out.end(), m_src.begin() + long(r.nameAt), m_src.begin() + long(r.nameAt + r.nameBytes));
        if (r.newProps.empty())
            out.insert(out.end(), m_src.begin() + long(r.propsAt), m_src.begin() + long(r.propsAt + r.propsBytes));
        else
            out.insert(out.end(), r.newProps.begin(), r.newProps.end());
        if (!r.children.empty() || scoped) {
            const std::string_view name(reinterpret_cast<const char*>(&m_src[r.nameAt]), r.nameBytes);
            list(r.children, name == "Objects");
            nullRecord();
        }
        put(start, out.size());
    }

    std::span<const unsigned char> m_src;
    bool m_wide;
};

}  // namespace

std::vector<unsigned char> mendFbxFraming(std::span<unsigned char> bytes, const FbxShotTime& time,
                                          std::string& error)
{
    if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kMagic, sizeof kMagic - 1) != 0) {
        error = "not a binary FBX file";
        return {};
    }
    const std::uint32_t version =
        std::uint32_t(bytes[23]) | std::uint32_t(bytes[24]) << 8 | std::uint32_t(bytes[25]) << 16 |
        std::uint32_t(bytes[26]) << 24;
    const bool wide = version >= 7500;
    std::vector<Record> records;
    bool read = false;
    std::size_t recordCount = 0, sentinelBytes = 0;
    for (const bool sentinels : {true, false}) {  // well formed first, then as assimp 5.2 writes
        records.clear();
        Reader reader(bytes, wide, sentinels);
        std::size_t pos = kHeaderBytes;
        if (reader.readList(pos, bytes.size(), records, true) && !records.empty()) {
            read = true;
            recordCount = reader.records();
            sentinelBytes = reader.sentinelBytes();
            break;
        }
    }
    if (!read) {
        error = "the FBX file's records cannot be read (version " + std::to_string(version) + ")";
        return {};
    }
    setShotTime(bytes, records, time);
    renameScaleConnections(bytes, records);
    Writer writer(bytes, wide);
    // At most: the records as they are, a null record after each and after the file's
    // list, each renamed connection 2 bytes longer, and the footer (172 bytes): one
    // allocation, never a copy of what is written so far.
    writer.out.reserve(bytes.size() + recordCount * (sentinelBytes + 2) + sentinelBytes + 256);
    writer.out.assign(bytes.begin(), bytes.begin() + kHeaderBytes);
    writer.list(records);
    writer.nullRecord();
    // The footer: its id, zeros to a 16-byte boundary (16 when already on one), the
    // version, 120 zeros, the magic.
    std::vector<unsigned char>& out = writer.out;
    out.insert(out.end(), std::begin(kFooterId), std::end(kFooterId));
    std::size_t pad = ((out.size() + 15) & ~std::size_t(15)) - out.size();
    out.insert(out.end(), pad == 0 ? 16 : pad, 0);
    for (int k = 0; k < 4; ++k)
        out.push_back(static_cast<unsigned char>(version >> (8 * k)));
    out.insert(out.end(), 120, 0);
    out.insert(out.end(), std::begin(kFooterMagic), std::end(kFooterMagic));
    return out;
}

}  // namespace throng::exporting::detail
