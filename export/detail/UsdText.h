#pragma once
// Appends USD's text form (.usda) of plain values: numbers that read back to the same
// float, tuples, quaternions in USD's (real, i, j, k) order, row-vector matrices, and
// names made valid as prim names and joint path elements. Knows no scene.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <string>
#include <string_view>

namespace throng::exporting::detail {

// The shortest text that reads back as `value` (a float); "-0" is written "0".
void appendUsdFloat(std::string& out, float value);
// `value` to about `digits` significant digits: rotations, colours.
void appendUsdRounded(std::string& out, float value, int digits);
void appendUsdDouble(std::string& out, double value);
// (x, y, z), each shortest.
void appendUsdVec3(std::string& out, glm::vec3 v);
// (r, g, b), each to 4 digits.
void appendUsdColour(std::string& out, glm::vec3 rgb);
// (w, x, y, z): USD writes the real part first; each to 6 digits.
void appendUsdQuat(std::string& out, glm::quat q);
// ((row 0), ..., (row 3)) with the translation in row 3: USD's row-vector convention, so
// row i is glm's column i.
void appendUsdMatrix(std::string& out, const glm::mat4& m);
// A valid prim name: [A-Za-z_][A-Za-z0-9_]*, anything else becomes '_' (a leading digit
// gets a '_' before it); never empty.
std::string usdIdentifier(std::string_view name);
// `text` as a USD string literal, quotes and backslashes escaped.
std::string usdQuoted(std::string_view text);
// `depth` levels of four spaces.
void indent(std::string& out, int depth);

}  // namespace throng::exporting::detail
