#!/usr/bin/env bash
# The SDK as an outside firmware project uses it (docs/firmware-abi.md):
# cmake --install into a fresh prefix, a C-only project elsewhere that does
# find_package(stereosim) and stereosim_add_firmware(), built there, then run
# by the installed stereosim; then the example firmware in C
# (examples/firmware-c) built the same way and run on the default scenario,
# where it must track the ball and keep the budget and the contract.
# Usage: test_sdk_install.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d /tmp/stereosim-sdk-XXXXXX)
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log" 2>&1 ||
  { echo "cmake --install $build failed:"; cat "$work/install.log"; exit 1; }
for f in include/stereosim/firmware.h lib/cmake/stereosim/stereosimConfig.cmake \
         bin/stereosim lib/stereosim/libstereosim_fw_reference.so; do
  [ -e "$work/prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done

mkdir -p "$work/myfw"
cp "$source/tests/firmware/plugins/minimal_firmware.c" "$work/myfw/myfw.c"
cat > "$work/myfw/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.16)
project(myfw C)
find_package(stereosim 1.0 REQUIRED)
stereosim_add_firmware(myfw SOURCES myfw.c)
target_compile_options(myfw PRIVATE -std=c11 -Wall -Wextra -pedantic -Werror)
CMAKE
cmake -S "$work/myfw" -B "$work/myfw/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/myfw/build" > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
plugin="$work/myfw/build/libmyfw.so"
[ -f "$plugin" ] || { echo "no $plugin"; cat "$work/build.log"; exit 1; }

# Only the entry is exported.
exported=$(nm -D --defined-only "$plugin" | awk '$2 == "T" { print $3 }')
[ "$exported" = "stereosim_firmware" ] || { echo "exported: $exported"; exit 1; }

# First lines by expansion, not `echo | head`: under pipefail, head closing the
# pipe early makes echo's later writes fail, and the check with them.
info=$("$work/prefix/bin/stereosim" firmware info "$plugin")
[ "${info%%$'\n'*}" = "firmware  minimal 0.1 (ABI version 1)" ] ||
  { echo "firmware info said: $info"; exit 1; }
ref=$("$work/prefix/bin/stereosim" firmware info "$work/prefix/lib/stereosim/libstereosim_fw_reference.so")
[ "${ref%%$'\n'*}" = "firmware  stereosim-reference 1.0 (ABI version 1)" ] ||
  { echo "firmware info said: $ref"; exit 1; }
echo "sdk: installed, an outside C firmware built against it and loaded by the installed stereosim"

# The example firmware: copied out of the repository (no path back into it),
# built against the installed SDK alone, run by the installed stereosim.
cp -r "$source/examples/firmware-c" "$work/paper"
rm -rf "$work/paper/build"
cmake -S "$work/paper" -B "$work/paper/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/paper-configure.log" 2>&1 || { cat "$work/paper-configure.log"; exit 1; }
cmake --build "$work/paper/build" > "$work/paper-build.log" ||
  { cat "$work/paper-build.log"; exit 1; }
paper="$work/paper/build/libpaper_fw.so"
"$work/prefix/bin/stereosim" run --quiet --frames 12 --firmware "$paper" --out "$work/run" ||
  { echo "the example firmware's run exited $?"; exit 1; }
python3 - "$work/run/report.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["tool"]["firmware"]["name"] == "paper-c", r["tool"]["firmware"]
s = r["summary"]
acc = s["accuracy"]
# Independent figures: the scene's ground truth, scored by the platform.
assert acc["frames_tracked"] >= 5, acc
assert acc["depth_err_pct_max"] is not None and acc["depth_err_pct_max"] < 3.0, acc
assert acc["box_err_px_max"] is not None and acc["box_err_px_max"] < 10.0, acc
assert s["timing"]["frames_over_budget"] == 0, s["timing"]
assert s["sync"]["unsynced_pairs_used"] == 0, s["sync"]
print("example firmware: %d frames tracked, box error max %.2f px, depth error max %.2f %%"
      % (acc["frames_tracked"], acc["box_err_px_max"], acc["depth_err_pct_max"]))
PY
# Its host entry (host.c): the sweep's closed form prices its pairs, near
# what the co-simulation measured at the same point.
paper_info=$("$work/prefix/bin/stereosim" firmware info "$paper")
grep -qx "host      yes (the sweep's closed form prices its pairs)" <<<"$paper_info" ||
  { echo "the example firmware has no host entry"; exit 1; }
"$work/prefix/bin/stereosim" sweep --grid dsk.cpu_mhz=600 --frames 12 --firmware "$paper" \
  --out "$work/sweep" > "$work/sweep.log" 2>&1 || { cat "$work/sweep.log"; exit 1; }
python3 - "$work/sweep/sweep.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))["points"][0]
host, cosim = p["closed_form"]["processing_ms"], p["processing_ms_max"]
assert host is not None and cosim, p
assert abs(host / cosim - 1) < 0.15, (host, cosim)
assert p["closed_form_agrees"] is True, p
print("example firmware's host entry: closed form %.3f ms, co-simulation %.3f ms" % (host, cosim))
PY
