#!/usr/bin/env python3
"""Writes the glTF test corpus: hostile or broken files here (tests/data/bad, with expected.txt:
file<TAB>substring its error message must contain) and small good files in ../good.
Run it after changing a case; commit its outputs. Python standard library only."""
import base64
import copy
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
GOOD = os.path.normpath(os.path.join(HERE, "..", "good"))

FLOAT, UINT16, UINT32 = 5126, 5123, 5125
TRIANGLE = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)  # 36 bytes, counter-clockwise seen from +Z


def data_uri(payload, media="application/octet-stream"):
    return "data:%s;base64,%s" % (media, base64.b64encode(payload).decode())


def png(width, height, rows, colour_type=6, bit_depth=8):
    """A PNG from raw scanlines (each already prefixed by its filter byte)."""
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    header = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows))
            + chunk(b"IEND", b""))


def png_header_only(width, height):
    """Signature and IHDR, no pixels: enough for a decoder to read (and refuse) the size."""
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + b"IHDR" + header
            + struct.pack(">I", zlib.crc32(b"IHDR" + header)))


def triangle_doc(buffer_uri=None):
    """One emissive triangle: the smallest file that loads. Cases below break one thing each."""
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
        "materials": [{"name": "lamp", "emissiveFactor": [1.0, 1.0, 1.0]}],
        "accessors": [{"bufferView": 0, "componentType": FLOAT, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "buffers": [{"byteLength": 36, "uri": buffer_uri or data_uri(TRIANGLE)}],
    }


def glb(doc, binary):
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text
    if binary:
        chunks += struct.pack("<II", len(binary), 0x004E4942) + binary
    return struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks


def with_uri(uri):
    return triangle_doc(buffer_uri=uri)


def changed(change):
    doc = triangle_doc()
    change(doc)
    return doc


def bad_cases():
    """(file name, contents: dict (JSON) or bytes, expected message substring)."""
    cases = []

    def add(name, contents, expected):
        cases.append((name, contents, expected))

    add("empty.gltf", b"", "the file is empty")
    add("malformed.gltf", b'{"asset": {"version": "2.0"}, "meshes": [ }', "malformed JSON")
    add("not_gltf2.gltf", changed(lambda d: d["asset"].update(version="1.0")), "asset.version")
    add("deep_json.gltf", b'{"asset": {"version": "2.0"}, "extras": ' + b"[" * 100000 + b"]" * 100000 + b"}",
        "JSON nested deeper than 64 levels")
    add("unsupported_extension.gltf",
        changed(lambda d: d.update(extensionsRequired=["KHR_draco_mesh_compression"])),
        "extensionsRequired: KHR_draco_mesh_compression is required by the file but not supported")
    add("accessor_missing.gltf",
        changed(lambda d: d["meshes"][0]["primitives"][0]["attributes"].update(POSITION=7)),
        "meshes[0].primitives[0].attributes.POSITION: accessors[7] does not exist")
    add("accessor_out_of_range.gltf", changed(lambda d: d["accessors"][0].update(count=100)),
        "meshes[0].primitives[0]: accessors[0]: 100 elements")
    add("accessor_offset_overflow.gltf", changed(lambda d: d["accessors"][0].update(byteOffset=2 ** 62)),
        "accessors[0]: 3 elements")

    def indices(values, component=UINT16):
        def change(d):
            fmt = "<%dH" % len(values) if component == UINT16 else "<%df" % len(values)
            raw = struct.pack(fmt, *values)
            raw += b"\0" * (-len(raw) % 4)
            d["buffers"].append({"byteLength": len(raw), "uri": data_uri(raw)})
            d["bufferViews"].append({"buffer": 1, "byteLength": len(raw)})
            d["accessors"].append({"bufferView": 1, "componentType": component, "count": len(values),
                                   "type": "SCALAR"})
            d["meshes"][0]["primitives"][0]["indices"] = 1
        return changed(change)

    add("index_out_of_range.gltf", indices([0, 1, 5]), "meshes[0].primitives[0]: index 5")
    add("index_float.gltf", indices([0.0, 1.0, 2.0], FLOAT), "indices must be unsigned")
    add("missing_buffer.gltf", with_uri("nothere.bin"),
        'buffers[0].uri: file "nothere.bin" not found inside the scene\'s folder')
    add("short_buffer.gltf", with_uri("short.bin"), "short buffer")
    add("short_data_uri.gltf", changed(lambda d: d["buffers"][0].update(uri=data_uri(TRIANGLE[:12]))),
        "buffers[0]: the data: URI holds 12 bytes but byteLength is 36")
    add("bufferview_out_of_range.gltf", changed(lambda d: d["bufferViews"][0].update(byteLength=48)),
        "bufferViews[0]: bytes [0, 48) exceed buffers[0] (36 bytes)")
    add("nan_position.gltf",
        changed(lambda d: d["buffers"][0].update(uri=data_uri(TRIANGLE[:12] + struct.pack("<f", float("nan"))
                                                               + TRIANGLE[16:]))),
        "meshes[0].primitives[0]: POSITION 1 is NaN or infinite (accessors[0])")
    add("inf_position.gltf",
        changed(lambda d: d["buffers"][0].update(uri=data_uri(TRIANGLE[:32] + struct.pack("<f", float("inf"))))),
        "POSITION 2 is NaN or infinite")
    add("no_scene.gltf", changed(lambda d: (d.pop("scenes"), d.pop("scene"))), "scenes: the file has no scene")

    def light_only(d):
        d["nodes"] = [{"extensions": {"KHR_lights_punctual": {"light": 0}}}]
        d["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 100}]}}
    add("no_geometry.gltf", changed(light_only), "scenes[0]: no triangle geometry")
    add("degenerate_only.gltf",
        changed(lambda d: d["buffers"][0].update(uri=data_uri(struct.pack("<9f", 0, 0, 0, 1, 1, 1, 2, 2, 2)))),
        "no triangle geometry")
    add("lines_only.gltf", changed(lambda d: d["meshes"][0]["primitives"][0].update(mode=1)),
        "primitives of other modes are skipped")
    add("no_lights.gltf", changed(lambda d: d["materials"][0].pop("emissiveFactor")), "scenes[0]: no lights")
    add("absolute_uri.gltf", with_uri("/etc/passwd"), "absolute paths are not allowed")
    add("dotdot_uri.gltf", with_uri("../good/triangle.bin"), "'..' leaves the scene's folder")
    add("encoded_dotdot_uri.gltf", with_uri("%2E%2E/good/triangle.bin"), "'..' leaves the scene's folder")
    add("home_uri.gltf", with_uri("$HOME/triangle.bin"), "shell expansion characters")
    add("tilde_uri.gltf", with_uri("~/triangle.bin"), "'~' expansion is not allowed")
    add("backtick_uri.gltf", with_uri("`id`.bin"), "shell expansion characters")
    add("http_uri.gltf", with_uri("http://example.com/triangle.bin"), "only relative paths and data: URIs are allowed")
    add("bad_percent_uri.gltf", with_uri("tri%zzangle.bin"), "malformed percent-escape")

    def textured(image):
        def change(d):
            d["materials"][0]["pbrMetallicRoughness"] = {"baseColorTexture": {"index": 0}}
            d["textures"] = [{"source": 0}]
            d["images"] = [image]
        return changed(change)

    add("image_too_large.gltf", textured({"uri": data_uri(png_header_only(20000, 20000), "image/png")}),
        "images[0]: 20000x20000 pixels exceeds the image size limit")
    add("image_too_many_pixels.gltf", textured({"uri": data_uri(png_header_only(9000, 9000), "image/png")}),
        "images[0]: 9000x9000 pixels exceeds the image size limit (16384 per side, 67108864 pixels in all)")
    add("image_not_png.gltf", textured({"uri": data_uri(b"GIF89a" + b"\0" * 32, "image/png")}),
        "images[0]: not a PNG or JPEG image")
    add("image_absolute_uri.gltf", textured({"uri": "/etc/hosts"}), "images[0].uri")
    add("image_missing.gltf", textured({"uri": "nothere.png"}),
        'images[0].uri: file "nothere.png" not found inside the scene\'s folder')
    add("image_view_missing.gltf", textured({"bufferView": 4, "mimeType": "image/png"}),
        "images[0].bufferView: bufferViews[4] does not exist")
    add("texture_missing.gltf",
        changed(lambda d: d["materials"][0].update(pbrMetallicRoughness={"baseColorTexture": {"index": 3}})),
        "materials[0].pbrMetallicRoughness.baseColorTexture.index: textures[3] does not exist")
    add("node_missing.gltf", changed(lambda d: d["scenes"][0].update(nodes=[5])),
        "scenes[0].nodes[0]: nodes[5] does not exist")
    add("node_negative.gltf", changed(lambda d: d["nodes"][0].update(mesh=-1)), "nodes[0].mesh: not a non-negative integer")
    add("node_cycle.gltf", changed(lambda d: d.update(nodes=[{"children": [1]}, {"mesh": 0, "children": [0]}])),
        "nodes[0]: is reached twice")
    add("node_two_parents.gltf",
        changed(lambda d: d.update(nodes=[{"children": [2]}, {"children": [2]}, {"mesh": 0}],
                                   scenes=[{"nodes": [0, 1]}])),
        "nodes[2]: is reached twice")
    add("bad_rotation.gltf", changed(lambda d: d["nodes"][0].update(rotation=[0, 0, 0, 0])),
        "nodes[0].rotation: is not a unit quaternion")
    add("bad_matrix.gltf", changed(lambda d: d["nodes"][0].update(matrix=[1, 0, 0, 0, 1])),
        "nodes[0].matrix: needs 16 numbers")

    def spot(d):
        d["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}})
        d["scenes"][0]["nodes"].append(1)
        d["extensions"] = {"KHR_lights_punctual": {"lights": [
            {"type": "spot", "intensity": 10, "spot": {"innerConeAngle": 1.0, "outerConeAngle": 0.5}}]}}
    add("bad_spot.gltf", changed(spot), "extensions.KHR_lights_punctual.lights[0].spot: cone angles")

    def missing_light(d):
        d["nodes"][0]["extensions"] = {"KHR_lights_punctual": {"light": 2}}
    add("light_missing.gltf", changed(missing_light),
        "nodes[0].extensions.KHR_lights_punctual.light: extensions.KHR_lights_punctual.lights[2] does not exist")

    def sparse(d):
        raw = struct.pack("<HH", 9, 0) + struct.pack("<3f", 5, 5, 5)
        d["buffers"].append({"byteLength": len(raw), "uri": data_uri(raw)})
        d["bufferViews"] += [{"buffer": 1, "byteLength": 4}, {"buffer": 1, "byteOffset": 4, "byteLength": 12}]
        d["accessors"][0]["sparse"] = {"count": 1, "indices": {"bufferView": 1, "componentType": UINT16},
                                       "values": {"bufferView": 2}}
    add("sparse_out_of_range.gltf", changed(sparse), "accessors[0].sparse: index 9 is out of range")
    add("negative_emission.gltf", changed(lambda d: d["materials"][0].update(emissiveFactor=[-1, 0, 0])),
        "materials[0]: material factors must be finite and non-negative")

    # Cases first written by tests/data/make_bad_corpus.py (same file names), regenerated here so
    # that one script owns this folder and expected.txt.
    def indexed_doc(positions=((0, 0, 0), (1, 0, 0), (0, 1, 0)), indices=(0, 1, 2), emissive=True):
        pos = b"".join(struct.pack("<3f", *p) for p in positions)
        idx = b"".join(struct.pack("<H", i) for i in indices)
        idx += b"\0" * (-len(idx) % 4)
        payload = pos + idx
        doc = triangle_doc()
        doc["meshes"][0]["primitives"][0]["indices"] = 1
        doc["materials"][0]["emissiveFactor"] = [1, 1, 1] if emissive else [0, 0, 0]
        doc["buffers"] = [{"byteLength": len(payload), "uri": data_uri(payload)}]
        doc["bufferViews"] = [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                              {"buffer": 0, "byteOffset": len(pos), "byteLength": len(indices) * 2}]
        doc["accessors"].append({"bufferView": 1, "componentType": UINT16, "count": len(indices), "type": "SCALAR"})
        return doc

    def indexed_changed(change):
        doc = indexed_doc()
        change(doc)
        return doc

    add("malformed-json.gltf", json.dumps(indexed_doc())[:-40].encode(), "malformed JSON")
    add("not-an-object.gltf", b"[1, 2, 3]", "the top level is not a JSON object")
    add("accessor-out-of-range.gltf",
        indexed_changed(lambda d: d["meshes"][0]["primitives"][0]["attributes"].update(POSITION=7)), "accessors[7]")
    add("accessor-overflows-view.gltf", indexed_changed(lambda d: d["accessors"][0].update(count=50)),
        "meshes[0].primitives[0]: accessors[0]")
    add("index-out-of-range.gltf", indexed_doc(indices=(0, 1, 9)), "index 9")
    add("missing-buffer.gltf", indexed_changed(lambda d: d["buffers"][0].update(uri="missing.bin")),
        'buffers[0].uri: file "missing.bin" not found')
    add("short-buffer.gltf", indexed_changed(lambda d: d["bufferViews"][1].update(byteLength=4000)),
        "bufferViews[1]: bytes [36, 4036) exceed buffers[0]")
    add("nan-position.gltf", indexed_doc(positions=((0, 0, 0), (float("nan"), 0, 0), (0, 1, 0))), "POSITION 1 is NaN")
    add("no-geometry.gltf", indexed_changed(lambda d: d.update(nodes=[{}])), "no triangle geometry")
    add("only-degenerate.gltf", indexed_doc(positions=((0, 0, 0), (1, 1, 1), (2, 2, 2))), "no triangle geometry")
    add("no-lights.gltf", indexed_doc(emissive=False), "no lights")
    for name, uri, expected in [("absolute-uri.gltf", "/etc/passwd", "absolute paths"),
                                ("dotdot-uri.gltf", "../secret.bin", "'..'"),
                                ("encoded-dotdot-uri.gltf", "sub/%2e%2e/%2e%2e/secret.bin", "'..'"),
                                ("shell-uri.gltf", "$HOME/buffer.bin", "shell expansion"),
                                ("tilde-uri.gltf", "~/buffer.bin", "'~'"),
                                ("remote-uri.gltf", "http://example.invalid/buffer.bin", "data: URIs")]:
        add(name, indexed_changed(lambda d, uri=uri: d["buffers"][0].update(uri=uri)), expected)

    def wide_image(d):
        d["images"] = [{"uri": data_uri(png_header_only(17000, 1), "image/png")}]
        d["textures"] = [{"source": 0}]
        d["materials"][0]["pbrMetallicRoughness"] = {"baseColorTexture": {"index": 0}}
    add("image-too-large.gltf", indexed_changed(wide_image), "exceeds the image size limit")
    add("material-out-of-range.gltf", indexed_changed(lambda d: d["meshes"][0]["primitives"][0].update(material=5)),
        "meshes[0].primitives[0].material: materials[5] does not exist")
    add("node-cycle.gltf", indexed_changed(lambda d: d.update(nodes=[{"mesh": 0, "children": [0]}])), "cycle")
    add("truncated-header.glb",
        b"glTF" + struct.pack("<II", 2, 1000) + struct.pack("<II", 500, 0x4E4F534A) + b'{"asset":',
        "GLB header: declares 1000 bytes")

    # GLB containers.
    glb_doc = triangle_doc()
    del glb_doc["buffers"][0]["uri"]
    good_glb = glb(glb_doc, TRIANGLE)
    add("truncated.glb", good_glb[:-8], "GLB header: declares")
    overrun = bytearray(good_glb)
    bin_at = len(good_glb) - 36 - 8
    struct.pack_into("<I", overrun, bin_at, 40)  # BIN chunk claims 40 bytes where 36 remain
    add("bin_overrun.glb", bytes(overrun), "GLB chunk 1")
    add("no_bin_chunk.glb", glb(glb_doc, b""), "buffers[0]: the .glb has no BIN chunk")
    add("bad_version.glb", good_glb[:4] + struct.pack("<I", 1) + good_glb[8:], "GLB header: version 1 is not 2")
    return cases


def write(path, contents):
    data = contents if isinstance(contents, bytes) else (json.dumps(contents, indent=1) + "\n").encode()
    with open(path, "wb") as f:
        f.write(data)


def write_bad():
    cases = bad_cases()
    for name, contents, _ in cases:
        write(os.path.join(HERE, name), contents)
    write(os.path.join(HERE, "short.bin"), TRIANGLE[:12])
    with open(os.path.join(HERE, "expected.txt"), "w") as f:
        f.write("# file<TAB>substring of the InputError message (which must also start with the file's path)\n")
        f.write("does_not_exist.gltf\tno such file\n")
        for name, _, expected in cases:
            f.write("%s\t%s\n" % (name, expected))


def write_good():
    os.makedirs(GOOD, exist_ok=True)
    write(os.path.join(GOOD, "triangle.bin"), TRIANGLE)
    write(os.path.join(GOOD, "triangle.gltf"), with_uri("triangle.bin"))
    glb_doc = triangle_doc()
    del glb_doc["buffers"][0]["uri"]
    write(os.path.join(GOOD, "triangle.glb"), glb(glb_doc, TRIANGLE))
    # A textured triangle with an external 2x2 PNG (red, green / blue, white) and external UVs.
    rows = b"".join(b"\0" + bytes(row) for row in ([255, 0, 0, 255, 0, 255, 0, 255],
                                                    [0, 0, 255, 255, 255, 255, 255, 255]))
    write(os.path.join(GOOD, "checker.png"), png(2, 2, rows))
    write(os.path.join(GOOD, "uv.bin"), struct.pack("<6f", 0, 0, 1, 0, 0, 1))
    doc = with_uri("triangle.bin")
    doc["buffers"].append({"byteLength": 24, "uri": "uv.bin"})
    doc["bufferViews"].append({"buffer": 1, "byteLength": 24})
    doc["accessors"].append({"bufferView": 1, "componentType": FLOAT, "count": 3, "type": "VEC2"})
    doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 1
    doc["materials"][0]["pbrMetallicRoughness"] = {"baseColorTexture": {"index": 0}}
    doc["textures"] = [{"source": 0}]
    doc["images"] = [{"uri": "checker.png"}]
    write(os.path.join(GOOD, "textured.gltf"), doc)


if __name__ == "__main__":
    write_bad()
    write_good()
