#!/usr/bin/python3
"""Writes eight_influences.gltf beside this script: the hand-made glTF of
tests/core/gltf_character_test.cpp (an 8-joint chain under a rotated, scaled armature, a strip
skinned with 8 influences, normalized texture coordinates, CUBICSPLINE / LINEAR / STEP samplers
and a scale channel). Standard library only."""

import base64
import json
import math
import struct
from pathlib import Path

def qmul(a, b):
    ax, ay, az, aw = a; bx, by, bz, bw = b
    return (aw*bx + ax*bw + ay*bz - az*by, aw*by - ax*bz + ay*bw + az*bx, aw*bz + ax*by - ay*bx + az*bw, aw*bw - ax*bx - ay*by - az*bz)
def axis_angle(axis, angle):
    n = math.sqrt(sum(c*c for c in axis)); s = math.sin(angle/2)
    return tuple(c/n*s for c in axis) + (math.cos(angle/2),)
def qmat(q):
    x, y, z, w = q
    return [[1-2*(y*y+z*z), 2*(x*y-z*w), 2*(x*z+y*w)], [2*(x*y+z*w), 1-2*(x*x+z*z), 2*(y*z-x*w)], [2*(x*z-y*w), 2*(y*z+x*w), 1-2*(x*x+y*y)]]
def trs(t=(0,0,0), r=(0,0,0,1), s=(1,1,1)):
    R = qmat(r)
    return [[R[i][0]*s[0], R[i][1]*s[1], R[i][2]*s[2], t[i]] for i in range(3)] + [[0,0,0,1]]
