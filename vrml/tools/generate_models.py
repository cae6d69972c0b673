#!/usr/bin/env python3
"""Generate HandSim's VRML97 models (vrml/hand/*.wrl, vrml/objects/*.wrl) and vrml/models.json.

Standard library only, deterministic: the same arguments always write the same bytes.

Every body is one closed, consistently oriented (counter-clockwise seen from outside), welded
triangle mesh written as a strict VRML97 IndexedFaceSet (solid TRUE, ccw TRUE, convex TRUE,
triangles only). Units: metres. Coordinates are written with 9 decimals (a 1 nm grid) and every
figure in models.json is computed from the coordinates exactly as written:

  * volume_m3 and centroid_m: divergence theorem in exact rational arithmetic (fractions),
    then rounded once to the nearest double;
  * area_m2: per-triangle |cross product| / 2 from exact rational cross products, square roots
    and sum in 50-digit decimal arithmetic, rounded once to the nearest double;
  * bounds: the written coordinates themselves.

Before anything is written every mesh is checked: closed (each directed edge once, its reverse
once), vertex-manifold (one fan per vertex), no duplicate or unused vertex, no zero-area
triangle (exact test), positive volume (outward orientation), no two triangles that share no
vertex intersect, and the Euler characteristic gives the expected genus. A failed check stops
the generator with exit code 1 and writes nothing.

Usage (from the project root):
  python3 vrml/tools/generate_models.py                  # rewrite vrml/ (the committed files)
  python3 vrml/tools/generate_models.py --divisions 64 --out /tmp/models64
  python3 vrml/tools/generate_models.py --big 20000      # vrml/objects/sphere_big.wrl only
  python3 vrml/tools/generate_models.py --convergence    # print the convergence table

Options:
  --divisions N        segments around every curved object (sphere longitudes, cylinder,
                       cone, ring major circle, mug); default 32. Sphere latitude bands and
                       ring minor segments are N/2.
  --cube-divisions M   each cube face split into M x M squares (2 M^2 triangles); default 1.
  --hand-segments S    segments per full circle for the rounded ends of the hand links and
                       palm corners; default 32.
  --out DIR            write into DIR (DIR/hand, DIR/objects, DIR/models.json) instead of vrml/.
  --big N              write only objects/sphere_big.wrl, a UV sphere of about N triangles
                       (radius 0.040 m), for GUI speed tests; not committed (vrml/.gitignore).
  --convergence        print a Markdown table of area/volume errors against the analytic
                       shapes for N = 8 ... 256 and exit.
"""

import argparse
import json
import math
import os
import sys
from decimal import Decimal, localcontext
from fractions import Fraction

# --------------------------------------------------------------------------------------------
# The hand description (paper Tables I-II; BH8 manual Table 9), metres and radians.
# --------------------------------------------------------------------------------------------
A1, A2, A3 = 0.050, 0.070, 0.056
PHI2 = math.radians(2.46)
PHI3 = math.radians(50.0)
AW, DW = 0.025, 0.084
FINGER_R = (-1, 1, 0)     # spread axis of finger k at x = r*Aw
FINGER_J = (1, 1, -1)     # base frame {k0} turned by -(pi/2)*j about the palm z axis

# Palm: a rounded block, bottom at z = 0, top 30 mm below the finger base frames.
PALM_TOP = 0.054          # = Dw - 0.030
PALM_HALF_X = 0.045       # footprint 0.090 m in x ...
PALM_HALF_Y = 0.065       # ... by 0.130 m in y (fingers 1, 2 on -y, finger 3 on +y)
PALM_CORNER_R = 0.022     # corner radius of the footprint
PALM_CHAMFER = 0.003      # 45-degree chamfer round the top edge

# Link 1 (knuckle), side profile in the x-y plane of {k1} (y = palm normal), extruded in z.
L1_BACK = 0.010           # the block reaches 10 mm behind the spread axis (x = -A1 - 0.010)
L1_BOTTOM = -0.028        # underside 28 mm below the joint-2 axis (2 mm above the palm top)
L1_KNUCKLE_R = 0.012      # rounded knuckle about the joint-2 axis (z1 through the origin)
L1_PLATE_TOP = -0.010     # top of the arm between the knuckle and the spread axis
L1_HALF_W_BACK = 0.0095   # half-width (z) at the spread end ...
L1_HALF_W_FRONT = 0.011   # ... growing linearly to the knuckle end

# Link 2 (inner link), in {k2}: hull of two circles round the joint axes, constant width.
L2_R_PROX, L2_R_DIST = 0.011, 0.009
L2_HALF_W = 0.0125

# Link 3 (outer link), in {k3}: tapering to a rounded tip whose extreme point is the origin.
L3_R_PROX, L3_R_TIP = 0.0095, 0.0055
L3_HALF_W_PROX, L3_HALF_W_TIP = 0.0115, 0.0075

# Table III centres of mass (each link's own frame), for the README's sanity check only.
TABLE3_COM = {
    1: (-0.01798334, -0.01569925, 0.00086502),
    2: (-0.03827982, 0.00107042, -0.00058628),
    3: (-0.03629026, 0.00182016, 0.00020041),
}
TABLE3_MASS = {1: 0.16252678, 2: 0.05795741, 3: 0.03421781}

# --------------------------------------------------------------------------------------------
# Objects (vrml/objects), metres.
# --------------------------------------------------------------------------------------------
CUBE_EDGE = 0.060
SPHERE_R = 0.040
CYL_R, CYL_H = 0.030, 0.120
CONE_R, CONE_H = 0.035, 0.090
LBLOCK_OUTER, LBLOCK_ARM, LBLOCK_THICK = 0.080, 0.040, 0.040
RING_MAJOR, RING_MINOR = 0.045, 0.012
MUG_R_OUT, MUG_WALL, MUG_H, MUG_BOTTOM = 0.040, 0.004, 0.100, 0.006
MUG_HANDLE_Z = 0.024          # handle centre line leaves the wall at z = +-0.024
MUG_HANDLE_T = 0.012          # handle section: 12 mm high (along the path normal) ...
MUG_HANDLE_W = 0.016          # ... about 16 mm wide (snapped to whole wall columns)
MUG_HANDLE_OUT = 0.004        # straight run out of the wall before the bend
DEFAULT_DIVISIONS = 32
DEFAULT_CUBE_DIVISIONS = 1
DEFAULT_HAND_SEGMENTS = 32
DECIMALS = 9                  # coordinates written on a 1 nm grid


# --------------------------------------------------------------------------------------------
# Mesh
# --------------------------------------------------------------------------------------------
def fmt(x):
    """A coordinate as written: fixed point, 9 decimals, trailing zeros dropped, no '-0'."""
    s = '%.*f' % (DECIMALS, x)
    if '.' in s:
        s = s.rstrip('0').rstrip('.')
    if s in ('-0', ''):
        s = '0'
    return s


class Mesh:
    """An indexed triangle mesh; points are quantised to the written grid when added."""

    def __init__(self, name):
        self.name = name
        self.text = []       # coordinate strings as written, per vertex
        self.points = []     # the same as doubles
        self.tris = []

    def add(self, p):
        t = tuple(fmt(c) for c in p)
        self.text.append(t)
        self.points.append(tuple(float(c) for c in t))
        return len(self.points) - 1

    def tri(self, a, b, c):
        self.tris.append((a, b, c))

    def quad(self, a, b, c, d):
        """Quad a-b-c-d counter-clockwise from outside, as two triangles (diagonal a-c)."""
        self.tri(a, b, c)
        self.tri(a, c, d)


