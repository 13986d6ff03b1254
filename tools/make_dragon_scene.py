#!/usr/bin/env python3
"""Writes a Cornell-style room with the Stanford dragon as glTF: OUT_DIR/dragon.gltf + dragon.bin.

usage: make_dragon_scene.py DRAGON.ply[.gz] OUT_DIR

The room (2 m cube, +Y up, open towards the camera at +Z) uses the bundled Cornell box's
materials (assets/cornell-box/cbox.gltf: white, red, green walls, Lambertian via
KHR_materials_specular specularFactor 0) and its ceiling light's emission. The dragon (ascii PLY
as in the Stanford repository: x y z per vertex, "3 i j k" per face) gets smooth area-weighted
vertex normals, is scaled to 1.3 m long and stands on the floor; it is double-sided, as the
scan's winding is not guaranteed. Only the Python standard
library is used; tools/fetch_dragon.sh calls this.
"""
import array
import gzip
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_writer import ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, FLOAT, UINT, Buffer  # noqa: E402

WHITE = [0.885809, 0.698859, 0.666422, 1]
RED = [0.570068, 0.0430135, 0.0443706, 1]
GREEN = [0.105421, 0.37798, 0.076425, 1]
DRAGON = [0.75, 0.75, 0.75, 1]
LIGHT_EMISSION = [1, 0.5975580573231086, 0.14975634959482242]
LIGHT_STRENGTH = 18.387


def read_ply(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt") as f:
        if f.readline().strip() != "ply":
            sys.exit(f"{path}: not a PLY file")
        counts = {}
        while True:
            line = f.readline()
            if not line:
                sys.exit(f"{path}: no end_header")
            words = line.split()
            if words[:1] == ["format"] and words[1] != "ascii":
                sys.exit(f"{path}: only ascii PLY is expected here")
            if words[:1] == ["element"]:
                counts[words[1]] = int(words[2])
            if words[:1] == ["end_header"]:
                break
        positions = []
        for _ in range(counts["vertex"]):
            x, y, z = f.readline().split()[:3]
            positions.append((float(x), float(y), float(z)))
        faces = []
        for _ in range(counts["face"]):
            w = f.readline().split()
            n = int(w[0])
            idx = [int(i) for i in w[1:1 + n]]
            for k in range(1, n - 1):  # fan, as mvpl's own PLY loader does
                faces.append((idx[0], idx[k], idx[k + 1]))
    return positions, faces


def place_dragon(positions):
    lo = [min(p[i] for p in positions) for i in range(3)]
    hi = [max(p[i] for p in positions) for i in range(3)]
    scale = 1.3 / max(hi[0] - lo[0], hi[2] - lo[2])
    cx, cz = 0.5 * (lo[0] + hi[0]), 0.5 * (lo[2] + hi[2])
    return [((x - cx) * scale, (y - lo[1]) * scale, (z - cz) * scale) for x, y, z in positions]


def smooth_normals(positions, faces):
    n = [[0.0, 0.0, 0.0] for _ in positions]
    for a, b, c in faces:
        pa, pb, pc = positions[a], positions[b], positions[c]
        u = (pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2])
        v = (pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2])
        # The cross product's length is twice the area: area-weighted sum.
        w = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        for i in (a, b, c):
            n[i][0] += w[0]
            n[i][1] += w[1]
            n[i][2] += w[2]
    out = []
    for x, y, z in n:
        length = math.sqrt(x * x + y * y + z * z)
        out.append((x / length, y / length, z / length) if length > 0 else (0.0, 1.0, 0.0))
    return out


def quad(p0, p1, p2, p3):
    """Two triangles (p0 p1 p2), (p0 p2 p3), counter-clockwise seen from the front side."""
    e1 = [p1[i] - p0[i] for i in range(3)]
    e2 = [p3[i] - p0[i] for i in range(3)]
    nrm = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
           e1[0] * e2[1] - e1[1] * e2[0]]
    length = math.sqrt(sum(c * c for c in nrm))
    nrm = tuple(c / length for c in nrm)
    return [p0, p1, p2, p3], [nrm] * 4, [(0, 1, 2), (0, 2, 3)]


