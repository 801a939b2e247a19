#!/usr/bin/env python3
"""Writes vkphoton's shipped glTF 2.0 scenes into scenes/ (deterministic: same bytes every run).

Each scene is one .gltf with its binary buffer embedded as a base64 data: URI. Units: metres, y up.
Run: python3 scripts/make_scenes.py [--out scenes]
"""
import argparse
import base64
import json
import math
import os
import struct

WHITE = (0.73, 0.73, 0.73)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)
# Radiance of the ceiling light (W/m^2/sr per channel), warm like the original Cornell box light.
LIGHT_RADIANCE = (17.0, 12.0, 4.0)


class GltfBuilder:
    def __init__(self):
        self.data = bytearray()
        self.doc = {
            "asset": {"version": "2.0", "generator": "vkphoton scripts/make_scenes.py"},
            "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [],
            "accessors": [], "bufferViews": [], "buffers": [],
        }
        self.extensions = set()

    def _view(self, payload, target):
        while len(self.data) % 4:
            self.data.append(0)
        offset = len(self.data)
        self.data.extend(payload)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": len(payload), "target": target})
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, values, kind):
        if kind == "VEC3":
            payload = b"".join(struct.pack("<3f", *v) for v in values)
            view = self._view(payload, 34962)
            acc = {"bufferView": view, "componentType": 5126, "count": len(values), "type": "VEC3"}
            acc["min"] = [min(v[i] for v in values) for i in range(3)]
            acc["max"] = [max(v[i] for v in values) for i in range(3)]
        else:  # indices
            payload = b"".join(struct.pack("<I", i) for i in values)
            view = self._view(payload, 34963)
            acc = {"bufferView": view, "componentType": 5125, "count": len(values), "type": "SCALAR"}
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def material(self, name, color, metallic=0.0, roughness=1.0, emissive=None, extensions=None, double_sided=False):
        m = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [*color, 1.0],
                                                     "metallicFactor": metallic, "roughnessFactor": roughness}}
        if emissive is not None:
            strength = max(emissive)
            m["emissiveFactor"] = [c / strength for c in emissive]
            m.setdefault("extensions", {})["KHR_materials_emissive_strength"] = {"emissiveStrength": strength}
            self.extensions.add("KHR_materials_emissive_strength")
        for key, value in (extensions or {}).items():
            m.setdefault("extensions", {})[key] = value
            self.extensions.add(key)
        if double_sided:
            m["doubleSided"] = True
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def mesh(self, name, positions, normals, indices, material):
        prim = {"attributes": {"POSITION": self._accessor(positions, "VEC3"),
                               "NORMAL": self._accessor(normals, "VEC3")},
                "indices": self._accessor(indices, "SCALAR"), "material": material}
        self.doc["meshes"].append({"name": name, "primitives": [prim]})
        self.node({"name": name, "mesh": len(self.doc["meshes"]) - 1})

    def node(self, node):
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def camera(self, position, yfov=0.6911):
        self.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": yfov, "aspectRatio": 1.0, "znear": 0.01}}]
        self.node({"name": "camera", "camera": 0, "translation": list(position)})

    def write(self, path):
        self.doc["buffers"] = [{"byteLength": len(self.data),
                                "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.data)).decode()}]
        if self.extensions:
            self.doc["extensionsUsed"] = sorted(self.extensions)
        with open(path, "w") as f:
            json.dump(self.doc, f, indent=1, sort_keys=True)
            f.write("\n")


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def quad(b, name, corners, material):
    """A quad p0 p1 p2 p3, counter-clockwise seen from the side its normal points to."""
    n = normalize(cross(sub(corners[1], corners[0]), sub(corners[2], corners[0])))
    b.mesh(name, list(corners), [n] * 4, [0, 1, 2, 0, 2, 3], material)


def box_mesh(b, name, center, size, angle, material):
    """An axis-aligned box of `size` rotated by `angle` radians about y, resting on y = 0."""
    hx, hy, hz = size[0] / 2, size[1], size[2] / 2
    c, s = math.cos(angle), math.sin(angle)

    def p(x, y, z):
        return (center[0] + c * x + s * z, y, center[2] - s * x + c * z)

    faces = [  # outward-facing, counter-clockwise seen from outside
        [p(-hx, 0, hz), p(hx, 0, hz), p(hx, hy, hz), p(-hx, hy, hz)],
        [p(hx, 0, -hz), p(-hx, 0, -hz), p(-hx, hy, -hz), p(hx, hy, -hz)],
        [p(hx, 0, hz), p(hx, 0, -hz), p(hx, hy, -hz), p(hx, hy, hz)],
        [p(-hx, 0, -hz), p(-hx, 0, hz), p(-hx, hy, hz), p(-hx, hy, -hz)],
        [p(-hx, hy, hz), p(hx, hy, hz), p(hx, hy, -hz), p(-hx, hy, -hz)],
        [p(-hx, 0, -hz), p(hx, 0, -hz), p(hx, 0, hz), p(-hx, 0, hz)],
    ]
    positions, normals, indices = [], [], []
    for f in faces:
        n = normalize(cross(sub(f[1], f[0]), sub(f[2], f[0])))
        base = len(positions)
        positions += f
        normals += [n] * 4
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    b.mesh(name, positions, normals, indices, material)


def sphere_mesh(b, name, center, radius, material, segments=48, rings=24):
    positions, normals, indices = [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            positions.append(tuple(center[i] + radius * n[i] for i in range(3)))
            normals.append(n)
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            c = a + segments + 1
            if r != 0:
                indices += [a, c, a + 1]
            if r != rings - 1:
                indices += [a + 1, c, c + 1]
    b.mesh(name, positions, normals, indices, material)


def cornell_room(b, light_faces_up=False):
    white = b.material("white", WHITE)
    red = b.material("red", RED)
    green = b.material("green", GREEN)
    quad(b, "floor", [(-1, 0, 1), (1, 0, 1), (1, 0, -1), (-1, 0, -1)], white)
    quad(b, "ceiling", [(-1, 2, -1), (1, 2, -1), (1, 2, 1), (-1, 2, 1)], white)
    quad(b, "back", [(-1, 0, -1), (1, 0, -1), (1, 2, -1), (-1, 2, -1)], white)
    quad(b, "left", [(-1, 0, 1), (-1, 0, -1), (-1, 2, -1), (-1, 2, 1)], red)
    quad(b, "right", [(1, 0, -1), (1, 0, 1), (1, 2, 1), (1, 2, -1)], green)
    light = b.material("light", (0.0, 0.0, 0.0), emissive=LIGHT_RADIANCE)
    hx, hz = 0.25, 0.2
    if light_faces_up:
        y = 1.6
        quad(b, "light", [(-hx, y, hz), (hx, y, hz), (hx, y, -hz), (-hx, y, -hz)], light)
        # The light's back is a black panel so it is seen dark from below.
        quad(b, "light-back", [(-hx, y - 0.001, -hz), (hx, y - 0.001, -hz), (hx, y - 0.001, hz), (-hx, y - 0.001, hz)],
             b.material("black", (0.02, 0.02, 0.02)))
    else:
        y = 1.98
        quad(b, "light", [(-hx, y, -hz), (hx, y, -hz), (hx, y, hz), (-hx, y, hz)], light)
    b.camera((0.0, 1.0, 3.9))
    return white


def cornell_box(path):
    b = GltfBuilder()
    white = cornell_room(b)
    box_mesh(b, "tall-box", (-0.33, 0, -0.3), (0.6, 1.2, 0.6), 0.29, white)
    box_mesh(b, "short-box", (0.35, 0, 0.3), (0.6, 0.6, 0.6), -0.29, white)
    b.write(path)


def cornell_ceiling(path):
    b = GltfBuilder()
    white = cornell_room(b, light_faces_up=True)
    box_mesh(b, "tall-box", (-0.33, 0, -0.3), (0.6, 1.2, 0.6), 0.29, white)
    box_mesh(b, "short-box", (0.35, 0, 0.3), (0.6, 0.6, 0.6), -0.29, white)
    b.write(path)


def cornell_glass(path):
    b = GltfBuilder()
    cornell_room(b)
    radius = 0.35
    glass = b.material("glass", (1.0, 1.0, 1.0), metallic=0.0, roughness=0.0, extensions={
        "KHR_materials_transmission": {"transmissionFactor": 1.0},
        "KHR_materials_ior": {"ior": 1.5},
        "KHR_materials_volume": {"thicknessFactor": 2 * radius},
    })
    sphere_mesh(b, "glass-sphere", (0.35, radius, 0.25), radius, glass)
    mirror = b.material("chrome", (0.95, 0.95, 0.95), metallic=1.0, roughness=0.05)
    sphere_mesh(b, "metal-sphere", (-0.45, 0.3, -0.4), 0.3, mirror)
    b.write(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "scenes"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    cornell_box(os.path.join(args.out, "cornell-box.gltf"))
    cornell_ceiling(os.path.join(args.out, "cornell-ceiling.gltf"))
    cornell_glass(os.path.join(args.out, "cornell-glass.gltf"))


if __name__ == "__main__":
    main()
