#!/usr/bin/env python3
"""Write the procedurally built test scenes bundled under assets/.

    python3 tools/make_scenes.py            # writes both scenes
    python3 tools/make_scenes.py --check    # also re-reads and validates the files

Scenes (each a .gltf plus one .bin buffer, standard library only, same bytes on every run):

  assets/two-room/two-room.gltf   two rooms joined by a small hole; the light is in the room the
                                  camera does not see (Segovia et al. 2007, Fig. 4 style)
  assets/glossy/glossy.gltf       8 spheres (4 metal, 4 plastic, roughness 0.05/0.2/0.4/0.8) on a
                                  checkered floor, one emissive quad and one point light

Conventions (docs: docs/design.md "Units and conventions"): right-handed, metres, +Y up, the camera
looks down its local -Z. Emissive triangles emit from their front face only: the face whose
counter-clockwise winding (a, b, c) gives the normal (b - a) x (c - a). Every flat face here is
wound so that this geometric normal equals the stored NORMAL.
"""

import json
import math
import os
import struct
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_writer import ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, FLOAT, UINT, Buffer  # noqa: E402


# --------------------------------------------------------------------------------------------
# small vector helpers
# --------------------------------------------------------------------------------------------

def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(a):
    n = math.sqrt(dot(a, a))
    return (a[0] / n, a[1] / n, a[2] / n)


