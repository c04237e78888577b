#!/usr/bin/env python3
"""The firmware boundary (docs/firmware-abi.md): the testbench and the chip's
model include nothing of the reference firmware's sources. Of dsp/, tb/ may
include only the card's register map (generated from rtl/card_regs.csv);
model/c6416 and model/c64x include nothing of dsp/. One line per breach,
exit 1 if any. Direct includes only: tb/ still reaches dsp/'s image, Bayer
and rig types through model/scene and model/sensor."""
import pathlib
import re
import sys

repo = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
allowed = {
    "tb": {"dsp/card_regs.h"},
    "model/c6416": set(),
    "model/c64x": set(),
}
# Any spelling of an include that reaches dsp/ ("dsp/x.h", <dsp/x.h>, "../dsp/x.h").
include = re.compile(r'^\s*#\s*include\s+["<](?:\.\./)*(dsp/[^">]+)[">]', re.M)
sources = (".h", ".hh", ".hpp", ".inl", ".c", ".cc", ".cpp")
breaches = []
for folder, ok in allowed.items():
    if not (repo / folder).is_dir():
        breaches.append(f"{folder}: no such folder (the check would see nothing)")
        continue
    for path in sorted((repo / folder).rglob("*")):
        if path.suffix not in sources:
            continue
        for header in include.findall(path.read_text(errors="replace")):
            if header not in ok:
                breaches.append(f"{path.relative_to(repo)} includes {header}")
for line in breaches:
    print(line)
if breaches:
    sys.exit(1)
print("boundary kept: tb/ includes of dsp/ only", ", ".join(sorted(allowed["tb"])))
