#!/usr/bin/env python3
"""Writes a scene description of N x N copies of one small glTF model (BoxTextured, 12 triangles,
Debian's assimp-testmodels), every other one overridden to transparent glass alike: the case
where per-object submission cost, not triangles or pixels, decides the frame (issue 23's
instanced draws). Usage: instanced_boxes.py OUT.json [N (default 100)] [MODEL]."""
import json
import os
import sys

out = sys.argv[1]
n = int(sys.argv[2]) if len(sys.argv) > 2 else 100
model = sys.argv[3] if len(sys.argv) > 3 else '/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb'
if not os.path.exists(model):
    sys.exit(f'instanced_boxes.py: {model} is absent (Debian package assimp-testmodels)')
# A short relative path keeps 10^4 objects under the description's 1 MiB limit.
os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
link = os.path.join(os.path.dirname(os.path.abspath(out)), 'box.glb')
if not os.path.exists(link):
    os.symlink(model, link)
objects = []
for i in range(n * n):
    x, z = i % n, i // n
    o = {'model': 'box.glb', 'translate': [round(x * 1.5 - n * 0.75, 2), 0, -z * 1.5], 'scale': 0.5}
    if (x + z) % 2 == 0:
        o['material'] = {'alpha': 0.4, 'alpha_mode': 'BLEND'}
    objects.append(o)
scene = {'camera': {'position': [0, 0.4 * n, 0.4 * n], 'target': [0, 0, -0.75 * n], 'fov_y_deg': 60},
         'objects': objects}
with open(out, 'w') as f:
    json.dump(scene, f, separators=(',', ':'))