def f32(x):
    """Round to the float32 value that is stored in the .bin."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def clean(x, digits=6):
    """Short, deterministic JSON numbers."""
    r = round(x, digits)
    if r == 0:
        r = 0.0  # no "-0.0"
    if r == int(r) and abs(r) < 1e9:
        return int(r)
    return r


def look_at_quaternion(eye, target, up=(0.0, 1.0, 0.0)):
    """Unit quaternion [x, y, z, w] that turns the camera's -Z towards target, +Y towards up."""
    f = normalize(sub(target, eye))  # forward = -Z_cam
    r = normalize(cross(f, up))  # +X_cam
    u = cross(r, f)  # +Y_cam
    z = scale(f, -1.0)
    # rotation matrix columns: r, u, z
    m00, m01, m02 = r[0], u[0], z[0]
    m10, m11, m12 = r[1], u[1], z[1]
    m20, m21, m22 = r[2], u[2], z[2]
    tr = m00 + m11 + m22
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        w, x, y, zq = 0.25 * s, (m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s
    elif m00 > m11 and m00 > m22:
        s = math.sqrt(1.0 + m00 - m11 - m22) * 2
        w, x, y, zq = (m21 - m12) / s, 0.25 * s, (m01 + m10) / s, (m02 + m20) / s
    elif m11 > m22:
        s = math.sqrt(1.0 + m11 - m00 - m22) * 2
        w, x, y, zq = (m02 - m20) / s, (m01 + m10) / s, 0.25 * s, (m12 + m21) / s
    else:
        s = math.sqrt(1.0 + m22 - m00 - m11) * 2
        w, x, y, zq = (m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25 * s
    if w < 0:
        w, x, y, zq = -w, -x, -y, -zq
    return [x, y, zq, w]


# --------------------------------------------------------------------------------------------
# mesh building
# --------------------------------------------------------------------------------------------

class Mesh:
    """Triangle list with per-vertex positions and normals (one glTF primitive)."""

    def __init__(self, name, material):
        self.name = name
        self.material = material
        self.positions = []
        self.normals = []
        self.indices = []
        self.flat = True  # flat faces: winding must agree with NORMAL

    def polygon(self, pts, normal):
        """Convex planar polygon, fan-triangulated, front face towards `normal`.

        The winding is reversed if needed so that (b - a) x (c - a) points along `normal`."""
        n = normalize(normal)
        g = cross(sub(pts[1], pts[0]), sub(pts[2], pts[0]))
        if dot(g, n) < 0:
            pts = list(reversed(pts))
        base = len(self.positions)
        for p in pts:
            self.positions.append(tuple(float(c) for c in p))
            self.normals.append(n)
        for i in range(1, len(pts) - 1):
            self.indices += [base, base + i, base + i + 1]

    def rect(self, axis, coord, lo, hi, normal):
        """Axis-aligned rectangle in the plane `axis` = coord; lo/hi are the other two coordinates
        in (x, y, z) order with the `axis` component left out."""
        (a0, b0), (a1, b1) = lo, hi
        corners = [(a0, b0), (a1, b0), (a1, b1), (a0, b1)]
        pts = []
        for u, v in corners:
            if axis == 0:
                pts.append((coord, u, v))
            elif axis == 1:
                pts.append((u, coord, v))
            else:
                pts.append((u, v, coord))
        self.polygon(pts, normal)

    def triangle_count(self):
        return len(self.indices) // 3


def wall_with_hole(mesh, x, y0, y1, z0, z1, hy0, hy1, hz0, hz1, normal):
    """Plane x = const covering [y0,y1] x [z0,z1] minus the hole [hy0,hy1] x [hz0,hz1].

    Four trapezoids between the outer and the inner rectangle (8 triangles, no T-junctions)."""
    o = [(x, y0, z0), (x, y0, z1), (x, y1, z1), (x, y1, z0)]
    h = [(x, hy0, hz0), (x, hy0, hz1), (x, hy1, hz1), (x, hy1, hz0)]
    for i in range(4):
        j = (i + 1) % 4
        mesh.polygon([o[i], o[j], h[j], h[i]], normal)


def uv_sphere(mesh, center, radius, segments=32, rings=16):
    """UV sphere with smooth outward normals: 2 pole vertices + (rings-1) rings of `segments`."""
    mesh.flat = False
    base = len(mesh.positions)
    cx, cy, cz = center

    def put(n):
        mesh.normals.append(n)
        mesh.positions.append((cx + radius * n[0], cy + radius * n[1], cz + radius * n[2]))

    put((0.0, 1.0, 0.0))  # north pole
    for r in range(1, rings):
        theta = math.pi * r / rings
        st, ct = math.sin(theta), math.cos(theta)
        for s in range(segments):
            phi = 2.0 * math.pi * s / segments
            put((st * math.cos(phi), ct, -st * math.sin(phi)))
    put((0.0, -1.0, 0.0))  # south pole
    north, south = base, base + 1 + (rings - 1) * segments

    def ring(r, s):  # r in 1..rings-1
        return base + 1 + (r - 1) * segments + (s % segments)

    # counter-clockwise seen from outside: phi grows counter-clockwise seen from +Y
    for s in range(segments):
        mesh.indices += [north, ring(1, s), ring(1, s + 1)]
    for r in range(1, rings - 1):
        for s in range(segments):
            a, b = ring(r, s), ring(r, s + 1)
            c, d = ring(r + 1, s), ring(r + 1, s + 1)
            mesh.indices += [a, c, d, a, d, b]
    for s in range(segments):
        mesh.indices += [south, ring(rings - 1, s + 1), ring(rings - 1, s)]


# --------------------------------------------------------------------------------------------
# glTF assembly
# --------------------------------------------------------------------------------------------

class Gltf:
    def __init__(self, name, generator):
        self.name = name
        self.doc = {
            "asset": {"version": "2.0", "generator": generator},
            "extensionsUsed": [],
            "scene": 0,
            "scenes": [{"name": name, "nodes": []}],
            "nodes": [],
            "meshes": [],
            "materials": [],
            "accessors": [],
            "bufferViews": [],
            "buffers": [],
        }
        self.buffer = Buffer(self.doc["bufferViews"])
        self.material_index = {}
        self.shared_index_accessors = {}

    def use_extension(self, ext):
        if ext not in self.doc["extensionsUsed"]:
            self.doc["extensionsUsed"].append(ext)

    def material(self, name, base, metallic=0.0, roughness=1.0, lambertian=False,
                 emission=None, strength=None):
        m = {
            "name": name,
            "pbrMetallicRoughness": {
                "baseColorFactor": [clean(c) for c in base] + [1],
                "metallicFactor": clean(metallic),
                "roughnessFactor": clean(roughness),
            },
        }
        ext = {}
        if emission is not None:
            m["emissiveFactor"] = [clean(c) for c in emission]
            if strength is not None and strength != 1.0:
                ext["KHR_materials_emissive_strength"] = {"emissiveStrength": clean(strength)}
        if lambertian:
            ext["KHR_materials_specular"] = {"specularFactor": 0}
        if ext:
            m["extensions"] = ext
            for k in ext:
                self.use_extension(k)
        self.material_index[name] = len(self.doc["materials"])
        self.doc["materials"].append(m)
        return self.material_index[name]

    def _vec3_accessor(self, values, with_bounds):
        data = b"".join(struct.pack("<3f", *v) for v in values)
        acc = {"bufferView": self.buffer.view(data, ARRAY_BUFFER, 12), "byteOffset": 0,
               "componentType": FLOAT, "count": len(values), "type": "VEC3"}
        if with_bounds:
            stored = [tuple(f32(c) for c in v) for v in values]
            # float32 values written with repr(): exact round trip to the stored bits
            acc["min"] = [min(v[i] for v in stored) for i in range(3)]
            acc["max"] = [max(v[i] for v in stored) for i in range(3)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def _index_accessor(self, indices):
        key = tuple(indices)
        if key in self.shared_index_accessors:
            return self.shared_index_accessors[key]
        data = struct.pack("<%dI" % len(indices), *indices)
        acc = {"bufferView": self.buffer.view(data, ELEMENT_ARRAY_BUFFER), "byteOffset": 0,
               "componentType": UINT, "count": len(indices), "type": "SCALAR",
               "min": [min(indices)], "max": [max(indices)]}
        self.doc["accessors"].append(acc)
        self.shared_index_accessors[key] = len(self.doc["accessors"]) - 1
        return self.shared_index_accessors[key]

    def add_mesh(self, mesh):
        pos = self._vec3_accessor(mesh.positions, True)
        nrm = self._vec3_accessor(mesh.normals, False)
        idx = self._index_accessor(mesh.indices)
        self.doc["meshes"].append({
            "name": mesh.name,
            "primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm}, "indices": idx,
                            "material": mesh.material, "mode": 4}],
        })
        self.add_node({"name": mesh.name, "mesh": len(self.doc["meshes"]) - 1})

    def add_node(self, node):
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def add_camera(self, name, eye, target, yfov_deg, aspect=1.0, znear=0.01, zfar=100.0):
        self.doc.setdefault("cameras", []).append({
            "name": name, "type": "perspective",
            "perspective": {"yfov": clean(math.radians(yfov_deg), 9), "aspectRatio": clean(aspect),
                            "znear": clean(znear), "zfar": clean(zfar)}})
        q = look_at_quaternion(eye, target)
        self.add_node({"name": name, "camera": len(self.doc["cameras"]) - 1,
                       "translation": [clean(c) for c in eye],
                       "rotation": [clean(c, 9) for c in q]})

    def add_point_light(self, name, position, color, intensity):
        self.use_extension("KHR_lights_punctual")
        lights = self.doc.setdefault("extensions", {}).setdefault(
            "KHR_lights_punctual", {"lights": []})["lights"]
        lights.append({"name": name, "type": "point", "color": [clean(c) for c in color],
                       "intensity": clean(intensity)})
        self.add_node({"name": name, "translation": [clean(c) for c in position],
                       "extensions": {"KHR_lights_punctual": {"light": len(lights) - 1}}})

    def finish(self, bin_name):
        self.buffer.pad()
        self.doc["buffers"].append({"uri": bin_name, "byteLength": len(self.buffer.data)})
        self.doc["extensionsUsed"].sort()
        if not self.doc["extensionsUsed"]:
            del self.doc["extensionsUsed"]
        # move the big arrays to the end for readability
        for k in ("accessors", "bufferViews", "buffers"):
            self.doc[k] = self.doc.pop(k)
        text = json.dumps(self.doc, indent=1) + "\n"
        return text, bytes(self.buffer.data)


# --------------------------------------------------------------------------------------------
# validation (runs on what is about to be written, and again on the files with --check)
# --------------------------------------------------------------------------------------------

def validate(doc, binary, label):
    errors = []

    def err(msg):
        errors.append("%s: %s" % (label, msg))

    buffers = doc["buffers"]
    if len(buffers) != 1 or buffers[0]["byteLength"] != len(binary):
        err("buffer byteLength %s != .bin size %d" % (buffers[0]["byteLength"], len(binary)))
    if len(binary) >= 300 * 1024:
        err(".bin is %d bytes (limit 300 KB)" % len(binary))
    sizes = {FLOAT: 4, UINT: 4}
    ncomp = {"SCALAR": 1, "VEC3": 3}
    views = doc["bufferViews"]
    end = 0
    for i, v in enumerate(views):
        if v["byteOffset"] % 4:
            err("bufferView %d offset %d not 4-byte aligned" % (i, v["byteOffset"]))
        if v["byteOffset"] < end:
            err("bufferView %d overlaps the previous one" % i)
        end = v["byteOffset"] + v["byteLength"]
        if end > len(binary):
            err("bufferView %d runs past the buffer" % i)
    accs = doc["accessors"]
    for i, a in enumerate(accs):
        v = views[a["bufferView"]]
        elem = sizes[a["componentType"]] * ncomp[a["type"]]
        stride = v.get("byteStride", elem)
        need = a.get("byteOffset", 0) + stride * (a["count"] - 1) + elem
        if need > v["byteLength"]:
            err("accessor %d needs %d bytes, view has %d" % (i, need, v["byteLength"]))
        if a.get("byteOffset", 0) % 4:
            err("accessor %d offset not aligned" % i)

    def read(ai):
        a = accs[ai]
        v = views[a["bufferView"]]
        n = ncomp[a["type"]]
        fmt = "<%d%s" % (n, "f" if a["componentType"] == FLOAT else "I")
        elem = 4 * n
        stride = v.get("byteStride", elem)
        off = v["byteOffset"] + a.get("byteOffset", 0)
        return [struct.unpack_from(fmt, binary, off + k * stride) for k in range(a["count"])]

    tris = {}
    for mi, m in enumerate(doc["meshes"]):
        for p in m["primitives"]:
            if p.get("mode", 4) != 4:
                err("mesh %s: not triangles" % m["name"])
            pa = p["attributes"]["POSITION"]
            na = p["attributes"].get("NORMAL")
            if "min" not in accs[pa] or "max" not in accs[pa]:
                err("mesh %s: POSITION accessor lacks min/max" % m["name"])
            pos = read(pa)
            mn = [min(q[k] for q in pos) for k in range(3)]
            mx = [max(q[k] for q in pos) for k in range(3)]
            if mn != accs[pa]["min"] or mx != accs[pa]["max"]:
                err("mesh %s: POSITION min/max do not match the data" % m["name"])
            if na is None:
                err("mesh %s: no NORMAL" % m["name"])
                continue
            if accs[na]["count"] != len(pos):
                err("mesh %s: NORMAL count != POSITION count" % m["name"])
            nrm = read(na)
            for q in nrm:
                if abs(math.sqrt(dot(q, q)) - 1.0) > 1e-5:
                    err("mesh %s: normal not unit length" % m["name"])
                    break
            ia = accs[p["indices"]]
            if ia["componentType"] != UINT:
                err("mesh %s: indices not UNSIGNED_INT" % m["name"])
            idx = [t[0] for t in read(p["indices"])]
            if len(idx) % 3:
                err("mesh %s: index count not a multiple of 3" % m["name"])
            if max(idx) >= len(pos):
                err("mesh %s: index %d >= vertex count %d" % (m["name"], max(idx), len(pos)))
                continue
            bad = 0
            for t in range(0, len(idx), 3):
                a, b, c = (pos[idx[t + k]] for k in range(3))
                g = cross(sub(b, a), sub(c, a))
                gl = math.sqrt(dot(g, g))
                if gl < 1e-12:
                    bad += 1
                    continue
                navg = add(add(nrm[idx[t]], nrm[idx[t + 1]]), nrm[idx[t + 2]])
                if dot(g, navg) / (gl * math.sqrt(dot(navg, navg))) < 0.5:
                    bad += 1
            if bad:
                err("mesh %s: %d triangles degenerate or wound against their normal"
                    % (m["name"], bad))
            if m["name"].startswith("sphere"):  # closed, consistently oriented: every edge once each way
                edges = set()
                for t in range(0, len(idx), 3):
                    for k in range(3):
                        edges.add((idx[t + k], idx[t + (k + 1) % 3]))
                if len(edges) != len(idx) or any((j, i) not in edges for i, j in edges):
                    err("mesh %s: sphere not closed or inconsistently wound" % m["name"])
            tris[m["name"]] = tris.get(m["name"], 0) + len(idx) // 3
    return errors, tris


# --------------------------------------------------------------------------------------------
# scene 1: two rooms joined by a small hole
# --------------------------------------------------------------------------------------------

# Room A (lit):   x in [-4.05, -0.05]; room B (camera): x in [0.05, 4.05]; both y in [0, 3],
# z in [-1.5, 1.5]. The shared wall is the slab x in [-0.05, 0.05] with a square hole.
TR_W, TR_H, TR_D = 4.0, 3.0, 3.0  # room size along x, y, z
TR_T = 0.1  # shared wall thickness
TR_HOLE = 0.3  # hole side
TR_HOLE_Y = 1.2  # hole centre height
TR_HOLE_Z = 0.0
TR_LIGHT = 0.5  # emissive quad side
TR_LIGHT_STRENGTH = 3000.0  # emitted radiance = (1,1,1) * strength W/(sr m^2)


def two_room():
    g = Gltf("two-room", "mvpl tools/make_scenes.py (two rooms joined by a small hole)")
    grey = g.material("wall_grey", (0.7, 0.7, 0.7), lambertian=True)
    red = g.material("wall_red_roomA", (0.7, 0.12, 0.1), lambertian=True)
    blue = g.material("wall_blue_roomB", (0.12, 0.2, 0.7), lambertian=True)
    light = g.material("light", (0.0, 0.0, 0.0), lambertian=True,
                       emission=(1.0, 1.0, 1.0), strength=TR_LIGHT_STRENGTH)

    h = TR_T / 2  # shared wall faces at x = -h and x = +h
    xa0, xa1 = -h - TR_W, -h  # room A
    xb0, xb1 = h, h + TR_W  # room B
    y0, y1 = 0.0, TR_H
    z0, z1 = -TR_D / 2, TR_D / 2
    hy0, hy1 = TR_HOLE_Y - TR_HOLE / 2, TR_HOLE_Y + TR_HOLE / 2
    hz0, hz1 = TR_HOLE_Z - TR_HOLE / 2, TR_HOLE_Z + TR_HOLE / 2

    # Floor, ceiling and side walls of each room run on to the middle of the slab (x = 0), so the
    # corners where they meet the slab faces are overlapped, not just touching: no crack through
    # which a ray could pass from one room to the other except the hole.
    meshes = []
    for room, (xo, xi, sign) in (("roomA", (xa0, 0.0, +1)), ("roomB", (xb1, 0.0, -1))):
        lo_x, hi_x = min(xo, xi), max(xo, xi)
        m = Mesh(room + "_walls", grey)
        m.rect(1, y0, (lo_x, z0), (hi_x, z1), (0, 1, 0))  # floor, facing up
        m.rect(1, y1, (lo_x, z0), (hi_x, z1), (0, -1, 0))  # ceiling, facing down
        m.rect(0, xo, (y0, z0), (y1, z1), (sign, 0, 0))  # far end wall, facing the hole
        if room == "roomA":
            m.rect(2, z1, (lo_x, y0), (hi_x, y1), (0, 0, -1))  # side wall z = +1.5
        else:
            m.rect(2, z0, (lo_x, y0), (hi_x, y1), (0, 0, 1))  # side wall z = -1.5
        meshes.append(m)
        c = Mesh(room + "_coloured_wall", red if room == "roomA" else blue)
        if room == "roomA":
            c.rect(2, z0, (lo_x, y0), (hi_x, y1), (0, 0, 1))  # red wall z = -1.5 of room A
        else:
            c.rect(2, z1, (lo_x, y0), (hi_x, y1), (0, 0, -1))  # blue wall z = +1.5 of room B
        meshes.append(c)

    s = Mesh("shared_wall", grey)
    wall_with_hole(s, -h, y0, y1, z0, z1, hy0, hy1, hz0, hz1, (-1, 0, 0))  # face into room A
    wall_with_hole(s, +h, y0, y1, z0, z1, hy0, hy1, hz0, hz1, (1, 0, 0))  # face into room B
    # the hole's four side faces, facing into the opening
    s.rect(1, hy0, (-h, hz0), (h, hz1), (0, 1, 0))
    s.rect(1, hy1, (-h, hz0), (h, hz1), (0, -1, 0))
    s.rect(2, hz0, (-h, hy0), (h, hy1), (0, 0, 1))
    s.rect(2, hz1, (-h, hy0), (h, hy1), (0, 0, -1))
    meshes.append(s)

    # the luminaire: a 0.5 m square 1 cm below room A's ceiling, centred, emitting downwards
    lx = (xa0 + xa1) / 2
    ly = y1 - 0.01
    L = Mesh("light_roomA", light)
    L.rect(1, ly, (lx - TR_LIGHT / 2, -TR_LIGHT / 2), (lx + TR_LIGHT / 2, TR_LIGHT / 2),
           (0, -1, 0))
    meshes.append(L)

    for m in meshes:
        g.add_mesh(m)

    # camera in room B, near its far corner, looking back at the shared wall and the hole
    eye = (3.7, 1.75, 1.05)
    target = (0.0, 0.6, -0.15)
    g.add_camera("camera_roomB", eye, target, 60.0, 1.0)
    info = {
        "room A": "x [%g, %g]" % (xa0, xa1), "room B": "x [%g, %g]" % (xb0, xb1),
        "y": "[%g, %g]" % (y0, y1), "z": "[%g, %g]" % (z0, z1),
        "hole": "%g x %g m, y [%g, %g], z [%g, %g], wall %g m thick" % (
            TR_HOLE, TR_HOLE, hy0, hy1, hz0, hz1, TR_T),
        "light": "%g x %g m at y %g centred (%g, %g), radiance (%g, %g, %g) W/(sr m^2)" % (
            TR_LIGHT, TR_LIGHT, ly, lx, 0.0, TR_LIGHT_STRENGTH, TR_LIGHT_STRENGTH,
            TR_LIGHT_STRENGTH),
        "camera": "eye %s target %s yfov 60" % (eye, target),
    }
    return g, info


# --------------------------------------------------------------------------------------------
# scene 2: glossy spheres
# --------------------------------------------------------------------------------------------

GL_RADIUS = 0.3
GL_ROUGHNESS = (0.05, 0.2, 0.4, 0.8)
GL_SPACING = 0.8
GL_LIGHT_STRENGTH = 20.0  # area light radiance (1,1,1) * 20 W/(sr m^2)
GL_POINT_INTENSITY = 6.0  # W/sr (candela taken 1:1)


def glossy():
    g = Gltf("glossy", "mvpl tools/make_scenes.py (glossy spheres)")
    floor_a = g.material("floor_light", (0.6, 0.6, 0.6), lambertian=True)
    floor_b = g.material("floor_dark", (0.25, 0.25, 0.25), lambertian=True)
    wall = g.material("back_wall", (0.55, 0.6, 0.65), lambertian=True)
    light = g.material("light", (0.0, 0.0, 0.0), lambertian=True,
                       emission=(1.0, 1.0, 1.0), strength=GL_LIGHT_STRENGTH)
    # metals: baseColor = F0 (linear) of gold, copper, silver, aluminium
    metals = (("gold", (1.0, 0.766, 0.336)), ("copper", (0.955, 0.638, 0.538)),
              ("silver", (0.972, 0.960, 0.915)), ("aluminium", (0.913, 0.922, 0.924)))
    plastics = (("red", (0.7, 0.06, 0.05)), ("green", (0.08, 0.5, 0.1)),
                ("blue", (0.06, 0.12, 0.7)), ("yellow", (0.75, 0.6, 0.06)))

    # checkered floor: 0.5 m tiles over x [-4, 4], z [-2, 4]
    tile = 0.5
    fa, fb = Mesh("floor_light", floor_a), Mesh("floor_dark", floor_b)
    nx, nz = 16, 12
    for i in range(nx):
        for k in range(nz):
            x0, z0 = -4.0 + i * tile, -2.0 + k * tile
            (fa if (i + k) % 2 == 0 else fb).rect(1, 0.0, (x0, z0), (x0 + tile, z0 + tile),
                                                   (0, 1, 0))
    bw = Mesh("back_wall", wall)
    bw.rect(2, -2.0, (-4.0, 0.0), (4.0, 4.0), (0, 0, 1))
    meshes = [fa, fb, bw]

    # the area light: 1.2 m x 0.6 m, 2.6 m up, left-front of the spheres, facing down
    L = Mesh("light_quad", light)
    L.rect(1, 2.6, (-1.6, 0.4), (-0.4, 1.0), (0, -1, 0))
    meshes.append(L)

    xs = [(i - 1.5) * GL_SPACING for i in range(4)]
    for row, (kind, table, zc, metallic) in enumerate((("metal", metals, -0.6, 1.0),
                                                       ("plastic", plastics, 0.5, 0.0))):
        for i, ((cname, col), rough) in enumerate(zip(table, GL_ROUGHNESS)):
            name = "%s_%s_r%g" % (kind, cname, rough)
            mat = g.material(name, col, metallic=metallic, roughness=rough)
            m = Mesh("sphere_" + name, mat)
            uv_sphere(m, (xs[i], GL_RADIUS, zc), GL_RADIUS)
            meshes.append(m)

    for m in meshes:
        g.add_mesh(m)
    g.add_point_light("point_light", (1.8, 2.2, 1.6), (1.0, 0.92, 0.82), GL_POINT_INTENSITY)
    eye = (0.0, 2.4, 4.8)
    target = (0.0, 0.3, -0.1)
    g.add_camera("camera", eye, target, 42.0, 1.0)
    info = {
        "spheres": "radius %g, x %s, metal row z -0.6, plastic row z 0.5" % (
            GL_RADIUS, [clean(x) for x in xs]),
        "area light": "1.2 x 0.6 m at y 2.6, x [-1.6,-0.4], z [0.4,1.0], radiance %g" % (
            GL_LIGHT_STRENGTH),
        "point light": "(1.8, 2.2, 1.6), %g W/sr x (1, 0.92, 0.82)" % GL_POINT_INTENSITY,
        "camera": "eye %s target %s yfov 42" % (eye, target),
    }
    return g, info


# --------------------------------------------------------------------------------------------

def write_scene(builder, folder, stem):
    g, info = builder()
    bin_name = stem + ".bin"
    text, binary = g.finish(bin_name)
    errors, tris = validate(json.loads(text), binary, stem)
    if errors:
        for e in errors:
            print("ERROR", e, file=sys.stderr)
        sys.exit(1)
    out = os.path.join(ROOT, "assets", folder)
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, stem + ".gltf"), "w", newline="\n") as f:
        f.write(text)
    with open(os.path.join(out, bin_name), "wb") as f:
        f.write(binary)
    total = sum(tris.values())
    print("assets/%s/%s.gltf: %d triangles, %d bytes .bin" % (folder, stem, total, len(binary)))
    for k, v in tris.items():
        print("    %-32s %6d triangles" % (k, v))
    for k, v in info.items():
        print("    %-12s %s" % (k, v))
    return os.path.join(out, stem + ".gltf")


def check_file(path):
    with open(path) as f:
        doc = json.load(f)
    with open(os.path.join(os.path.dirname(path), doc["buffers"][0]["uri"]), "rb") as f:
        binary = f.read()
    errors, _ = validate(doc, binary, os.path.basename(path))
    for e in errors:
        print("ERROR", e, file=sys.stderr)
    return not errors


def main():
    paths = [write_scene(two_room, "two-room", "two-room"),
             write_scene(glossy, "glossy", "glossy")]
    if "--check" in sys.argv[1:]:
        ok = all(check_file(p) for p in paths)
        print("re-read check:", "ok" if ok else "FAILED")
        sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
