#include "tb/app/cli/host_figures.h"

#include <string>

namespace cli {

nlohmann::json without_host_figures(const nlohmann::json& j) {
    if (j.is_object()) {
        nlohmann::json out = nlohmann::json::object();
        for (auto it = j.begin(); it != j.end(); ++it) {
            const std::string& key = it.key();
            if (key.find("wall") != std::string::npos || key == "ratio" ||
                key.find("snapshot") != std::string::npos)
                continue;
            out[key] = without_host_figures(it.value());
        }
        return out;
    }
    if (j.is_array()) {
        nlohmann::json out = nlohmann::json::array();
        for (const nlohmann::json& x : j) out.push_back(without_host_figures(x));
        return out;
    }
    return j;
}

}  // namespace cli
