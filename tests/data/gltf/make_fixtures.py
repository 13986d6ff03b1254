#!/usr/bin/env python3
"""Writes the glTF test fixtures: good scenes into tests/data/gltf/ and the bad-input corpus into
tests/data/bad/ (one file per defect, named after it). Python 3 standard library only.

The JSON of every scene is written out here by hand; the script only packs the binary data
(buffers as base64 data URIs, PNG images, GLB containers). Run it after changing a fixture:
    python3 tests/data/gltf/make_fixtures.py
"""
import base64
import copy
import json
import math
import pathlib
import struct
import sys

HERE = pathlib.Path(__file__).resolve().parent
BAD = HERE.parent / "bad"

sys.path.insert(0, str(HERE.parents[2] / "tools"))
from gltf_writer import FLOAT, UBYTE, UINT, USHORT, Buffer, png  # noqa: E402  (tools/)
POINTS, LINES, TRIANGLES, STRIP, FAN = 0, 1, 4, 5, 6
NEAREST, LINEAR = 9728, 9729
REPEAT, CLAMP, MIRROR = 10497, 33071, 33648
# Placeholders for numbers JSON cannot spell; replaced in the text after json.dumps.
INF = "@@1e999@@"
NAN = "@@NaN@@"


class Builder(Buffer):
    """One binary buffer with its buffer views (tools/gltf_writer.py) and accessors."""

    def __init__(self):
        super().__init__()
        self.accessors = []

    def accessor(self, view, ctype, count, type_, **extra):
        accessor = {"componentType": ctype, "count": count, "type": type_}
        if view is not None:
            accessor["bufferView"] = view
        accessor.update(extra)
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def vec(self, rows, type_, minmax=False):
        payload = b"".join(struct.pack("<%df" % len(r), *r) for r in rows)
        extra = {}
        if minmax:
            extra["min"] = [min(r[i] for r in rows) for i in range(len(rows[0]))]
            extra["max"] = [max(r[i] for r in rows) for i in range(len(rows[0]))]
        return self.accessor(self.view(payload), FLOAT, len(rows), type_, **extra)

    def indices(self, values, ctype=USHORT):
        fmt = {UBYTE: "B", USHORT: "H", UINT: "I"}[ctype]
        return self.accessor(self.view(struct.pack("<%d%s" % (len(values), fmt), *values)), ctype,
                             len(values), "SCALAR")

    def gltf(self, **fields):
        doc = {"asset": {"version": "2.0", "generator": "mvpl make_fixtures.py"}}
        if self.data:
            uri = "data:application/octet-stream;base64," + base64.b64encode(self.data).decode()
            doc["buffers"] = [{"byteLength": len(self.data), "uri": uri}]
            doc["bufferViews"] = self.views
            doc["accessors"] = self.accessors
        doc.update(fields)
        return doc


def png_uri(data):
    return "data:image/png;base64," + base64.b64encode(data).decode()


def text(doc):
    out = json.dumps(doc, indent=1, allow_nan=False)
    return out.replace('"' + INF + '"', "1e999").replace('"' + NAN + '"', "NaN") + "\n"


def glb(doc, bin_data, version=2):
    j = json.dumps(doc, separators=(",", ":")).encode()
    j += b" " * (-len(j) % 4)
    out = struct.pack("<II", len(j), 0x4E4F534A) + j
    if bin_data is not None:
        b = bytes(bin_data) + b"\0" * (-len(bin_data) % 4)
        out += struct.pack("<II", len(b), 0x004E4942) + b
    return struct.pack("<III", 0x46546C67, version, 12 + len(out)) + out


def write(path, content):
    path.write_bytes(content.encode() if isinstance(content, str) else content)


def quat(axis, degrees):
    s = math.sin(math.radians(degrees) / 2)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(math.radians(degrees) / 2)]


TRIANGLE = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]


# ---------------------------------------------------------------------------------------------
# Good fixtures


