"""What make_features.py and make_anisotropy.py share: PNG images, data: URIs, and one buffer of
accessors embedded in the glTF file."""
import base64, struct, zlib


def png(width, height, pixel):
    rows = b"".join(b"\0" + b"".join(bytes(pixel(x, y)) for x in range(width)) for y in range(height))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def data_uri(mime, data):
    return "data:%s;base64,%s" % (mime, base64.b64encode(data).decode())


class Buffer:
    """Buffer 0: its bytes, bufferViews and accessors (each accessor its own 4-byte aligned view)."""

    def __init__(self):
        self.data, self.views, self.accessors = b"", [], []

    def add(self, values, fmt, kind, count, component, target, minmax=False):
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        while len(self.data) % 4:
            self.data += b"\0"
        self.views.append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(data), "target": target})
        self.data += data
        accessor = {"bufferView": len(self.views) - 1, "componentType": component, "count": count, "type": kind}
        if minmax:
            n = len(values) // count
            accessor["min"] = [min(values[i::n]) for i in range(n)]
            accessor["max"] = [max(values[i::n]) for i in range(n)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def gltf(self):
        """The file's buffers, bufferViews and accessors."""
        return {"buffers": [{"byteLength": len(self.data), "uri": data_uri("application/octet-stream", self.data)}],
                "bufferViews": self.views, "accessors": self.accessors}
