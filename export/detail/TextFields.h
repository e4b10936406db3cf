#pragma once
// Formatting of the numbers in Throng's text exports: shortest text that reads back as
// the same float, and headings in degrees. Never rounds to a fixed number of digits.

#include <charconv>
#include <numbers>
#include <string>

namespace throng::exporting::detail {

// Appends `value` as the shortest text that parses back to the same float.
inline void appendFloat(std::string& out, float value)
{
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, result.ptr);
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
