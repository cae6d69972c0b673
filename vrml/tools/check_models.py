#!/usr/bin/env python3
"""Re-read the written .wrl files and check them against vrml/models.json (standard library only).

Independent of the generator's in-memory meshes: a small reader for the VRML97 subset the
generator writes (DEF/USE, Transform translation/rotation, Shape, IndexedFaceSet with
Coordinate and coordIndex, Inline) parses every file, then checks

  * the header line is exactly '#VRML V2.0 utf8';
  * every face has 3 indices ending in -1, every index is in range;
  * triangle and vertex counts, bounds (exact; hand.wrl within 1e-9 m), area and volume
    (floating point, within 1e-12 relative) match models.json;
  * every single-body file is closed (each directed edge once, its reverse once) with a
    positive volume.

Usage: python3 vrml/tools/check_models.py [DIR]   (DIR defaults to vrml/; exit code 1 on a mismatch)
"""

import json
import math
import os
import re
import sys

TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[{}\[\]]|[^\s{}\[\],"]+')
NUMBER = re.compile(r'^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$')


def tokens(text):
    out = []
    for line in text.split('\n'):
        # drop comments (no '#' inside our strings)
        if '#' in line:
            line = line[:line.index('#')]
        out.extend(TOKEN.findall(line))
    return out


class Node:
    def __init__(self, kind):
        self.kind = kind
        self.fields = {}


class Parser:
    def __init__(self, toks):
        self.t = toks
        self.i = 0
        self.defs = {}

    def peek(self, k=0):
        return self.t[self.i + k] if self.i + k < len(self.t) else None

    def take(self, want=None):
        tok = self.t[self.i]
        if want is not None and tok != want:
            raise ValueError('expected %r, got %r at token %d' % (want, tok, self.i))
        self.i += 1
        return tok

    def scene(self):
        nodes = []
        while self.peek() is not None:
            nodes.append(self.node())
        return nodes

    def node(self):
        tok = self.take()
        if tok == 'USE':
            return self.defs[self.take()]
        name = None
        if tok == 'DEF':
            name = self.take()
            tok = self.take()
        n = Node(tok)
        if name:
            self.defs[name] = n
        self.take('{')
        while self.peek() != '}':
            field = self.take()
            n.fields[field] = self.value()
        self.take('}')
        return n

    def is_node_start(self):
        tok = self.peek()
        return tok in ('DEF', 'USE') or (self.peek(1) == '{' and not NUMBER.match(tok))

    def value(self):
        if self.peek() == '[':
            self.take()
            items = []
            while self.peek() != ']':
                items.append(self.node() if self.is_node_start() else self.scalar())
            self.take()
            return items
        if self.is_node_start():
            return self.node()
        vals = [self.scalar()]
        while self.peek() is not None and (NUMBER.match(self.peek()) or self.peek() in ('TRUE', 'FALSE')):
            vals.append(self.scalar())
        return vals

    def scalar(self):
        tok = self.take()
        if tok.startswith('"'):
            return tok[1:-1]
        if NUMBER.match(tok):
            return float(tok) if any(c in tok for c in '.eE') else int(tok)
        if tok in ('TRUE', 'FALSE'):
            return tok == 'TRUE'
        raise ValueError('unexpected token %r' % tok)


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def transform_matrix(node):
    t = node.fields.get('translation', [0, 0, 0])
    r = node.fields.get('rotation', [0, 0, 1, 0])
    x, y, z, a = (float(v) for v in r)
    n = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    c, s, C = math.cos(a), math.sin(a), 1 - math.cos(a)
    R = [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
         [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
         [z * x * C - y * s, z * y * C + x * s, c + z * z * C]]
    return [R[0] + [float(t[0])], R[1] + [float(t[1])], R[2] + [float(t[2])], [0, 0, 0, 1]]


IDENTITY = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]


def load(path):
    with open(path, encoding='utf-8') as f:
        text = f.read()
    if text.split('\n', 1)[0] != '#VRML V2.0 utf8':
        raise ValueError('%s: first line is not "#VRML V2.0 utf8"' % path)
    return Parser(tokens(text)).scene()


def shapes(path, M=IDENTITY, out=None):
    """[(points (transformed by M), triangles)] of every Shape reachable from the file."""
    out = [] if out is None else out
    stack = [(n, M) for n in reversed(load(path))]
    while stack:
        n, T = stack.pop()
        if n.kind == 'Transform':
            T2 = mat_mul(T, transform_matrix(n))
            stack.extend((c, T2) for c in reversed(n.fields.get('children', [])))
        elif n.kind in ('Group',):
            stack.extend((c, T) for c in reversed(n.fields.get('children', [])))
        elif n.kind == 'Inline':
            url = n.fields['url']
            url = url[0] if isinstance(url, list) else url
            shapes(os.path.join(os.path.dirname(path), url), T, out)
        elif n.kind == 'Shape':
            g = n.fields['geometry']
            if g.kind != 'IndexedFaceSet':
                raise ValueError('%s: unexpected geometry %s' % (path, g.kind))
            for flag in ('solid', 'ccw', 'convex'):
                if g.fields.get(flag) != [True]:
                    raise ValueError('%s: %s is not TRUE' % (path, flag))
            flat = g.fields['coord'].fields['point']
            pts = [tuple(T[i][0] * flat[k] + T[i][1] * flat[k + 1] + T[i][2] * flat[k + 2] + T[i][3]
                         for i in range(3)) for k in range(0, len(flat), 3)]
            idx = g.fields['coordIndex']
            if len(idx) % 4 or any(idx[k + 3] != -1 for k in range(0, len(idx), 4)):
                raise ValueError('%s: coordIndex is not triangles separated by -1' % path)
            tris = [tuple(idx[k:k + 3]) for k in range(0, len(idx), 4)]
            if any(not 0 <= v < len(pts) for t in tris for v in t):
                raise ValueError('%s: coordIndex out of range' % path)
            out.append((pts, tris))
    return out


def figures(parts):
    areas, vols = [], []
    for pts, tris in parts:
        for a, b, c in tris:
            pa, pb, pc = pts[a], pts[b], pts[c]
            u = [pb[k] - pa[k] for k in range(3)]
            v = [pc[k] - pa[k] for k in range(3)]
            n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
            areas.append(math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2) / 2)
            vols.append((pa[0] * (pb[1] * pc[2] - pb[2] * pc[1]) + pa[1] * (pb[2] * pc[0] - pb[0] * pc[2])
                         + pa[2] * (pb[0] * pc[1] - pb[1] * pc[0])) / 6)
    return math.fsum(areas), math.fsum(vols)


