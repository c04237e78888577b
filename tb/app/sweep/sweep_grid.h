// The grid of a design-space sweep (docs/sweep.md): axes of config keys
// (KEY=V1,V2,... or KEY=LO:HI:STEP), every combination a point, points in a
// fixed order (the first axis outermost) so that a point's index, and the
// shard it lands in, is the same on any machine.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tb/app/cli/config_keys.h"

namespace sweep {

struct grid_axis {
    std::string key;                     // a config key (tb/app/cli/config_keys.h)
    std::vector<nlohmann::json> values;  // type- and range-checked
};

// One --grid argument. false + *error (one line) for a malformed argument,
// an unknown key, an empty list, a value of the wrong type or out of range,
// a range on a key that is not a number, or LO > HI / STEP <= 0.
bool parse_axis(const std::string& text, grid_axis* axis, std::string* error);

// The axes of every --grid argument; also a key given twice is an error.
bool parse_grid(const std::vector<std::string>& args, std::vector<grid_axis>* axes,
                std::string* error);

// Number of points (product of the axes' sizes), saturating at `cap` + 1.
size_t point_count(const std::vector<grid_axis>& axes, size_t cap);

struct grid_point {
    size_t index = 0;                           // in the whole grid
    std::vector<cli::key_assignment> settings;  // one per axis, in axis order
};

// Point `index` of the grid (first axis outermost).
grid_point point_at(const std::vector<grid_axis>& axes, size_t index);

// The points of shard K of M (1-based): index % M == K - 1.
std::vector<grid_point> shard_points(const std::vector<grid_axis>& axes, int shard, int shards);

// "K/M" with 1 <= K <= M; false + *error otherwise.
bool parse_shard(const std::string& text, int* shard, int* shards, std::string* error);

// A value as the user would write it after KEY= (strings unquoted).
std::string value_text(const nlohmann::json& value);

}  // namespace sweep
