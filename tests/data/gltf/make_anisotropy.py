#!/usr/bin/env python3
"""Writes anisotropy.gltf: two unit spheres side by side (TANGENT along the parallels, w = 1), one
KHR_materials_anisotropy material each (tests/runtime/test_gltf_materials.cpp,
GltfMaterials.AnisotropyExtensionDrawsTheExtensionsLobe):
  0 (left)  factors only: roughness 0.3, strength 0.6, rotation 0.5 rad
  1 (right) an anisotropyTexture, uniform: direction 30 degrees (R 238, G 191), strength B 204 (0.8),
            times anisotropyStrength 0.9, turned by anisotropyRotation -0.3 rad; roughness 0.25
The texture is one colour, so that a hand-written Facet material with the mapped constants draws
the same image. Run from this folder: python3 make_anisotropy.py"""
import json, math

from gltf_writer import Buffer, data_uri, png


# 2 · rg − 1 ≈ (cos 30°, sin 30°): R = round(255 (1 + cos 30°) / 2), G = round(255 (1 + sin 30°) / 2).
direction = png(4, 4, lambda x, y: (238, 191, 204, 255))

rings, segments = 16, 32
positions, normals, tangents, uvs, indices = [], [], [], [], []
for i in range(rings + 1):
    theta = math.pi * i / rings
    for j in range(segments + 1):
        phi = 2 * math.pi * j / segments
        p = [math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi)]
        positions += p
        normals += p
        tangents += [math.cos(phi), 0.0, -math.sin(phi), 1.0]  # dP/dphi: u grows along it
        uvs += [j / segments, i / rings]
for i in range(rings):
    for j in range(segments):
        a, b = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
        indices += [a, b, a + 1, a + 1, b, b + 1]

buffer = Buffer()


n = (rings + 1) * (segments + 1)
attributes = {"POSITION": buffer.add(positions, "f", "VEC3", n, 5126, 34962, True),
              "NORMAL": buffer.add(normals, "f", "VEC3", n, 5126, 34962),
              "TANGENT": buffer.add(tangents, "f", "VEC4", n, 5126, 34962),
              "TEXCOORD_0": buffer.add(uvs, "f", "VEC2", n, 5126, 34962)}
a_idx = buffer.add(indices, "H", "SCALAR", len(indices), 5123, 34963)

gltf = {
    "asset": {"version": "2.0", "generator": "Facet tests/data/gltf/make_anisotropy.py"},
    "extensionsUsed": ["KHR_materials_anisotropy"],
    "scene": 0,
    "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"mesh": 0, "translation": [-1.1, 0, 0]}, {"mesh": 1, "translation": [1.1, 0, 0]}],
    "meshes": [{"primitives": [{"attributes": attributes, "indices": a_idx, "material": m}]} for m in (0, 1)],
    "materials": [
        {"name": "brushed",
         "pbrMetallicRoughness": {"baseColorFactor": [0.95, 0.93, 0.88, 1], "metallicFactor": 1,
                                  "roughnessFactor": 0.3},
         "extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": 0.6, "anisotropyRotation": 0.5}}},
        {"name": "brushed_textured",
         "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.7, 0.5, 1], "metallicFactor": 1,
                                  "roughnessFactor": 0.25},
         "extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": 0.9, "anisotropyRotation": -0.3,
                                                     "anisotropyTexture": {"index": 0}}}},
    ],
    "textures": [{"source": 0}],
    "images": [{"uri": data_uri("image/png", direction)}],
    **buffer.gltf(),
}
with open("anisotropy.gltf", "w") as f:
    json.dump(gltf, f, separators=(", ", ": "))
    f.write("\n")
