"""Reading calibrateGranularMixture's log (python3 standard library only).

Each condition whose fines' diffusivity fails the diffusive-regime check gets a
progress line after its "done in" line (applications/utilities/
calibrateGranularMixture/conditionScheduler.C):

    not in the diffusive regime (stored as not converged, weighted down in the fit): <verdict>
"""

NOT_DIFFUSIVE = "    not in the diffusive regime (stored"


def notDiffusiveConditions(log, marker=""):
    """How many conditions of the log text failed the check with `marker` in their
    verdict (e.g. "no Green-Kubo plateau"; "": all that failed)."""
    return sum(1 for line in log.splitlines()
               if line.startswith(NOT_DIFFUSIVE) and marker in line)
