"""What the glTF writers of this repository share: glTF's enum values, buffer views packed into
one binary buffer, and PNG encoding. Standard library only.

Users: tools/make_scenes.py, tools/make_textured_scene.py, tools/make_dragon_scene.py and
tests/data/gltf/make_fixtures.py. Each finds this module by a sys.path entry relative to its own
file, so that it runs from any working directory. Accessors and the document itself stay with
each writer on purpose: the files they write are committed (or compared) byte for byte, and each
spells its accessors' keys in its own order, with its own bounds.
"""

import struct
import zlib

# componentType
UBYTE, USHORT, UINT, FLOAT = 5121, 5123, 5125, 5126
# bufferView.target
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963


class Buffer:
    """One binary buffer (data) and its buffer views (views, the document's "bufferViews")."""

    def __init__(self, views=None):
        self.data = bytearray()
        self.views = [] if views is None else views

    def pad(self):
        """Zero bytes up to a multiple of four: where every view starts, and the buffer's end."""
        self.data.extend(bytes(-len(self.data) % 4))

    def view(self, payload, target=None, stride=None):
        """Appends payload as a new view of buffer 0; returns the view's index."""
        self.pad()
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload)}
        if stride:
            view["byteStride"] = stride
        if target is not None:
            view["target"] = target
        self.data.extend(payload)
        self.views.append(view)
        return len(self.views) - 1


def png(width, height, channels, samples, bits=8, level=-1):
    """A PNG (no filtering, zlib at level) of samples: width × height pixels of `channels` values
    each (grey, grey+alpha, RGB, RGBA), row 0 at the top, 0..255 or, with bits=16, 0..65535."""
    colour_type = {1: 0, 2: 4, 3: 2, 4: 6}[channels]
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter: none
        row = samples[y * width * channels:(y + 1) * width * channels]
        raw += struct.pack(">%dH" % len(row), *row) if bits == 16 else bytes(row)

    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data +
                struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", width, height, bits, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(bytes(raw), level)) + chunk(b"IEND", b""))
