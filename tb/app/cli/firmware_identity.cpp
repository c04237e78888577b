#include "tb/app/cli/firmware_identity.h"

#include "tb/firmware/builtin.h"

namespace cli {

using nlohmann::json;

json firmware_identity(const stereosim_fw_descriptor& d, const firmware::plugin* plugin) {
    return {{"name", d.name},
            {"version", d.version},
            {"abi_version", d.abi_version},
            {"file", plugin ? json(plugin->path()) : json(nullptr)},
            {"sha256", plugin ? json(plugin->sha256()) : json(nullptr)},
            {"stages", std::vector<std::string>(d.stage_names, d.stage_names + d.stage_count)},
            {"tracker_states",
             std::vector<std::string>(d.tracker_state_names,
                                      d.tracker_state_names + d.tracker_state_count)}};
}

json firmware_identity_of(const std::string& path, std::string* error) {
    if (path.empty()) return firmware_identity(firmware::builtin(), nullptr);
    const std::unique_ptr<firmware::plugin> p = firmware::plugin::load(path, error);
    return p ? firmware_identity(p->descriptor(), p.get()) : json(nullptr);
}

json firmware_of_document(const json& document) {
    if (document.contains("firmware")) return document.at("firmware");
    return firmware_identity(firmware::builtin(), nullptr);
}

}  // namespace cli
