#!/usr/bin/env python3
"""Reference values for the grasp wrench space: qhull (through SciPy) on seeded contact sets.

Writes src/test/resources/org/handsim/grasp/qhull-reference.csv, which GraspQualityReferenceTest
reads: for each contact set the contacts, mu, m, c, R and qhull's force closure, epsilon, volume
and facet count. The wrenches are built exactly as org.handsim.grasp.FrictionCone and
GraspWrenches build them (same formulas, same order of operations):
  a = e_x if |n_x| < 0.9 else e_y, t1 = n x a / |n x a|, t2 = n x t1,
  f_i = n + mu (cos(2 pi i/m) t1 + sin(2 pi i/m) t2),  w = (f, (p - c) x f / R).

qhull options: "Qt Qx" (triangulated output, exact pre-merges; SciPy adds Qt anyway). Not QJ:
joggling moves every input point by a random ~1e-11 relative, which moves the volume by up to
~2e-9 relative and epsilon by ~4e-10 (measured on the benchmark sets), so a 1e-9 comparison would
fail on the reference's own noise; without joggling, qhull's volume and facet offsets are those
of the exact input up to rounding (~1e-14 relative), and merged coplanar facets keep one
hyperplane, so the facets of the polytope can be counted.

Definitions (the same as org.handsim.grasp.WrenchSpace; S = the largest |wrench coordinate|):
  lower-dimensional: the 6th singular value of the centred wrenches is below 1e-6 S
    (then volume 0, epsilon 0, no force closure, 0 facets; qhull is not asked);
  epsilon: min over facets of -offset (SciPy's equations are n.x + offset <= 0 inside);
  force closure: epsilon > 1e-11 S; else epsilon is reported as 0;
  facets: simplices of the Qt output grouped with their neighbours when the two hyperplanes
    agree within 1e-9 S (qhull's merged facets).
So that the reference does not depend on where those thresholds sit, every set is generated
either exactly degenerate (6th singular value < 1e-12 S) or clearly full (> 1e-4 S), and with
|epsilon| either < 1e-12 S or > 1e-6 S; sets that fall between are redrawn (the script checks).

Usage: python3 tools/grasp/qhull_reference.py [OUT.csv]
  needs numpy and scipy, e.g.  python3 -m venv ~/.cache/handsim-py &&
  ~/.cache/handsim-py/bin/pip install numpy scipy && ~/.cache/handsim-py/bin/python tools/grasp/qhull_reference.py
"""
import math
import os
import random
import sys

import numpy as np
from scipy.spatial import ConvexHull

OUT = os.path.join(os.path.dirname(__file__), '..', '..', 'src', 'test', 'resources', 'org', 'handsim', 'grasp',
                   'qhull-reference.csv')
SEED = 20261124
QHULL_OPTIONS = 'Qt Qx'


def cone(nx, ny, nz, mu, m):
    """org.handsim.grasp.FrictionCone.edges, operation for operation."""
    ln = math.sqrt(nx * nx + ny * ny + nz * nz)
    nx /= ln; ny /= ln; nz /= ln
    if abs(nx) < 0.9:
        t1x, t1y, t1z = 0.0, nz, -ny
    else:
        t1x, t1y, t1z = -nz, 0.0, nx
    tl = math.sqrt(t1x * t1x + t1y * t1y + t1z * t1z)
    t1x /= tl; t1y /= tl; t1z /= tl
    t2x = ny * t1z - nz * t1y; t2y = nz * t1x - nx * t1z; t2z = nx * t1y - ny * t1x
    out = []
    for i in range(m):
        ang = 2 * math.pi * i / m
        c = mu * math.cos(ang); s = mu * math.sin(ang)
        out.append((nx + c * t1x + s * t2x, ny + c * t1y + s * t2y, nz + c * t1z + s * t2z))
    return out


def wrenches(points, normals, mu, m, c, r):
    """org.handsim.grasp.GraspWrenches.of, operation for operation."""
    w = []
    for (px, py, pz), (nx, ny, nz) in zip(points, normals):
        rx, ry, rz = px - c[0], py - c[1], pz - c[2]
        for fx, fy, fz in cone(nx, ny, nz, mu, m):
            w.append((fx, fy, fz, (ry * fz - rz * fy) / r, (rz * fx - rx * fz) / r, (rx * fy - ry * fx) / r))
    return np.array(w)


