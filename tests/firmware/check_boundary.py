#!/usr/bin/env python3
"""The firmware boundary (docs/firmware-abi.md): the testbench and the chip's
model include nothing of the reference firmware's sources. Of dsp/, tb/ may
include only the card's register map (generated from rtl/card_regs.csv);
model/c6416 and model/c64x include nothing of dsp/. One line per breach,
exit 1 if any."""
import pathlib
import re
import sys

repo = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
allowed = {
    "tb": {"dsp/card_regs.h"},
    "model/c6416": set(),
    "model/c64x": set(),
}
include = re.compile(r'^\s*#\s*include\s+"(dsp/[^"]+)"', re.M)
breaches = []
for folder, ok in allowed.items():
    for path in sorted((repo / folder).rglob("*")):
        if path.suffix not in (".h", ".hpp", ".c", ".cpp"):
            continue
        for header in include.findall(path.read_text(errors="replace")):
            if header not in ok:
                breaches.append(f"{path.relative_to(repo)} includes {header}")
for line in breaches:
    print(line)
if breaches:
    sys.exit(1)
print("boundary kept: tb/ includes of dsp/ only", ", ".join(sorted(allowed["tb"])))
