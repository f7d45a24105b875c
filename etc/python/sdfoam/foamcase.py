"""Minimal readers for ASCII OpenFOAM cases (python3 standard library only).

Used by the validation checks, the test helpers and the tutorials' scripts:
list the written time
directories, read the internal field of a volScalarField, and compute cell
centres from constant/polyMesh (the mean of the cell's vertices, which is the
exact centroid for the parallelepiped cells that blockMesh makes here).
"""

import math
import os
import re

__all__ = [
    "timeDirs", "latestTime", "readScalarField", "readVectorField",
    "cellCentres", "errorNorms", "observedOrder", "writeColumns",
    "readColumns", "stripComments", "nCells",
]


def _isTime(name):
    try:
        float(name)
    except ValueError:
        return False
    return True


def timeDirs(case, includeZero=False):
    """Written time directories of case (names), sorted by value."""
    names = [
        d for d in os.listdir(case)
        if _isTime(d) and os.path.isdir(os.path.join(case, d))
    ]
    if not includeZero:
        names = [d for d in names if float(d) != 0.0]
    return sorted(names, key=float)


def latestTime(case):
    t = timeDirs(case, includeZero=True)
    if not t:
        raise RuntimeError("no time directories in %s" % case)
    return t[-1]


_comment = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)


def stripComments(text):
    """text without its // and /* */ comments."""
    return _comment.sub(" ", text)


def _body(path):
    with open(path) as f:
        text = stripComments(f.read())
    # drop the FoamFile header
    m = re.search(r"FoamFile\s*\{[^}]*\}", text)
    if m:
        text = text[m.end():]
    return text


def _header(path):
    with open(path) as f:
        text = stripComments(f.read())
    m = re.search(r"FoamFile\s*\{([^}]*)\}", text)
    if not m:
        return {}
    out = {}
    for line in m.group(1).split(";"):
        p = line.split()
        if len(p) >= 2:
            out[p[0]] = " ".join(p[1:]).strip('"')
    return out


def _readList(text, pos, ncomp):
    """Read an OpenFOAM ascii list starting at text[pos:] (after 'List<T>').

    Returns (values, endpos); values is a list of floats (ncomp == 1) or of
    tuples. Handles 'N ( ... )' and the uniform short form 'N{value}'.
    """
    m = re.compile(r"\s*(\d+)\s*").match(text, pos)
    if not m:
        raise ValueError("list size expected")
    n = int(m.group(1))
    pos = m.end()
    if text[pos] == "{":
        end = text.index("}", pos)
        val = _parseValue(text[pos + 1:end], ncomp)
        return [val] * n, end + 1
    if text[pos] != "(":
        raise ValueError("'(' expected after list size")
    if ncomp == 1:
        end = text.index(")", pos)
        vals = [float(v) for v in text[pos + 1:end].split()]
    else:
        # find the closing bracket of the outer list
        depth = 0
        end = pos
        while True:
            c = text[end]
            if c == "(":
                depth += 1
            elif c == ")":
                depth -= 1
                if depth == 0:
                    break
            end += 1
        inner = text[pos + 1:end]
        vals = [
            tuple(float(x) for x in g.split())
            for g in re.findall(r"\(([^()]*)\)", inner)
        ]
    if len(vals) != n:
        raise ValueError("list size %d but %d values read" % (n, len(vals)))
    return vals, end + 1


def _parseValue(s, ncomp):
    s = s.strip()
    if ncomp == 1:
        return float(s)
    return tuple(float(x) for x in s.strip("()").split())


def _readInternal(path, ncomp, ncells=None):
    text = _body(path)
    m = re.search(r"\binternalField\s+", text)
    if not m:
        raise ValueError("no internalField in %s" % path)
    pos = m.end()
    if text.startswith("uniform", pos):
        end = text.index(";", pos)
        val = _parseValue(text[pos + len("uniform"):end], ncomp)
        if ncells is None:
            raise ValueError("uniform field %s: number of cells needed" % path)
        return [val] * ncells
    if text.startswith("nonuniform", pos):
        m2 = re.compile(r"nonuniform\s+List<\w+>").match(text, pos)
        if not m2:
            raise ValueError("bad nonuniform field in %s" % path)
        vals, _ = _readList(text, m2.end(), ncomp)
        return vals
    raise ValueError("cannot parse internalField of %s" % path)


