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
import zlib

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
        view = {"buffer": 0, "byteOffset": offset, "byteLength": len(payload)}
        if target is not None:
            view["target"] = target
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, values, kind, target=34962):
        if kind == "TIME":  # animation key times: float SCALAR with min and max (glTF requires them)
            payload = b"".join(struct.pack("<f", v) for v in values)
            acc = {"bufferView": self._view(payload, None), "componentType": 5126, "count": len(values),
                   "type": "SCALAR", "min": [min(values)], "max": [max(values)]}
            self.doc["accessors"].append(acc)
            return len(self.doc["accessors"]) - 1
        if kind == "VEC3":
            payload = b"".join(struct.pack("<3f", *v) for v in values)
            view = self._view(payload, target)
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
        return self.node({"name": name, "mesh": len(self.doc["meshes"]) - 1})

    def node(self, node):
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)
        return len(self.doc["nodes"]) - 1

    def animate_translation(self, name, node, times, translations, interpolation="LINEAR"):
        """A glTF animation moving `node` through `translations` (VEC3) at `times` (seconds)."""
        sampler = {"input": self._accessor(times, "TIME"), "output": self._accessor(translations, "VEC3", None),
                   "interpolation": interpolation}
        self.doc.setdefault("animations", []).append(
            {"name": name, "samplers": [sampler], "channels": [{"sampler": 0, "target": {"node": node, "path": "translation"}}]})

    def camera(self, position, yfov=0.6911, aspect=1.0, rotation=None):
        self.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": yfov, "aspectRatio": aspect, "znear": 0.01}}]
        node = {"name": "camera", "camera": 0, "translation": list(position)}
        if rotation is not None:
            node["rotation"] = list(rotation)
        self.node(node)

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


