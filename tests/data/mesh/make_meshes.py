#!/usr/bin/env python3
"""Writes the PLY/OBJ test meshes (tests/data/mesh) and the malformed ones (tests/data/bad/ply-*,
obj-*) that tests/scene/test_mesh_loaders.cpp reads. Run from anywhere; deterministic output."""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
BAD = os.path.join(HERE, "..", "bad")

# A unit cube with quad faces (counter-clockwise seen from outside) plus a pentagon cap beside
# it, so that fan triangulation of 4- and 5-gons is exercised.
CUBE_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_F = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (1, 2, 6, 5), (0, 4, 7, 3)]
PENTA_V = [(3, 0, 0), (4, 0, 0), (4.3, 1, 0), (3.5, 1.6, 0), (2.7, 1, 0)]
VERTS = CUBE_V + PENTA_V
FACES = CUBE_F + [tuple(8 + i for i in range(5))]


def ply_header(fmt, nv, nf, normals=False, index_type="int", count_type="uchar"):
    h = ["ply", f"format {fmt} 1.0", "comment mvpl test mesh", f"element vertex {nv}",
         "property float x", "property float y", "property float z"]
    if normals:
        h += ["property float nx", "property float ny", "property float nz"]
    h += [f"element face {nf}", f"property list {count_type} {index_type} vertex_indices",
          "end_header"]
    return ("\n".join(h) + "\n").encode()


def ply_binary(endian, verts, faces):
    e = "<" if endian == "little" else ">"
    data = ply_header(f"binary_{endian}_endian", len(verts), len(faces))
    for v in verts:
        data += struct.pack(e + "3f", *v)
    for f in faces:
        data += struct.pack(e + "B", len(f)) + struct.pack(e + f"{len(f)}i", *f)
    return data


def ply_ascii(verts, faces, normals=None):
    data = ply_header("ascii", len(verts), len(faces), normals is not None)
    for i, v in enumerate(verts):
        vals = list(v) + (list(normals[i]) if normals else [])
        data += (" ".join(f"{x:g}" for x in vals) + "\n").encode()
    for f in faces:
        data += (f"{len(f)} " + " ".join(str(i) for i in f) + "\n").encode()
    return data


def obj(verts, faces, extra=""):
    s = "# mvpl test mesh\n" + extra
    s += "".join(f"v {x:g} {y:g} {z:g}\n" for x, y, z in verts)
    s += "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in faces)
    return s.encode()


def write(path, data):
    with open(path, "wb") as f:
        f.write(data)


def main():
    write(os.path.join(HERE, "cube-ascii.ply"), ply_ascii(VERTS, FACES))
    write(os.path.join(HERE, "cube-le.ply"), ply_binary("little", VERTS, FACES))
    write(os.path.join(HERE, "cube-be.ply"), ply_binary("big", VERTS, FACES))
    write(os.path.join(HERE, "cube.obj"), obj(VERTS, FACES))
    # One triangle with a normal per vertex (not unit length: the loader normalises).
    tri = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    write(os.path.join(HERE, "normals.ply"), ply_ascii(tri, [(0, 1, 2)], [(0, 0, 2)] * 3))
    # Two quads, a grey floor without a material and a light with Kd and Ke from lit.mtl.
    write(os.path.join(HERE, "lit.mtl"),
          b"newmtl lamp\nKd 0.1 0.2 0.3\nKe 5 4 3\n")
    write(os.path.join(HERE, "lit.obj"),
          b"mtllib lit.mtl\n"
          b"v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
          b"v -0.2 1 -0.2\nv 0.2 1 -0.2\nv 0.2 1 0.2\nv -0.2 1 0.2\n"
          b"vn 0 -1 0\n"
          b"o floor\nf 1 4 3 2\n"
          b"o lamp\nusemtl lamp\nf 5//1 6//1 7//1 8//1\n")

    good = ply_binary("little", VERTS, FACES)
    bad = {
        "ply-truncated-binary.ply": good[: len(good) - 7],
        "ply-index-out-of-range.ply": ply_ascii(tri, [(0, 1, 3)]),
        "ply-negative-index.ply": ply_ascii(tri, [(0, -1, 2)]),
        "ply-bad-magic.ply": b"plx\nformat ascii 1.0\nend_header\n",
        "ply-unknown-format.ply": b"ply\nformat binary_middle_endian 1.0\nend_header\n",
        "ply-unknown-type.ply":
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n0\n",
        "ply-no-end-header.ply": b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n",
        "ply-nan-vertex.ply": ply_ascii(tri, [(0, 1, 2)]).replace(b"\n1 0 0\n", b"\nnan 0 0\n"),
        "ply-inf-vertex-binary.ply": ply_binary("little", [(0, 0, 0), (float("inf"), 0, 0),
                                                           (0, 1, 0)], [(0, 1, 2)]),
        "ply-huge-count.ply": ply_header("binary_little_endian", 4000000000, 1) + b"\0" * 64,
        "ply-two-vertex-face.ply": ply_ascii(tri, [(0, 1)]),
        "ply-point-cloud.ply": b"ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                               b"property float y\nproperty float z\nend_header\n0 0 0\n1 1 1\n",
        "ply-bad-number.ply": ply_ascii(tri, [(0, 1, 2)]).replace(b"\n1 0 0\n", b"\n1 zero 0\n"),
        "ply-no-xyz.ply": b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float u\n"
                          b"element face 0\nproperty list uchar int vertex_indices\n"
                          b"end_header\n0\n",
        "ply-empty.ply": b"",
        "obj-index-out-of-range.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
        "obj-two-vertex-face.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n",
        "obj-no-faces.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\n",
        "obj-inf-vertex.obj": b"v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n",
        "obj-empty.obj": b"",
        # Finite floats beyond scene_range.h's kMaxCoordinate (1e9).
        "ply-vertex-beyond-range.ply": ply_ascii(tri, [(0, 1, 2)]).replace(b"\n0 1 0\n",
                                                                           b"\n0 5e13 0\n"),
        "ply-vertex-beyond-range-binary.ply": ply_binary("little", [(0, 0, 0), (0, 0, -3e20),
                                                                    (0, 1, 0)], [(0, 1, 2)]),
        "obj-vertex-beyond-range.obj": b"v 0 0 0\nv 2e12 0 0\nv 0 1 0\nf 1 2 3\n",
    }
    for name, data in bad.items():
        write(os.path.join(BAD, name), data)


if __name__ == "__main__":
    main()