# --------------------------------------------------------------------------------------------
# 2D helpers
# --------------------------------------------------------------------------------------------
def cross2(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def arc(cx, cy, r, a0, a1, segments_per_circle, even=False):
    """Points on a circle from angle a0 to a1 (counter-clockwise if a1 > a0), both ends included."""
    span = a1 - a0
    n = max(1, int(math.ceil(abs(span) / (2 * math.pi / segments_per_circle) - 1e-9)))
    if even and n % 2:
        n += 1
    return [(cx + r * math.cos(a0 + span * i / n), cy + r * math.sin(a0 + span * i / n)) for i in range(n + 1)]


def ear_clip(poly):
    """Triangulate a simple counter-clockwise polygon; returns counter-clockwise index triples.

    Deterministic ear clipping that always cuts the best-shaped ear (largest smallest angle)."""
    idx = list(range(len(poly)))
    out = []
    while len(idx) > 3:
        best, best_q = None, -1.0
        m = len(idx)
        for k in range(m):
            i0, i1, i2 = idx[k - 1], idx[k], idx[(k + 1) % m]
            a, b, c = poly[i0], poly[i1], poly[i2]
            if cross2(a, b, c) <= 1e-18:
                continue
            inside = False
            for j in idx:
                if j in (i0, i1, i2):
                    continue
                p = poly[j]
                if cross2(a, b, p) >= 0 and cross2(b, c, p) >= 0 and cross2(c, a, p) >= 0:
                    inside = True
                    break
            if inside:
                continue
            q = min_angle(a, b, c)
            if q > best_q + 1e-12:
                best, best_q = k, q
        if best is None:
            raise RuntimeError('ear clipping failed: polygon not simple or not counter-clockwise')
        m = len(idx)
        out.append((idx[best - 1], idx[best], idx[(best + 1) % m]))
        del idx[best]
    out.append(tuple(idx))
    return out


def min_angle(a, b, c):
    def ang(p, q, r):
        ux, uy, vx, vy = q[0] - p[0], q[1] - p[1], r[0] - p[0], r[1] - p[1]
        return math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy)
    return min(ang(a, b, c), ang(b, c, a), ang(c, a, b))


