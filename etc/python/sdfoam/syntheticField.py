"""Write a synthetic volScalarField into a case's time directory.

For testing the check scripts without the solver: the field's header and
boundaryField are copied from 0.orig/<field>; the internal field is the
python expression EXPR evaluated at every cell centre, with x, y, z (cell
centre), h (1/number of cells), n (number of cells) and the math module's
names in scope.

Usage: python3 -m sdfoam.syntheticField --case DIR --time T --field n.fine --expr EXPR
       (repeat --field/--expr pairs for several fields)
"""

import argparse
import math
import os
import re
import sys

from sdfoam import foamcase


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--case", required=True)
    p.add_argument("--time", required=True)
    p.add_argument("--field", action="append", required=True)
    p.add_argument("--expr", action="append", required=True)
    a = p.parse_args()
    if len(a.field) != len(a.expr):
        raise SystemExit("one --expr per --field")
    C = foamcase.cellCentres(a.case)
    n = len(C)
    ns = {k: getattr(math, k) for k in dir(math) if not k.startswith("_")}
    os.makedirs(os.path.join(a.case, a.time), exist_ok=True)
    for field, expr in zip(a.field, a.expr):
        code = compile(expr, "<expr>", "eval")
        vals = []
        for c in C:
            ns.update(x=c[0], y=c[1], z=c[2], h=1.0 / n, n=n)
            vals.append(float(eval(code, ns)))
        with open(os.path.join(a.case, "0.orig", field)) as f:
            text = f.read()
        body = "internalField   nonuniform List<scalar>\n%d\n(\n%s\n)\n;" % (
            n, "\n".join("%.14g" % v for v in vals))
        text = re.sub(r"internalField\s+uniform\s+[^;]*;", body, text)
        text = re.sub(r'location\s+"[^"]*";', 'location    "%s";' % a.time,
                      text)
        with open(os.path.join(a.case, a.time, field), "w") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
