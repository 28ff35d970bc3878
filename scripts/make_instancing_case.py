#!/usr/bin/env python3
"""Writes the instancing stress case: one mesh of TRIANGLES triangles (a grid on the unit square,
indexed, with normals) whose every primitive reads the same accessors, PRIMITIVES primitives in
the mesh, and NODES nodes that each place the mesh (a row along +x). Flattened it is
TRIANGLES x PRIMITIVES x NODES triangles (10^8 by default), instanced one stored primitive.

  make_instancing_case.py OUT.gltf [TRIANGLES PRIMITIVES NODES]

Writes OUT.gltf (the JSON) and OUT.bin (the buffer) beside it, and OUT.json (a camera seeing the
row, for `strata render`).
"""
import json
import math
import os
import struct
import sys


def main():
    out = sys.argv[1]
    triangles, primitives, nodes = (int(a) for a in sys.argv[2:5]) if len(sys.argv) >= 5 else (10000, 100, 100)
    # A grid of n x m quads, two triangles each, n m = triangles / 2.
    quads = triangles // 2
    n = int(math.sqrt(quads))
    while quads % n:
        n -= 1
    m = quads // n
    positions = [(i / n, j / m, 0.0) for j in range(m + 1) for i in range(n + 1)]
    indices = []
    for j in range(m):
        for i in range(n):
            a = j * (n + 1) + i
            indices += [a, a + 1, a + n + 2, a, a + n + 2, a + n + 1]
    index_format = "H" if len(positions) < 65536 else "I"
    index_bytes = struct.pack("<%d%s" % (len(indices), index_format), *indices)
    index_bytes += b"\0" * (-len(index_bytes) % 4)
    position_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
    normal_bytes = struct.pack("<3f", 0.0, 0.0, 1.0) * len(positions)
    buffer = index_bytes + position_bytes + normal_bytes
    base = os.path.splitext(out)[0]
    with open(base + ".bin", "wb") as f:
        f.write(buffer)
    gltf = {
        "asset": {"version": "2.0"},
        "buffers": [{"uri": os.path.basename(base) + ".bin", "byteLength": len(buffer)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(index_bytes), "target": 34963},
            {"buffer": 0, "byteOffset": len(index_bytes), "byteLength": len(position_bytes), "target": 34962},
            {"buffer": 0, "byteOffset": len(index_bytes) + len(position_bytes), "byteLength": len(normal_bytes),
             "target": 34962},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5123 if index_format == "H" else 5125, "count": len(indices),
             "type": "SCALAR"},
            {"bufferView": 1, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 2, "componentType": 5126, "count": len(positions), "type": "VEC3"},
        ],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 1, "NORMAL": 2}, "indices": 0, "material": 0}
                                   for _ in range(primitives)]}],
        "nodes": [{"mesh": 0, "translation": [1.1 * k, 0, 0]} for k in range(nodes)],
        "scenes": [{"nodes": list(range(nodes))}],
        "scene": 0,
    }
    with open(out, "w") as f:
        json.dump(gltf, f, separators=(",", ":"))
    width = 1.1 * nodes
    camera = {"position": [width / 2, 0.5, width], "look_at": [width / 2, 0.5, 0], "up": [0, 1, 0],
              "fov_y": 60, "width": 256, "height": 128}
    with open(base + ".json", "w") as f:
        json.dump(camera, f, indent=1)


if __name__ == "__main__":
    main()