def look_at_rotation(eye, target):
    """The unit quaternion (x, y, z, w) that turns a glTF camera (looking down -Z, +Y up) at `target`."""
    zc = normalize(sub(eye, target))
    xc = normalize(cross((0.0, 1.0, 0.0), zc))
    yc = cross(zc, xc)
    # Columns xc, yc, zc of the rotation matrix; m[r][c].
    m = [[xc[0], yc[0], zc[0]], [xc[1], yc[1], zc[1]], [xc[2], yc[2], zc[2]]]
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 2 * math.sqrt(1 + trace)
        q = ((m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, s / 4)
    elif m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = 2 * math.sqrt(1 + m[0][0] - m[1][1] - m[2][2])
        q = (s / 4, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s)
    elif m[1][1] > m[2][2]:
        s = 2 * math.sqrt(1 + m[1][1] - m[0][0] - m[2][2])
        q = ((m[0][1] + m[1][0]) / s, s / 4, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s)
    else:
        s = 2 * math.sqrt(1 + m[2][2] - m[0][0] - m[1][1])
        q = ((m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, s / 4, (m[1][0] - m[0][1]) / s)
    return normalize(q)


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
    return b.mesh(name, positions, normals, indices, material)


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


def cornell_moving(path):
    """The glass sphere of cornell-glass.gltf moving left to right under the light and back (2 s, LINEAR
    translation keys at 0, 1 and 2 s), so its caustic sweeps across the floor; the tall box stays."""
    b = GltfBuilder()
    white = cornell_room(b)
    box_mesh(b, "tall-box", (-0.5, 0, -0.55), (0.5, 1.0, 0.4), 0.29, white)
    radius = 0.25
    glass = b.material("glass", (1.0, 1.0, 1.0), metallic=0.0, roughness=0.0, extensions={
        "KHR_materials_transmission": {"transmissionFactor": 1.0},
        "KHR_materials_ior": {"ior": 1.5},
        "KHR_materials_volume": {"thicknessFactor": 2 * radius},
    })
    sphere = sphere_mesh(b, "glass-sphere", (0.0, 0.0, 0.0), radius, glass)
    # Keys exact in float, so frame 0 (and 48 at 24 fps) equal the still pose bit for bit.
    y, z = 0.5, 0.25
    start, middle = (-0.625, y, z), (0.625, y, z)
    b.doc["nodes"][sphere]["translation"] = list(start)  # the still render's pose: frame 0's
    b.animate_translation("sphere-moves", sphere, [0.0, 1.0, 2.0], [start, middle, start])
    b.write(path)


# Keller & Wald 2000's room scenes: a grid of square rooms whose walls (WALL_THICKNESS thick) are centred on
# the grid lines, so room (ix, iz) of a grid with origin (x0, z0) is the square
# [x0 + ix * ROOM_SIZE, x0 + (ix + 1) * ROOM_SIZE] x [z0 + iz * ROOM_SIZE, z0 + (iz + 1) * ROOM_SIZE].
ROOM_SIZE = 4.0
ROOM_HEIGHT = 2.5
WALL_THICKNESS = 0.1
DOOR_WIDTH = 0.9
DOOR_HEIGHT = 2.0
SLIT_WIDTH = 0.1
FLOOR_COLOR = (0.5, 0.45, 0.4)
WALL_X_COLOR = (0.7, 0.68, 0.6)  # walls in the planes x = const
WALL_Z_COLOR = (0.55, 0.62, 0.7)  # walls in the planes z = const
ROOM_LIGHT_SIZE = 0.5
ROOM_LIGHT_RADIANCE = (30.0, 27.0, 22.0)
SLIT_LIGHT_RADIANCE = (2000.0, 1800.0, 1500.0)


class Parts:
    """Quads gathered into one mesh (one node, one material)."""

    def __init__(self):
        self.positions, self.normals, self.indices = [], [], []

    def quad(self, corners, facing):
        """A planar quad whose front face (and normal) is turned towards the axis direction `facing`."""
        n = cross(sub(corners[1], corners[0]), sub(corners[2], corners[0]))
        if sum(a * b for a, b in zip(n, facing)) < 0:
            corners = corners[::-1]
        base = len(self.positions)
        self.positions += corners
        self.normals += [facing] * 4
        self.indices += [base, base + 1, base + 2, base, base + 2, base + 3]

    def emit(self, b, name, material):
        b.mesh(name, self.positions, self.normals, self.indices, material)


def wall(parts, axis, c, u0, u1, openings):
    """A floor-to-ceiling wall WALL_THICKNESS thick centred on the plane `axis` = c ("x" or "z"), running from u0
    to u1 along the other horizontal axis, with door openings (centre, width, height). Its two end faces are left
    out: they touch another wall or lie outside the building."""
    h = WALL_THICKNESS / 2

    def p(u, y, w):
        return (c + w, y, u) if axis == "x" else (u, y, c + w)

    def n(du, dy, dw):
        return (float(dw), float(dy), float(du)) if axis == "x" else (float(du), float(dy), float(dw))

    def faces(a, b, y0):  # both sides of the part of the wall over [a, b] from height y0 to the ceiling
        for side in (-h, h):
            parts.quad([p(a, y0, side), p(b, y0, side), p(b, ROOM_HEIGHT, side), p(a, ROOM_HEIGHT, side)],
                       n(0, 0, 1 if side > 0 else -1))

    start = u0
    for centre, width, height in openings:
        a, b = centre - width / 2, centre + width / 2
        faces(start, a, 0.0)
        faces(a, b, height)  # the lintel
        parts.quad([p(a, 0, -h), p(a, 0, h), p(a, height, h), p(a, height, -h)], n(1, 0, 0))  # jambs
        parts.quad([p(b, 0, -h), p(b, 0, h), p(b, height, h), p(b, height, -h)], n(-1, 0, 0))
        parts.quad([p(a, height, -h), p(b, height, -h), p(b, height, h), p(a, height, h)], n(0, -1, 0))
        start = b
    faces(start, u1, 0.0)


def room_grid(b, nx, nz, origin, door_width, lit_rooms, light_radiance):
    """nx x nz rooms; every interior wall has a door of door_width x DOOR_HEIGHT in its middle, the outer walls,
    floor and ceiling are closed. Rooms in lit_rooms get a single-sided ROOM_LIGHT_SIZE square light facing down
    just under the ceiling, in the room's centre. Nodes are named room-IX-IZ-walls-x (the walls in planes x = const
    that the room owns: its -x wall, and its +x wall on the grid's +x edge), room-IX-IZ-walls-z (likewise its -z
    and, on the +z edge, +z wall) and room-IX-IZ-light."""
    x0, z0 = origin
    s, t = ROOM_SIZE, WALL_THICKNESS
    floor = b.material("floor", FLOOR_COLOR)
    ceiling = b.material("ceiling", WHITE)
    wall_x = b.material("wall-x", WALL_X_COLOR)
    wall_z = b.material("wall-z", WALL_Z_COLOR)
    light = b.material("light", (0.0, 0.0, 0.0), emissive=light_radiance)
    xa, xb, za, zb = x0 - t / 2, x0 + nx * s + t / 2, z0 - t / 2, z0 + nz * s + t / 2
    for name, y, facing, material in (("floor", 0.0, 1.0, floor), ("ceiling", ROOM_HEIGHT, -1.0, ceiling)):
        parts = Parts()
        parts.quad([(xa, y, za), (xb, y, za), (xb, y, zb), (xa, y, zb)], (0.0, facing, 0.0))
        parts.emit(b, name, material)
    for iz in range(nz):
        for ix in range(nx):
            x1, x2, z1, z2 = x0 + ix * s, x0 + (ix + 1) * s, z0 + iz * s, z0 + (iz + 1) * s
            # Walls in planes z = const run the whole width of the grid (through the crossings)...
            walls = Parts()
            u0, u1 = (x1 - t / 2 if ix == 0 else x1), (x2 + t / 2 if ix == nx - 1 else x2)
            wall(walls, "z", z1, u0, u1, [] if iz == 0 else [(x1 + s / 2, door_width, DOOR_HEIGHT)])
            if iz == nz - 1:
                wall(walls, "z", z2, u0, u1, [])
            walls.emit(b, f"room-{ix}-{iz}-walls-z", wall_z)
            # ...the walls in planes x = const stop at their faces.
            walls = Parts()
            wall(walls, "x", x1, z1 + t / 2, z2 - t / 2, [] if ix == 0 else [(z1 + s / 2, door_width, DOOR_HEIGHT)])
            if ix == nx - 1:
                wall(walls, "x", x2, z1 + t / 2, z2 - t / 2, [])
            walls.emit(b, f"room-{ix}-{iz}-walls-x", wall_x)
            if (ix, iz) in lit_rooms:
                cx, cz, r, y = x1 + s / 2, z1 + s / 2, ROOM_LIGHT_SIZE / 2, ROOM_HEIGHT - 0.01
                parts = Parts()
                parts.quad([(cx - r, y, cz - r), (cx + r, y, cz - r), (cx + r, y, cz + r), (cx - r, y, cz + r)],
                           (0.0, -1.0, 0.0))
                parts.emit(b, f"room-{ix}-{iz}-light", light)


def rooms_10x10(path):
    """Keller & Wald 2000, figures 1 and 2: 10 x 10 rooms, each with its own light, doors to every neighbour."""
    b = GltfBuilder()
    room_grid(b, 10, 10, (-20.0, -20.0), DOOR_WIDTH, {(ix, iz) for ix in range(10) for iz in range(10)},
              ROOM_LIGHT_RADIANCE)
    # In room (5, 5) = [0, 4] x [0, 4], looking through its -z door (x = 2, z = 0) into rooms (5, 4), (5, 3)...
    eye = (2.5, 1.6, 3.7)
    b.camera(eye, yfov=math.radians(55), aspect=4 / 3, rotation=look_at_rotation(eye, (1.9, 1.1, -8.0)))
    b.write(path)


def door_slit(path):
    """Keller & Wald 2000, figure 4: the camera's room is lit only through a slit in the wall to a lit room."""
    b = GltfBuilder()
    # Room (0, 0) = [-4, 0] x [-2, 2] (camera, no light), room (1, 0) = [0, 4] x [-2, 2] (light); the slit is at
    # x = 0, z in [-0.05, 0.05], 2 m high.
    room_grid(b, 2, 1, (-4.0, -2.0), SLIT_WIDTH, {(1, 0)}, SLIT_LIGHT_RADIANCE)
    eye = (-3.6, 1.7, 1.7)
    b.camera(eye, yfov=math.radians(55), aspect=4 / 3, rotation=look_at_rotation(eye, (-1.2, 0.3, -0.2)))
    b.write(path)


# A hall of cubicles lit by many small lights among the partitions (">= 1,000 small lights among
# occluders"): CUBICLES x CUBICLES cells of CUBICLE_SIZE, partitions PARTITION_HEIGHT high (below the ceiling) with
# a doorway at one end of every cell edge, and in every cell a LIGHTS_PER_SIDE x LIGHTS_PER_SIDE grid of small
# single-triangle lights facing down under the partitions' top, so most lights are hidden from most places.
CUBICLES = 8
CUBICLE_SIZE = 2.0
HALL_HEIGHT = 3.0
PARTITION_HEIGHT = 2.0
PARTITION_THICKNESS = 0.06
CUBICLE_DOOR = 0.7
LIGHTS_PER_SIDE = 4
SMALL_LIGHT_SIZE = 0.12
SMALL_LIGHT_HEIGHT = 1.8
SMALL_LIGHT_RADIANCE = (24.0, 21.0, 17.0)


def partition_box(parts, x0, x1, z0, z1):
    """The four sides and the top of a partition segment [x0, x1] x [0, PARTITION_HEIGHT] x [z0, z1]."""
    h = PARTITION_HEIGHT
    parts.quad([(x0, 0, z0), (x0, 0, z1), (x0, h, z1), (x0, h, z0)], (-1.0, 0.0, 0.0))
    parts.quad([(x1, 0, z0), (x1, 0, z1), (x1, h, z1), (x1, h, z0)], (1.0, 0.0, 0.0))
    parts.quad([(x0, 0, z0), (x1, 0, z0), (x1, h, z0), (x0, h, z0)], (0.0, 0.0, -1.0))
    parts.quad([(x0, 0, z1), (x1, 0, z1), (x1, h, z1), (x0, h, z1)], (0.0, 0.0, 1.0))
    parts.quad([(x0, h, z0), (x1, h, z0), (x1, h, z1), (x0, h, z1)], (0.0, 1.0, 0.0))


def cubicles_1024(path):
    """1,024 small lights (one triangle each) in 8 x 8 cubicles of a closed hall."""
    b = GltfBuilder()
    n, s, t = CUBICLES, CUBICLE_SIZE, PARTITION_THICKNESS / 2
    e = n * s / 2
    shell = Parts()
    shell.quad([(-e, 0, -e), (e, 0, -e), (e, 0, e), (-e, 0, e)], (0.0, 1.0, 0.0))
    shell.emit(b, "floor", b.material("floor", FLOOR_COLOR))
    shell = Parts()
    shell.quad([(-e, HALL_HEIGHT, -e), (e, HALL_HEIGHT, -e), (e, HALL_HEIGHT, e), (-e, HALL_HEIGHT, e)], (0.0, -1.0, 0.0))
    for axis_n, c in (((1.0, 0.0, 0.0), -e), ((-1.0, 0.0, 0.0), e)):
        shell.quad([(c, 0, -e), (c, 0, e), (c, HALL_HEIGHT, e), (c, HALL_HEIGHT, -e)], axis_n)
    for axis_n, c in (((0.0, 0.0, 1.0), -e), ((0.0, 0.0, -1.0), e)):
        shell.quad([(-e, 0, c), (e, 0, c), (e, HALL_HEIGHT, c), (-e, HALL_HEIGHT, c)], axis_n)
    shell.emit(b, "shell", b.material("shell", WHITE))
    walls = Parts()
    for line in range(1, n):
        c = -e + line * s
        for cell in range(n):
            u0, u1 = -e + cell * s, -e + (cell + 1) * s
            # the doorway alternates ends so that no straight corridor crosses the hall
            a, b_ = (u0 + CUBICLE_DOOR, u1) if (line + cell) % 2 == 0 else (u0, u1 - CUBICLE_DOOR)
            partition_box(walls, c - t, c + t, a, b_)  # partitions in planes x = const
            partition_box(walls, a, b_, c - t, c + t)  # and z = const
    walls.emit(b, "partitions", b.material("partition", WALL_Z_COLOR))
    positions, normals, indices = [], [], []
    r = SMALL_LIGHT_SIZE / 2
    for iz in range(n * LIGHTS_PER_SIDE):
        for ix in range(n * LIGHTS_PER_SIDE):
            cx = -e + (ix + 0.5) * s / LIGHTS_PER_SIDE
            cz = -e + (iz + 0.5) * s / LIGHTS_PER_SIDE
            base = len(positions)
            # counter-clockwise seen from below: the front face looks down
            positions += [(cx - r, SMALL_LIGHT_HEIGHT, cz - r), (cx + r, SMALL_LIGHT_HEIGHT, cz - r),
                          (cx, SMALL_LIGHT_HEIGHT, cz + r)]
            normals += [(0.0, -1.0, 0.0)] * 3
            indices += [base, base + 1, base + 2]
    b.mesh("lights", positions, normals, indices, b.material("light", (0.0, 0.0, 0.0), emissive=SMALL_LIGHT_RADIANCE))
    # In cell (3, 3) near its corner, looking diagonally across the hall through the doorways.
    eye = (-1.8, 1.55, -1.8)
    b.camera(eye, yfov=math.radians(60), aspect=4 / 3, rotation=look_at_rotation(eye, (5.0, 0.9, 4.0)))
    b.write(path)


# A small object moving in a large room (the second selective-update benchmark scene, Dmitriev et al. 2002 §6): a closed
# HALL_SIZE hall lit by four ceiling lights, six pillars and two benches, and a glass sphere of 0.5 m rolling 3 m
# over the floor under one light in the first two seconds, then standing still. Most photon paths never meet it.
HALL_SIZE = (20.0, 5.0, 10.0)  # x, y (height), z
HALL_LIGHT_SIZE = 1.0
HALL_LIGHT_RADIANCE = (40.0, 36.0, 30.0)
HALL_LIGHTS_X = (-7.5, -2.5, 2.5, 7.5)  # centres of the lights (z = 0)
PILLAR_SIZE = 0.4
PILLARS = [(x, z) for z in (-2.5, 2.5) for x in (-5.0, 0.0, 5.0)]
BENCHES = [((-6.0, -4.3), (2.0, 0.45, 0.5)), ((4.0, -4.3), (2.0, 0.45, 0.5))]  # (centre x, z), size (x, y, z)


def solid_box(parts, x0, x1, y0, y1, z0, z1, top=True):
    """The four sides (and the top) of the box [x0, x1] x [y0, y1] x [z0, z1], facing out."""
    parts.quad([(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)], (-1.0, 0.0, 0.0))
    parts.quad([(x1, y0, z0), (x1, y0, z1), (x1, y1, z1), (x1, y1, z0)], (1.0, 0.0, 0.0))
    parts.quad([(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)], (0.0, 0.0, -1.0))
    parts.quad([(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)], (0.0, 0.0, 1.0))
    if top:
        parts.quad([(x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)], (0.0, 1.0, 0.0))


def hall_moving(path):
    """A 20 x 10 x 5 m hall (floor, ceiling, walls of two colours, pillars, benches; 88 triangles without the sphere)
    and a glass sphere (radius 0.25, 960 triangles) moving from x = -4 to -1 at z = 1 on the floor (LINEAR keys at
    0 and 2 s; the node's static translation is the start), passing under the light at x = -2.5."""
    b = GltfBuilder()
    ex, h, ez = HALL_SIZE[0] / 2, HALL_SIZE[1], HALL_SIZE[2] / 2
    floor = Parts()
    floor.quad([(-ex, 0, -ez), (ex, 0, -ez), (ex, 0, ez), (-ex, 0, ez)], (0.0, 1.0, 0.0))
    floor.emit(b, "floor", b.material("floor", FLOOR_COLOR))
    ceiling = Parts()
    ceiling.quad([(-ex, h, -ez), (ex, h, -ez), (ex, h, ez), (-ex, h, ez)], (0.0, -1.0, 0.0))
    ceiling.emit(b, "ceiling", b.material("ceiling", WHITE))
    ends = Parts()  # the walls in the planes x = const
    for facing, c in (((1.0, 0.0, 0.0), -ex), ((-1.0, 0.0, 0.0), ex)):
        ends.quad([(c, 0, -ez), (c, 0, ez), (c, h, ez), (c, h, -ez)], facing)
    ends.emit(b, "end-walls", b.material("wall-x", WALL_X_COLOR))
    sides = Parts()  # the long walls in the planes z = const
    for facing, c in (((0.0, 0.0, 1.0), -ez), ((0.0, 0.0, -1.0), ez)):
        sides.quad([(-ex, 0, c), (ex, 0, c), (ex, h, c), (-ex, h, c)], facing)
    sides.emit(b, "side-walls", b.material("wall-z", WALL_Z_COLOR))
    furniture = Parts()
    r = PILLAR_SIZE / 2
    for x, z in PILLARS:
        solid_box(furniture, x - r, x + r, 0.0, h, z - r, z + r, top=False)
    for (x, z), (sx, sy, sz) in BENCHES:
        solid_box(furniture, x - sx / 2, x + sx / 2, 0.0, sy, z - sz / 2, z + sz / 2)
    furniture.emit(b, "pillars-and-benches", b.material("stone", WHITE))
    lights = Parts()
    r, y = HALL_LIGHT_SIZE / 2, h - 0.01
    for x in HALL_LIGHTS_X:
        lights.quad([(x - r, y, -r), (x + r, y, -r), (x + r, y, r), (x - r, y, r)], (0.0, -1.0, 0.0))
    lights.emit(b, "lights", b.material("light", (0.0, 0.0, 0.0), emissive=HALL_LIGHT_RADIANCE))
    radius = 0.25
    glass = b.material("glass", (1.0, 1.0, 1.0), metallic=0.0, roughness=0.0, extensions={
        "KHR_materials_transmission": {"transmissionFactor": 1.0},
        "KHR_materials_ior": {"ior": 1.5},
        "KHR_materials_volume": {"thicknessFactor": 2 * radius},
    })
    sphere = sphere_mesh(b, "glass-sphere", (0.0, 0.0, 0.0), radius, glass, segments=32, rings=16)
    # Keys exact in float, so frame 0 equals the still pose bit for bit and every frame from 2 s on the end pose.
    start, end = (-4.0, radius, 1.0), (-1.0, radius, 1.0)
    b.doc["nodes"][sphere]["translation"] = list(start)
    b.animate_translation("sphere-rolls", sphere, [0.0, 2.0], [start, end])
    # Between the pillar rows, looking down the hall (-x) along the sphere's path; most of the view is static.
    eye = (3.5, 1.7, 0.8)
    b.camera(eye, yfov=math.radians(50), aspect=4 / 3, rotation=look_at_rotation(eye, (-3.0, 0.4, 0.5)))
    b.write(path)


# A small glass sphere sliding over the floor of a room, its caustic in view: the case pilot photons find
# worst (few of them meet a small refractive object) and the selective update's path tracks find exactly.
def glass_moving(path):
    """A 3 x 2.5 x 3 m room (white floor and ceiling, red and green side walls) lit by a 0.3 m ceiling light, and a
    glass sphere (radius 0.15, ior 1.5) sliding along x on the floor from x = -0.8 to 0.8 in the first second
    (LINEAR keys at 0 and 1 s, then still), its caustic on the floor beside it; a camera looks down at its way."""
    b = GltfBuilder()
    white = b.material("white", WHITE)
    red = b.material("red", RED)
    green = b.material("green", GREEN)
    ex, h, ez = 1.5, 2.5, 1.5
    quad(b, "floor", [(-ex, 0, ez), (ex, 0, ez), (ex, 0, -ez), (-ex, 0, -ez)], white)
    quad(b, "ceiling", [(-ex, h, -ez), (ex, h, -ez), (ex, h, ez), (-ex, h, ez)], white)
    quad(b, "back", [(-ex, 0, -ez), (ex, 0, -ez), (ex, h, -ez), (-ex, h, -ez)], white)
    quad(b, "front", [(-ex, 0, ez), (-ex, h, ez), (ex, h, ez), (ex, 0, ez)], white)
    quad(b, "left", [(-ex, 0, ez), (-ex, 0, -ez), (-ex, h, -ez), (-ex, h, ez)], red)
    quad(b, "right", [(ex, 0, -ez), (ex, 0, ez), (ex, h, ez), (ex, h, -ez)], green)
    light = b.material("light", (0.0, 0.0, 0.0), emissive=(60.0, 55.0, 45.0))
    r, y = 0.15, h - 0.01
    quad(b, "light", [(-r, y, -r), (r, y, -r), (r, y, r), (-r, y, r)], light)
    radius = 0.15
    glass = b.material("glass", (1.0, 1.0, 1.0), metallic=0.0, roughness=0.0, extensions={
        "KHR_materials_transmission": {"transmissionFactor": 1.0},
        "KHR_materials_ior": {"ior": 1.5},
        "KHR_materials_volume": {"thicknessFactor": 2 * radius},
    })
    sphere = sphere_mesh(b, "glass-sphere", (0.0, 0.0, 0.0), radius, glass, segments=32, rings=16)
    # Keys exact in float, so frame 0 equals the still pose bit for bit and every frame from 1 s on the end pose.
    start, end = (-0.8, radius, 0.25), (0.8, radius, 0.25)
    b.doc["nodes"][sphere]["translation"] = list(start)
    b.animate_translation("sphere-slides", sphere, [0.0, 1.0], [start, end])
    eye = (0.0, 1.6, 2.2)
    b.camera(eye, yfov=math.radians(45), aspect=1.0, rotation=look_at_rotation(eye, (0.0, 0.0, 0.1)))
    b.write(path)


def spheres_outdoor(path):
    """Three spheres on a ground square and no lights: a scene for environments (--env, docs/environment.md)."""
    b = GltfBuilder()
    ground = b.material("ground", (0.5, 0.5, 0.5))
    quad(b, "ground", [(-3, 0, 3), (3, 0, 3), (3, 0, -3), (-3, 0, -3)], ground)
    glass = b.material("glass", (1.0, 1.0, 1.0), metallic=0.0, roughness=0.0, extensions={
        "KHR_materials_transmission": {"transmissionFactor": 1.0},
        "KHR_materials_ior": {"ior": 1.5},
        "KHR_materials_volume": {"thicknessFactor": 1.0},
    })
    sphere_mesh(b, "glass-sphere", (0.0, 0.5, 0.0), 0.5, glass)
    chrome = b.material("chrome", (0.95, 0.95, 0.95), metallic=1.0, roughness=0.05)
    sphere_mesh(b, "metal-sphere", (-1.2, 0.5, -0.6), 0.5, chrome)
    clay = b.material("clay", (0.7, 0.25, 0.15), metallic=0.0, roughness=0.6)
    sphere_mesh(b, "diffuse-sphere", (1.2, 0.5, -0.6), 0.5, clay)
    eye = (2.2, 1.6, 3.4)
    b.camera(eye, yfov=math.radians(40), aspect=4 / 3, rotation=look_at_rotation(eye, (0.0, 0.4, -0.3)))
    b.write(path)


def png_data_uri(width, height, rgb_rows):
    """A data: URI of an 8-bit RGB PNG (rows of (r, g, b) byte triples, top row first)."""
    def chunk(kind, payload):
        return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))
    raw = b"".join(b"\x00" + bytes(c for texel in row for c in texel) for row in rgb_rows)
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    return "data:image/png;base64," + base64.b64encode(png).decode()


