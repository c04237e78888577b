#include "tb/firmware/plugin.h"

#include <dlfcn.h>
#include <openssl/evp.h>

#include <cstdio>
#include <fstream>
#include <vector>

#include "tb/firmware/descriptor_check.h"

namespace firmware {

std::string file_sha256(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "";
    EVP_MD_CTX* ctx = EVP_MD_CTX_new();
    EVP_DigestInit_ex(ctx, EVP_sha256(), nullptr);
    std::vector<char> block(1 << 16);
    while (in) {
        in.read(block.data(), static_cast<std::streamsize>(block.size()));
        EVP_DigestUpdate(ctx, block.data(), static_cast<size_t>(in.gcount()));
    }
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    EVP_DigestFinal_ex(ctx, digest, &length);
    EVP_MD_CTX_free(ctx);
    std::string hex;
    char byte[3];
    for (unsigned int i = 0; i < length; ++i) {
        std::snprintf(byte, sizeof byte, "%02x", digest[i]);
        hex += byte;
    }
    return hex;
}

std::unique_ptr<plugin> plugin::load(const std::string& path, std::string* error) {
    const std::string file = "firmware '" + path + "': ";
    // A bare name would make dlopen search the library path: a plugin is a file.
    const std::string where = path.find('/') == std::string::npos ? "./" + path : path;
    void* handle = dlopen(where.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        const char* why = dlerror();
        *error = file + "cannot load: " + (why ? why : "unknown reason");
        return nullptr;
    }
    const auto entry =
        reinterpret_cast<stereosim_firmware_entry>(dlsym(handle, STEREOSIM_FIRMWARE_ENTRY));
    const stereosim_fw_descriptor* d = entry ? entry() : nullptr;
    std::string problem = entry == nullptr ? std::string("no symbol ") + STEREOSIM_FIRMWARE_ENTRY
                          : d == nullptr   ? std::string("its entry returned no descriptor")
                                           : descriptor_problem(*d);
    // The host entry is optional; one that is there must be usable.
    const auto host_entry = reinterpret_cast<stereosim_firmware_host_entry>(
        dlsym(handle, STEREOSIM_FIRMWARE_HOST_ENTRY));
    const stereosim_fw_host* host = host_entry ? host_entry() : nullptr;
    if (problem.empty() && host_entry != nullptr)
        problem =
            host == nullptr ? std::string("its host entry returned no table") : host_problem(*host);
    if (!problem.empty()) {
        dlclose(handle);
        *error = file + problem;
        return nullptr;
    }
    std::unique_ptr<plugin> p(new plugin);
    p->m_handle = handle;
    p->m_descriptor = d;
    p->m_host = host;
    p->m_path = path;
    p->m_sha256 = file_sha256(where);
    return p;
}

plugin::~plugin() {
    if (m_handle != nullptr) dlclose(m_handle);
}

}  // namespace firmware
