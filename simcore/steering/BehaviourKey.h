#pragma once
// The scene-file keys of a steering behaviour's parameters: each key's name, meaning, kind,
// accepted range and the field it sets, declared by the behaviour beside its parameters
// (its descriptor, BehaviourTable.h). Plain constant data; reads and parses nothing itself.

#include <glm/vec3.hpp>

#include <string_view>

namespace throng::sim {

enum class ParamKind {
    Number,    // one number within [lo, hi]
    AngleDeg,  // one number of degrees within [lo, hi], stored in radians
    Flag,      // true/yes/on or false/no/off
    Vector3,   // [x, y, z]
    Choice,    // one of the words `meaning` lists
};

inline constexpr float kParamBig = 1e6f;  // an upper bound that bounds nothing

// One key of parameters struct P. Exactly the pointer its kind needs is set.
template <class P>
struct ParamKey {
    const char* key;      // in the scene file, under the behaviour's name
    const char* meaning;  // unit and range, for the docs and the out-of-range message
    ParamKind kind = ParamKind::Number;
    float lo = 0.0f, hi = kParamBig;                  // Number, AngleDeg (degrees)
    float P::*number = nullptr;                       // Number, AngleDeg
    bool P::*flag = nullptr;                          // Flag
    glm::vec3 P::*vector = nullptr;                   // Vector3
    bool (*choose)(P&, std::string_view) = nullptr;   // Choice: false when the word is not one
};

}  // namespace throng::sim