def room():
    """(material index, quad) for the room: x, z in [-1, 1], y in [0, 2], open at +Z."""
    return [
        (0, quad((-1, 0, 1), (1, 0, 1), (1, 0, -1), (-1, 0, -1))),  # floor, normal +Y
        (0, quad((-1, 2, -1), (1, 2, -1), (1, 2, 1), (-1, 2, 1))),  # ceiling, normal -Y
        (0, quad((-1, 0, -1), (1, 0, -1), (1, 2, -1), (-1, 2, -1))),  # back, normal +Z
        (1, quad((-1, 0, 1), (-1, 0, -1), (-1, 2, -1), (-1, 2, 1))),  # left red, normal +X
        (2, quad((1, 0, -1), (1, 0, 1), (1, 2, 1), (1, 2, -1))),  # right green, normal -X
        # The light: 0.5 m square just below the ceiling, emitting downwards.
        (4, quad((-0.25, 1.995, -0.25), (0.25, 1.995, -0.25), (0.25, 1.995, 0.25),
                 (-0.25, 1.995, 0.25))),
    ]


def material(name, colour, emission=None):
    m = {"name": name,
         "pbrMetallicRoughness": {"baseColorFactor": colour, "metallicFactor": 0,
                                  "roughnessFactor": 1.0},
         "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}
    if emission:
        m["emissiveFactor"] = emission
        m["extensions"]["KHR_materials_emissive_strength"] = {"emissiveStrength": LIGHT_STRENGTH}
    return m


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    ply, out_dir = sys.argv[1], sys.argv[2]
    positions, faces = read_ply(ply)
    positions = place_dragon(positions)
    normals = smooth_normals(positions, faces)
    meshes = [(3, (positions, normals, faces))] + room()

    gltf = {"asset": {"version": "2.0", "generator": "mvpl tools/make_dragon_scene.py"},
            "extensionsUsed": ["KHR_materials_emissive_strength", "KHR_materials_specular"],
            "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [],
            "accessors": [], "bufferViews": [],
            "materials": [material("white", WHITE), material("red", RED),
                          material("green", GREEN), dict(material("dragon", DRAGON),
                                                         doubleSided=True),
                          material("light", WHITE, LIGHT_EMISSION)],
            "cameras": [{"type": "perspective", "perspective": {
                "yfov": 0.6860487863861751, "znear": 0.01, "aspectRatio": 1}}]}

    buffer = Buffer(gltf["bufferViews"])

    def add_view(data, target, count, component, kind, bounds=None):
        acc = {"bufferView": buffer.view(data, target), "componentType": component,
               "count": count, "type": kind}
        if bounds:
            acc["min"], acc["max"] = bounds
        gltf["accessors"].append(acc)
        return len(gltf["accessors"]) - 1

    for m, (pos, nrm, tri) in meshes:
        flat_p = array.array("f", [c for p in pos for c in p])
        flat_n = array.array("f", [c for n in nrm for c in n])
        flat_i = array.array("I", [i for t in tri for i in t])
        if sys.byteorder != "little":
            for a in (flat_p, flat_n, flat_i):
                a.byteswap()
        lo = [min(p[i] for p in pos) for i in range(3)]
        hi = [max(p[i] for p in pos) for i in range(3)]
        attributes = {"POSITION": add_view(flat_p.tobytes(), ARRAY_BUFFER, len(pos), FLOAT, "VEC3",
                                           (lo, hi)),
                      "NORMAL": add_view(flat_n.tobytes(), ARRAY_BUFFER, len(nrm), FLOAT, "VEC3")}
        indices = add_view(flat_i.tobytes(), ELEMENT_ARRAY_BUFFER, len(flat_i), UINT, "SCALAR")
        gltf["meshes"].append({"primitives": [{"attributes": attributes, "indices": indices,
                                               "material": m}]})
        gltf["nodes"].append({"mesh": len(gltf["meshes"]) - 1})
    # Camera on +Z looking down -Z at the room's centre, like the Cornell box's.
    gltf["nodes"].append({"name": "camera", "camera": 0, "translation": [0, 1, 3.85]})
    gltf["scenes"][0]["nodes"] = list(range(len(gltf["nodes"])))
    gltf["buffers"] = [{"uri": "dragon.bin", "byteLength": len(buffer.data)}]

    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "dragon.bin"), "wb") as f:
        f.write(buffer.data)
    with open(os.path.join(out_dir, "dragon.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
    print(f"{out_dir}/dragon.gltf: dragon {len(faces)} triangles, "
          f"{len(faces) + 2 * (len(meshes) - 1)} in all")


if __name__ == "__main__":
    main()
