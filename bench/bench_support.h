// Small helpers the bench programs share: settings from the environment and
// the median of repeated measurements.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

namespace bench {

// An environment variable's text, or `fallback` when unset or empty.
inline std::string env_text(const char* name, const char* fallback) {
    const char* text = std::getenv(name);
    return text && *text ? text : fallback;
}

// A positive integer from the environment, or `fallback`.
inline int env_int(const char* name, int fallback) {
    const int value = std::atoi(env_text(name, "0").c_str());
    return value > 0 ? value : fallback;
}

inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace bench
