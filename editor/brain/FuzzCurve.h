#pragma once
// The membership curve of a fuzz node and its draggable handles, as plain functions of
// the node's parameters: the truth at x, the x range worth drawing, where each handle
// sits and which parameter moving it changes. No drawing, no Qt widgets.

#include "simcore/scene/BrainGraph.h"

#include <string>
#include <vector>

namespace throng::editor {

struct FuzzHandle {
    float x = 0.0f;      // input value where the handle sits
    float truth = 0.0f;  // 0..1
};

bool isFuzzType(const std::string& type);
float fuzzTruth(const std::string& type, const std::vector<sim::BrainParam>& params, float x);
// The input range drawn: the curve's features with a margin.
void fuzzDomain(const std::string& type, const std::vector<sim::BrainParam>& params, float& lo, float& hi);
std::vector<FuzzHandle> fuzzHandles(const std::string& type, const std::vector<sim::BrainParam>& params);
// The parameters after handle `handle` moved to input value x (points stay in order).
std::vector<sim::BrainParam> moveFuzzHandle(const std::string& type, std::vector<sim::BrainParam> params,
                                            int handle, float x);
// A number parameter's values (empty when absent).
std::vector<float> paramNumbers(const std::vector<sim::BrainParam>& params, const std::string& key);

}  // namespace throng::editor
