// docs/config.md's table of keys, as `stereosim config --markdown` prints it.
#include <string>

#include "tb/app/cli/config_keys.h"

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

}  // namespace cli