def circle_hull(x0, r0, x1, r1, segments_per_circle):
    """Counter-clockwise outline of the convex hull of two circles centred on the x axis
    (x0 < x1): the stadium-like side profile of a finger link. The arc round the distal
    circle has an even number of segments so that its extreme point (x1 + r1, 0) is a vertex."""
    d = x1 - x0
    alpha = math.acos((r0 - r1) / d)     # tangent points at angles +-alpha on both circles
    dist = arc(x1, 0.0, r1, -alpha, alpha, segments_per_circle, even=True)
    dist[len(dist) // 2] = (x1 + r1, 0.0)  # the tip exactly
    prox = arc(x0, 0.0, r0, alpha, 2 * math.pi - alpha, segments_per_circle, even=True)
    prox[len(prox) // 2] = (x0 - r0, 0.0)
    return dist + prox


def rounded_rect(hx, hy, rc, segments_per_circle):
    """Counter-clockwise outline of a rounded rectangle |x| <= hx, |y| <= hy, corner radius rc."""
    n = max(1, int(math.ceil(segments_per_circle / 4 - 1e-9)))
    pts = []
    for cx, cy, a0 in ((hx - rc, -hy + rc, -math.pi / 2), (hx - rc, hy - rc, 0.0),
                       (-hx + rc, hy - rc, math.pi / 2), (-hx + rc, -hy + rc, math.pi)):
        for i in range(n + 1):
            a = a0 + (math.pi / 2) * i / n
            pts.append((cx + rc * math.cos(a), cy + rc * math.sin(a)))
    return pts


# --------------------------------------------------------------------------------------------
# Mesh builders
# --------------------------------------------------------------------------------------------
def extrude_profile(name, profile, half_width):
    """A prism over a counter-clockwise x-y profile, z from -w(x) to +w(x).

    half_width(x) must be affine in x, so both side caps are planes and every side quad is a
    planar isosceles trapezoid."""
    m = Mesh(name)
    lo = [m.add((x, y, -half_width(x))) for x, y in profile]
    hi = [m.add((x, y, half_width(x))) for x, y in profile]
    n = len(profile)
    for i in range(n):
        j = (i + 1) % n
        m.quad(lo[i], lo[j], hi[j], hi[i])
    for a, b, c in ear_clip(profile):
        m.tri(hi[a], hi[b], hi[c])
        m.tri(lo[c], lo[b], lo[a])
    return m


def revolve(name, profile, segments, closed=False):
    """Surface of revolution about z.

    profile: (r, z) points going counter-clockwise round the body's cross-section in the
    (r, z) half-plane. Open profiles start and end on the axis (r = 0): those points become
    single pole vertices. closed=True: the profile is a loop with r > 0 everywhere (a torus).
    Returns the mesh and grid(i, j) -> vertex index of profile point i at angle 2*pi*j/segments."""
    m = Mesh(name)
    n = len(profile)
    rows = []
    for i, (r, z) in enumerate(profile):
        if r == 0.0:
            if closed or i not in (0, n - 1):
                raise ValueError('only the ends of an open profile may lie on the axis')
            rows.append([m.add((0.0, 0.0, z))] * segments)
        else:
            rows.append([m.add((r * math.cos(2 * math.pi * j / segments),
                                r * math.sin(2 * math.pi * j / segments), z)) for j in range(segments)])
    bands = n if closed else n - 1
    for i in range(bands):
        i2 = (i + 1) % n
        for j in range(segments):
            j2 = (j + 1) % segments
            a, b, c, d = rows[i][j], rows[i][j2], rows[i2][j2], rows[i2][j]
            if a == b:          # fan round the pole at the start
                m.tri(a, c, d)
            elif c == d:        # fan round the pole at the end
                m.tri(a, b, c)
            else:
                m.quad(a, b, c, d)
    return m, (lambda i, j: rows[i][j % segments])


def box_grid(name, edge, div):
    """An axis-aligned cube centred at the origin, every face an div x div grid of squares."""
    m = Mesh(name)
    ids = {}
    h = edge / 2

    def vid(i, j, k):
        key = (i, j, k)
        if key not in ids:
            ids[key] = m.add((-h + edge * i / div, -h + edge * j / div, -h + edge * k / div))
        return ids[key]

    # (axis, side): face normal +-axis; (u, v) the other two axes with u x v = +axis.
    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for side in (0, div):
            for a in range(div):
                for b in range(div):
                    def corner(da, db):
                        c = [0, 0, 0]
                        c[axis], c[u], c[v] = side, a + da, b + db
                        return vid(*c)
                    p00, p10, p11, p01 = corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)
                    if side == div:
                        m.quad(p00, p10, p11, p01)
                    else:
                        m.quad(p00, p01, p11, p10)
    return m


def sphere_mesh(name, radius, segments, bands):
    prof = [(0.0, -radius)]
    for i in range(1, bands):
        t = math.pi * i / bands
        prof.append((radius * math.sin(t), -radius * math.cos(t)))
    prof.append((0.0, radius))
    return revolve(name, prof, segments)[0]


def torus_mesh(name, major, minor, segments, minor_segments):
    prof = [(major + minor * math.cos(2 * math.pi * i / minor_segments),
             minor * math.sin(2 * math.pi * i / minor_segments)) for i in range(minor_segments)]
    return revolve(name, prof, segments, closed=True)[0]


def mug_mesh(name, segments):
    """An open-topped cup (wall, bottom) revolved about z, centred on the origin (z from -0.05 to
    +0.05), and a D-shaped handle on the +x side whose ends are welded into holes in the outer wall.

    The outer wall has vertex rings at the handle's heights; the handle section spans the wall
    columns with angles in [-k*2pi/N, +k*2pi/N]. Each handle end is the hole's own loop of wall
    vertices; in between, the section is a flat (2k+1)-by-2 grid swept along a straight run
    out of the wall, a half circle in the x-z plane, and a straight run back."""
    ro, ri = MUG_R_OUT, MUG_R_OUT - MUG_WALL
    zb, zt = -MUG_H / 2, MUG_H / 2
    zi = zb + MUG_BOTTOM
    zh, th = MUG_HANDLE_Z, MUG_HANDLE_T
    # outer wall rings, bottom to top: the handle ends occupy z in [-zh-th/2, -zh+th/2] and
    # [zh-th/2, zh+th/2]
    prof = [(0.0, zb), (ro, zb), (ro, -zh - th / 2), (ro, -zh + th / 2),
            (ro, zh - th / 2), (ro, zh + th / 2), (ro, zt), (ri, zt), (ri, zi), (0.0, zi)]
    m, grid = revolve(name, prof, segments)
    row_lo = (2, 3)     # profile rows of the lower handle end (bottom, top)
    row_hi = (4, 5)     # upper handle end
    dphi = 2 * math.pi / segments
    k = max(1, int(round(math.asin(MUG_HANDLE_W / 2 / ro) / dphi)))
    if 2 * k + 1 > segments // 2:
        raise ValueError('too few divisions for the mug handle')
    cols = list(range(-k, k + 1))
    # remove the wall quads covered by the two handle ends (2 triangles each)
    doomed = set()
    for r0, r1 in (row_lo, row_hi):
        for j in cols[:-1]:
            a, b, c, d = grid(r0, j), grid(r0, j + 1), grid(r1, j + 1), grid(r1, j)
            doomed.add((a, b, c))
            doomed.add((a, c, d))
    before = len(m.tris)
    m.tris = [t for t in m.tris if t not in doomed]
    assert before - len(m.tris) == len(doomed)

    # section loop: "bottom" edge j = -k..k, then "top" edge j = k..-k
    ys = [ro * math.sin(j * dphi) for j in cols]

    def section(c, nrm):
        """Flat section at centre c with section 'up' = nrm; lateral axis = +y."""
        bottom = [m.add((c[0] - nrm[0] * th / 2, y, c[2] - nrm[2] * th / 2)) for y in ys]
        top = [m.add((c[0] + nrm[0] * th / 2, y, c[2] + nrm[2] * th / 2)) for y in ys]
        return bottom + top[::-1]

    first = [grid(row_hi[0], j) for j in cols] + [grid(row_hi[1], j) for j in cols][::-1]
    # at the lower end the section has turned over: its 'bottom' edge is the upper wall ring
    last = [grid(row_lo[1], j) for j in cols] + [grid(row_lo[0], j) for j in cols][::-1]
    stations = [first]
    xc = ro + MUG_HANDLE_OUT       # centre of the half circle (xc, 0, 0), radius zh
    nbend = max(4, segments // 2)
    for i in range(nbend + 1):
        psi = math.pi / 2 - math.pi * i / nbend          # +90 deg (top) ... -90 deg (bottom)
        c = (xc + zh * math.cos(psi), 0.0, zh * math.sin(psi))
        t = (math.sin(psi), 0.0, -math.cos(psi))          # direction of travel
        nrm = (-t[2], 0.0, t[0])                          # t x (+y): the section's 'up'
        stations.append(section(c, nrm))
    stations.append(last)
    ln = len(first)
    for s in range(len(stations) - 1):
        p, q = stations[s], stations[s + 1]
        for i in range(ln):
            i2 = (i + 1) % ln
            m.quad(p[i], p[i2], q[i2], q[i])
    return m, {'handle_columns': 2 * k, 'handle_width_m': 2 * ro * math.sin(k * dphi),
               'handle_bend_segments': nbend}


def palm_mesh(name, segments_per_circle):
    """Rounded block: footprint |x| <= 0.045, |y| <= 0.065 (corner radius 0.022), z from 0 to
    0.054, with a 3 mm 45-degree chamfer round the top edge."""
    outer = rounded_rect(PALM_HALF_X, PALM_HALF_Y, PALM_CORNER_R, segments_per_circle)
    inner = rounded_rect(PALM_HALF_X - PALM_CHAMFER, PALM_HALF_Y - PALM_CHAMFER,
                         PALM_CORNER_R - PALM_CHAMFER, segments_per_circle)
    m = Mesh(name)
    rings = [[m.add((x, y, 0.0)) for x, y in outer],
             [m.add((x, y, PALM_TOP - PALM_CHAMFER)) for x, y in outer],
             [m.add((x, y, PALM_TOP)) for x, y in inner]]
    n = len(outer)
    for r in range(2):
        for i in range(n):
            j = (i + 1) % n
            m.quad(rings[r][i], rings[r][j], rings[r + 1][j], rings[r + 1][i])
    cb = m.add((0.0, 0.0, 0.0))
    ct = m.add((0.0, 0.0, PALM_TOP))
    for i in range(n):
        j = (i + 1) % n
        m.tri(cb, rings[0][j], rings[0][i])
        m.tri(ct, rings[2][i], rings[2][j])
    return m


def link1_profile(seg):
    """Side profile of link 1 in {k1} (x along the link, y = palm normal), counter-clockwise."""
    x_back = -A1 - L1_BACK
    pts = [(x_back, L1_BOTTOM), (L1_KNUCKLE_R, L1_BOTTOM)]
    pts += arc(0.0, 0.0, L1_KNUCKLE_R, 0.0, math.pi, seg)
    pts[-1] = (-L1_KNUCKLE_R, 0.0)
    pts += [(-L1_KNUCKLE_R, L1_PLATE_TOP), (x_back, L1_PLATE_TOP)]
    return pts


def affine(x0, w0, x1, w1):
    return lambda x: w0 + (w1 - w0) * (x - x0) / (x1 - x0)


def link_meshes(seg):
    x_back = -A1 - L1_BACK
    l1 = extrude_profile('FINGER_LINK1', link1_profile(seg),
                         affine(x_back, L1_HALF_W_BACK, L1_KNUCKLE_R, L1_HALF_W_FRONT))
    l2 = extrude_profile('FINGER_LINK2', circle_hull(-A2, L2_R_PROX, 0.0, L2_R_DIST, seg),
                         lambda x: L2_HALF_W)
    l3 = extrude_profile('FINGER_LINK3', circle_hull(-A3, L3_R_PROX, -L3_R_TIP, L3_R_TIP, seg),
                         affine(-A3 - L3_R_PROX, L3_HALF_W_PROX, 0.0, L3_HALF_W_TIP))
    return l1, l2, l3


def lblock_mesh(name):
    o, a, t = LBLOCK_OUTER, LBLOCK_ARM, LBLOCK_THICK
    h = o / 2
    # L = [-h, h] x [-h, -h + a]  U  [-h, -h + a] x [-h, h], extruded z in [-t/2, t/2]
    prof = [(-h, -h), (h, -h), (h, -h + a), (-h + a, -h + a), (-h + a, h), (-h, h)]
    return extrude_profile(name, prof, lambda x: t / 2)


# --------------------------------------------------------------------------------------------
# Checks and exact figures
# --------------------------------------------------------------------------------------------
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def orient3d(a, b, c, d):
    return dot(sub(b, a), cross(sub(c, a), sub(d, a)))


def topology(mesh):
    """Raise AssertionError unless the mesh is a closed, oriented, welded 2-manifold.
    Returns (edges, genus)."""
    name = mesh.name
    nv, nt = len(mesh.points), len(mesh.tris)
    directed = {}
    used = [False] * nv
    for t, (a, b, c) in enumerate(mesh.tris):
        if len({a, b, c}) != 3:
            raise AssertionError('%s: triangle %d repeats a vertex' % (name, t))
        for e in ((a, b), (b, c), (c, a)):
            if e in directed:
                raise AssertionError('%s: directed edge %s used twice (triangles %d, %d): '
                                     'not consistently oriented or not manifold' % (name, e, directed[e], t))
            directed[e] = t
        used[a] = used[b] = used[c] = True
    for (a, b) in directed:
        if (b, a) not in directed:
            raise AssertionError('%s: edge %d-%d has no opposite: the mesh is not closed' % (name, a, b))
    if not all(used):
        raise AssertionError('%s: vertex %d is unused' % (name, used.index(False)))
    if len(set(mesh.text)) != nv:
        raise AssertionError('%s: two vertices share a position (not welded)' % name)
    # vertex manifoldness: the triangles round each vertex form one cycle
    nxt = {}
    for a, b, c in mesh.tris:
        for v, p, q in ((a, b, c), (b, c, a), (c, a, b)):
            nxt.setdefault(v, {})[p] = q     # around v: from edge v-p to edge v-q
    for v, ring in nxt.items():
        start = next(iter(ring))
        p, steps = start, 0
        while True:
            p = ring[p]
            steps += 1
            if p == start:
                break
        if steps != len(ring):
            raise AssertionError('%s: vertex %d is not manifold (its %d triangles form more than one fan)'
                                 % (name, v, len(ring)))
    ne = len(directed) // 2
    chi = nv - ne + nt
    if chi % 2:
        raise AssertionError('%s: odd Euler characteristic %d' % (name, chi))
    return ne, (2 - chi) // 2


def grid_points(mesh):
    """The written coordinates as exact integers on the 1 nm grid."""
    scale = 10 ** DECIMALS
    out = []
    for t in mesh.text:
        q = tuple(Fraction(c) * scale for c in t)
        assert all(c.denominator == 1 for c in q)
        out.append(tuple(int(c) for c in q))
    return out


def self_intersections(mesh, limit=5):
    """Pairs of triangles that share no vertex yet touch or cross (exact integer arithmetic on
    the written grid; a sweep on x prunes the pairs)."""
    pts, tris = grid_points(mesh), mesh.tris
    boxes = []
    for t, tri in enumerate(tris):
        ps = [pts[i] for i in tri]
        boxes.append((min(p[0] for p in ps), max(p[0] for p in ps),
                      min(p[1] for p in ps), max(p[1] for p in ps),
                      min(p[2] for p in ps), max(p[2] for p in ps), t))
    boxes.sort()
    found = []
    active = []
    for b in boxes:
        active = [a for a in active if a[1] >= b[0]]
        for a in active:
            if a[3] < b[2] or b[3] < a[2] or a[5] < b[4] or b[5] < a[4]:
                continue
            ta, tb = tris[a[6]], tris[b[6]]
            if set(ta) & set(tb):
                continue
            if triangles_touch([pts[i] for i in ta], [pts[i] for i in tb]):
                found.append((a[6], b[6]))
                if len(found) >= limit:
                    return found
        active.append(b)
    return found


def segment_touches_triangle(p, q, a, b, c):
    """Exact for integer points: does segment pq meet triangle abc (boundaries included)?"""
    s1, s2 = orient3d(a, b, c, p), orient3d(a, b, c, q)
    if (s1 > 0 and s2 > 0) or (s1 < 0 and s2 < 0):
        return False
    if s1 == 0 and s2 == 0:
        return coplanar_segment_touches(p, q, a, b, c)
    u, v, w = orient3d(p, q, a, b), orient3d(p, q, b, c), orient3d(p, q, c, a)
    return (u >= 0 and v >= 0 and w >= 0) or (u <= 0 and v <= 0 and w <= 0)


def coplanar_segment_touches(p, q, a, b, c):
    n = cross(sub(b, a), sub(c, a))
    drop = max(range(3), key=lambda k: abs(n[k]))
    keep = [k for k in range(3) if k != drop]
    P, Q, A, B, C = ([x[keep[0]], x[keep[1]]] for x in (p, q, a, b, c))
    tri = (A, B, C) if cross2(A, B, C) > 0 else (A, C, B)

    def inside(X):
        return all(cross2(tri[i], tri[(i + 1) % 3], X) >= 0 for i in range(3))

    def seg_meet(p1, p2, p3, p4):
        d1, d2 = cross2(p3, p4, p1), cross2(p3, p4, p2)
        d3, d4 = cross2(p1, p2, p3), cross2(p1, p2, p4)
        if ((d1 > 0 and d2 < 0) or (d1 < 0 and d2 > 0)) and ((d3 > 0 and d4 < 0) or (d3 < 0 and d4 > 0)):
            return True

        def on(x, y, z):     # z on segment xy, given collinear
            return min(x[0], y[0]) <= z[0] <= max(x[0], y[0]) and min(x[1], y[1]) <= z[1] <= max(x[1], y[1])
        return ((d1 == 0 and on(p3, p4, p1)) or (d2 == 0 and on(p3, p4, p2)) or
                (d3 == 0 and on(p1, p2, p3)) or (d4 == 0 and on(p1, p2, p4)))
    if inside(P) or inside(Q):
        return True
    return any(seg_meet(P, Q, tri[i], tri[(i + 1) % 3]) for i in range(3))


def triangles_touch(t1, t2):
    for x, y in ((t1, t2), (t2, t1)):
        for i in range(3):
            if segment_touches_triangle(x[i], x[(i + 1) % 3], *y):
                return True
    return False


def triangles_cross(t1, t2):
    """Floating-point version for placed (transformed) meshes: proper crossings only."""
    for x, y in ((t1, t2), (t2, t1)):
        for i in range(3):
            p, q = x[i], x[(i + 1) % 3]
            s1, s2 = orient3d(*y, p), orient3d(*y, q)
            if (s1 > 0 and s2 > 0) or (s1 < 0 and s2 < 0) or (s1 == 0 and s2 == 0):
                continue
            u, v, w = orient3d(p, q, y[0], y[1]), orient3d(p, q, y[1], y[2]), orient3d(p, q, y[2], y[0])
            if (u > 0 and v > 0 and w > 0) or (u < 0 and v < 0 and w < 0):
                return True
    return False


def exact_figures(mesh):
    """Exact volume, centroid, area (see the module docstring), bounds, degenerate count."""
    P = [tuple(Fraction(c) for c in t) for t in mesh.text]
    vol6 = Fraction(0)
    mom = [Fraction(0)] * 3
    degenerate = 0
    min_area2 = None
    with localcontext() as ctx:
        ctx.prec = 50
        area2 = Decimal(0)
        for a, b, c in mesh.tris:
            pa, pb, pc = P[a], P[b], P[c]
            n = cross(sub(pb, pa), sub(pc, pa))
            nn = dot(n, n)
            if nn == 0:
                degenerate += 1
            else:
                s = (Decimal(nn.numerator) / Decimal(nn.denominator)).sqrt()
                area2 += s
                if min_area2 is None or s < min_area2:
                    min_area2 = s
            v = dot(pa, cross(pb, pc))        # 6 x signed volume of tetrahedron (0, a, b, c)
            vol6 += v
            for k in range(3):
                mom[k] += v * (pa[k] + pb[k] + pc[k])
        area = float(area2 / 2)
        min_area = float(min_area2 / 2) if min_area2 is not None else 0.0
    volume = vol6 / 6
    centroid = [float(mom[k] / (4 * vol6)) for k in range(3)] if vol6 != 0 else None
    pts = mesh.points
    bounds = [[min(p[k] for p in pts) for k in range(3)], [max(p[k] for p in pts) for k in range(3)]]
    return {'area': area, 'volume': float(volume), 'centroid': centroid, 'bounds': bounds,
            'degenerate': degenerate, 'min_triangle_area': min_area}


def float_figures(mesh):
    """Area and volume in floating point (fast; used for the convergence table)."""
    pts = mesh.points
    areas, vols = [], []
    for a, b, c in mesh.tris:
        pa, pb, pc = pts[a], pts[b], pts[c]
        n = cross(sub(pb, pa), sub(pc, pa))
        areas.append(math.sqrt(dot(n, n)) / 2)
        vols.append(dot(pa, cross(pb, pc)) / 6)
    return math.fsum(areas), math.fsum(vols)


def check(mesh, genus_expected):
    edges, genus = topology(mesh)
    if genus != genus_expected:
        raise AssertionError('%s: genus %d, expected %d' % (mesh.name, genus, genus_expected))
    fig = exact_figures(mesh)
    if fig['degenerate']:
        raise AssertionError('%s: %d zero-area triangles' % (mesh.name, fig['degenerate']))
    if not fig['volume'] > 0:
        raise AssertionError('%s: volume %r is not positive: faces point inwards' % (mesh.name, fig['volume']))
    hits = self_intersections(mesh)
    if hits:
        raise AssertionError('%s: triangles touch or cross: %s' % (mesh.name, hits))
    fig['edges'] = edges
    fig['genus'] = genus
    return fig


# --------------------------------------------------------------------------------------------
# VRML writing
# --------------------------------------------------------------------------------------------
def vrml_shape(mesh, color, crease, indent=''):
    i = indent
    lines = [
        '%sDEF %s Shape {' % (i, mesh.name),
        '%s  appearance Appearance {' % i,
        '%s    material Material {' % i,
        '%s      diffuseColor %s %s %s' % ((i,) + tuple(fmt(c) for c in color)),
        '%s      specularColor 0.3 0.3 0.3' % i,
        '%s      shininess 0.3' % i,
        '%s    }' % i,
        '%s  }' % i,
        '%s  geometry IndexedFaceSet {' % i,
        '%s    solid TRUE' % i,
        '%s    ccw TRUE' % i,
        '%s    convex TRUE' % i,
        '%s    creaseAngle %s' % (i, fmt(crease)),
        '%s    coord Coordinate {' % i,
        '%s      point [' % i,
    ]
    n = len(mesh.text)
    for k, t in enumerate(mesh.text):
        lines.append('%s        %s %s %s%s' % (i, t[0], t[1], t[2], ',' if k < n - 1 else ''))
    lines += ['%s      ]' % i, '%s    }' % i, '%s    coordIndex [' % i]
    for a, b, c in mesh.tris:
        lines.append('%s      %d, %d, %d, -1,' % (i, a, b, c))
    lines[-1] = lines[-1].rstrip(',')
    lines += ['%s    ]' % i, '%s  }' % i, '%s}' % i]
    return lines


def vrml_file(mesh, comments, color, crease):
    lines = ['#VRML V2.0 utf8',
             '# Generated by vrml/tools/generate_models.py - do not edit; regenerate instead.']
    lines += ['# ' + c if c else '#' for c in comments]
    lines.append('# %d triangles, %d vertices, metres.' % (len(mesh.tris), len(mesh.points)))
    lines.append('')
    lines += vrml_shape(mesh, color, crease)
    return '\n'.join(lines) + '\n'


def num(x):
    """A number in VRML text: shortest repr that round-trips, never exponent notation."""
    r = repr(float(x))
    if 'e' in r or 'E' in r:
        r = ('%.17f' % x).rstrip('0').rstrip('.')
    if r in ('-0.0', '-0'):
        r = '0'
    if r.endswith('.0'):
        r = r[:-2]
    return r


def hand_world():
    """hand.wrl: the palm and the nine links at the zero pose, as the nested DH chain.

    Each joint is 'DEF Fk_Jj Transform { rotation 0 0 1 theta }' holding
    'Transform { translation a 0 0 rotation 1 0 0 alpha }' = Rz(theta) Tx(a) Rx(alpha)
    (standard DH, d = 0); the link file is Inlined in the frame {kj} it belongs to."""
    L = ['#VRML V2.0 utf8',
         '# Generated by vrml/tools/generate_models.py - do not edit; regenerate instead.',
         '# The BarrettHand at the zero pose (all joint angles 0), for viewing only. The simulator',
         '# does not read this file: it loads palm.wrl and finger_link{1,2,3}.wrl and places the',
         '# links itself from forward kinematics.',
         '# Frames: palm frame {P} at the root. Finger k: base {k0} = Trans(r*Aw, 0, Dw) Rz(-(pi/2)*j)',
         '# with Aw = 0.025, Dw = 0.084, r = (-1, 1, 0), j = (1, 1, -1); then per joint the standard',
         '# DH step Rz(theta) Tz(d) Tx(a) Rx(alpha) as two nested Transforms. The rotation of each',
         '# DEF Fk_Jj Transform is theta_kj (+ Phi2 = 2.46 deg, Phi3 = 50 deg for joints 2 and 3):',
         '# edit it to pose the hand in a viewer. Spread: theta_11 = -s, theta_21 = +s, theta_31 = 0.',
         '',
         'DEF PALM_INLINE Inline { url "palm.wrl" }',
         '']
    dh = ((A1, math.pi / 2, 0.0), (A2, 0.0, PHI2), (A3, 0.0, PHI3))
    for k in range(3):
        r, j = FINGER_R[k], FINGER_J[k]
        ind = ''
        L.append('DEF F%d_BASE Transform {' % (k + 1))
        L.append('  translation %s 0 %s' % (num(r * AW), num(DW)))
        L.append('  rotation 0 0 1 %s' % num(-math.pi / 2 * j))
        L.append('  children [')
        ind = '    '
        closers = []
        for jj, (a, alpha, offset) in enumerate(dh):
            L.append('%sDEF F%d_J%d Transform {' % (ind, k + 1, jj + 1))
            L.append('%s  rotation 0 0 1 %s' % (ind, num(offset)))
            L.append('%s  children [' % ind)
            L.append('%s    Transform {' % ind)
            L.append('%s      translation %s 0 0' % (ind, num(a)))
            if alpha:
                L.append('%s      rotation 1 0 0 %s' % (ind, num(alpha)))
            L.append('%s      children [' % ind)
            link = 'LINK%d_INLINE' % (jj + 1)
            if k == 0:
                L.append('%s        DEF %s Inline { url "finger_link%d.wrl" }' % (ind, link, jj + 1))
            else:
                L.append('%s        USE %s' % (ind, link))
            closers.append(ind)
            ind += '        '
        for ind in reversed(closers):
            L.append('%s      ]' % ind)
            L.append('%s    }' % ind)
            L.append('%s  ]' % ind)
            L.append('%s}' % ind)
        L.append('  ]')
        L.append('}')
    return '\n'.join(L) + '\n'


# --------------------------------------------------------------------------------------------
# Forward kinematics (only to place the links for the hand.wrl figures and the overlap check)
# --------------------------------------------------------------------------------------------
def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def rot_z(t):
    c, s = math.cos(t), math.sin(t)
    return [[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]


def rot_x(t):
    c, s = math.cos(t), math.sin(t)
    return [[1, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1]]


def trans(x, y, z):
    return [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]]


def link_poses(k, theta=(0.0, 0.0, 0.0)):
    """Poses P <- {k1}, {k2}, {k3} of finger k (0-based) for joint angles theta (radians)."""
    T = mat_mul(trans(FINGER_R[k] * AW, 0, DW), rot_z(-math.pi / 2 * FINGER_J[k]))
    out = []
    for (a, alpha, off), th in zip(((A1, math.pi / 2, 0.0), (A2, 0.0, PHI2), (A3, 0.0, PHI3)), theta):
        T = mat_mul(T, mat_mul(rot_z(th + off), mat_mul(trans(a, 0, 0), rot_x(alpha))))
        out.append(T)
    return out


def transformed(mesh, T, name):
    m = Mesh(name)
    for p in mesh.points:
        m.points.append(tuple(T[i][0] * p[0] + T[i][1] * p[1] + T[i][2] * p[2] + T[i][3] for i in range(3)))
    m.tris = list(mesh.tris)
    return m


def meshes_cross(m1, m2):
    """True if any triangle of m1 crosses any triangle of m2 (floating point, brute force with boxes)."""
    def boxes(m):
        out = []
        for tri in m.tris:
            ps = [m.points[i] for i in tri]
            out.append(([min(p[k] for p in ps) for k in range(3)], [max(p[k] for p in ps) for k in range(3)], ps))
        return out
    b1, b2 = boxes(m1), boxes(m2)
    for lo1, hi1, t1 in b1:
        for lo2, hi2, t2 in b2:
            if all(lo1[k] <= hi2[k] and lo2[k] <= hi1[k] for k in range(3)) and triangles_cross(t1, t2):
                return True
    return False


# --------------------------------------------------------------------------------------------
# The model set
# --------------------------------------------------------------------------------------------
def build_objects(divisions, cube_divisions):
    n = divisions
    if n < 8 or n % 2:
        raise SystemExit('--divisions must be an even number >= 8')
    if cube_divisions < 1:
        raise SystemExit('--cube-divisions must be >= 1')
    bands = n // 2
    minor = n // 2
    objs = []

    cube = box_grid('CUBE', CUBE_EDGE, cube_divisions)
    objs.append(('objects/cube.wrl', cube, 0, (0.85, 0.25, 0.2), 0.0,
                 ['The paper\'s cube: edge 0.060 m, axis-aligned, centred at the origin.',
                  'Each face split into %d x %d squares (2 triangles each).' % (cube_divisions, cube_divisions)],
                 {'cube_divisions': cube_divisions},
                 {'shape': 'cube', 'edge_m': CUBE_EDGE,
                  'area_m2': 6 * CUBE_EDGE ** 2, 'volume_m3': CUBE_EDGE ** 3}))

    sph = sphere_mesh('SPHERE', SPHERE_R, n, bands)
    objs.append(('objects/sphere.wrl', sph, 0, (0.2, 0.45, 0.85), 1.0,
                 ['Sphere, radius 0.040 m, centred at the origin. UV sphere: %d longitudes,' % n,
                  '%d latitude bands, poles on the z axis, vertices on the true sphere.' % bands],
                 {'segments': n, 'bands': bands},
                 {'shape': 'sphere', 'radius_m': SPHERE_R,
                  'area_m2': 4 * math.pi * SPHERE_R ** 2, 'volume_m3': 4 / 3 * math.pi * SPHERE_R ** 3}))

    cyl = revolve('CYLINDER', [(0.0, -CYL_H / 2), (CYL_R, -CYL_H / 2), (CYL_R, CYL_H / 2), (0.0, CYL_H / 2)], n)[0]
    objs.append(('objects/cylinder.wrl', cyl, 0, (0.25, 0.7, 0.3), 0.5,
                 ['Cylinder, radius 0.030 m, height 0.120 m, axis z, centred at the origin.',
                  '%d segments; each cap a fan round its centre vertex.' % n],
                 {'segments': n},
                 {'shape': 'cylinder', 'radius_m': CYL_R, 'height_m': CYL_H,
                  'area_m2': 2 * math.pi * CYL_R ** 2 + 2 * math.pi * CYL_R * CYL_H,
                  'volume_m3': math.pi * CYL_R ** 2 * CYL_H}))

    cone = revolve('CONE', [(0.0, -CONE_H / 2), (CONE_R, -CONE_H / 2), (0.0, CONE_H / 2)], n)[0]
    objs.append(('objects/cone.wrl', cone, 0, (0.9, 0.65, 0.15), 0.5,
                 ['Cone, base radius 0.035 m, height 0.090 m, axis z: base at z = -0.045,',
                  'apex at z = +0.045 (bounding box centred, as a VRML Cone). %d segments.' % n],
                 {'segments': n},
                 {'shape': 'cone', 'radius_m': CONE_R, 'height_m': CONE_H,
                  'area_m2': math.pi * CONE_R ** 2 + math.pi * CONE_R * math.hypot(CONE_R, CONE_H),
                  'volume_m3': math.pi * CONE_R ** 2 * CONE_H / 3}))

    lb = lblock_mesh('LBLOCK')
    la = LBLOCK_OUTER * LBLOCK_ARM + LBLOCK_ARM * (LBLOCK_OUTER - LBLOCK_ARM)
    objs.append(('objects/lblock.wrl', lb, 0, (0.6, 0.35, 0.75), 0.0,
                 ['Concave L-block: the L = [-0.04,0.04]x[-0.04,0] U [-0.04,0]x[0,0.04] (arms 0.040 m',
                  'wide) extruded 0.040 m along z, z in [-0.02, 0.02]; bounding box centred at the origin.'],
                 {},
                 {'shape': 'lblock', 'outer_m': LBLOCK_OUTER, 'arm_m': LBLOCK_ARM, 'thickness_m': LBLOCK_THICK,
                  'area_m2': 2 * la + 4 * LBLOCK_OUTER * LBLOCK_THICK,
                  'volume_m3': la * LBLOCK_THICK}))

    ring = torus_mesh('RING', RING_MAJOR, RING_MINOR, n, minor)
    objs.append(('objects/ring.wrl', ring, 1, (0.8, 0.75, 0.3), 1.0,
                 ['Ring (torus): major radius 0.045 m, minor radius 0.012 m, axis z, centred at the',
                  'origin. %d segments round the axis, %d round the tube.' % (n, minor)],
                 {'segments': n, 'minor_segments': minor},
                 {'shape': 'torus', 'major_radius_m': RING_MAJOR, 'minor_radius_m': RING_MINOR,
                  'area_m2': 4 * math.pi ** 2 * RING_MAJOR * RING_MINOR,
                  'volume_m3': 2 * math.pi ** 2 * RING_MAJOR * RING_MINOR ** 2}))

    mug, info = mug_mesh('MUG', n)
    objs.append(('objects/mug.wrl', mug, 1, (0.95, 0.95, 0.9), 0.6,
                 ['Mug: open cup, outer radius 0.040 m, height 0.100 m (z from -0.05 to +0.05, axis z),',
                  'wall 0.004 m, bottom 0.006 m; D-shaped handle on the +x side (section 0.012 m x',
                  '%.4f m, reaching x = %.3f m) welded into the wall: one closed genus-1 surface.'
                  % (info['handle_width_m'], MUG_R_OUT + MUG_HANDLE_OUT + MUG_HANDLE_Z + MUG_HANDLE_T / 2),
                  '%d segments round the axis.' % n],
                 dict({'segments': n}, **info), None))
    return objs


def build_hand(seg):
    l1, l2, l3 = link_meshes(seg)
    palm = palm_mesh('PALM', seg)
    grey = (0.55, 0.57, 0.6)
    hand = [
        ('hand/palm.wrl', palm, 0, (0.25, 0.25, 0.28), 0.5,
         ['BarrettHand palm in the palm frame {P}: rounded block |x| <= 0.045, |y| <= 0.065',
          '(corner radius 0.022), bottom z = 0, top z = 0.054 = Dw - 0.030, 3 mm top chamfer.',
          'Finger base frames {k0} at (r*Aw, 0, Dw) = (-0.025, 0, 0.084), (0.025, 0, 0.084),',
          '(0, 0, 0.084); fingers 1, 2 extend along -y, finger 3 along +y at the zero pose.'],
         {'segments_per_circle': seg}, None),
        ('hand/finger_link1.wrl', l1, 0, grey, 0.5,
         ['Finger link 1 (knuckle) in its DH frame {k1}: x from the spread axis (x = -A1 = -0.050)',
          'to the joint-2 axis (the z axis); y = palm normal. Side profile extruded in z: underside',
          'y = %s, arm top y = %s, knuckle rounded with radius %s about the z axis;'
          % (fmt(L1_BOTTOM), fmt(L1_PLATE_TOP), fmt(L1_KNUCKLE_R)),
          'x in [%s, %s]; half-width %s at the back end growing linearly to %s at the front.'
          % (fmt(-A1 - L1_BACK), fmt(L1_KNUCKLE_R), fmt(L1_HALF_W_BACK), fmt(L1_HALF_W_FRONT))],
         {'segments_per_circle': seg}, None),
        ('hand/finger_link2.wrl', l2, 0, grey, 0.5,
         ['Finger link 2 (inner link) in its DH frame {k2}: joint-2 axis at (-A2, 0) = (-0.070, 0),',
          'joint-3 axis = the z axis. Side profile = hull of circles r 0.011 at x = -0.070 and',
          'r 0.009 at x = 0, extruded z in [-0.0125, 0.0125]. Grasping side = +y.'],
         {'segments_per_circle': seg}, None),
        ('hand/finger_link3.wrl', l3, 0, grey, 0.5,
         ['Finger link 3 (outer link) in its DH frame {k3}: joint-3 axis at (-A3, 0) = (-0.056, 0),',
          'fingertip = the origin (the extreme point of the rounded tip). Side profile = hull of',
          'circles r 0.0095 at x = -0.056 and r 0.0055 at x = -0.0055; half-width 0.0115 at',
          'x = -0.0655 tapering to 0.0075 at x = 0. Grasping side = +y.'],
         {'segments_per_circle': seg}, None),
    ]
    return hand


def describe(entry, fig):
    path, mesh, genus, color, crease, comments, resolution, analytic = entry
    d = {'triangles': len(mesh.tris), 'vertices': len(mesh.points), 'shapes': 1, 'def': mesh.name,
         'closed': True, 'genus': genus, 'degenerate': 0,
         'area_m2': fig['area'], 'volume_m3': fig['volume'],
         'centroid_m': fig['centroid'], 'bounds': fig['bounds'],
         'min_triangle_area_m2': fig['min_triangle_area']}
    if resolution:
        d['resolution'] = resolution
    if analytic:
        d['analytic'] = analytic
        d['area_rel_error'] = fig['area'] / analytic['area_m2'] - 1
        d['volume_rel_error'] = fig['volume'] / analytic['volume_m3'] - 1
    return d


def hand_figures(hand_entries, figs):
    """Figures for hand.wrl (floating point: the parts are placed by the FK chain)."""
    parts = {e[0]: e[1] for e in hand_entries}
    placed = [transformed(parts['hand/palm.wrl'], trans(0, 0, 0), 'PALM')]
    for k in range(3):
        for j, T in enumerate(link_poses(k)):
            placed.append(transformed(parts['hand/finger_link%d.wrl' % (j + 1)], T, 'F%d_L%d' % (k + 1, j + 1)))
    lo = [min(min(p[i] for p in m.points) for m in placed) for i in range(3)]
    hi = [max(max(p[i] for p in m.points) for m in placed) for i in range(3)]
    # the palm must not touch any link, and fingers must not touch each other, at the zero pose
    for m in placed[1:]:
        if meshes_cross(placed[0], m):
            raise AssertionError('hand.wrl: %s crosses the palm at the zero pose' % m.name)
    for a in range(1, 10):
        for b in range(a + 1, 10):
            if (a - 1) // 3 != (b - 1) // 3 and meshes_cross(placed[a], placed[b]):
                raise AssertionError('hand.wrl: %s crosses %s at the zero pose' % (placed[a].name, placed[b].name))
    # the knuckles of fingers 1 and 2 swing about their spread axes (0 ... 180 degrees) past the
    # fixed knuckle of finger 3: they must never touch it
    link1 = parts['hand/finger_link1.wrl']
    f3 = transformed(link1, link_poses(2)[0], 'F3_L1')
    for deg in range(0, 181, 5):
        for k, sign in ((0, -1), (1, 1)):
            m = transformed(link1, link_poses(k, (sign * math.radians(deg), 0.0, 0.0))[0], 'F%d_L1' % (k + 1))
            if meshes_cross(f3, m):
                raise AssertionError('hand: link 1 of finger %d crosses link 1 of finger 3 at spread %d deg'
                                     % (k + 1, deg))
    tips = [link_poses(k)[2] for k in range(3)]
    return {'shapes': 10, 'inlines': ['palm.wrl'] + ['finger_link%d.wrl' % (j + 1) for j in range(3)] * 3,
            'triangles': sum(len(m.tris) for m in placed), 'vertices': sum(len(m.points) for m in placed),
            'area_m2_sum': math.fsum(figs['hand/palm.wrl']['area'] if m.name == 'PALM'
                                     else figs['hand/finger_link%s.wrl' % m.name[-1]]['area'] for m in placed),
            'bounds': [lo, hi], 'bounds_note': 'floating-point forward kinematics; compare within 1e-9 m',
            'fingertips_m': [[T[i][3] for i in range(3)] for T in tips],
            'pose': 'zero pose: all joint angles 0 (link 2 at Phi2 = 2.46 deg, link 3 at Phi3 = 50 deg)'}


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w', encoding='utf-8', newline='\n') as f:
        f.write(text)


def polygon_closed_forms(n):
    """Area and volume of the N-segment cylinder and cone meshes by hand (inscribed regular
    N-gons), to cross-check exact_figures: (cyl_area, cyl_volume, cone_area, cone_volume)."""
    cap = n / 2 * math.sin(2 * math.pi / n)          # area of the inscribed N-gon / r^2
    cyl_a = 2 * cap * CYL_R ** 2 + n * 2 * CYL_R * math.sin(math.pi / n) * CYL_H
    cyl_v = cap * CYL_R ** 2 * CYL_H
    slant = math.hypot(CONE_H, CONE_R * math.cos(math.pi / n))
    cone_a = cap * CONE_R ** 2 + n * CONE_R * math.sin(math.pi / n) * slant
    cone_v = cap * CONE_R ** 2 * CONE_H / 3
    return cyl_a, cyl_v, cone_a, cone_v


def self_test(figs, float_figs, divisions):
    """The exact figures against hand-computed ones (coordinates are rounded to 1 nm, so they
    agree to about 1e-8 relative)."""
    cyl_a, cyl_v, cone_a, cone_v = polygon_closed_forms(divisions)
    for key, got, want in (('cylinder area', figs['objects/cylinder.wrl']['area'], cyl_a),
                           ('cylinder volume', figs['objects/cylinder.wrl']['volume'], cyl_v),
                           ('cone area', figs['objects/cone.wrl']['area'], cone_a),
                           ('cone volume', figs['objects/cone.wrl']['volume'], cone_v),
                           ('cube volume', figs['objects/cube.wrl']['volume'], CUBE_EDGE ** 3),
                           ('L-block area', figs['objects/lblock.wrl']['area'], 0.0224),
                           ('L-block volume', figs['objects/lblock.wrl']['volume'], 0.000192)):
        if abs(got / want - 1) > 1e-7:
            raise AssertionError('self-test: %s %r, by hand %r' % (key, got, want))
    for path, f in figs.items():
        a, v = float_figs[path]
        if abs(a / f['area'] - 1) > 1e-12 or abs(v / f['volume'] - 1) > 1e-12:
            raise AssertionError('self-test: %s exact and floating-point figures disagree' % path)


def generate(out, divisions, cube_divisions, hand_segments, quiet=False):
    hand = build_hand(hand_segments)
    objs = build_objects(divisions, cube_divisions)
    entries = hand + objs
    figs, float_figs = {}, {}
    for e in entries:
        figs[e[0]] = check(e[1], e[2])
        float_figs[e[0]] = float_figures(e[1])
    self_test(figs, float_figs, divisions)
    hf = hand_figures(hand, figs)
    files = {}
    for e in entries:
        files[e[0]] = describe(e, figs[e[0]])
    files['hand/hand.wrl'] = hf
    models = {
        'generator': 'vrml/tools/generate_models.py',
        'command': 'python3 vrml/tools/generate_models.py --divisions %d --cube-divisions %d --hand-segments %d'
                   % (divisions, cube_divisions, hand_segments),
        'units': 'm',
        'coordinate_decimals': DECIMALS,
        'figures': 'area_m2, volume_m3, centroid_m: exact for the coordinates as written, rounded once to double; '
                   'volume by the divergence theorem; analytic: the ideal shape the mesh approximates',
        'divisions': divisions, 'cube_divisions': cube_divisions, 'hand_segments': hand_segments,
        'files': files,
    }
    for e in entries:
        path, mesh, genus, color, crease, comments, resolution, analytic = e
        write(os.path.join(out, path), vrml_file(mesh, comments, color, crease))
    write(os.path.join(out, 'hand/hand.wrl'), hand_world())
    write(os.path.join(out, 'models.json'), json.dumps(models, indent=2) + '\n')
    if not quiet:
        print('%-26s %9s %8s %22s %22s' % ('file', 'triangles', 'vertices', 'area_m2', 'volume_m3'))
        for path, d in files.items():
            print('%-26s %9d %8d %22s %22s' % (path, d['triangles'], d['vertices'],
                                               repr(d.get('area_m2', d.get('area_m2_sum'))),
                                               repr(d['volume_m3']) if 'volume_m3' in d else '-'))
        print('wrote %s' % os.path.join(out, 'models.json'))
    return models


def big_sphere(out, triangles):
    # a UV sphere with n longitudes and n/2 bands has n (n - 2) triangles
    best = None
    for n in range(8, 4 * int(math.sqrt(max(triangles, 64))) + 16, 2):
        t = n * (n - 2)
        if best is None or abs(t - triangles) < abs(best[1] - triangles):
            best = (n, t)
    n = best[0]
    m = sphere_mesh('SPHERE_BIG', SPHERE_R, n, n // 2)
    edges, genus = topology(m)
    area, volume = float_figures(m)
    path = os.path.join(out, 'objects/sphere_big.wrl')
    write(path, vrml_file(m, ['Big UV sphere for GUI speed tests (not committed): radius 0.040 m,',
                              '%d longitudes, %d latitude bands.' % (n, n // 2)], (0.2, 0.45, 0.85), 1.0))
    print(json.dumps({'file': path, 'triangles': len(m.tris), 'vertices': len(m.points), 'segments': n,
                      'bands': n // 2, 'area_m2': area, 'volume_m3': volume, 'closed': True, 'genus': genus}))


def convergence(ns=(8, 16, 32, 64, 128, 256)):
    shapes = [
        ('sphere', lambda n: sphere_mesh('S', SPHERE_R, n, n // 2),
         4 * math.pi * SPHERE_R ** 2, 4 / 3 * math.pi * SPHERE_R ** 3),
        ('cylinder', lambda n: revolve('C', [(0.0, -CYL_H / 2), (CYL_R, -CYL_H / 2), (CYL_R, CYL_H / 2),
                                            (0.0, CYL_H / 2)], n)[0],
         2 * math.pi * CYL_R ** 2 + 2 * math.pi * CYL_R * CYL_H, math.pi * CYL_R ** 2 * CYL_H),
        ('cone', lambda n: revolve('K', [(0.0, -CONE_H / 2), (CONE_R, -CONE_H / 2), (0.0, CONE_H / 2)], n)[0],
         math.pi * CONE_R ** 2 + math.pi * CONE_R * math.hypot(CONE_R, CONE_H), math.pi * CONE_R ** 2 * CONE_H / 3),
        ('ring', lambda n: torus_mesh('R', RING_MAJOR, RING_MINOR, n, n // 2),
         4 * math.pi ** 2 * RING_MAJOR * RING_MINOR, 2 * math.pi ** 2 * RING_MAJOR * RING_MINOR ** 2),
    ]
    lines = ['| object | N | triangles | area rel. error | volume rel. error | error ratio to N/2 (area, volume) |',
             '|---|---:|---:|---:|---:|---|']
    for name, make, a_ref, v_ref in shapes:
        prev = None
        for n in ns:
            m = make(n)
            topology(m)
            a, v = float_figures(m)
            ea, ev = a / a_ref - 1, v / v_ref - 1
            ratio = '%.2f, %.2f' % (prev[0] / ea, prev[1] / ev) if prev else ''
            lines.append('| %s | %d | %d | %.3e | %.3e | %s |' % (name, n, len(m.tris), ea, ev, ratio))
            prev = (ea, ev)
    return '\n'.join(lines)


def main(argv=None):
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))   # .../vrml
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--divisions', type=int, default=DEFAULT_DIVISIONS)
    ap.add_argument('--cube-divisions', type=int, default=DEFAULT_CUBE_DIVISIONS)
    ap.add_argument('--hand-segments', type=int, default=DEFAULT_HAND_SEGMENTS)
    ap.add_argument('--out', default=here)
    ap.add_argument('--big', type=int, metavar='N')
    ap.add_argument('--convergence', action='store_true')
    args = ap.parse_args(argv)
    try:
        if args.convergence:
            print(convergence())
        elif args.big:
            big_sphere(args.out, args.big)
        else:
            if args.hand_segments < 8:
                raise SystemExit('--hand-segments must be >= 8')
            generate(args.out, args.divisions, args.cube_divisions, args.hand_segments)
    except AssertionError as e:
        print('generate_models.py: check failed: %s' % e, file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