def mul(A, B): return [[sum(A[i][k]*B[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
def inv_affine(M):
    a = [[M[i][j] for j in range(3)] for i in range(3)]
    det = (a[0][0]*(a[1][1]*a[2][2]-a[1][2]*a[2][1]) - a[0][1]*(a[1][0]*a[2][2]-a[1][2]*a[2][0]) + a[0][2]*(a[1][0]*a[2][1]-a[1][1]*a[2][0]))
    inv = [[0]*3 for _ in range(3)]
    for i in range(3):
        for j in range(3):
            r = [k for k in range(3) if k != j]; c = [k for k in range(3) if k != i]
            minor = a[r[0]][c[0]]*a[r[1]][c[1]] - a[r[0]][c[1]]*a[r[1]][c[0]]
            inv[i][j] = (-1)**(i+j) * minor / det
    t = [-sum(inv[i][k]*M[k][3] for k in range(3)) for i in range(3)]
    return [inv[i] + [t[i]] for i in range(3)] + [[0,0,0,1]]

armature = dict(t=(0.1, 0, 0), r=axis_angle((0,1,0), math.pi/2), s=(2,2,2))
joints = []  # (name, translation, rotation)
for i in range(8):
    r = axis_angle((1, 0.3*i, 0.2), 0.1*(i+1))
    joints.append(("j%d" % i, (0, 0.5 if i else 1.0, 0.05*i), r))
world = [mul(trs(**armature), trs(joints[0][1], joints[0][2]))]
for i in range(1, 8):
    world.append(mul(world[-1], trs(joints[i][1], joints[i][2])))
ibm = [inv_affine(W) for W in world]

# A strip of 4 vertices along the chain (in the mesh node's space, which skinning ignores: bind space
# is the armature's world, so positions are world positions mapped back by the bind matrices).
positions = [(-0.2, 1.0, 0), (0.2, 1.0, 0), (-0.2, 4.0, 0.5), (0.2, 4.0, 0.5)]
indices = [0, 1, 2, 2, 1, 3]
joints0 = [(0, 1, 2, 3), (0, 0, 0, 0), (3, 2, 1, 0), (1, 2, 3, 4)]
weights0 = [(0.2, 0.2, 0.1, 0.1), (1, 0, 0, 0), (0.25, 0.25, 0.25, 0.25), (0.1, 0.1, 0.1, 0.1)]
joints1 = [(4, 5, 6, 7), (0, 0, 0, 0), (0, 0, 0, 0), (5, 6, 7, 0)]
weights1 = [(51, 51, 51, 51), (0, 0, 0, 0), (0, 0, 0, 0), (102, 102, 51, 0)]  # normalized bytes
texcoords = [(0, 0), (65535, 0), (0, 32768), (65535, 65535)]

def pack(fmt, rows):
    b = b"".join(struct.pack("<" + fmt, *row) for row in rows)
    return b + b"\0" * (-len(b) % 4)

# Animation "Cubic": j1 rotation CUBICSPLINE (in-tangent, value, out-tangent per key), j0 (root)
# translation LINEAR, j2 translation STEP.
q0 = joints[1][2]; q1 = qmul(axis_angle((0, 0, 1), 0.8), q0)
cubic = [(0, 0.3, 0, 0), q0, (0.4, 0, 0.2, 0), (0.1, 0, -0.3, 0), q1, (0, 0, 0, 0)]
times2 = [(0.0,), (1.0,)]
rootT = [(0, 1.0, 0), (0.3, 1.2, -0.1)]
stepTimes = [(0.0,), (0.5,)]
stepT = [(0, 0.5, 0.1), (0.1, 0.7, 0.1)]
# Animation "Step": j3 rotation STEP over three keys.
step3 = [(0.0,), (0.4,), (0.8,)]
stepR = [joints[3][2], qmul(axis_angle((1, 0, 0), 0.5), joints[3][2]), qmul(axis_angle((0, 1, 0), -0.5), joints[3][2])]
# Animation "Scaled": only a changing scale on j4 (not imported: a warning names j4).
scaleV = [(1, 1, 1), (1.5, 1.5, 1.5)]

blobs = [
    ("5126", "VEC3", pack("3f", positions)),
    ("5121", "SCALAR", pack("B", [(i,) for i in indices])),
    ("5121", "VEC4", pack("4B", joints0)),
    ("5126", "VEC4", pack("4f", weights0)),
    ("5123", "VEC4", pack("4H", joints1)),
    ("5121n", "VEC4", pack("4B", weights1)),
    ("5123n", "VEC2", pack("2H", texcoords)),
    ("5126", "MAT4", pack("16f", [[M[r][c] for c in range(4) for r in range(4)] for M in ibm])),
    ("5126", "SCALAR", pack("f", times2)),
    ("5126", "VEC4", pack("4f", cubic)),
    ("5126", "VEC3", pack("3f", rootT)),
    ("5126", "SCALAR", pack("f", stepTimes)),
    ("5126", "VEC3", pack("3f", stepT)),
    ("5126", "SCALAR", pack("f", step3)),
    ("5126", "VEC4", pack("4f", stepR)),
    ("5126", "VEC3", pack("3f", scaleV)),
]
counts = [4, 6, 4, 4, 4, 4, 4, 8, 2, 6, 2, 2, 2, 3, 3, 2]
buffer = b""; views = []; accessors = []
for (ctype, typ, blob), count in zip(blobs, counts):
    views.append({"buffer": 0, "byteOffset": len(buffer), "byteLength": len(blob)})
    acc = {"bufferView": len(views) - 1, "componentType": int(ctype.rstrip("n")), "count": count, "type": typ}
    if ctype.endswith("n"): acc["normalized"] = True
    accessors.append(acc)
    buffer += blob
accessors[0]["min"] = [-0.2, 1.0, 0]; accessors[0]["max"] = [0.2, 4.0, 0.5]
accessors[8]["min"] = [0.0]; accessors[8]["max"] = [1.0]
accessors[11]["min"] = [0.0]; accessors[11]["max"] = [0.5]
accessors[13]["min"] = [0.0]; accessors[13]["max"] = [0.8]

nodes = [{"name": "Armature", "translation": list(armature["t"]), "rotation": list(armature["r"]), "scale": list(armature["s"]), "children": [1, 9]}]
for i, (name, t, r) in enumerate(joints):
    node = {"name": name, "translation": list(t), "rotation": list(r)}
    if i < 7: node["children"] = [i + 2]
    nodes.append(node)
nodes.append({"name": "Strip", "mesh": 0, "skin": 0})
doc = {
    "asset": {"version": "2.0", "generator": "hand-made for tests/core/gltf_character_test.cpp: an 8-joint chain under a rotated, scaled armature; a strip skinned with JOINTS_0/WEIGHTS_0 (ubyte, float) and JOINTS_1/WEIGHTS_1 (ushort, normalized ubyte); normalized ushort TEXCOORD_0; CUBICSPLINE, LINEAR and STEP samplers; a scale channel"},
    "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": nodes,
    "meshes": [{"name": "Strip", "primitives": [{"attributes": {"POSITION": 0, "JOINTS_0": 2, "WEIGHTS_0": 3, "JOINTS_1": 4, "WEIGHTS_1": 5, "TEXCOORD_0": 6}, "indices": 1, "material": 0}]}],
    "materials": [{"name": "Paint", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1.0]}}],
    "skins": [{"joints": list(range(1, 9)), "inverseBindMatrices": 7, "skeleton": 1}],
    "animations": [
        {"name": "Cubic", "samplers": [{"input": 8, "output": 9, "interpolation": "CUBICSPLINE"}, {"input": 8, "output": 10}, {"input": 11, "output": 12, "interpolation": "STEP"}],
         "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}, {"sampler": 1, "target": {"node": 1, "path": "translation"}}, {"sampler": 2, "target": {"node": 3, "path": "translation"}}]},
        {"name": "Step", "samplers": [{"input": 13, "output": 14, "interpolation": "STEP"}], "channels": [{"sampler": 0, "target": {"node": 4, "path": "rotation"}}]},
        {"name": "Scaled", "samplers": [{"input": 8, "output": 15}], "channels": [{"sampler": 0, "target": {"node": 5, "path": "scale"}}]},
    ],
    "bufferViews": views, "accessors": accessors,
    "buffers": [{"byteLength": len(buffer), "uri": "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()}],
}
(Path(__file__).resolve().parent / "eight_influences.gltf").write_text(json.dumps(doc, indent=1) + "\n")
