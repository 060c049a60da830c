# Writes examples/scenes/meshes/torus.gltf (python3 make_torus.py > torus.gltf): a torus (R 1, r 0.4) with KHR_mesh_quantization
# attributes, the buffer embedded as base64. Deterministic.
import base64, json, math, struct, sys
R, r, N, M = 1.0, 0.4, 64, 32
pos, nrm, tan, uv = [], [], [], []
for i in range(N + 1):
    u = i / N; a = 2 * math.pi * u
    for j in range(M + 1):
        v = j / M; b = 2 * math.pi * v
        cx, cz = math.cos(a), math.sin(a)
        p = ((R + r * math.cos(b)) * cx, r * math.sin(b), (R + r * math.cos(b)) * cz)
        n = (math.cos(b) * cx, math.sin(b), math.cos(b) * cz)
        t = (-math.sin(a), 0.0, math.cos(a))
        pos.append(p); nrm.append(n); tan.append(t); uv.append((u * 4, v))
idx = []
for i in range(N):
    for j in range(M):
        a0 = i * (M + 1) + j; b0 = a0 + (M + 1)
        idx += [a0, a0 + 1, b0, b0, a0 + 1, b0 + 1]
# Positions quantised to SHORT normalized over the bounds; the node's scale and translation decode.
ext = [max(abs(p[k]) for p in pos) for k in range(3)]
def q16(x): return max(-32767, min(32767, round(x * 32767)))
def q8(x): return max(-127, min(127, round(x * 127)))
buf = bytearray()
for p in pos: buf += struct.pack('<hhhh', *(q16(p[k] / ext[k]) for k in range(3)), 0)
o_n = len(buf)
for n in nrm: buf += struct.pack('<bbbb', *(q8(c) for c in n), 0)
o_t = len(buf)
for t in tan: buf += struct.pack('<bbbb', *(q8(c) for c in t), -127)
o_uv = len(buf)
for t in uv: buf += struct.pack('<HH', *(max(0, min(65535, round(c / 4 * 65535))) for c in t))
o_i = len(buf)
for i in idx: buf += struct.pack('<H', i)
n = len(pos)
doc = {
  "asset": {"version": "2.0", "generator": "examples/scenes/meshes/make_torus.py (KHR_mesh_quantization)"},
  "extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"],
  "buffers": [{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(buf)).decode()}],
  "bufferViews": [
    {"buffer": 0, "byteOffset": 0, "byteLength": o_n, "byteStride": 8},
    {"buffer": 0, "byteOffset": o_n, "byteLength": o_t - o_n, "byteStride": 4},
    {"buffer": 0, "byteOffset": o_t, "byteLength": o_uv - o_t, "byteStride": 4},
    {"buffer": 0, "byteOffset": o_uv, "byteLength": o_i - o_uv, "byteStride": 4},
    {"buffer": 0, "byteOffset": o_i, "byteLength": len(buf) - o_i}],
  "accessors": [
    {"bufferView": 0, "componentType": 5122, "normalized": True, "count": n, "type": "VEC3", "min": [-1, -1, -1], "max": [1, 1, 1]},
    {"bufferView": 1, "componentType": 5120, "normalized": True, "count": n, "type": "VEC3"},
    {"bufferView": 2, "componentType": 5120, "normalized": True, "count": n, "type": "VEC4"},
    {"bufferView": 3, "componentType": 5123, "normalized": True, "count": n, "type": "VEC2"},
    {"bufferView": 4, "componentType": 5123, "count": len(idx), "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TANGENT": 2, "TEXCOORD_0": 3}, "indices": 4}]}],
  "nodes": [{"mesh": 0, "scale": [round(e, 6) for e in ext]}],
  "scenes": [{"nodes": [0]}], "scene": 0}
sys.stdout.write(json.dumps(doc, indent=1) + "\n")
