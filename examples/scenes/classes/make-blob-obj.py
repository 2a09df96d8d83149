#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# Writes blob.obj, the mesh of the "mesh" scene class: an icosahedron subdivided twice (320
# triangles) and pushed out of round into a lumpy, bunny-like blob (a squashed body with a bump for
# a head), resting on y = 0, about 0.8 m long. Deterministic: rerunning it gives the same file.
#   examples/scenes/classes/make-blob-obj.py > examples/scenes/classes/blob.obj
import math

t = (1 + math.sqrt(5)) / 2
verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
         (6, 2, 10), (8, 6, 7), (9, 8, 1)]


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


verts = [unit(v) for v in verts]
for _ in range(2):  # each triangle into four, new vertices on the unit sphere
    midpoint = {}

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoint:
            verts.append(unit(tuple((p + q) / 2 for p, q in zip(verts[a], verts[b]))))
            midpoint[key] = len(verts) - 1
        return midpoint[key]

    faces = [f for a, b, c in faces
             for f in ((a, mid(a, b), mid(c, a)), (b, mid(b, c), mid(a, b)), (c, mid(c, a), mid(b, c)),
                       (mid(a, b), mid(b, c), mid(c, a)))]


def shape(p):
    x, y, z = p
    head = 0.45 * math.exp(-((x - 0.65) ** 2 + (y - 0.55) ** 2 + z * z) / 0.12)  # a bump up front
    lumps = 0.06 * math.sin(5 * x) * math.cos(4 * z)
    r = 1 + head + lumps
    return (0.4 * r * x, 0.28 * r * y, 0.3 * r * z)


shaped = [shape(v) for v in verts]
lowest = min(v[1] for v in shaped)
print("# A lumpy, bunny-like blob for the mesh scene class, written by make-blob-obj.py:")
print(f"# {len(shaped)} vertices, {len(faces)} triangles, faces wound outward, resting on y = 0.")
print("o blob")
for x, y, z in shaped:
    print(f"v {x:.6f} {y - lowest:.6f} {z:.6f}")
for a, b, c in faces:
    print(f"f {a + 1} {b + 1} {c + 1}")
