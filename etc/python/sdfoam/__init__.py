"""Python helpers of segregationDegradationFoam (python3 standard library only).

On the path through etc/bashrc (PYTHONPATH=<project>/etc/python).

  sdfoam.foamcase        read ASCII OpenFOAM cases: time directories, scalar
                         and vector fields, cell centres; error norms and
                         observed orders for the validation checks
  sdfoam.fieldStats      checks on a solver case's written fields (bounds,
                         comparison with another case, change, emptying);
                         python3 -m sdfoam.fieldStats CASE CHECK ...
  sdfoam.ziffMcGrady     the exact breakage solution of Ziff & McGrady (1985)
                         and its fixed-pivot class numbers (breakage checks)
  sdfoam.calibrationLog  counts of calibrateGranularMixture's conditions that
                         failed the diffusive-regime check
  sdfoam.syntheticField  write a field from an expression of the cell centre
                         (to test the checks without the solver);
                         python3 -m sdfoam.syntheticField --case DIR ...
"""
