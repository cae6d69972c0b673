"""Convex pieces of a mesh with CoACD (MuJoCo collides each geom's convex hull), for
tools/mujoco-compare.   python decompose.py IN.obj THRESHOLD OUT_PREFIX
Writes OUT_PREFIX_00.obj, OUT_PREFIX_01.obj ... (one piece, the mesh itself, when it is convex)
and prints their names, comma-separated."""
import sys

import coacd
import numpy as np
import trimesh

src, threshold, prefix = sys.argv[1], float(sys.argv[2]), sys.argv[3]
mesh = trimesh.load(src, force='mesh', process=False)
# convex when no vertex lies in front of any face's plane (outward normals from the winding)
v, f = mesh.vertices, mesh.faces
n = mesh.face_normals
ahead = np.einsum('fk,vk->fv', n, v) - np.einsum('fk,fk->f', n, v[f[:, 0]])[:, None]
if ahead.max() <= 1e-9 * mesh.scale:
    parts = [(mesh.vertices, mesh.faces)]
else:
    coacd.set_log_level('error')
    parts = coacd.run_coacd(coacd.Mesh(mesh.vertices, mesh.faces), threshold=threshold, seed=1)
names = []
for i, (v, f) in enumerate(parts):
    name = f'{prefix}_{i:02d}.obj'
    trimesh.Trimesh(v, f).export(name)
    names.append(name)
print(','.join(names))
