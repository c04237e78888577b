// docs/config.md's tables of keys, as `stereosim config --markdown` prints
// them: the platform's, then the built-in firmware's own.
#include <string>

#include "tb/firmware/builtin.h"
#include "tb/app/cli/config_keys.h"
#include "tb/app/cli/firmware_keys.h"

namespace cli {

namespace {

// A Markdown table cell: a `|` would end the cell, in a code span too.
std::string markdown_cell(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

}  // namespace

std::string config_table_markdown() {
    const run_setup defaults;
    std::string out = "| key | type / range | default | what |\n|---|---|---|---|\n";
    for (const config_key& k : config_keys())
        out += "| `" + k.name + "` | " + markdown_cell(k.range_text()) + " | `" +
               markdown_cell(k.get(defaults).dump()) + "` | " + markdown_cell(k.doc) + " |\n";
    return out;
}

std::string firmware_table_markdown() {
    const stereosim_fw_descriptor& d = firmware::builtin();
    std::vector<double> defaults;
    for (uint32_t k = 0; k < d.key_count; ++k) defaults.push_back(d.keys[k].default_value);
    const nlohmann::json values = firmware_values_json(d, defaults);
    std::string out = "| firmware key | type / range | default | what |\n|---|---|---|---|\n";
    for (const config_key& k : firmware_own_keys(d))
        out += "| `" + k.name + "` | " + markdown_cell(k.range_text()) + " | `" +
               markdown_cell(values.at(k.name.substr(k.name.find('.') + 1)).dump()) + "` | " +
               markdown_cell(k.doc) + " |\n";
    return out;
}

}  // namespace cli