def transforms():
    b = Builder()
    pos = b.vec(TRIANGLE, "VEC3", minmax=True)
    nrm = b.vec([(0.0, 0.0, 1.0)] * 3, "VEC3")
    idx = b.indices([0, 1, 2])
    # A triangle in the plane x + y = 0 whose normal (1, 1, 0)/√2 tests the inverse transpose.
    slant_pos = b.vec([(0.0, 0.0, 0.0), (0.0, 0.0, 1.0), (1.0, -1.0, 0.0)], "VEC3", minmax=True)
    h = math.sqrt(0.5)
    slant_nrm = b.vec([(h, h, 0.0)] * 3, "VEC3")
    return b.gltf(
        meshes=[{"name": "tri", "primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm},
                                                "indices": idx}]},
                {"name": "slant", "primitives": [{"attributes": {"POSITION": slant_pos,
                                                                 "NORMAL": slant_nrm}}]}],
        nodes=[{"name": "parent", "translation": [10, 0, 0], "rotation": quat((0, 0, 1), 90),
                "scale": [2, 2, 2], "children": [1]},
               {"name": "child", "translation": [0, 1, 0], "mesh": 0},
               {"name": "matrix", "mesh": 1,
                "matrix": [2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1]},
               {"name": "mirror", "scale": [-1, 1, 1], "mesh": 0},
               {"name": "unused", "mesh": 1}],
        scenes=[{"nodes": [4]}, {"nodes": [0, 2, 3]}],
        scene=1)


def flat_normals():
    b = Builder()
    quad = b.vec([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0)], "VEC3",
                 minmax=True)
    uv = b.vec([(0.0, 1.0), (1.0, 1.0), (1.0, 0.0), (0.0, 0.0)], "VEC2")
    quad_idx = b.indices([0, 1, 2, 0, 2, 3])
    # A tilted triangle with a degenerate one after it: both kept, both with finite normals.
    tilt = b.vec([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 1.0), (2.0, 2.0, 2.0),
                  (2.0, 2.0, 2.0), (2.0, 2.0, 2.0)], "VEC3", minmax=True)
    # NORMAL with one zero-length normal: replaced by the face normal.
    rep_pos = b.vec(TRIANGLE, "VEC3", minmax=True)
    rep_nrm = b.vec([(0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0)], "VEC3")
    return b.gltf(
        meshes=[{"name": "quad", "primitives": [{"attributes": {"POSITION": quad, "TEXCOORD_0": uv},
                                                 "indices": quad_idx}]},
                {"name": "tilt", "primitives": [{"attributes": {"POSITION": tilt}}]},
                {"name": "repair", "primitives": [{"attributes": {"POSITION": rep_pos,
                                                                  "NORMAL": rep_nrm}}]}],
        nodes=[{"mesh": 0}, {"mesh": 1}, {"mesh": 2}],
        scenes=[{"nodes": [0, 1, 2]}])


def strip_fan():
    b = Builder()
    strip = b.vec([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (1.0, 1.0, 0.0)], "VEC3",
                  minmax=True)
    fan = b.vec([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0)], "VEC3",
                minmax=True)
    fan_idx = b.indices([0, 1, 2, 3], UBYTE)
    line_idx = b.indices([0, 1, 1, 2])
    return b.gltf(
        meshes=[{"name": "mixed", "primitives": [
                    {"attributes": {"POSITION": strip}, "mode": POINTS},
                    {"attributes": {"POSITION": strip}, "mode": STRIP},
                    {"attributes": {"POSITION": strip}, "indices": line_idx, "mode": LINES}]},
                {"name": "fan", "primitives": [{"attributes": {"POSITION": fan}, "indices": fan_idx,
                                                "mode": FAN}]}],
        nodes=[{"mesh": 0}, {"mesh": 1, "translation": [0, 0, 1]}],
        scenes=[{"nodes": [0, 1]}])