def quality(w):
    """(rank, force_closure, epsilon, volume, facets) by qhull; None if the set is ambiguous."""
    s_max = float(np.abs(w).max())
    sv = np.linalg.svd(w - w.mean(axis=0), compute_uv=False)
    rank = int(np.sum(sv > 1e-6 * s_max))
    if len(w) < 7 or rank < 6:
        if len(sv) >= 6 and sv[5] > 1e-12 * s_max:
            return None
        return rank, False, 0.0, 0.0, 0
    if sv[5] < 1e-4 * s_max:
        return None
    h = ConvexHull(w, qhull_options=QHULL_OPTIONS)
    eps = float(-h.equations[:, -1].max())
    if 1e-12 * s_max <= abs(eps) <= 1e-6 * s_max:
        return None
    closure = eps > 1e-11 * s_max
    # facets of the polytope: Qt simplices joined across ridges when their hyperplanes agree
    parent = list(range(len(h.simplices)))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    groups = len(parent)
    for a, nbrs in enumerate(h.neighbors):
        for b in nbrs:
            if b > a and np.abs(h.equations[a] - h.equations[b]).max() <= 1e-9 * s_max:
                ra, rb = find(a), find(b)
                if ra != rb:
                    parent[ra] = rb
                    groups -= 1
    return rank, closure, eps if closure else 0.0, float(h.volume), groups


# ----------------------------------------------------------------- objects: (centroid, R, sampler)

def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return tuple(x / n for x in v)


def sphere(rng, radius=0.04):
    def sample():
        d = unit((rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1)))
        return tuple(radius * x for x in d), tuple(-x for x in d)
    return (0.0, 0.0, 0.0), radius, sample


def box(rng, hx=0.05, hy=0.03, hz=0.02, faces=(0, 1, 2, 3, 4, 5)):
    h = (hx, hy, hz)

    def sample():
        f = rng.choice(faces)
        axis, sign = f // 2, 1 if f % 2 == 0 else -1
        p = [rng.uniform(-h[k], h[k]) for k in range(3)]
        p[axis] = sign * h[axis]
        n = [0.0, 0.0, 0.0]
        n[axis] = -sign
        return tuple(p), tuple(n)
    return (0.0, 0.0, 0.0), math.sqrt(hx * hx + hy * hy + hz * hz), sample


def cylinder(rng, radius=0.035, half=0.06):
    def sample():
        t = rng.uniform(0, 2 * math.pi)
        if rng.random() < 0.8:
            p = (radius * math.cos(t), radius * math.sin(t), rng.uniform(-half, half))
            n = (-math.cos(t), -math.sin(t), 0.0)
        else:
            s = 1 if rng.random() < 0.5 else -1
            rr = radius * math.sqrt(rng.random())
            p = (rr * math.cos(t), rr * math.sin(t), s * half)
            n = (0.0, 0.0, -float(s))
        return p, n
    return (0.0, 0.0, 0.0), math.sqrt(radius * radius + half * half), sample


def tilt(rng, n, amount):
    """The normal turned by a random small amount (contacts on curved or rough surfaces)."""
    if amount == 0:
        return n
    return unit(tuple(x + amount * rng.gauss(0, 1) for x in n))


