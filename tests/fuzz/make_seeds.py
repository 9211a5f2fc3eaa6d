#!/usr/bin/python3
"""Writes the synthetic seed inputs of the lighting fuzz targets (nothing from ../shared/data):
corpus/gltf/  a two-segment skinned glTF made here (.glb, and .gltf with an embedded buffer), and
              the same with two named morph targets (one sparse),
corpus/hdr/   a small Radiance .hdr (RLE and flat scanlines),
corpus/bake_file/ a bake of the glTF without its trailing CRC (the fuzz target appends it).
Needs the built `thespis` package and thespis-cli: PYTHONPATH=build/python THESPIS_CLI=... ."""

import base64
import json
import os
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("PYTHONPATH", ""))
from thespis import lighting  # noqa: E402


def skinned_quad_gltf():
    # Two quads (a "torso" and a "head" above it) skinned to two joints, one mesh node each.
    positions = np.array([[-0.2, 0.0, 0], [0.2, 0.0, 0], [0.2, 0.5, 0], [-0.2, 0.5, 0],
                          [-0.1, 0.55, 0.01], [0.1, 0.55, 0.01], [0.1, 0.75, 0.01], [-0.1, 0.75, 0.01]], np.float32)
    indices = np.array([0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7], np.uint16)
    joints = np.array([[0, 1, 0, 0]] * 4 + [[1, 0, 0, 0]] * 4, np.uint8)
    weights = np.array([[0.9, 0.1, 0, 0]] * 4 + [[1, 0, 0, 0]] * 4, np.float32)
    inverse_bind = np.array([np.eye(4), np.eye(4)], np.float32)
    inverse_bind[1][3][1] = -0.5  # column-major: translation of the head joint (0, 0.5, 0) inverted
    blobs = [positions.tobytes(), indices.tobytes() + b"\0" * 0, joints.tobytes(), weights.tobytes(),
             inverse_bind.tobytes()]
    offsets, buffer = [], b""
    for blob in blobs:
        offsets.append(len(buffer))
        buffer += blob + b"\0" * (-len(blob) % 4)
    views = [{"buffer": 0, "byteOffset": o, "byteLength": len(b)} for o, b in zip(offsets, blobs)]
    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
         "min": positions.min(0).tolist(), "max": positions.max(0).tolist()},
        {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"},
        {"bufferView": 2, "componentType": 5121, "count": 8, "type": "VEC4"},
        {"bufferView": 3, "componentType": 5126, "count": 8, "type": "VEC4"},
        {"bufferView": 4, "componentType": 5126, "count": 2, "type": "MAT4"},
    ]
    document = {
        "asset": {"version": "2.0", "generator": "thespis tests/fuzz/make_seeds.py"},
        "scene": 0, "scenes": [{"nodes": [0, 2]}],
        "nodes": [{"name": "spine", "children": [1]}, {"name": "skull", "translation": [0, 0.5, 0]},
                  {"name": "body", "mesh": 0, "skin": 0}],
        "skins": [{"joints": [0, 1], "inverseBindMatrices": 4}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "JOINTS_0": 2, "WEIGHTS_0": 3}, "indices": 1}]}],
        "buffers": [{"byteLength": len(buffer)}], "bufferViews": views, "accessors": accessors,
    }
    return document, buffer


def morphed_quads_gltf():
    # The two quads with two morph targets on their mesh, named as ARKit and an expression
    # ("jawOpen" moves the head quad's lower edge, "Angry", a sparse accessor, one corner of it),
    # "Angry" resting at weight 0.25: the face targets the character import keeps.
    document, buffer = skinned_quad_gltf()
    jaw = np.zeros((8, 3), np.float32)
    jaw[4:6] = [0, -0.05, 0.01]
    sparse_indices = np.array([6], np.uint16).tobytes() + b"\0\0"
    sparse_values = np.array([[0.02, 0.01, 0]], np.float32).tobytes()
    views = document["bufferViews"]
    for blob in (jaw.tobytes(), sparse_indices, sparse_values):
        views.append({"buffer": 0, "byteOffset": len(buffer), "byteLength": len(blob)})
        buffer += blob
    document["accessors"] += [
        {"bufferView": len(views) - 3, "componentType": 5126, "count": 8, "type": "VEC3",
         "min": jaw.min(0).tolist(), "max": jaw.max(0).tolist()},
        {"componentType": 5126, "count": 8, "type": "VEC3", "min": [0, 0, 0], "max": [0.02, 0.01, 0],
         "sparse": {"count": 1, "indices": {"bufferView": len(views) - 2, "componentType": 5123},
                    "values": {"bufferView": len(views) - 1}}},
    ]
    count = len(document["accessors"])
    mesh = document["meshes"][0]
    mesh["primitives"][0]["targets"] = [{"POSITION": count - 2}, {"POSITION": count - 1}]
    mesh["weights"] = [0, 0.25]
    mesh["extras"] = {"targetNames": ["jawOpen", "Angry"]}
    document["buffers"][0]["byteLength"] = len(buffer)
    return document, buffer


def glb(document, buffer):
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(buffer), 0x004E4942) + buffer
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


def main():
    document, buffer = skinned_quad_gltf()
    (HERE / "corpus/gltf").mkdir(parents=True, exist_ok=True)
    (HERE / "corpus/gltf/two_quads.glb").write_bytes(glb(document, buffer))
    embedded = json.loads(json.dumps(document))
    embedded["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()
    (HERE / "corpus/gltf/two_quads.gltf").write_text(json.dumps(embedded))
    (HERE / "corpus/gltf/morphed_quads.glb").write_bytes(glb(*morphed_quads_gltf()))

    (HERE / "corpus/hdr").mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(1)
    lighting.write_hdr(HERE / "corpus/hdr/rle.hdr", rng.uniform(0, 4, size=(4, 16, 3)).astype(np.float32))
    lighting.write_hdr(HERE / "corpus/hdr/flat.hdr", rng.uniform(0, 4, size=(3, 5, 3)).astype(np.float32))

    (HERE / "corpus/bake_file").mkdir(parents=True, exist_ok=True)
    bake = HERE / "corpus/bake_file/two_quads.prt"
    subprocess.run([os.environ["THESPIS_CLI"], "bake", str(HERE / "corpus/gltf/two_quads.glb"), "--order", "2",
                    "--rays", "4", "--transfer", "ds", "--quiet", "--out", str(bake)], check=True)
    bake.write_bytes(bake.read_bytes()[:-4])  # the fuzz target appends the CRC itself


if __name__ == "__main__":
    main()
