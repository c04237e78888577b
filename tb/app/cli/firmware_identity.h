// Which firmware a run or campaign ran (docs/firmware-abi.md), as report.json
// and campaign.json name it: the descriptor's name and version, the ABI
// version, and for a plugin its file and SHA-256 (null: the built-in one).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "stereosim/firmware.h"
#include "tb/firmware/plugin.h"

namespace cli {

nlohmann::json firmware_identity(const stereosim_fw_descriptor& d, const firmware::plugin* plugin);

// The identity of the plugin at `path`, or of the built-in firmware when
// `path` is empty; null and *error (one line) if the plugin cannot run.
nlohmann::json firmware_identity_of(const std::string& path, std::string* error);

// A campaign document's firmware; one written before campaigns named it ran
// the built-in firmware.
nlohmann::json firmware_of_document(const nlohmann::json& document);

}  // namespace cli
