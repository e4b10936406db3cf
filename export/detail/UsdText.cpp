#include "export/detail/UsdText.h"

#include <charconv>
#include <cmath>

namespace throng::exporting::detail {

void appendUsdFloat(std::string& out, float value)
{
    if (value == 0.0f || !std::isfinite(value)) {
        out += '0';
        return;
    }
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    out.append(buffer, end);
}

void appendUsdRounded(std::string& out, float value, int digits)
{
    if (value == 0.0f || !std::isfinite(value)) {
        out += '0';
        return;
    }
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits).ptr;
    const std::string_view text(buffer, static_cast<std::size_t>(end - buffer));
    out += text == "-0" ? std::string_view("0") : text;
}

void appendUsdDouble(std::string& out, double value)
{
    if (value == 0.0 || !std::isfinite(value)) {
        out += '0';
        return;
    }
    char buffer[40];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    out.append(buffer, end);
}

void appendUsdVec3(std::string& out, glm::vec3 v)
{
    out += '(';
    appendUsdFloat(out, v.x);
    out += ", ";
    appendUsdFloat(out, v.y);
    out += ", ";
    appendUsdFloat(out, v.z);
    out += ')';
}

void appendUsdColour(std::string& out, glm::vec3 rgb)
{
    out += '(';
    appendUsdRounded(out, rgb.r, 4);
    out += ", ";
    appendUsdRounded(out, rgb.g, 4);
    out += ", ";
    appendUsdRounded(out, rgb.b, 4);
    out += ')';
}

void appendUsdQuat(std::string& out, glm::quat q)
{
    out += '(';
    appendUsdRounded(out, q.w, 6);
    out += ", ";
    appendUsdRounded(out, q.x, 6);
    out += ", ";
    appendUsdRounded(out, q.y, 6);
    out += ", ";
    appendUsdRounded(out, q.z, 6);
    out += ')';
}

void appendUsdMatrix(std::string& out, const glm::mat4& m)
{
    out += '(';
    for (int row = 0; row < 4; ++row) {
        out += row ? ", (" : "(";
        for (int k = 0; k < 4; ++k) {
            if (k)
                out += ", ";
            appendUsdRounded(out, m[row][k], 7);
        }
        out += ')';
    }
    out += ')';
}

std::string usdIdentifier(std::string_view name)
{
    std::string id;
    for (const char c : name) {
        const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
        id += ok ? c : '_';
    }
    if (id.empty() || (id[0] >= '0' && id[0] <= '9'))
        id.insert(id.begin(), '_');
    return id;
}

std::string usdQuoted(std::string_view text)
{
    std::string quoted = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\')
            quoted += '\\';
        quoted += c == '\n' ? ' ' : c;
    }
    return quoted + '"';
}

void indent(std::string& out, int depth) { out.append(static_cast<std::size_t>(4 * depth), ' '); }

}  // namespace throng::exporting::detail
