#!/usr/bin/env python3
"""Write the planner's benchmark shapes that vrml/objects/ does not have, as Wavefront OBJ in metres.

Standard library only, deterministic (the same bytes every time). Each body is closed, welded and
counter-clockwise seen from outside.

  sphere40.obj, sphere60.obj, sphere100.obj   UV spheres of 40, 60 and 100 mm diameter
                                             (32 longitudes, 16 latitude bands, vertices on the sphere)
  box40x40x120.obj                            a 40 x 40 x 120 mm box, long axis z, each face a grid
                                             of 10 mm squares

Usage: python3 tools/plan-shapes/make-shapes.py [OUT_DIR]   (default: docs/plan-shapes)
"""
import math
import os
import sys


def sphere(radius, segments=32, bands=16):
    v = [(0.0, 0.0, -radius)]
    for b in range(1, bands):
        phi = -math.pi / 2 + math.pi * b / bands
        for s in range(segments):
            th = 2 * math.pi * s / segments
            v.append((radius * math.cos(phi) * math.cos(th), radius * math.cos(phi) * math.sin(th), radius * math.sin(phi)))
    v.append((0.0, 0.0, radius))
    top = len(v) - 1
    f = []
    ring = lambda b, s: 1 + (b - 1) * segments + s % segments
    for s in range(segments):
        f.append((0, ring(1, s + 1), ring(1, s)))
    for b in range(1, bands - 1):
        for s in range(segments):
            a, c, d, e = ring(b, s), ring(b, s + 1), ring(b + 1, s + 1), ring(b + 1, s)
            f.append((a, c, d))
            f.append((a, d, e))
    for s in range(segments):
        f.append((ring(bands - 1, s), ring(bands - 1, s + 1), top))
    return v, f


def box(sx, sy, sz, cell):
    """A welded box centred at the origin, each face a grid of squares of about `cell`."""
    n = [max(1, round(e / cell)) for e in (sx, sy, sz)]
    half = (sx / 2, sy / 2, sz / 2)
    index = {}
    v, f = [], []

    def vertex(i, j, k):
        key = (i, j, k)
        if key not in index:
            index[key] = len(v)
            v.append(tuple(-half[a] + (sx, sy, sz)[a] * (i, j, k)[a] / n[a] for a in range(3)))
        return index[key]

    # each face: the fixed axis, its side, and the two running axes ordered so the normal points out
    for axis in range(3):
        u, w = (axis + 1) % 3, (axis + 2) % 3
        for side in (0, n[axis]):
            for p in range(n[u]):
                for q in range(n[w]):
                    def g(dp, dq):
                        c = [0, 0, 0]
                        c[axis], c[u], c[w] = side, p + dp, q + dq
                        return vertex(*c)
                    a, b, c, d = g(0, 0), g(1, 0), g(1, 1), g(0, 1)
                    quad = (a, b, c, d) if side else (a, d, c, b)
                    f.append((quad[0], quad[1], quad[2]))
                    f.append((quad[0], quad[2], quad[3]))
    return v, f


def number(c):
    """Fixed point on a 1 nm grid, trailing zeros dropped ("0", never "-0")."""
    t = ("%.9f" % c).rstrip("0").rstrip(".")
    return "0" if t in ("-0", "") else t


def write(path, comment, v, f):
    with open(path, "w", newline="\n") as out:
        for line in comment:
            out.write("# " + line + "\n")
        out.write("# %d vertices, %d triangles, metres\n" % (len(v), len(f)))
        for p in v:
            out.write("v %s %s %s\n" % tuple(number(c) for c in p))
        for t in f:
            out.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join("docs", "plan-shapes")
    os.makedirs(out, exist_ok=True)
    for d in (40, 60, 100):
        v, f = sphere(d / 2000.0)
        write(os.path.join(out, "sphere%d.obj" % d), ["UV sphere, diameter %d mm, centred at the origin (tools/plan-shapes/make-shapes.py)" % d], v, f)
    v, f = box(0.040, 0.040, 0.120, 0.010)
    write(os.path.join(out, "box40x40x120.obj"), ["box 40 x 40 x 120 mm, long axis z, centred at the origin (tools/plan-shapes/make-shapes.py)"], v, f)


if __name__ == "__main__":
    main()
