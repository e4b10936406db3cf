#include "editor/brain/FuzzCurve.h"

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {

float number(const std::vector<sim::BrainParam>& params, const std::string& key, float fallback)
{
    const std::vector<float> v = paramNumbers(params, key);
    return v.empty() ? fallback : v[0];
}

void setNumber(std::vector<sim::BrainParam>& params, const std::string& key, std::size_t index, float value)
{
    for (sim::BrainParam& p : params)
        if (p.key == key) {
            if (p.numbers.size() <= index)
                p.numbers.resize(index + 1, value);
            p.numbers[index] = value;
            return;
        }
    sim::BrainParam p{key, {}, {}};
    p.numbers.assign(index + 1, value);
    params.push_back(p);
}

float ramp(float x, float from, float to)
{
    if (to <= from)
        return x >= to ? 1.0f : 0.0f;
    return std::clamp((x - from) / (to - from), 0.0f, 1.0f);
}

}  // namespace

std::vector<float> paramNumbers(const std::vector<sim::BrainParam>& params, const std::string& key)
{
    for (const sim::BrainParam& p : params)
        if (p.key == key)
            return p.numbers;
    return {};
}

bool isFuzzType(const std::string& type)
{
    return type == "fuzz.triangle" || type == "fuzz.trapezoid" || type == "fuzz.gaussian" || type == "fuzz.sigmoid";
}

float fuzzTruth(const std::string& type, const std::vector<sim::BrainParam>& params, float x)
{
    const std::vector<float> p = paramNumbers(params, "points");
    if (type == "fuzz.triangle" && p.size() == 3)
        return x <= p[1] ? ramp(x, p[0], p[1]) : 1.0f - ramp(x, p[1], p[2]);
    if (type == "fuzz.trapezoid" && p.size() == 4)
        return x <= p[1] ? ramp(x, p[0], p[1]) : (x <= p[2] ? 1.0f : 1.0f - ramp(x, p[2], p[3]));
    if (type == "fuzz.gaussian") {
        const float c = number(params, "centre", 0.0f), w = std::max(number(params, "width", 1.0f), 1e-6f);
        return std::exp(-(x - c) * (x - c) / (2.0f * w * w));
    }
    if (type == "fuzz.sigmoid")
        return 1.0f / (1.0f + std::exp(-number(params, "slope", 1.0f) * (x - number(params, "centre", 0.0f))));
    return 0.0f;
}

void fuzzDomain(const std::string& type, const std::vector<sim::BrainParam>& params, float& lo, float& hi)
{
    const std::vector<float> p = paramNumbers(params, "points");
    if ((type == "fuzz.triangle" || type == "fuzz.trapezoid") && !p.empty()) {
        lo = *std::min_element(p.begin(), p.end());
        hi = *std::max_element(p.begin(), p.end());
    } else if (type == "fuzz.gaussian") {
        const float c = number(params, "centre", 0.0f), w = std::max(number(params, "width", 1.0f), 1e-6f);
        lo = c - 3.0f * w;
        hi = c + 3.0f * w;
    } else {
        const float c = number(params, "centre", 0.0f), s = std::abs(number(params, "slope", 1.0f));
        const float half = s > 1e-6f ? 5.0f / s : 5.0f;
        lo = c - half;
        hi = c + half;
    }
    const float margin = std::max(0.2f * (hi - lo), 0.25f);
    lo -= margin;
    hi += margin;
}

std::vector<FuzzHandle> fuzzHandles(const std::string& type, const std::vector<sim::BrainParam>& params)
{
    const std::vector<float> p = paramNumbers(params, "points");
    if (type == "fuzz.triangle" && p.size() == 3)
        return {{p[0], 0.0f}, {p[1], 1.0f}, {p[2], 0.0f}};
    if (type == "fuzz.trapezoid" && p.size() == 4)
        return {{p[0], 0.0f}, {p[1], 1.0f}, {p[2], 1.0f}, {p[3], 0.0f}};
    if (type == "fuzz.gaussian") {
        const float c = number(params, "centre", 0.0f), w = std::max(number(params, "width", 1.0f), 1e-6f);
        return {{c, 1.0f}, {c + w, std::exp(-0.5f)}};
    }
    if (type == "fuzz.sigmoid") {
        const float c = number(params, "centre", 0.0f), s = number(params, "slope", 1.0f);
        const float d = std::abs(s) > 1e-6f ? 1.0f / s : 1.0f;
        return {{c, 0.5f}, {c + d, fuzzTruth(type, params, c + d)}};
    }
    return {};
}

std::vector<sim::BrainParam> moveFuzzHandle(const std::string& type, std::vector<sim::BrainParam> params, int handle,
                                            float x)
{
    if (type == "fuzz.triangle" || type == "fuzz.trapezoid") {
        std::vector<float> p = paramNumbers(params, "points");
        if (handle < 0 || std::size_t(handle) >= p.size())
            return params;
        const float lo = handle > 0 ? p[std::size_t(handle) - 1] : -1e30f;
        const float hi = std::size_t(handle) + 1 < p.size() ? p[std::size_t(handle) + 1] : 1e30f;
        setNumber(params, "points", std::size_t(handle), std::clamp(x, lo, hi));
    } else if (type == "fuzz.gaussian") {
        const float c = number(params, "centre", 0.0f);
        if (handle == 0)
            setNumber(params, "centre", 0, x);
        else
            setNumber(params, "width", 0, std::max(x - c, 1e-3f));
    } else if (type == "fuzz.sigmoid") {
        const float c = number(params, "centre", 0.0f);
        if (handle == 0) {
            setNumber(params, "centre", 0, x);
        } else {
            const float d = std::abs(x - c) < 1e-3f ? (x >= c ? 1e-3f : -1e-3f) : x - c;
            setNumber(params, "slope", 0, 1.0f / d);
        }
    }
    return params;
}

}  // namespace throng::editor
