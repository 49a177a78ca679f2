#!/usr/bin/env python3
"""Writes the small models of models/ (models/README.md says what each is), deterministically, with the
standard library only:

    scripts/make_models.py [folder]        (default: models/ beside this script's folder)

- cube.obj + cube.mtl: the unit cube (side 1, centred on the origin), closed, a normal per face, its
  material in the MTL.
- sphere.obj: shadelab's own sphere at level 3 (DESIGN §1: the tetrahedron split three times, midpoints
  pushed onto the unit sphere, its triangles in buildSphere's order) with its exact normals
  (normal = position). sphere.gltf + sphere.bin and sphere.glb: the same mesh as glTF 2.0 (float positions
  and normals, 32-bit indices).
- torus.obj: a torus without normals, so that shadelab makes them (DESIGN §1, area-weighted).

The sphere's numbers come from +, *, / and sqrt only (correctly rounded everywhere) and are written with
repr (the shortest text that reads back to the same double), so the files are the same on any machine.
The torus needs cos and sin, whose last bit may differ between C libraries: it is written with 6 decimals.
"""
import json
import math
import struct
import sys
from pathlib import Path


def write(folder, name, data):
    path = folder / name
    path.write_bytes(data if isinstance(data, bytes) else data.encode("ascii"))


def normalize(v):
    # As glm::normalize in double: v * (1 / sqrt(dot(v, v))).
    inverse = 1.0 / math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    return (v[0] * inverse, v[1] * inverse, v[2] * inverse)


def sphere(level):
    """DESIGN §1's sphere: positions and counter-clockwise triangles, in buildSphere's order."""
    s2, s6 = math.sqrt(2.0), math.sqrt(6.0)
    positions = [(0.0, 0.0, 1.0), (0.0, 2 * s2 / 3, -1.0 / 3), (-s6 / 3, -s2 / 3, -1.0 / 3),
                 (s6 / 3, -s2 / 3, -1.0 / 3)]
    triangles = [(3, 2, 1), (0, 1, 2), (0, 3, 1), (0, 2, 3)]
    for _ in range(level):
        midpoint_of = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint_of:
                pa, pb = positions[a], positions[b]
                midpoint_of[key] = len(positions)
                positions.append(normalize(((pa[0] + pb[0]) * 0.5, (pa[1] + pb[1]) * 0.5,
                                            (pa[2] + pb[2]) * 0.5)))
            return midpoint_of[key]

        children = []
        for a, b, c in triangles:
            ab, bc, ac = midpoint(a, b), midpoint(b, c), midpoint(a, c)
            children += [(a, ab, ac), (ab, b, bc), (bc, c, ac), (ab, bc, ac)]
        triangles = children
    return positions, triangles


def cube_files():
    corners = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
    # Per face: its normal and its four corners counter-clockwise seen from outside (1-based).
    faces = [((1, 0, 0), (5, 7, 8, 6)), ((-1, 0, 0), (1, 2, 4, 3)), ((0, 1, 0), (3, 4, 8, 7)),
             ((0, -1, 0), (1, 5, 6, 2)), ((0, 0, 1), (2, 6, 8, 4)), ((0, 0, -1), (1, 3, 7, 5))]
    obj = ["# The unit cube, closed: made by scripts/make_models.py", "mtllib cube.mtl"]
    obj += ["v %s %s %s" % p for p in corners]
    obj += ["vn %d %d %d" % n for n, _ in faces]
    obj.append("usemtl red_plastic")
    for n, (_, (a, b, c, d)) in enumerate(faces, 1):
        obj.append("f %d//%d %d//%d %d//%d" % (a, n, b, n, c, n))
        obj.append("f %d//%d %d//%d %d//%d" % (a, n, c, n, d, n))
    mtl = ["# The cube's material: made by scripts/make_models.py", "newmtl red_plastic",
           "Ka 0.1 0.02 0.02", "Kd 0.8 0.1 0.1", "Ks 0.5 0.5 0.5", "Ns 64"]
    return "\n".join(obj) + "\n", "\n".join(mtl) + "\n"


