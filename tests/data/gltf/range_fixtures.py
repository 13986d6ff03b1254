"""The bad-input fixtures for engine/scene/scene_range.h (values that are finite as doubles but
beyond what float positions, Embree and the shaders carry) and for refusals that must name the
right cause. Written by make_fixtures.py, which passes itself as `m` (its base scene, variant and
set_path helpers), into tests/data/bad/.
"""
import base64
import random
import struct

DIRECTIONAL = {"type": "directional", "intensity": 1e5}


def lit(d, light, node=None):
    """Adds KHR_lights_punctual light 0 on a new root node (or `node`, a dict, as given)."""
    d["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
    node = dict(node or {})
    node["extensions"] = {"KHR_lights_punctual": {"light": 0}}
    d["nodes"].append(node)
    d["scenes"][0]["nodes"].append(len(d["nodes"]) - 1)


def camera(d, perspective, node=None):
    d["cameras"] = [{"type": "perspective", "perspective": perspective}]
    node = dict(node or {})
    node["camera"] = 0
    d["nodes"].append(node)
    d["scenes"][0]["nodes"].append(len(d["nodes"]) - 1)


def textured(m, d, transform):
    d.update(images=[{"uri": m.png_uri(m.png(1, 1, 3, [1, 2, 3]))}], textures=[{"source": 0}])
    info = {"index": 0, "extensions": {"KHR_texture_transform": transform}}
    m.set_path(d, ["materials", 0], {"pbrMetallicRoughness": {"baseColorTexture": info}})


def random_positions():
    """Nine floats from random bytes (as a corrupt .bin gives them), kept finite so that the
    range check, not the finiteness check, is what refuses them."""
    rng = random.Random(19)
    values = []
    while len(values) < 9:
        (x,) = struct.unpack("<f", bytes(rng.randrange(256) for _ in range(4)))
        if x == x and abs(x) != float("inf"):
            values.append(x)
    assert max(abs(v) for v in values) > 1e9
    return [tuple(values[i:i + 3]) for i in range(0, 9, 3)]


def range_corpus(m):
    files = {}

    def setter(path, value):
        return m.variant(lambda d: m.set_path(d, path, value))

    def positions(rows, edit=None):
        doc = m.base(positions=rows)[0]
        if edit:
            edit(doc)
        return m.text(doc)

    files["translation-beyond-range.gltf"] = setter(["nodes", 0, "translation"], [0, 1e12, 0])
    files["matrix-beyond-range.gltf"] = setter(
        ["nodes", 0, "matrix"], [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 3e38, 0, 0, 1])
    files["vertex-beyond-range.gltf"] = positions([(0.0, 0.0, 0.0), (2e12, 0.0, 0.0),
                                                   (0.0, 1.0, 0.0)])
    # Each value is in range; the world-space vertex is not.
    files["scaled-vertex-beyond-range.gltf"] = positions(
        [(0.0, 0.0, 0.0), (1000.0, 0.0, 0.0), (0.0, 1000.0, 0.0)],
        lambda d: m.set_path(d, ["nodes", 0, "scale"], [1e7, 1e7, 1e7]))
    files["random-bytes-positions.gltf"] = positions(random_positions())
    files["emissive-factor-beyond-range.gltf"] = setter(["materials", 0],
                                                        {"emissiveFactor": [1e308, 0, 0]})
    files["emissive-strength-product-beyond-range.gltf"] = setter(["materials", 0], {
        "emissiveFactor": [1e10, 1, 1],
        "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 1e10}}})
    files["base-color-factor-beyond-range.gltf"] = setter(
        ["materials", 0], {"pbrMetallicRoughness": {"baseColorFactor": [0.5, 1e300, 0.5, 1]}})
    files["texture-transform-scale-beyond-range.gltf"] = m.variant(
        lambda d: textured(m, d, {"scale": [1e308, 1]}))
    files["texture-transform-offset-beyond-range.gltf"] = m.variant(
        lambda d: textured(m, d, {"offset": [0, -3e38]}))
    files["light-intensity-beyond-range.gltf"] = m.variant(
        lambda d: lit(d, {"type": "point", "intensity": 1e38}))
    files["light-color-beyond-range.gltf"] = m.variant(
        lambda d: lit(d, {"type": "point", "color": [1, 1e20, 1]}))
    files["light-position-beyond-range.gltf"] = m.variant(lambda d: (
        lit(d, {"type": "point"}, {"translation": [0, 0, 1e6]}),
        d["nodes"].append({"scale": [1e6, 1e6, 1e6], "children": [1]}),
        m.set_path(d, ["scenes", 0, "nodes"], [0, 2])))
    # A scene of 1e9 m (the limit), lit by the Sun's 1e5 W/m²: π r² E ≈ 1.6e23 W.
    files["directional-light-power-beyond-range.gltf"] = positions(
        [(0.0, 0.0, 0.0), (1e9, 0.0, 0.0), (0.0, 1e9, 0.0)], lambda d: lit(d, DIRECTIONAL))
    # An emissive triangle of 2e17 m² with radiance 1e6: π A L ≈ 6.4e23 W.
    files["area-light-power-beyond-range.gltf"] = positions(
        [(0.0, 0.0, 0.0), (6.4e8, 0.0, 0.0), (0.0, 6.4e8, 0.0)],
        lambda d: m.set_path(d, ["materials", 0], {
            "emissiveFactor": [1, 1, 1],
            "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 1e6}}}))
    files["camera-yfov-tiny.gltf"] = m.variant(lambda d: camera(d, {"yfov": 1e-30, "znear": 0.1},
                                                                {"translation": [0, 0, 5]}))
    files["camera-yfov-pi.gltf"] = m.variant(lambda d: camera(
        d, {"yfov": 3.14159265358979, "znear": 0.1}, {"translation": [0, 0, 5]}))
    files["camera-znear-tiny.gltf"] = m.variant(lambda d: camera(d, {"yfov": 0.7, "znear": 1e-30},
                                                                 {"translation": [0, 0, 5]}))
    files["camera-position-beyond-range.gltf"] = m.variant(lambda d: (
        camera(d, {"yfov": 0.7, "znear": 0.1}, {"translation": [0, 0, 1e6]}),
        d["nodes"].append({"scale": [1e6, 1e6, 1e6], "children": [1]}),
        m.set_path(d, ["scenes", 0, "nodes"], [0, 2])))
    # As a Draco file reads without the extension: the compressed primitive's accessors have no
    # buffer view of their own, and this one names a view that does not exist, which tinygltf
    # refuses before the loader sees extensionsRequired.
    files["draco-required-before-accessor-error.gltf"] = m.variant(lambda d: (
        m.set_path(d, ["accessors", 0, "bufferView"], 7),
        d.update(extensionsUsed=["KHR_draco_mesh_compression"],
                 extensionsRequired=["KHR_draco_mesh_compression"]),
        d["meshes"][0]["primitives"][0].update(extensions={
            "KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}})))
    # A JPEG's start-of-image marker and JFIF header, then a quantisation table cut short.
    jpeg = (b"\xff\xd8\xff\xe0\x00\x10JFIF\x00\x01\x01\x00\x00\x01\x00\x01\x00\x00"
            b"\xff\xdb\x00\x43\x00" + b"\x10" * 12)
    files["image-corrupt-jpeg.gltf"] = m.variant(lambda d: (
        textured(m, d, {}), d["images"][0].update(
            uri="data:image/jpeg;base64," + base64.b64encode(jpeg).decode())))
    # A WebP (RIFF container) that a file passes off as PNG.
    webp = b"RIFF\x1a\x00\x00\x00WEBPVP8L\x0d\x00\x00\x00\x2f\x00\x00\x00\x10\x07\x10\x11\x11\x88\x88\xfe\x07\x00"
    files["image-webp-as-png.gltf"] = m.variant(lambda d: (
        textured(m, d, {}), d["images"][0].update(
            uri="data:image/png;base64," + base64.b64encode(webp).decode())))
    return files