def random_set(rng, kind):
    """One contact set of the given kind: (points, normals, mu, m, c, R)."""
    mu = rng.choice([0.2, 0.5, 0.5, 1.0])
    m = rng.choice([4, 6, 8, 8])
    if kind == 'sphere':
        c, r, smp = sphere(rng)
        k = rng.randint(3, 16)
    elif kind == 'box':
        c, r, smp = box(rng)
        k = rng.randint(3, 16)
    elif kind == 'cylinder':
        c, r, smp = cylinder(rng)
        k = rng.randint(3, 16)
    elif kind == 'tilted':          # normals off the surface normal: rough contacts
        c, r, smp = sphere(rng)
        k = rng.randint(3, 12)
    elif kind == 'offcentre':       # torque origin away from the object's centre
        c0, r, smp = box(rng)
        c = (0.01, -0.02, 0.005)
        k = rng.randint(3, 12)
    elif kind == 'one-face':        # every contact on the same face: never force closure
        c, r, smp = box(rng, faces=(rng.randrange(6),))
        k = rng.randint(2, 10)
    elif kind == 'collinear':       # contacts on one line: no torque about it, rank <= 5
        c, r = (0.0, 0.0, 0.0), 0.05
        a = (rng.uniform(-0.02, 0.02), rng.uniform(-0.02, 0.02), rng.uniform(-0.02, 0.02))
        u = unit((rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1)))
        k = rng.randint(2, 8)
        ts = [rng.uniform(-0.03, 0.03) for _ in range(k)]
        pts = [tuple(a[j] + t * u[j] for j in range(3)) for t in ts]
        nrm = [unit((rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))) for _ in range(k)]
        return pts, nrm, mu, m, c, r
    elif kind == 'coincident':      # every contact at one point: rank <= 3
        c, r = (0.0, 0.0, 0.0), 0.05
        p = (0.01, 0.02, -0.015)
        k = rng.randint(2, 8)
        nrm = [unit((rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))) for _ in range(k)]
        return [p] * k, nrm, mu, m, c, r
    elif kind == 'frictionless':    # mu = 0: m identical edges per contact
        c, r, smp = box(rng)
        k = rng.randint(2, 16)
        mu = 0.0
    elif kind == 'few':             # one or two contacts: rank <= 5
        c, r, smp = sphere(rng)
        k = rng.randint(1, 2)
    elif kind == 'antipodal':       # two opposite contacts on a sphere: rank <= 5
        c, r = (0.0, 0.0, 0.0), 0.04
        d = unit((rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1)))
        pts = [tuple(0.04 * x for x in d), tuple(-0.04 * x for x in d)]
        return pts, [tuple(-x for x in d), d], mu, m, c, r
    elif kind == 'symmetric':       # face centres of a cube: exactly coplanar wrenches, big facets
        c, r = (0.0, 0.0, 0.0), math.sqrt(3) * 0.03
        faces = rng.choice([(0, 1, 2, 3, 4, 5), (0, 1, 2, 3), (0, 1, 2, 4), (0, 2, 4)])
        pts, nrm = [], []
        for f in faces:
            axis, sign = f // 2, 1 if f % 2 == 0 else -1
            p = [0.0, 0.0, 0.0]; p[axis] = sign * 0.03
            n = [0.0, 0.0, 0.0]; n[axis] = -float(sign)
            pts.append(tuple(p)); nrm.append(tuple(n))
        return pts, nrm, mu, m, c, r
    elif kind == 'near-coplanar':   # contacts a hair apart on a sphere: nearly coplanar facets
        c, r, smp = sphere(rng)
        base = [smp() for _ in range(rng.randint(3, 6))]
        pts, nrm = [], []
        for p, n in base:
            for _ in range(2):
                q = tuple(x + 1e-3 * rng.gauss(0, 1) * 0.04 for x in p)
                pts.append(q); nrm.append(n)
        return pts, nrm, mu, m, c, r
    else:
        raise ValueError(kind)
    pts, nrm = [], []
    for _ in range(k):
        p, n = smp()
        pts.append(p)
        nrm.append(tilt(rng, n, 0.3 if kind == 'tilted' else 0.0))
    return pts, nrm, mu, m, c, r


KINDS = [('sphere', 30), ('box', 30), ('cylinder', 25), ('tilted', 20), ('offcentre', 15),
         ('one-face', 15), ('collinear', 12), ('coincident', 10), ('frictionless', 20), ('few', 10),
         ('antipodal', 10), ('symmetric', 12), ('near-coplanar', 15)]


def fmt(values):
    return ';'.join(repr(float(v)) for v in values)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else OUT
    rng = random.Random(SEED)
    rows = []
    redrawn = 0
    for kind, count in KINDS:
        made = 0
        while made < count:
            pts, nrm, mu, m, c, r = random_set(rng, kind)
            w = wrenches(pts, nrm, mu, m, c, r)
            q = quality(w)
            if q is None:
                redrawn += 1
                continue
            rank, closure, eps, vol, facets = q
            rows.append((len(rows), kind, len(pts), mu, m, c, r, pts, nrm, rank, closure, eps, vol, facets))
            made += 1
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    with open(out, 'w') as f:
        f.write('case,kind,contacts,mu,edges,center,radius,points,normals,rank,force_closure,epsilon,volume,facets\n')
        for (i, kind, k, mu, m, c, r, pts, nrm, rank, closure, eps, vol, facets) in rows:
            f.write(','.join([str(i), kind, str(k), repr(mu), str(m), fmt(c), repr(r),
                              fmt([x for p in pts for x in p]), fmt([x for n in nrm for x in n]),
                              str(rank), 'true' if closure else 'false', repr(eps), repr(vol), str(facets)]) + '\n')
    fc = sum(1 for row in rows if row[10])
    low = sum(1 for row in rows if row[9] < 6)
    print(f'{len(rows)} sets ({fc} force closure, {low} lower-dimensional, {redrawn} redrawn) -> {out}')


if __name__ == '__main__':
    main()
