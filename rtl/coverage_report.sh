#!/usr/bin/env bash
# Merges the coverage files the rtl tests wrote (make coverage-rtl) and reports
# line and toggle coverage of the card RTL (files under rtl/; the negative
# control in tests/ is left out). Points of a module instantiated several
# times count once: covered if any instance covered it.
# Usage: rtl/coverage_report.sh <dir with *.dat> [min line %]
set -euo pipefail
dir=${1:?coverage directory}
min=${2:-90}
shopt -s nullglob
files=("$dir"/*.dat)
if [ ${#files[@]} -eq 0 ]; then
    echo "coverage-rtl: no .dat files in $dir" >&2
    exit 1
fi
verilator_coverage --write "$dir/merged.info.dat" "${files[@]}"
rm -rf "$dir/annotated"
verilator_coverage --annotate "$dir/annotated" --annotate-min 1 "$dir/merged.info.dat" 
awk -v min="$min" -v annotated="$dir/annotated" '
    /^C / {
        key = $0
        sub(/^C \047/, "", key)
        count = key
        sub(/\047 [0-9]+$/, "", key)
        sub(/^.*\047 /, "", count)
        n = split(key, parts, "\001")
        file = ""; line = ""; col = ""; page = ""; comment = ""
        for (i = 1; i <= n; ++i) {
            split(parts[i], kv, "\002")
            if (kv[1] == "f") file = kv[2]
            else if (kv[1] == "l") line = kv[2]
            else if (kv[1] == "n") col = kv[2]
            else if (kv[1] == "page") page = kv[2]
            else if (kv[1] == "o") comment = kv[2]
        }
        if (file !~ /\/rtl\/[^\/]+\.v$/ || file ~ /\/tests\/rtl\//) next
        type = page; sub(/\/.*/, "", type)
        kind = (type == "v_toggle") ? "toggle" : "line"
        sub(/^.*\/rtl\//, "rtl/", file)
        id = kind SUBSEP file SUBSEP line SUBSEP col SUBSEP comment
        if (!(id in seen)) { seen[id] = 1; total[kind]++; ftotal[kind, file]++ }
        if (count + 0 > 0 && !(id in hit)) { hit[id] = 1; covered[kind]++; fcovered[kind, file]++ }
        else if (count + 0 == 0 && kind == "line") where[file] = where[file] " " line
        files[file] = 1
    }
    END {
        for (f in files) {
            lt = ftotal["line", f]; lc = fcovered["line", f] + 0
            tt = ftotal["toggle", f]; tc = fcovered["toggle", f] + 0
            printf "  %-28s line %5.1f%% (%d/%d)  toggle %5.1f%% (%d/%d)\n", f,
                   lt ? 100 * lc / lt : 100, lc, lt, tt ? 100 * tc / tt : 100, tc, tt | "sort"
        }
        close("sort")
        lp = 100 * covered["line"] / total["line"]
        tp = total["toggle"] ? 100 * covered["toggle"] / total["toggle"] : 100
        printf "coverage-rtl: line %.1f%% (%d/%d points), toggle %.1f%% (%d/%d bits)\n",
               lp, covered["line"], total["line"], tp, covered["toggle"], total["toggle"]
        printf "coverage-rtl: annotated sources in %s\n", annotated
        if (lp < min) {
            printf "coverage-rtl: FAIL: line coverage %.1f%% is below %d%%\n", lp, min
            exit 1
        }
    }' "$dir/merged.info.dat"