def sphere_obj(positions, triangles):
    lines = ["# shadelab's level-3 sphere with its exact normals: made by scripts/make_models.py"]
    lines += ["v %r %r %r" % p for p in positions]
    lines += ["vn %r %r %r" % p for p in positions]
    lines += ["f %d//%d %d//%d %d//%d" % (a + 1, a + 1, b + 1, b + 1, c + 1, c + 1) for a, b, c in triangles]
    return "\n".join(lines) + "\n"


def sphere_gltf(positions, triangles, uri):
    """The glTF JSON (with `uri` for the buffer, or none for a GLB) and the buffer's bytes."""
    floats = struct.pack("<%df" % (3 * len(positions)), *[x for p in positions for x in p])
    indices = struct.pack("<%dI" % (3 * len(triangles)), *[i for t in triangles for i in t])
    buffer = floats + floats + indices  # positions, then the same numbers as normals, then indices
    # The accessor's bounds as the floats stored (glTF requires them for POSITION).
    stored = struct.unpack("<%df" % (3 * len(positions)), floats)
    low = [min(stored[k::3]) for k in range(3)]
    high = [max(stored[k::3]) for k in range(3)]
    n = len(floats)
    gltf = {
        "asset": {"version": "2.0", "generator": "shadelab scripts/make_models.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "sphere"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2,
                                    "material": 0}]}],
        "materials": [{"name": "blue", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.8, 1]}}],
        "buffers": [{"byteLength": len(buffer)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": n, "target": 34962},
                        {"buffer": 0, "byteOffset": n, "byteLength": n, "target": 34962},
                        {"buffer": 0, "byteOffset": 2 * n, "byteLength": len(indices), "target": 34963}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
                       "min": low, "max": high},
                      {"bufferView": 1, "componentType": 5126, "count": len(positions), "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5125, "count": 3 * len(triangles),
                       "type": "SCALAR"}],
    }
    if uri:
        gltf["buffers"][0]["uri"] = uri
    return json.dumps(gltf, indent=1, sort_keys=True) + "\n", buffer


def glb(json_text, buffer):
    chunk_json = json_text.encode("ascii")
    chunk_json += b" " * (-len(chunk_json) % 4)
    chunk_bin = buffer + b"\0" * (-len(buffer) % 4)
    total = 12 + 8 + len(chunk_json) + 8 + len(chunk_bin)
    return (struct.pack("<III", 0x46546C67, 2, total) + struct.pack("<II", len(chunk_json), 0x4E4F534A) +
            chunk_json + struct.pack("<II", len(chunk_bin), 0x004E4942) + chunk_bin)


def torus_obj(segments=32, sides=16, major=0.75, minor=0.25):
    lines = ["# A torus without normals (shadelab makes them): made by scripts/make_models.py"]
    for i in range(segments):
        u = 2 * math.pi * i / segments
        for j in range(sides):
            v = 2 * math.pi * j / sides
            r = major + minor * math.cos(v)
            lines.append("v %.6f %.6f %.6f" % (r * math.cos(u), minor * math.sin(v), -r * math.sin(u)))
    for i in range(segments):
        for j in range(sides):
            a = i * sides + j + 1
            b = ((i + 1) % segments) * sides + j + 1
            c = ((i + 1) % segments) * sides + (j + 1) % sides + 1
            d = i * sides + (j + 1) % sides + 1
            lines.append("f %d %d %d" % (a, b, c))
            lines.append("f %d %d %d" % (a, c, d))
    return "\n".join(lines) + "\n"


def main():
    folder = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "models"
    folder.mkdir(parents=True, exist_ok=True)
    obj, mtl = cube_files()
    write(folder, "cube.obj", obj)
    write(folder, "cube.mtl", mtl)
    positions, triangles = sphere(3)
    write(folder, "sphere.obj", sphere_obj(positions, triangles))
    json_text, buffer = sphere_gltf(positions, triangles, "sphere.bin")
    write(folder, "sphere.gltf", json_text)
    write(folder, "sphere.bin", buffer)
    json_text, buffer = sphere_gltf(positions, triangles, None)
    write(folder, "sphere.glb", glb(json_text, buffer))
    write(folder, "torus.obj", torus_obj())


if __name__ == "__main__":
    main()
