// `stereosim firmware info [PATH]` (docs/firmware-abi.md): what a firmware
// plugin declares, or the built-in firmware without PATH: name, version, ABI
// version, file and SHA-256, stages, tracker states and config keys.
// `stereosim firmware check [PATH]`: whether it is deterministic
// (firmware_check.h).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "stereosim/firmware.h"

namespace cli {

class firmware_command {
  public:
    explicit firmware_command(CLI::App& app);
    CLI::App* subcommand() const { return m_app; }
    int execute();

  private:
    CLI::App* m_app = nullptr;
    CLI::App* m_info = nullptr;
    CLI::App* m_check = nullptr;
    std::string m_path;
};

// A key's range as `config --list` shows one: 0..10000, a|b, true|false.
std::string key_range_text(const stereosim_fw_key& k);
// Its default as a value of that range.
std::string key_default_text(const stereosim_fw_key& k);

}  // namespace cli
