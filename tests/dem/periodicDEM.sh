# shellcheck shell=bash
# The periodicDEM utility on tutorials/periodicDEM/binaryDriven (sourced by
# tests/run; tests dem/periodicDEM/*).

# periodicDEM front door: a short driven cell in a case directory writes an
# HDF5 file that h5dump reads, with T at its target and D of both species
test_periodic_dem()
{
    local dir="$workRoot/periodicDEM"
    rm -rf "$dir"; cp -r "$projectDir/tutorials/periodicDEM/binaryDriven" "$dir"
    rm -rf "$dir/postProcessing"
    local d="$dir/system/periodicDEMDict"
    foamDictionary -entry particles -set 200 "$d" > /dev/null
    foamDictionary -entry equilibrationTime -set 0.002 "$d" > /dev/null
    foamDictionary -entry samplingTime -set 0.005 "$d" > /dev/null
    periodicDEM -case "$dir" > "$dir/log.periodicDEM" 2>&1 || { tail -20 "$dir/log.periodicDEM"; return 1; }
    local h5="$dir/postProcessing/periodicDEM/binaryDriven.h5"
    h5dump -H "$h5" > "$dir/h5dump.txt" || { echo "h5dump cannot read $h5"; return 1; }
    grep -q "GROUP" "$dir/h5dump.txt" || { echo "no groups in $h5"; return 1; }
    grep -E "^  T = |D_GK" "$dir/log.periodicDEM"
    python3 - "$dir/log.periodicDEM" <<'PY'
import re, sys
log = open(sys.argv[1]).read()
T = float(re.search(r"^  T = (\S+)", log, re.M).group(1))
D = [float(x) for x in re.findall(r"D_GK = (\S+)", log)]
print("T = %.6g (target 0.01), D_GK = %s" % (T, D))
ok = abs(T / 0.01 - 1) < 0.02 and len(D) == 2 and all(d > 0 for d in D)
sys.exit(0 if ok else 1)
PY
}

# periodicDEM bad input: unknown entry, restitution outside (0, 1], unknown
# mode: a
# FatalIOError naming the entry, no result file
test_periodic_dem_bad_input()
{
    local dir="$workRoot/periodicDEMBad" kind
    for kind in unknownEntry restitution mode
    do
        rm -rf "$dir"; cp -r "$projectDir/tutorials/periodicDEM/binaryDriven" "$dir"
        rm -rf "$dir/postProcessing"
        local d="$dir/system/periodicDEMDict" expect
        case "$kind" in
            unknownEntry) foamDictionary -entry sampleEvry -set 10 "$d" > /dev/null; expect="sampleEvry" ;;
            restitution) foamDictionary -entry contact/restitution -set 1.5 "$d" > /dev/null; expect="restitution" ;;
            mode) foamDictionary -entry mode -set shearing "$d" > /dev/null; expect="mode" ;;
        esac
        if periodicDEM -case "$dir" > "$dir/log" 2>&1
        then
            echo "$kind accepted"; return 1
        fi
        grep -A3 "FOAM FATAL" "$dir/log" | head -6
        grep -q "$expect" "$dir/log" || { echo "message lacks '$expect'"; return 1; }
        [ ! -e "$dir/postProcessing/periodicDEM/binaryDriven.h5" ] || { echo "result file written"; return 1; }
    done
}