def closed(tris):
    edges = set()
    for a, b, c in tris:
        for e in ((a, b), (b, c), (c, a)):
            if e in edges:
                return False
            edges.add(e)
    return all((b, a) in edges for a, b in edges)


def main(argv):
    root = argv[1] if len(argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    with open(os.path.join(root, 'models.json'), encoding='utf-8') as f:
        models = json.load(f)
    bad = 0
    for rel, want in models['files'].items():
        parts = shapes(os.path.join(root, rel))
        tris = sum(len(t) for _, t in parts)
        verts = sum(len(p) for p, _ in parts)
        area, vol = figures(parts)
        lo = [min(p[k] for pts, _ in parts for p in pts) for k in range(3)]
        hi = [max(p[k] for pts, _ in parts for p in pts) for k in range(3)]
        problems = []
        if len(parts) != want['shapes']:
            problems.append('shapes %d != %d' % (len(parts), want['shapes']))
        if tris != want['triangles'] or verts != want['vertices']:
            problems.append('counts %d/%d != %d/%d' % (tris, verts, want['triangles'], want['vertices']))
        want_area = want.get('area_m2', want.get('area_m2_sum'))
        if abs(area / want_area - 1) > 1e-12:
            problems.append('area %r != %r' % (area, want_area))
        tol = 1e-9 if len(parts) > 1 else 0.0
        if any(abs(x - y) > tol for x, y in zip(lo + hi, want['bounds'][0] + want['bounds'][1])):
            problems.append('bounds %r != %r' % ([lo, hi], want['bounds']))
        if len(parts) == 1:
            if abs(vol / want['volume_m3'] - 1) > 1e-12:
                problems.append('volume %r != %r' % (vol, want['volume_m3']))
            if not closed(parts[0][1]) or not vol > 0:
                problems.append('not closed or not outward')
        print('%-26s %s' % (rel, 'ok' if not problems else '; '.join(problems)))
        bad += bool(problems)
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