def materials():
    b = Builder()
    pos = b.vec(TRIANGLE, "VEC3", minmax=True)
    nrm = b.vec([(0.0, 0.0, 1.0)] * 3, "VEC3")
    uv0 = b.vec([(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], "VEC2")
    uv1 = b.vec([(0.5, 0.5), (1.0, 0.5), (0.5, 1.0)], "VEC2")
    attributes = {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": uv0, "TEXCOORD_1": uv1}
    images = [
        # 2×2 RGB: red, green / blue, sRGB grey 128.
        {"name": "rgb", "uri": png_uri(png(2, 2, 3, [255, 0, 0, 0, 255, 0, 0, 0, 255,
                                                      128, 128, 128]))},
        {"name": "grey", "uri": png_uri(png(2, 1, 1, [0, 188]))},
        {"name": "rgba16", "uri": png_uri(png(1, 1, 4, [65535, 32768, 0, 16384], bits=16))},
        {"name": "grey_alpha", "uri": png_uri(png(1, 1, 2, [100, 50]))},
    ]
    transform = {"KHR_texture_transform": {"offset": [0.5, 0.25], "rotation": 0.3,
                                           "scale": [2, 3], "texCoord": 1}}
    return b.gltf(
        extensionsUsed=["KHR_texture_transform", "KHR_materials_emissive_strength",
                        "KHR_materials_specular", "KHR_materials_ior"],
        extensionsRequired=["KHR_texture_transform", "KHR_materials_specular"],
        images=images,
        samplers=[{"magFilter": NEAREST, "wrapS": CLAMP, "wrapT": MIRROR},
                  {"magFilter": LINEAR, "wrapS": REPEAT, "wrapT": REPEAT}],
        textures=[{"source": 0, "sampler": 0}, {"source": 1}, {"source": 2, "sampler": 1},
                  {"source": 3}],
        materials=[
            {"name": "full",
             "pbrMetallicRoughness": {
                 "baseColorFactor": [0.5, 0.25, 1.0, 0.3],
                 "baseColorTexture": {"index": 0, "extensions": transform},
                 "metallicFactor": 0.2, "roughnessFactor": 0.7,
                 "metallicRoughnessTexture": {"index": 1}},
             "normalTexture": {"index": 2, "scale": 0.8, "texCoord": 1},
             "emissiveFactor": [1.0, 0.5, 0.25],
             "emissiveTexture": {"index": 0},
             "doubleSided": True,
             "alphaMode": "MASK",
             "alphaCutoff": 0.25,
             "extensions": {
                 "KHR_materials_emissive_strength": {"emissiveStrength": 4.0},
                 "KHR_materials_specular": {
                     "specularFactor": 0.6, "specularTexture": {"index": 2},
                     "specularColorFactor": [1.2, 0.9, 0.8],
                     "specularColorTexture": {"index": 3, "extensions": {
                         "KHR_texture_transform": {"offset": [0.1, 0.2]}}}},
                 "KHR_materials_ior": {"ior": 1.33}}},
            {"name": "linear_rgb", "pbrMetallicRoughness": {"metallicRoughnessTexture": {"index": 0}}},
            {"name": "defaults"},
        ],
        meshes=[{"name": "tri", "primitives": [
            {"attributes": attributes, "material": 0},
            {"attributes": attributes, "material": 1},
            {"attributes": attributes, "material": 2},
            {"attributes": attributes}]}],
        nodes=[{"mesh": 0}],
        scenes=[{"nodes": [0]}])


def lights_camera():
    b = Builder()
    pos = b.vec(TRIANGLE, "VEC3", minmax=True)
    return b.gltf(
        extensionsUsed=["KHR_lights_punctual"],
        extensions={"KHR_lights_punctual": {"lights": [
            {"name": "bulb", "type": "point", "color": [1.0, 0.5, 0.25], "intensity": 10.0},
            {"name": "spot_default", "type": "spot", "intensity": 5.0, "spot": {}},
            {"name": "spot", "type": "spot", "spot": {"innerConeAngle": 0.1, "outerConeAngle": 0.5}},
            {"name": "sun", "type": "directional", "intensity": 2.0}]}},
        cameras=[{"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.05, "zfar": 100}},
                 {"type": "orthographic",
                  "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}],
        meshes=[{"primitives": [{"attributes": {"POSITION": pos}}]}],
        nodes=[{"name": "bulb", "translation": [1, 2, 3],
                "extensions": {"KHR_lights_punctual": {"light": 0}}},
               {"name": "spot_default", "translation": [0, 5, 0], "rotation": quat((1, 0, 0), -90),
                "extensions": {"KHR_lights_punctual": {"light": 1}}},
               {"name": "spot", "extensions": {"KHR_lights_punctual": {"light": 2}}},
               {"name": "sun", "rotation": quat((0, 1, 0), 90),
                "extensions": {"KHR_lights_punctual": {"light": 3}}},
               {"name": "sun_parent", "scale": [5, 5, 5], "children": [3]},
               {"name": "ortho", "camera": 1},
               {"name": "camera_parent", "translation": [0, 0, 10], "scale": [2, 2, 2],
                "children": [7]},
               {"name": "camera", "camera": 0, "translation": [0, 1, 0], "rotation": [0, 1, 0, 0]},
               {"name": "second_camera", "camera": 0, "translation": [100, 100, 100]},
               {"name": "geometry", "mesh": 0}],
        scenes=[{"nodes": [0, 1, 2, 4, 5, 6, 8, 9]}])


def wide_angle():
    """A closed 2 m room lit from the ceiling, seen from its centre with yfov 3.1 (tan(yfov/2) ≈ 48)
    and znear 0.2: the near plane cuts through most of the view, so a renderer that does not clip
    where the rasteriser clips shows a different image."""
    b = Builder()
    # Origin and edges u, v of each face; u × v points into the room.
    quads = [((-1, -1, -1), (0, 0, 2), (2, 0, 0)),   # floor, facing up
             ((-1, 1, -1), (2, 0, 0), (0, 0, 2)),    # ceiling, facing down
             ((-1, -1, -1), (2, 0, 0), (0, 2, 0)),   # back wall (z = -1), facing +z
             ((-1, -1, 1), (0, 2, 0), (2, 0, 0)),    # front wall (z = 1), facing -z
             ((-1, -1, -1), (0, 2, 0), (0, 0, 2)),   # left wall (x = -1), facing +x
             ((1, -1, -1), (0, 0, 2), (0, 2, 0))]    # right wall (x = 1), facing -x
    meshes = []
    for i, (o, u, v) in enumerate(quads):
        corners = [o, tuple(o[k] + u[k] for k in range(3)),
                   tuple(o[k] + u[k] + v[k] for k in range(3)), tuple(o[k] + v[k] for k in range(3))]
        pos = b.vec([tuple(float(c) for c in p) for p in corners], "VEC3", minmax=True)
        idx = b.indices([0, 1, 2, 0, 2, 3])
        meshes.append({"primitives": [{"attributes": {"POSITION": pos}, "indices": idx,
                                       "material": 1 if i == 1 else 0}]})
    return b.gltf(
        materials=[{"pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.6, 0.5, 1],
                                             "metallicFactor": 0}},
                   {"pbrMetallicRoughness": {"metallicFactor": 0}, "emissiveFactor": [1, 1, 1]}],
        cameras=[{"type": "perspective", "perspective": {"yfov": 3.1, "znear": 0.2}}],
        meshes=meshes,
        nodes=[{"mesh": i} for i in range(6)] + [{"camera": 0, "translation": [0.3, 0, 0.5]}],
        scenes=[{"nodes": list(range(7))}])


def defaults():
    b = Builder()
    pos = b.vec([(-1.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 2.0, 0.0)], "VEC3", minmax=True)
    # No scenes: every parentless node is shown. No camera, no material.
    return b.gltf(meshes=[{"primitives": [{"attributes": {"POSITION": pos}}]}],
                  nodes=[{"mesh": 0, "children": [1]}, {"mesh": 0, "translation": [0, 0, -4]},
                         {"mesh": 0, "translation": [3, 0, 0]}])


def box_glb():
    b = Builder()
    faces = [((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
             ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
             ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (0, 1, 0), (1, 0, 0))]
    interleaved, uvs, tangents, indices = bytearray(), bytearray(), bytearray(), []
    for f, (n, u, v) in enumerate(faces):
        for su, sv, uv in ((-1, -1, (0, 65535)), (1, -1, (65535, 65535)), (1, 1, (65535, 0)),
                           (-1, 1, (0, 0))):
            p = [0.5 * (n[i] + su * u[i] + sv * v[i]) for i in range(3)]
            interleaved += struct.pack("<6f", *p, *n)
            uvs += struct.pack("<2H", *uv)
            tangents += struct.pack("<4f", *u, 1.0)
        indices += [4 * f, 4 * f + 1, 4 * f + 2, 4 * f, 4 * f + 2, 4 * f + 3]
    view = b.view(bytes(interleaved), stride=24)
    pos = b.accessor(view, FLOAT, 24, "VEC3", min=[-0.5] * 3, max=[0.5] * 3)
    nrm = b.accessor(view, FLOAT, 24, "VEC3", byteOffset=12)
    uv = b.accessor(b.view(bytes(uvs)), USHORT, 24, "VEC2", normalized=True)
    tan = b.accessor(b.view(bytes(tangents)), FLOAT, 24, "VEC4")
    idx = b.indices(indices)
    # Sparse: vertex 1 of the triangle moves to (2, 0, 0); TEXCOORD_1 is zeros but for two.
    tri = b.vec(TRIANGLE, "VEC3")
    sparse_pos = b.accessor(b.accessors[tri]["bufferView"], FLOAT, 3, "VEC3", min=[0, 0, 0],
                            max=[2, 1, 0], sparse={
                                "count": 1,
                                "indices": {"bufferView": b.view(bytes([1])), "componentType": UBYTE},
                                "values": {"bufferView": b.view(struct.pack("<3f", 2, 0, 0))}})
    sparse_uv = b.accessor(None, FLOAT, 3, "VEC2", sparse={
        "count": 2,
        "indices": {"bufferView": b.view(struct.pack("<2H", 0, 2)), "componentType": USHORT},
        "values": {"bufferView": b.view(struct.pack("<4f", 0.5, 0.5, 1, 1))}})
    ubyte_idx = b.indices([2, 1, 0], UBYTE)
    image_view = b.view(png(1, 1, 4, [255, 128, 0, 255]))
    doc = b.gltf(
        images=[{"bufferView": image_view, "mimeType": "image/png"}],
        textures=[{"source": 0}],
        materials=[{"name": "boxmat", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        meshes=[{"name": "box", "primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm,
                                                               "TEXCOORD_0": uv, "TANGENT": tan},
                                                "indices": idx, "material": 0}]},
                {"name": "sparse", "primitives": [{"attributes": {"POSITION": sparse_pos,
                                                                  "TEXCOORD_1": sparse_uv}}]},
                {"name": "ubyte", "primitives": [{"attributes": {"POSITION": tri},
                                                  "indices": ubyte_idx}]}],
        nodes=[{"name": "box", "mesh": 0, "translation": [0, 1, 0]},
               {"name": "sparse", "mesh": 1, "translation": [5, 0, 0]},
               {"name": "ubyte", "mesh": 2, "translation": [-5, 0, 0]}],
        scenes=[{"nodes": [0, 1, 2]}],
        scene=0)
    del doc["buffers"][0]["uri"]
    return glb(doc, b.data)


# ---------------------------------------------------------------------------------------------
# Bad-input corpus: a valid one-triangle scene with one thing wrong.


def base(positions=TRIANGLE, index_values=(0, 1, 2)):
    b = Builder()
    pos = b.vec(positions, "VEC3")
    idx = b.indices(list(index_values))
    doc = b.gltf(materials=[{}],
                 meshes=[{"primitives": [{"attributes": {"POSITION": pos}, "indices": idx,
                                          "material": 0}]}],
                 nodes=[{"mesh": 0}], scenes=[{"nodes": [0]}], scene=0)
    return doc, b


def variant(edit):
    doc, _ = base()
    edit(doc)
    return text(doc)


def base_glb():
    doc, b = base()
    del doc["buffers"][0]["uri"]
    return glb(doc, b.data)


def set_path(doc, path, value):
    node = doc
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value


def bad_corpus():
    files = {}
    setter = lambda path, value: variant(lambda d: set_path(d, path, value))  # noqa: E731

    files["empty.gltf"] = ""
    files["empty.glb"] = b""
    files["not-json.gltf"] = "this is not a glTF file\n"
    files["truncated-json.gltf"] = variant(lambda d: None)[:200]
    files["json-root-is-array.gltf"] = "[1, 2, 3]\n"
    files["missing-asset.gltf"] = variant(lambda d: d.pop("asset"))
    files["gltf-version-1.gltf"] = setter(["asset", "version"], "1.0")
    files["deep-nesting.gltf"] = ('{"asset": {"version": "2.0"}, "extras": ' + "[" * 20000 +
                                  "]" * 20000 + "}\n")
    files["accessor-past-buffer-view.gltf"] = setter(["accessors", 0, "count"], 4)
    files["accessor-past-buffer.gltf"] = setter(["bufferViews", 0, "byteLength"], 100)
    files["accessor-offset-overflow.gltf"] = setter(["accessors", 0, "byteOffset"],
                                                    2**64 - 12)
    files["buffer-view-offset-overflow.gltf"] = setter(["bufferViews", 0, "byteOffset"],
                                                       2**64 - 16)
    files["absurd-accessor-count.gltf"] = setter(["accessors", 0, "count"], 4000000000)
    files["absurd-count-without-buffer-view.gltf"] = variant(
        lambda d: (d["accessors"][0].pop("bufferView"), set_path(d, ["accessors", 0, "count"],
                                                                 300000000)))
    files["negative-buffer-length.gltf"] = setter(["buffers", 0, "byteLength"], -44)
    files["absurd-buffer-length.gltf"] = setter(["buffers", 0, "byteLength"], 10**15)
    files["empty-data-uri-buffer.gltf"] = variant(
        lambda d: d["buffers"][0].update(uri="data:application/octet-stream;base64,", byteLength=0))
    files["stride-smaller-than-element.gltf"] = setter(["bufferViews", 0, "byteStride"], 4)
    files["bad-accessor-index.gltf"] = setter(
        ["meshes", 0, "primitives", 0, "attributes", "POSITION"], 9)
    files["position-not-vec3.gltf"] = setter(["accessors", 0, "type"], "VEC2")
    files["position-unsigned-byte.gltf"] = setter(["accessors", 0, "componentType"], UBYTE)
    files["no-position.gltf"] = setter(["meshes", 0, "primitives", 0, "attributes"],
                                       {"NORMAL": 0})
    files["invalid-mode.gltf"] = setter(["meshes", 0, "primitives", 0, "mode"], 9)
    files["lines-only.gltf"] = setter(["meshes", 0, "primitives", 0, "mode"], LINES)
    files["points-only.gltf"] = setter(["meshes", 0, "primitives", 0, "mode"], POINTS)
    files["index-count-not-multiple-of-3.gltf"] = setter(["accessors", 1, "count"], 2)
    files["bad-material-index.gltf"] = setter(["meshes", 0, "primitives", 0, "material"], 5)
    files["bad-node-mesh-index.gltf"] = setter(["nodes", 0, "mesh"], 2)
    files["bad-default-scene.gltf"] = setter(["scene"], 4)
    files["scene-bad-node-index.gltf"] = setter(["scenes", 0, "nodes"], [0, 7])
    files["node-cycle.gltf"] = setter(["nodes"], [{"mesh": 0, "children": [1]},
                                                  {"children": [2]}, {"children": [1]}])
    files["node-self-child.gltf"] = setter(["nodes"], [{"mesh": 0, "children": [0]}])
    files["node-two-parents.gltf"] = variant(lambda d: (
        set_path(d, ["nodes"], [{"children": [2]}, {"children": [2]}, {"mesh": 0}]),
        set_path(d, ["scenes", 0, "nodes"], [0, 1])))
    files["node-bad-child-index.gltf"] = setter(["nodes", 0, "children"], [3])
    files["number-overflow-in-matrix.gltf"] = setter(
        ["nodes", 0, "matrix"], [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, INF, 0, 0, 1])
    files["position-beyond-float-range.gltf"] = setter(["nodes", 0, "translation"], [1e39, 0, 0])
    # Every scale in range (scene_range.h), their product (1e9^40) not even a double.
    files["nan-transform.gltf"] = setter(["nodes"], [
        {"scale": [1e9, 1e9, 1e9], "children": [i + 1]} for i in range(40)] + [{"mesh": 0}])
    files["nan-literal-in-transform.gltf"] = setter(["nodes", 0, "translation"], [NAN, 0, 0])
    files["zero-quaternion.gltf"] = setter(["nodes", 0, "rotation"], [0, 0, 0, 0])
    files["wrong-matrix-length.gltf"] = setter(["nodes", 0, "matrix"], [1, 0, 0, 0])
    files["inf-position.gltf"] = variant_positions([(0.0, 0.0, 0.0), (math.inf, 0.0, 0.0),
                                                    (0.0, 1.0, 0.0)])
    files["nan-position.gltf"] = variant_positions([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0),
                                                    (0.0, math.nan, 0.0)])
    files["index-past-vertex-count.gltf"] = text(base(index_values=(0, 1, 7))[0])
    files["missing-external-buffer.gltf"] = variant(lambda d: d["buffers"][0].update(
        uri="missing-buffer.bin"))
    files["buffer-uri-is-device.gltf"] = variant(lambda d: d["buffers"][0].update(
        uri="../../../../../../../../dev/zero"))
    files["required-extension-unsupported.gltf"] = setter(["extensionsRequired"],
                                                          ["KHR_draco_mesh_compression"])
    textured = lambda d, info: (  # noqa: E731
        d.update(images=[{"uri": png_uri(png(1, 1, 3, [1, 2, 3]))}], textures=[{"source": 0}]),
        set_path(d, ["materials", 0], {"pbrMetallicRoughness": {"baseColorTexture": info}}))
    files["bad-texture-index.gltf"] = variant(lambda d: textured(d, {"index": 3}))
    files["texcoord-set-2.gltf"] = variant(lambda d: textured(d, {"index": 0, "texCoord": 2}))
    files["missing-external-image.gltf"] = variant(lambda d: (
        textured(d, {"index": 0}), d["images"][0].update(uri="missing-image.png")))
    files["image-undecodable.gltf"] = variant(lambda d: (
        textured(d, {"index": 0}),
        d["images"][0].update(uri=png_uri(b"\x89PNG\r\n\x1a\nthis is no image at all"))))
    # Two images whose headers read and whose zlib streams end early: texture 0's (2048², slow
    # to inflate) is the one named, though texture 1's (1×1) fails first when the two decode in
    # parallel: the loader reports the first problem in the order the materials asked for them.
    def cut_short(width):
        whole = png(width, width, 3, [90] * (width * width * 3), level=9)
        stream = whole[41:-16]  # after the signature, IHDR and IDAT's length and tag; before CRC
        stream = stream[:len(stream) * 9 // 10]
        return (whole[:33] + struct.pack(">I", len(stream)) + b"IDAT" + stream + b"\0\0\0\0" +
                whole[-12:])
    files["images-cut-short.gltf"] = variant(lambda d: (
        d.update(images=[{"uri": png_uri(cut_short(2048))}, {"uri": png_uri(cut_short(1))}],
                 textures=[{"source": 0}, {"source": 1}]),
        set_path(d, ["materials", 0], {"pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1}}})))
    # Small enough for stb_image's own limit, too big for ours (and the IHDR CRC is left stale,
    # which stb_image does not check).
    huge = png(1, 1, 1, [0])
    huge = huge[:16] + struct.pack(">II", 16384, 16384) + huge[24:]
    files["image-huge-dimensions.gltf"] = variant(lambda d: (
        textured(d, {"index": 0}), d["images"][0].update(uri=png_uri(huge))))
    files["image-buffer-view-past-buffer.gltf"] = variant(lambda d: (
        textured(d, {"index": 0}),
        d["bufferViews"].append({"buffer": 0, "byteOffset": 40, "byteLength": 1000}),
        d["images"][0].pop("uri"), d["images"][0].update(bufferView=2, mimeType="image/png")))
    files["texture-without-source.gltf"] = variant(lambda d: (
        textured(d, {"index": 0}), d["textures"][0].pop("source")))
    files["bad-sampler-wrap.gltf"] = variant(lambda d: (
        textured(d, {"index": 0}), d.update(samplers=[{"wrapS": 1234}]),
        d["textures"][0].update(sampler=0)))
    files["negative-material-factor.gltf"] = setter(
        ["materials", 0], {"pbrMetallicRoughness": {"roughnessFactor": -0.5}})
    files["ior-below-one.gltf"] = setter(
        ["materials", 0], {"extensions": {"KHR_materials_ior": {"ior": 0.5}}})
    files["unknown-alpha-mode.gltf"] = setter(["materials", 0], {"alphaMode": "CUTOUT"})
    lit = lambda d, light, node_light=0: (  # noqa: E731
        d.update(extensions={"KHR_lights_punctual": {"lights": [light]}}),
        d["nodes"][0].update(extensions={"KHR_lights_punctual": {"light": node_light}}))
    files["bad-light-index.gltf"] = variant(lambda d: lit(d, {"type": "point"}, 3))
    files["spot-inner-above-outer.gltf"] = variant(lambda d: lit(
        d, {"type": "spot", "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.3}}))
    files["bad-camera-index.gltf"] = setter(["nodes", 0, "camera"], 2)
    files["camera-zero-yfov.gltf"] = variant(lambda d: (
        d.update(cameras=[{"type": "perspective", "perspective": {"yfov": 0, "znear": 0.1}}]),
        d["nodes"][0].update(camera=0)))
    files["sparse-index-past-count.gltf"] = sparse_past_count()
    files["normal-count-mismatch.gltf"] = normal_count_mismatch()

    good = base_glb()
    files["truncated.glb"] = good[:len(good) // 2]
    files["glb-short-header.glb"] = good[:10]
    files["glb-bad-version.glb"] = good[:4] + struct.pack("<I", 1) + good[8:]
    files["glb-length-past-end.glb"] = good[:8] + struct.pack("<I", len(good) + 100) + good[12:]
    files["glb-bad-json-chunk-length.glb"] = good[:12] + struct.pack("<I", 0x7FFFFFF0) + good[16:]
    json_length = struct.unpack("<I", good[12:16])[0]
    bin_at = 20 + json_length
    bin_length = struct.unpack("<I", good[bin_at:bin_at + 4])[0]
    # 8 bytes too long: tinygltf 2.7's own check forgets the chunk header and would read past.
    files["glb-bin-chunk-past-end.glb"] = (good[:bin_at] + struct.pack("<I", bin_length + 8) +
                                           good[bin_at + 4:])
    doc, b = base()
    del doc["buffers"][0]["uri"]
    files["glb-without-bin-chunk.glb"] = glb(doc, None)
    files["unknown-extension.xyz"] = "o triangle\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
    files["no-file-extension"] = text(base()[0])
    return files


def variant_positions(positions):
    return text(base(positions=positions)[0])


def sparse_past_count():
    doc, b = base()
    indices_view = b.view(bytes([5]))
    values_view = b.view(struct.pack("<3f", 1, 1, 1))
    doc = b.gltf(**{k: v for k, v in doc.items() if k not in ("asset", "buffers", "bufferViews",
                                                               "accessors")})
    doc["accessors"][0]["sparse"] = {"count": 1,
                                     "indices": {"bufferView": indices_view, "componentType": UBYTE},
                                     "values": {"bufferView": values_view}}
    return text(doc)


def normal_count_mismatch():
    doc, b = base()
    normals = b.vec([(0.0, 0.0, 1.0)] * 2, "VEC3")
    doc = b.gltf(**{k: v for k, v in doc.items() if k not in ("asset", "buffers", "bufferViews",
                                                               "accessors")})
    doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = normals
    return text(doc)


def main():
    good = {
        "transforms.gltf": text(transforms()),
        "flat_normals.gltf": text(flat_normals()),
        "strip_fan.gltf": text(strip_fan()),
        "materials.gltf": text(materials()),
        "lights_camera.gltf": text(lights_camera()),
        "defaults.gltf": text(defaults()),
        "wide_angle.gltf": text(wide_angle()),
        "box.glb": box_glb(),
    }
    for name, content in good.items():
        write(HERE / name, content)
    BAD.mkdir(exist_ok=True)
    from range_fixtures import range_corpus  # beside this file; it uses the helpers above
    for name, content in {**bad_corpus(), **range_corpus(sys.modules[__name__])}.items():
        write(BAD / name, content)


if __name__ == "__main__":
    main()
