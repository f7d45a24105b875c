"""Straight-line (ballistic) first impacts in a 90-degree pipe bend
(python3 standard library only; docs/user/pipe-bend.md, "Ballistic limit").

Geometry of tutorials/pipeBend/writeBendSTL: pipe radius a = D/2, the
upstream leg along +x ends at the origin, the bend's centreline is the
circle of radius R about (0, R, 0) in the plane z = 0. A particle moving
along +x at (y0, z0) in the cross-section (y0 < 0 towards the outer wall)
meets the torus (sqrt(x^2 + (y - R)^2) - R)^2 + z^2 = a^2 on its outer side
where its distance from the bend axis is R + sqrt(a^2 - z0^2):

    x = sqrt((R + sqrt(a^2 - z0^2))^2 - (R - y0)^2)

at the bend angle atan2(x, R - y0); the wall normal there is the torus
gradient, and the impact angle to the wall is asin(|e_x . n|).
"""

import math

__all__ = ["firstImpact", "diskPoints", "statistics"]


def firstImpact(RD, y0, z0, D=1.0):
    """(bend angle [deg], impact angle [deg], normal/total speed) of the
    particle at (y0, z0) of the inlet section (units of D)."""
    a = 0.5 * D
    R = RD * D
    rho = R + math.sqrt(max(a * a - z0 * z0, 0.0))
    x = math.sqrt(rho * rho - (R - y0) ** 2)
    phi = math.degrees(math.atan2(x, R - y0))
    dy = y0 - R
    q = math.hypot(x, dy)
    n = ((q - R) * x / q, (q - R) * dy / q, z0)
    un = abs(n[0]) / math.sqrt(sum(c * c for c in n))
    return phi, math.degrees(math.asin(un)), un


def diskPoints(nRings, nAngles, D=1.0):
    """Points sampling the disk of diameter D uniformly: nAngles points on
    each of nRings equal-area rings (each stands for the same area)."""
    a = 0.5 * D
    pts = []
    for i in range(nRings):
        r = a * math.sqrt((i + 0.5) / nRings)
        for k in range(nAngles):
            t = 2 * math.pi * (k + 0.5) / nAngles
            pts.append((r * math.cos(t), r * math.sin(t)))
    return pts


def statistics(RD, points, D=1.0):
    """Mean impact angle [deg], mean normal/total speed ratio, largest bend
    angle [deg] of the first impacts of the points (y0, z0), and the bend
    angle of the centreline particle."""
    hits = [firstImpact(RD, y, z, D) for y, z in points]
    n = len(hits)
    return (sum(h[1] for h in hits) / n, sum(h[2] for h in hits) / n,
            max(h[0] for h in hits), firstImpact(RD, 0.0, 0.0, D)[0])


if __name__ == "__main__":
    pts = diskPoints(400, 400)
    print("# R/D  meanAngle[deg]  meanUn/U  maxBendAngle[deg]  centrelineBendAngle[deg]")
    for RD in (1.5, 3, 5):
        print("%g %.3f %.4f %.2f %.2f" % ((RD,) + statistics(RD, pts)))
