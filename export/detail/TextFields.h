#pragma once
// Formatting of the numbers in Throng's text exports: shortest text that reads back as
// the same float, and headings in degrees. Never rounds to a fixed number of digits.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include <charconv>
#include <cstddef>
#include <numbers>
#include <string>

namespace throng::exporting::detail {

// How much text a writer gathers before it writes it to its file.
inline constexpr std::size_t kFlushBytes = 1 << 16;

// Appends `value` as the shortest text that parses back to the same float.
inline void appendFloat(std::string& out, float value)
{
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, result.ptr);
}

// Appends a coordinate of the scene: `relative` (a frame's float, relative to the cache's
// origin) plus `origin`, added in double. Near (0, 0) (origin 0) exactly appendFloat; a
// far scene's coordinate gets micrometres (a float relative to an origin holds less),
// trailing zeros dropped, so 1e6 m keeps its centimetres.
inline void appendCoordinate(std::string& out, float relative, double origin)
{
    if (origin == 0.0) {
        appendFloat(out, relative);
        return;
    }
    char buf[48];
    const auto result = std::to_chars(buf, buf + sizeof buf, static_cast<double>(relative) + origin,
                                      std::chars_format::fixed, 6);
    char* end = result.ptr;
    while (end > buf && end[-1] == '0')
        --end;
    if (end > buf && end[-1] == '.')
        --end;
    out.append(buf, end);
}

inline void appendUnsigned(std::string& out, unsigned long long value)
{
    char buf[24];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, result.ptr);
}

// AgentFrame::headingRad in degrees, same convention (0 = +x, counter-clockwise from above),
// not wrapped: it is the same angle as the cache's, so curves stay continuous.
inline float headingDegrees(float headingRad)
{
    return static_cast<float>(static_cast<double>(headingRad) * (180.0 / std::numbers::pi));
}

}  // namespace throng::exporting::detail
