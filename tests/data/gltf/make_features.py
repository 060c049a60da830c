#!/usr/bin/env python3
"""Writes features.gltf (and features_base.png beside it): small quads, one glTF material each,
covering what the material path reads (tests/runtime/test_gltf_materials.cpp):
  0 every texture slot, occlusion on TEXCOORD_1, emissive strength, an unknown optional extension
  1 the same feature set as 0 with other factors (one shared .mat)
  2 MASK (cutoff 0.3), double-sided, a clamping sampler (reported: drawn as repeat),
    KHR_materials_specular coloured, halved and textured (drawn by its luminance; reported)
  3 BLEND without textures, with vertex colours
  4 KHR_texture_transform (offset, rotation, scale, texCoord 1), KHR_materials_ior and a grey
    KHR_materials_specular colour
  a primitive without a material (glTF's default material)
Run from this folder: python3 make_features.py"""
import json

from gltf_writer import Buffer, data_uri, png


checker = png(8, 8, lambda x, y: (230, 60, 40, 255) if (x // 2 + y // 2) % 2 else (40, 90, 220, 255))
metal_rough = png(8, 8, lambda x, y: (255, 32 * (y % 8), 32 * (x % 8), 255))
flat_normal = png(4, 4, lambda x, y: (128, 128, 255, 255))
cutout = png(8, 8, lambda x, y: (250, 250, 250, 255 if x < 4 else 20))
with open("features_base.png", "wb") as f:
    f.write(png(16, 16, lambda x, y: (16 * x, 16 * y, 128, 255)))

quads = 6
positions, normals, tangents, uv0, uv1, colours, indices = [], [], [], [], [], [], []
for q in range(quads):
    x0 = (q - quads / 2) * 1.2
    for (u, v) in [(0, 0), (1, 0), (1, 1), (0, 1)]:
        positions += [x0 + u, 1 - v, 0]  # v = 0 at the top, as glTF's UVs
        normals += [0, 0, 1]
        tangents += [1, 0, 0, 1]
        uv0 += [u, v]
        uv1 += [0.5 * u, 0.5 * v]
        colours += [1.0, 0.5 * u, 0.25 + 0.5 * v, 1.0]
for q in range(quads):
    b = 4 * q
    indices += [b, b + 3, b + 1, b + 1, b + 3, b + 2]

buffer = Buffer()


n = 4 * quads
a_pos = buffer.add(positions, "f", "VEC3", n, 5126, 34962, True)
a_nor = buffer.add(normals, "f", "VEC3", n, 5126, 34962)
a_tan = buffer.add(tangents, "f", "VEC4", n, 5126, 34962)
a_uv0 = buffer.add(uv0, "f", "VEC2", n, 5126, 34962)
a_uv1 = buffer.add(uv1, "f", "VEC2", n, 5126, 34962)
a_col = buffer.add(colours, "f", "VEC4", n, 5126, 34962)
prims = []
for q, material in enumerate([0, 1, 2, 3, 4, None]):
    a_idx = buffer.add(indices[6 * q:6 * q + 6], "H", "SCALAR", 6, 5123, 34963)
    attributes = {"POSITION": a_pos, "NORMAL": a_nor, "TANGENT": a_tan, "TEXCOORD_0": a_uv0, "TEXCOORD_1": a_uv1}
    if material == 3:
        attributes["COLOR_0"] = a_col
    prim = {"attributes": attributes, "indices": a_idx}
    if material is not None:
        prim["material"] = material
    prims.append(prim)

gltf = {
    "asset": {"version": "2.0", "generator": "Facet tests/data/gltf/make_features.py"},
    "extensionsUsed": ["KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_materials_ior",
                       "KHR_materials_specular", "EXT_facet_unknown"],
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": prims}],
    "materials": [
        {"name": "everything",
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1},
                                  "baseColorFactor": [1, 0.9, 0.8, 1], "metallicFactor": 0.7,
                                  "roughnessFactor": 0.6},
         "normalTexture": {"index": 2, "scale": 0.5},
         "occlusionTexture": {"index": 1, "texCoord": 1, "strength": 0.8},
         "emissiveTexture": {"index": 0}, "emissiveFactor": [1, 0.5, 0.2],
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2},
                        "EXT_facet_unknown": {}}},
        {"name": "everything_twin",
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 4}, "metallicRoughnessTexture": {"index": 1},
                                  "metallicFactor": 0.1, "roughnessFactor": 0.9},
         "normalTexture": {"index": 2},
         "occlusionTexture": {"index": 1, "texCoord": 1},
         "emissiveTexture": {"index": 0}},
        {"name": "cutout", "alphaMode": "MASK", "alphaCutoff": 0.3, "doubleSided": True,
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 3}, "metallicFactor": 0},
         "extensions": {"KHR_materials_specular": {"specularFactor": 0.5, "specularColorFactor": [1, 0.5, 0.25],
                                                   "specularTexture": {"index": 1}}}},
        {"name": "glass", "alphaMode": "BLEND",
         "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.6, 0.9, 0.5], "metallicFactor": 0,
                                  "roughnessFactor": 0.1}},
        {"name": "transformed",
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {
             "offset": [0.25, -0.5], "rotation": 0.5, "scale": [2, 3], "texCoord": 1}}},
             "metallicFactor": 0, "roughnessFactor": 0.4},
         "extensions": {"KHR_materials_ior": {"ior": 1.45},
                        "KHR_materials_specular": {"specularColorFactor": [1.5, 1.5, 1.5]}}},
    ],
    "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}, {"source": 2, "sampler": 0},
                 {"source": 3, "sampler": 1}, {"source": 4, "sampler": 0}],
    "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497},
                 {"magFilter": 9729, "minFilter": 9987, "wrapS": 33071, "wrapT": 33071}],
    "images": [{"uri": data_uri("image/png", checker)}, {"uri": data_uri("image/png", metal_rough)},
               {"uri": data_uri("image/png", flat_normal)}, {"uri": data_uri("image/png", cutout)},
               {"uri": "features_base.png"}],
    **buffer.gltf(),
}
with open("features.gltf", "w") as f:
    json.dump(gltf, f, separators=(", ", ": "))
    f.write("\n")