def checker_floor(path):
    """A textured floor to the horizon under a sun: texture minification (mipmaps, ray cones)."""
    b = GltfBuilder()
    # 256 x 256 texels: 8 x 8 cells of 32 texels, light and dark, each cell with a thin dark
    # line along its top and left edges (detail that aliases long before the cells do).
    size, cell = 256, 32
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            light = (x // cell + y // cell) % 2 == 0
            edge = x % cell < 2 or y % cell < 2
            row.append((40, 40, 45) if edge else (230, 225, 215) if light else (120, 60, 40))
        rows.append(row)
    b.doc["images"] = [{"name": "checker", "uri": png_data_uri(size, size, rows)}]
    b.doc["samplers"] = [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}]
    b.doc["textures"] = [{"source": 0, "sampler": 0}]
    floor = b.material("floor", (1.0, 1.0, 1.0))
    b.doc["materials"][floor]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    # 400 x 400 m, the texture repeated every 4 m (TEXCOORD_0 = position / 4).
    h, tile = 200.0, 4.0
    corners = [(-h, 0.0, h), (h, 0.0, h), (h, 0.0, -h), (-h, 0.0, -h)]
    uvs = [(c[0] / tile, c[2] / tile) for c in corners]
    payload = b"".join(struct.pack("<2f", *uv) for uv in uvs)
    b.doc["accessors"].append({"bufferView": b._view(payload, 34962), "componentType": 5126, "count": 4, "type": "VEC2"})
    uv_accessor = len(b.doc["accessors"]) - 1
    b.mesh("floor", corners, [(0.0, 1.0, 0.0)] * 4, [0, 1, 2, 0, 2, 3], floor)
    b.doc["meshes"][-1]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv_accessor
    # The sun: 3 W/m^2 (lux / 683) from 50 degrees above the horizon.
    b.doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"name": "sun", "type": "directional", "intensity": 2049.0}]}}
    b.extensions.add("KHR_lights_punctual")
    b.node({"name": "sun", "rotation": list(look_at_rotation((0.0, 0.0, 0.0), (0.3, -math.sin(math.radians(50)), -0.6))),
            "extensions": {"KHR_lights_punctual": {"light": 0}}})
    eye = (0.3, 1.6, 6.0)
    b.camera(eye, yfov=math.radians(45), aspect=16 / 9, rotation=look_at_rotation(eye, (0.0, 0.0, -20.0)))
    b.write(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "scenes"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    cornell_box(os.path.join(args.out, "cornell-box.gltf"))
    cornell_ceiling(os.path.join(args.out, "cornell-ceiling.gltf"))
    cornell_glass(os.path.join(args.out, "cornell-glass.gltf"))
    cornell_moving(os.path.join(args.out, "cornell-moving.gltf"))
    hall_moving(os.path.join(args.out, "hall-moving.gltf"))
    glass_moving(os.path.join(args.out, "glass-moving.gltf"))
    rooms_10x10(os.path.join(args.out, "rooms-10x10.gltf"))
    door_slit(os.path.join(args.out, "door-slit.gltf"))
    spheres_outdoor(os.path.join(args.out, "spheres-outdoor.gltf"))
    cubicles_1024(os.path.join(args.out, "cubicles-1024.gltf"))
    checker_floor(os.path.join(args.out, "checker-floor.gltf"))


if __name__ == "__main__":
    main()