def readListFile(path, ncomp):
    """The list a file holds whole (a mesh's owner, a cloud's field such
    as <time>/lagrangian/<cloud>/U): floats (ncomp 1) or tuples, from
    'N ( ... )' or the uniform short form 'N{value}'."""
    vals, _ = _readList(_body(path), 0, ncomp)
    return vals


def _readLabelList(path):
    return [int(v) for v in readListFile(path, 1)]


def _meshDir(case):
    return os.path.join(case, "constant", "polyMesh")


def nCells(case):
    owner = os.path.join(_meshDir(case), "owner")
    h = _header(owner)
    note = h.get("note", "")
    m = re.search(r"nCells:\s*(\d+)", note)
    if m:
        return int(m.group(1))
    return len(cellCentres(case))


def readScalarField(case, time, name):
    """Internal field values of volScalarField <case>/<time>/<name>."""
    path = os.path.join(case, time, name)
    vals = _readInternal(path, 1, ncells=None if _isNonUniform(path)
                         else nCells(case))
    return vals


def readVectorField(case, time, name):
    path = os.path.join(case, time, name)
    return _readInternal(path, 3, ncells=None if _isNonUniform(path)
                         else nCells(case))


def _isNonUniform(path):
    with open(path) as f:
        return "nonuniform" in f.read()


_centreCache = {}


def cellCentres(case):
    """Cell centres (x, y, z) from constant/polyMesh, as mean of vertices."""
    key = os.path.abspath(case)
    if key in _centreCache:
        return _centreCache[key]
    md = _meshDir(case)
    text = _body(os.path.join(md, "points"))
    points, _ = _readList(text, 0, 3)
    text = _body(os.path.join(md, "faces"))
    # faces: N ( 4(a b c d) ... )  -- faceList, ascii
    m = re.compile(r"\s*(\d+)\s*\(").match(text)
    if not m:
        raise ValueError("cannot read faces (ascii faceList expected)")
    faces = [
        [int(v) for v in g.split()]
        for g in re.findall(r"\d+\s*\(([^()]*)\)", text[m.end():])
    ]
    owner = _readLabelList(os.path.join(md, "owner"))
    neighbour = _readLabelList(os.path.join(md, "neighbour"))
    nc = max(owner) + 1
    verts = [set() for _ in range(nc)]
    for fi, o in enumerate(owner):
        verts[o].update(faces[fi])
    for fi, nb in enumerate(neighbour):
        verts[nb].update(faces[fi])
    centres = []
    for vs in verts:
        sx = sy = sz = 0.0
        for v in vs:
            p = points[v]
            sx += p[0]
            sy += p[1]
            sz += p[2]
        k = float(len(vs))
        centres.append((sx / k, sy / k, sz / k))
    _centreCache[key] = centres
    return centres


def errorNorms(numerical, exact):
    """(max |e|, L2 = sqrt(mean e^2)) over equal-volume cells."""
    if len(numerical) != len(exact):
        raise ValueError("size mismatch")
    emax = 0.0
    s2 = 0.0
    for a, b in zip(numerical, exact):
        e = abs(a - b)
        if not math.isfinite(e):
            return float("inf"), float("inf")
        emax = max(emax, e)
        s2 += e * e
    return emax, math.sqrt(s2 / len(numerical))


def observedOrder(h1, e1, h2, e2):
    """Observed order between a coarse (h1, e1) and a fine (h2, e2) mesh."""
    if e1 <= 0 or e2 <= 0:
        return float("nan")
    return math.log(e1 / e2) / math.log(h1 / h2)


def writeColumns(path, header, rows):
    d = os.path.dirname(path)
    if d:
        os.makedirs(d, exist_ok=True)
    with open(path, "w") as f:
        f.write("# " + " ".join(header) + "\n")
        for r in rows:
            f.write(" ".join("%.12g" % v for v in r) + "\n")


def readColumns(path):
    """The rows of a text table as writeColumns writes it (and the DEM
    peer's files): lists of floats, '#' lines and blank lines skipped."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(v) for v in line.split()])
    return rows
