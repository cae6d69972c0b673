#!/usr/bin/env python3
"""FCL's distance query on the collision bench's pairs: the reference for HandSim's mesh distance.

Reads ../shared/bench-meshes (scenarios.csv and its VRML IndexedFaceSets), places mesh B by the
row's pose (translation, then axis-angle rotation vector, as HandSim's RigidTransform.fromPose),
and asks python-fcl (FCL's BVHModel with OBBRSS, fcl.distance with nearest points) for the
smallest distance between the two surfaces. The vertices are rounded to single precision first,
as HandSim's VRML loader (Java3D) keeps them, so both measure the same triangles. Writes a CSV that
src/test/java/org/handsim/collision/DistanceQueryTest.java compares with (to 1e-9 m):

  /work/mjc/venv/bin/python tools/fcl/distance_reference.py ../shared/bench-meshes \
      > src/test/resources/org/handsim/collision/fcl-distances.csv
"""
import csv
import math
import re
import sys

import fcl
import numpy as np


def read_wrl(path):
    text = open(path).read()
    pts = re.search(r"point\s*\[(.*?)\]", text, re.S).group(1)
    # HandSim's VRML loader keeps coordinates as Java3D floats (round to nearest): FCL gets the same
    verts = np.array([[float(x) for x in p.split()] for p in pts.split(",") if p.strip()]).astype(np.float32).astype(np.float64)
    idx = re.search(r"coordIndex\s*\[(.*?)\]", text, re.S).group(1).split()
    tris, face = [], []
    for t in idx:
        i = int(t)
        if i < 0:
            for k in range(1, len(face) - 1):
                tris.append([face[0], face[k], face[k + 1]])
            face = []
        else:
            face.append(i)
    return verts, np.array(tris, dtype=np.int64)


def rotation(rx, ry, rz):
    angle = math.sqrt(rx * rx + ry * ry + rz * rz)
    if angle < 1e-300:
        return np.eye(3)
    x, y, z = rx / angle, ry / angle, rz / angle
    c, s = math.cos(angle), math.sin(angle)
    v = 1 - c
    return np.array([[x * x * v + c, x * y * v - z * s, x * z * v + y * s],
                     [y * x * v + z * s, y * y * v + c, y * z * v - x * s],
                     [z * x * v - y * s, z * y * v + x * s, z * z * v + c]])


def model(verts, tris):
    m = fcl.BVHModel()
    m.beginModel(len(verts), len(tris))
    m.addSubModel(verts, tris)
    m.endModel()
    return m


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "../shared/bench-meshes"
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(["scenario", "mesh_a", "mesh_b", "pose_b", "fcl_distance_m", "fcl_point_a", "fcl_point_b"])
    with open(folder + "/scenarios.csv") as f:
        for row in csv.DictReader(f):
            va, ta = read_wrl(folder + "/" + row["mesh_a"])
            vb, tb = read_wrl(folder + "/" + row["mesh_b"])
            p = [float(x) for x in row["pose_b"].split(",")]
            tf = fcl.Transform(rotation(p[3], p[4], p[5]), np.array(p[:3]))
            a = fcl.CollisionObject(model(va, ta), fcl.Transform())
            b = fcl.CollisionObject(model(vb, tb), tf)
            req = fcl.DistanceRequest(enable_nearest_points=True)
            res = fcl.DistanceResult()
            d = fcl.distance(a, b, req, res)
            pa, pb = res.nearest_points
            out.writerow([row["scenario"], row["mesh_a"], row["mesh_b"], row["pose_b"], repr(float(d)),
                          " ".join(repr(float(x)) for x in pa), " ".join(repr(float(x)) for x in pb)])


if __name__ == "__main__":
    main()
