#!/usr/bin/env python3
"""Writes assets/textured/: a closed room lit by an emissive ceiling quad, with a glossy floor
that has a base-colour checker texture and a normal map (bumps), a back wall whose
metallic-roughness texture stripes metal and dielectric, and diffuse side walls. The textures
are procedural (no inputs); PNGs are written with zlib. The image test of the shader chain
(tests/render/test_textured_scene.cpp) renders it.

    python3 tools/make_textured_scene.py [OUT_DIR]
"""
import json
import math
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gltf_writer  # noqa: E402  (found beside this file)


def write_png(path, width, height, channels, pixel):
    """pixel(x, y) -> tuple of `channels` ints in 0..255; row 0 is the top."""
    samples = [v for y in range(height) for x in range(width) for v in pixel(x, y)]
    with open(path, "wb") as f:
        f.write(gltf_writer.png(width, height, channels, samples, level=9))


def checker(x, y):
    # 8×8 squares of a warm and a cool colour (sRGB-encoded, the loader decodes them).
    return (200, 170, 120) if ((x // 8) + (y // 8)) % 2 == 0 else (70, 90, 140)


def bumps_normal(x, y, size=64, cells=4):
    # Height h = 0.5·(sin(2π·cells·u) · sin(2π·cells·v)); tangent-space normal of the surface
    # z = k·h, n = normalize(−k ∂h/∂u, −k ∂h/∂v, 1), encoded (n + 1) / 2 (glTF §3.9.3). v grows
    # downwards in the image, as glTF's uv.
    k = 0.04
    u = (x + 0.5) / size
    v = (y + 0.5) / size
    w = 2.0 * math.pi * cells
    dh_du = 0.5 * w * math.cos(w * u) * math.sin(w * v)
    dh_dv = 0.5 * w * math.sin(w * u) * math.cos(w * v)
    n = (-k * dh_du, -k * dh_dv, 1.0)
    length = math.sqrt(sum(c * c for c in n))
    return tuple(int(round((c / length * 0.5 + 0.5) * 255)) for c in n)


def stripes_mr(x, y):
    # glTF metallicRoughness: G = roughness, B = metallic. Vertical stripes: metal / dielectric,
    # roughness ramping down the image from 0.2 to 0.6.
    metal = 255 if (x // 8) % 2 == 0 else 0
    rough = int(round((0.2 + 0.4 * y / 31.0) * 255))
    return (0, rough, metal)


class Builder:
    def __init__(self):
        self.buffer = gltf_writer.Buffer()
        self.accessors = []
        self.meshes = []
        self.nodes = []

    def _add(self, values, fmt, count, type_, with_bounds=False):
        view = self.buffer.view(struct.pack("<" + fmt * len(values), *values))
        acc = {"bufferView": view,
               "componentType": gltf_writer.FLOAT if fmt == "f" else gltf_writer.UINT,
               "count": count, "type": type_}
        if with_bounds:
            comps = len(values) // count
            acc["min"] = [min(values[i::comps]) for i in range(comps)]
            acc["max"] = [max(values[i::comps]) for i in range(comps)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def quad(self, name, p, a, b, material, uv_scale=1.0):
        """The quad p, p+a, p+a+b, p+b; its winding normal is a × b."""
        corners = [p, [p[i] + a[i] for i in range(3)], [p[i] + a[i] + b[i] for i in range(3)],
                   [p[i] + b[i] for i in range(3)]]
        n = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
        ln = math.sqrt(sum(c * c for c in n))
        n = [c / ln for c in n]
        uvs = [(0, 0), (uv_scale, 0), (uv_scale, uv_scale), (0, uv_scale)]
        pos = self._add([c for v in corners for c in v], "f", 4, "VEC3", True)
        nor = self._add(n * 4, "f", 4, "VEC3")
        tex = self._add([c for uv in uvs for c in uv], "f", 4, "VEC2")
        idx = self._add([0, 1, 2, 0, 2, 3], "I", 6, "SCALAR")
        self.meshes.append({"name": name, "primitives": [{
            "attributes": {"POSITION": pos, "NORMAL": nor, "TEXCOORD_0": tex},
            "indices": idx, "material": material}]})
        self.nodes.append({"name": name, "mesh": len(self.meshes) - 1})


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "assets", "textured")
    os.makedirs(out, exist_ok=True)
    write_png(os.path.join(out, "checker.png"), 64, 64, 3, checker)
    write_png(os.path.join(out, "bumps_normal.png"), 64, 64, 3, bumps_normal)
    write_png(os.path.join(out, "stripes_mr.png"), 32, 32, 3, stripes_mr)

    b = Builder()
    # Room [-1, 1] × [0, 2] × [-1, 1], open towards the camera (+z).
    b.quad("floor", [-1, 0, -1], [0, 0, 2], [2, 0, 0], 0)
    b.quad("ceiling", [-1, 2, -1], [2, 0, 0], [0, 0, 2], 1)
    b.quad("back", [-1, 0, -1], [2, 0, 0], [0, 2, 0], 4)
    b.quad("left", [-1, 0, -1], [0, 2, 0], [0, 0, 2], 2)
    b.quad("right", [1, 0, -1], [0, 0, 2], [0, 2, 0], 3)
    b.quad("light", [-0.3, 1.98, -0.3], [0.6, 0, 0], [0, 0, 0.6], 5)
    b.nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 1.0, 3.4]})

    def diffuse(name, rgb):
        return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": rgb + [1.0],
                                                        "metallicFactor": 0.0},
                "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}

    materials = [
        {"name": "glossy textured floor",
         "pbrMetallicRoughness": {
             "baseColorTexture": {"index": 0, "extensions": {
                 "KHR_texture_transform": {"scale": [2.0, 2.0], "offset": [0.1, 0.0]}}},
             "metallicFactor": 0.0, "roughnessFactor": 0.35},
         "normalTexture": {"index": 1, "scale": 1.0}},
        diffuse("white", [0.75, 0.75, 0.75]),
        diffuse("red", [0.6, 0.08, 0.06]),
        diffuse("green", [0.1, 0.45, 0.1]),
        {"name": "striped metal", "pbrMetallicRoughness": {
            "baseColorFactor": [0.9, 0.75, 0.5, 1.0], "metallicFactor": 1.0,
            "roughnessFactor": 1.0, "metallicRoughnessTexture": {"index": 2}}},
        {"name": "light", "emissiveFactor": [1.0, 0.9, 0.8],
         "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0},
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 12.0},
                        "KHR_materials_specular": {"specularFactor": 0.0}}},
    ]
    gltf = {
        "asset": {"version": "2.0", "generator": "tools/make_textured_scene.py"},
        "extensionsUsed": ["KHR_texture_transform", "KHR_materials_specular",
                           "KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"nodes": list(range(len(b.nodes)))}],
        "nodes": b.nodes,
        "meshes": b.meshes,
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": 0.75, "znear": 0.01, "aspectRatio": 1.0}}],
        "materials": materials,
        "images": [{"uri": "checker.png"}, {"uri": "bumps_normal.png"}, {"uri": "stripes_mr.png"}],
        "samplers": [{"magFilter": 9729, "minFilter": 9729, "wrapS": 10497, "wrapT": 10497},
                     {"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33648}],
        "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0},
                     {"source": 2, "sampler": 1}],
        "buffers": [{"uri": "textured.bin", "byteLength": len(b.buffer.data)}],
        "bufferViews": b.buffer.views,
        "accessors": b.accessors,
    }
    with open(os.path.join(out, "textured.bin"), "wb") as f:
        f.write(bytes(b.buffer.data))
    with open(os.path.join(out, "textured.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
