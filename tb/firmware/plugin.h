// A firmware plugin loaded from a shared object (docs/firmware-abi.md): the
// entry symbol's descriptor, checked, and the file's identity for the
// report (path, SHA-256). The object stays loaded while the plugin lives.
#pragma once

#include <memory>
#include <string>

#include "stereosim/firmware.h"

namespace firmware {

class plugin {
  public:
    // Loads `path` (dlopen, the entry symbol STEREOSIM_FIRMWARE_ENTRY) and
    // checks its descriptor. Null, with one line in *error naming the file
    // and the problem, if it cannot be used; nothing stays loaded then.
    static std::unique_ptr<plugin> load(const std::string& path, std::string* error);
    ~plugin();
    plugin(const plugin&) = delete;
    plugin& operator=(const plugin&) = delete;

    const stereosim_fw_descriptor& descriptor() const { return *m_descriptor; }
    // Its optional host entry (STEREOSIM_FIRMWARE_HOST_ENTRY); null if none.
    const stereosim_fw_host* host() const { return m_host; }
    const std::string& path() const { return m_path; }
    const std::string& sha256() const { return m_sha256; }

  private:
    plugin() = default;

    void* m_handle = nullptr;
    const stereosim_fw_descriptor* m_descriptor = nullptr;
    const stereosim_fw_host* m_host = nullptr;
    std::string m_path;
    std::string m_sha256;
};

// The file's SHA-256 as 64 lowercase hex digits, or empty if unreadable.
std::string file_sha256(const std::string& path);

}  // namespace firmware
