# shellcheck shell=bash
# Tests of the validation cases (sourced by tests/run; tests validation/*):
# the case scripts and checks themselves live in the case folders.

# Gray-Thornton chute with second-order TVD schemes for the bulk advection
# (shared limiter) and the segregation flux: bounds to 1e-8, n.fine +
# n.coarse = 1, meeting point within 2 % (the check's assertions)
test_chute_tvd()
{
    local dir="$workRoot/chuteTVD"
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$validationDir/grayThorntonChute" "$dir/"
    "$dir/grayThorntonChute/Allrun" -n 40 -div "Gauss vanLeer01" -reconstruct vanLeer -tol 0.02
}

test_convergence_study()
{
    validation/convergenceStudy --no-docs --work "$workRoot/validation"
}
