// What the platform requires of a firmware's descriptor before it runs it
// (docs/firmware-abi.md "The descriptor"): the ABI version, names the
// waveform and reports can carry, config keys whose defaults lie in their
// ranges, and every entry point. Plain C++, no loading: tests hand it
// descriptors built in memory.
#pragma once

#include <string>

#include "stereosim/firmware.h"

namespace firmware {

// The first problem found, as a phrase for a one-line error ("built for ABI
// version 2, this stereosim speaks 1"), or empty when the descriptor is
// usable.
std::string descriptor_problem(const stereosim_fw_descriptor& d);
// The same for the optional host entry's table.
std::string host_problem(const stereosim_fw_host& h);

// A name the reports, --set and the waveform can carry: [a-z0-9_]+,
// starting with a letter; with `upper`, capitals too (tracker states, shown
// as the waveform's translated state signal: DETECT, TRACK).
bool is_plain_name(const char* name, bool upper = false);

}  // namespace firmware
