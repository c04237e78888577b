// A plain VCD reader for the tests (docs/waveforms.md): the declarations by
// full name (scopes joined by '.', vectors as NAME[msb:lsb]), the values at
// the file's first time (the window start: Verilator's first dump, or a
// $dumpvars block) and every later change, by signal. Vector values are the
// bits without leading zeros ("0" at least), so a reader does not depend on
// how wide a writer prints them. Independent of the writers it reads.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace testsupport {

struct vcd_change {
    int64_t fs;
    std::string value;  // "0", "1", "x", "z" or a vector's bits
    bool operator==(const vcd_change& o) const { return fs == o.fs && value == o.value; }
};

struct vcd_file {
    bool ok = false;  // read to the end of a header and at least one signal
    std::string timescale;
    std::map<std::string, std::string> code_of;              // full name -> code
    std::map<std::string, int> width_of;                     // full name -> width
    std::map<std::string, std::string> first;                // code -> value at the first time
    std::map<std::string, std::vector<vcd_change>> changes;  // code -> changes after it
    int64_t first_fs = -1, last_fs = -1;
    bool times_increase = true;
    size_t value_count = 0;    // every value written, the first time's included

    // Changes after the first time (none for an unknown name).
    const std::vector<vcd_change>& of(const std::string& name) const;
    // The value at the first time, then the changes.
    std::vector<vcd_change> history(const std::string& name) const;
};

vcd_file read_vcd(const std::string& path);

}  // namespace testsupport
