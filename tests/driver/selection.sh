# shellcheck shell=bash
# The test driver itself (sourced by tests/run; tests driver/*).

# tests/run -k PATTERN selects exactly the registered names that contain
# PATTERN, ctest tests included: for several patterns, "tests/run -l -k X"
# equals the full list filtered here by substring; every ctest test of
# calibration/ is in the full list as calibration/<name>; a pattern that
# matches nothing selects nothing and runs nothing ("0 passed, 0 failed",
# exit 0); "-k <one ctest name>" runs that ctest test alone. The runs
# here write their logs under their own work directory, not over the
# outer run's (build/tests/calibration-ctest.log is what the outer run
# names for a failed ctest test)
test_driver_selection()
{
    local dir="$workRoot/driverSelection"
    rm -rf "$dir"; mkdir -p "$dir"
    # tests/run works in <project>/build/tests of the tree it is started
    # from: a tree of links to this project whose build/ holds only the
    # calibration build keeps the inner runs' logs in $dir/tree/build/tests
    local tree="$dir/tree" entry
    mkdir -p "$tree/build"
    for entry in "$projectDir"/*
    do
        [ "${entry##*/}" = build ] || ln -s "$entry" "$tree/${entry##*/}"
    done
    ln -s "$projectDir/build/calibration" "$tree/build/calibration"
    local run="$tree/tests/run" outerLog="$workRoot/calibration-ctest.log" outerBefore
    outerBefore=$(cksum < "$outerLog" 2>/dev/null || echo none)
    "$run" -l > "$dir/all.txt" || { echo "tests/run -l failed"; return 1; }
    local total
    total=$(wc -l < "$dir/all.txt")
    echo "tests/run -l: $total tests"
    [ "$total" -gt 10 ] || { echo "implausibly short list"; cat "$dir/all.txt"; return 1; }
    [ "$(sort "$dir/all.txt" | uniq -d | wc -l)" -eq 0 ] \
        || { echo "duplicate names:"; sort "$dir/all.txt" | uniq -d; return 1; }

    # every ctest test appears as calibration/<name>
    ctest --test-dir build/calibration -N \
        | sed -nE 's/^ *Test +#[0-9]+: +([^ ]+) *$/calibration\/\1/p' > "$dir/ctest.txt"
    local nCtest
    nCtest=$(wc -l < "$dir/ctest.txt")
    [ "$nCtest" -gt 0 ] || { echo "ctest lists no test"; return 1; }
    if grep -vxFf "$dir/all.txt" "$dir/ctest.txt" > "$dir/missing.txt"
    then
        echo "ctest tests missing from the list:"; cat "$dir/missing.txt"; return 1
    fi
    local firstCtest
    firstCtest=$(head -1 "$dir/ctest.txt")

    local pattern expected got n
    for pattern in silo input calibration/ "$firstCtest" "${firstCtest%%.*}." \
        periodicDEM /run validation/ driver/ noTestIsCalledThis
    do
        grep -F -- "$pattern" "$dir/all.txt" > "$dir/expected.txt"
        "$run" -l -k "$pattern" > "$dir/got.txt" || { echo "tests/run -l -k '$pattern' failed"; return 1; }
        n=$(wc -l < "$dir/got.txt")
        printf '  -k %-40s %3d selected\n' "'$pattern'" "$n"
        diff "$dir/expected.txt" "$dir/got.txt" > /dev/null \
            || { echo "selection for '$pattern' differs (< expected, > selected):"; diff "$dir/expected.txt" "$dir/got.txt"; return 1; }
    done
    [ "$("$run" -l -k noTestIsCalledThis | wc -l)" -eq 0 ] || { echo "a pattern matching nothing selected tests"; return 1; }
    [ "$("$run" -l -k "$firstCtest" | wc -l)" -ge 1 ] || return 1
    [ "$(grep -c "^calibration/" "$dir/all.txt")" -gt "$nCtest" ] \
        || { echo "no non-ctest calibration/ tests in the list"; return 1; }

    # running: nothing selected runs nothing; one ctest name runs just it
    "$run" -k noTestIsCalledThis > "$dir/none.txt" 2>&1 || { echo "exit status non-zero with nothing run"; cat "$dir/none.txt"; return 1; }
    tail -1 "$dir/none.txt" | grep -qx "0 passed, 0 failed" || { cat "$dir/none.txt"; return 1; }
    grep -q "^PASS\|^FAIL" "$dir/none.txt" && { echo "something ran"; return 1; }
    "$run" -k "$firstCtest" > "$dir/one.txt" 2>&1 || { cat "$dir/one.txt"; return 1; }
    cat "$dir/one.txt"
    [ "$(grep -c "^PASS\|^FAIL" "$dir/one.txt")" -eq "$(grep -cF -- "$firstCtest" "$dir/all.txt")" ] \
        || { echo "-k '$firstCtest' ran other tests"; return 1; }
    grep -q "^PASS  $firstCtest " "$dir/one.txt" || return 1
    tail -1 "$dir/one.txt" | grep -qE "^[0-9]+ passed, 0 failed$" || return 1
    # the inner ctest run's log is its own, the outer run's is untouched
    grep -q "Test .*: ${firstCtest#calibration/} " "$tree/build/tests/calibration-ctest.log" \
        || { echo "no ctest log of the inner run in $tree/build/tests"; return 1; }
    [ "$(cksum < "$outerLog" 2>/dev/null || echo none)" = "$outerBefore" ] \
        || { echo "the inner run wrote $outerLog, the outer run's ctest log"; return 1; }
    echo "selection by name holds for ctest and driver tests"
}
