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
        changed(lambda d: d.update(extensionsRequired=["KHR_texture_basisu"])),
        "extensionsRequired: KHR_texture_basisu is required by the file but not supported")
    add("accessor_missing.gltf",
        changed(lambda d: d["meshes"][0]["primitives"][0]["attributes"].update(POSITION=7)),
        "meshes[0].primitives[0].attributes.POSITION: accessors[7] does not exist")
    add("accessor_out_of_range.gltf", changed(lambda d: d["accessors"][0].update(count=100)),
        "meshes[0].primitives[0]: accessors[0]: 100 elements")
    add("accessor_offset_overflow.gltf", changed(lambda d: d["accessors"][0].update(byteOffset=2 ** 62)),
        "accessors[0].byteOffset: 4611686018427387904 is out of range")

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

    # Issue 13, morph targets and skins: each accessor in a buffer of its own.
    def accessor(d, raw, component, kind, count):
        raw += b"\0" * (-len(raw) % 4)
        d["buffers"].append({"byteLength": len(raw), "uri": data_uri(raw)})
        d["bufferViews"].append({"buffer": len(d["buffers"]) - 1, "byteLength": len(raw)})
        d["accessors"].append({"bufferView": len(d["bufferViews"]) - 1, "componentType": component, "count": count,
                               "type": kind})
        return len(d["accessors"]) - 1

    def morph(displacements, weights=None):
        def change(d):
            target = accessor(d, struct.pack("<%df" % len(displacements), *displacements), FLOAT, "VEC3",
                              len(displacements) // 3)
            d["meshes"][0]["primitives"][0]["targets"] = [{"POSITION": target}]
            if weights is not None:
                d["meshes"][0]["weights"] = weights
        return changed(change)
    add("morph_target_count.gltf", morph([0, 0, 1, 0, 0, 1]),
        "meshes[0].primitives[0].targets[0].POSITION: accessors[1] has 2 elements but POSITION has 3")
    add("morph_target_nan.gltf", morph([0, 0, 1, 0, float("nan"), 1, 0, 0, 1]),
        "meshes[0].primitives[0].targets[0].POSITION: element 1 is NaN or infinite")
    add("morph_weights_length.gltf", morph([0, 0, 1, 0, 0, 1, 0, 0, 1], [0.5, 0.5]),
        "meshes[0].primitives[0]: has 1 morph target(s) but meshes[0].weights has 2 weight(s)")

    def skinned(joints, inverse_bind=None, influences=True):
        def change(d):
            d["nodes"][0]["skin"] = 0
            d["nodes"].append({})
            d["scenes"][0]["nodes"].append(1)
            d["skins"] = [{"joints": [1]}]
            if inverse_bind is not None:
                d["skins"][0]["inverseBindMatrices"] = accessor(d, struct.pack("<16f", *inverse_bind), FLOAT, "MAT4", 1)
            if influences:
                attributes = d["meshes"][0]["primitives"][0]["attributes"]
                attributes["JOINTS_0"] = accessor(d, bytes(joints), 5121, "VEC4", 3)
                attributes["WEIGHTS_0"] = accessor(d, struct.pack("<12f", *([1, 0, 0, 0] * 3)), FLOAT, "VEC4", 3)
        return changed(change)
    add("skin_joint_out_of_range.gltf", skinned([0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0]),
        "meshes[0].primitives[0]: JOINTS_0 element 1 names joint 1, but the skin has 1 joints")
    add("skin_without_joints_attribute.gltf", skinned([], influences=False),
        "meshes[0].primitives[0]: is drawn by a skinned node but has no JOINTS_0 and WEIGHTS_0")
    add("skin_inverse_bind_not_finite.gltf", skinned([0] * 12, [float("inf")] + [0] * 15),
        "skins[0].inverseBindMatrices: matrix 0 is not finite")
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
    add("node_negative.gltf", changed(lambda d: d["nodes"][0].update(mesh=-1)), "nodes[0].mesh: -1 is below the minimum 0")
    add("node_cycle.gltf", changed(lambda d: d.update(nodes=[{"children": [1]}, {"mesh": 0, "children": [0]}])),
        "nodes[0]: is reached twice")
    add("node_two_parents.gltf",
        changed(lambda d: d.update(nodes=[{"children": [2]}, {"children": [2]}, {"mesh": 0}],
                                   scenes=[{"nodes": [0, 1]}])),
        "nodes[2]: is reached twice")
    add("bad_rotation.gltf", changed(lambda d: d["nodes"][0].update(rotation=[0, 0, 0, 0])),
        "nodes[0].rotation: is not a unit quaternion")
    add("bad_matrix.gltf", changed(lambda d: d["nodes"][0].update(matrix=[1, 0, 0, 0, 1])),
        "nodes[0].matrix: has 5 items, needs at least 16")

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
        "materials[0].emissiveFactor[0]: -1 is below the minimum 0")

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

    # Issue 18, schema: tinygltf skips optional values of the wrong type and wraps integer casts;
    # the glTF schema (third_party/gltf-schema) refuses them first, naming the element.
    def acc(**kw):
        return changed(lambda d: d["accessors"][0].update(**kw))
    add("schema_byteoffset_negative.gltf", acc(byteOffset=-12), "accessors[0].byteOffset: -12 is out of range")
    add("schema_byteoffset_fraction.gltf", acc(byteOffset=1.5), "accessors[0].byteOffset: 1.5 is not an integer")
    add("schema_byteoffset_string.gltf", acc(byteOffset="12"), 'accessors[0].byteOffset: "12" is not an integer')
    add("schema_byteoffset_unaligned.gltf", changed(lambda d: (d["accessors"][0].update(byteOffset=2, count=2))),
        "accessors[0].byteOffset: 2 is not a multiple of the component size (4 bytes)")
    add("schema_count_as_float.gltf", acc(count=3.0), "accessors[0].count: 3.0 must be written as an integer")
    add("schema_normalized_string.gltf", acc(normalized="yes"), 'accessors[0].normalized: "yes" is not a boolean')
    add("schema_normalized_float.gltf", acc(normalized=True), "accessors[0].normalized: must not be true for FLOAT")
    add("schema_component_type_unknown.gltf", acc(componentType=5127), "accessors[0].componentType: 5127 is not one of")
    add("schema_type_unknown.gltf", acc(type="VEC5"), 'accessors[0].type: "VEC5" is not one of')
    add("schema_count_zero.gltf", acc(count=0), "accessors[0].count: 0 is below the minimum 1")
    prim = lambda **kw: changed(lambda d: d["meshes"][0]["primitives"][0].update(**kw))
    add("schema_mode_string.gltf", prim(mode="4"), 'meshes[0].primitives[0].mode: "4" is not one of 0 (POINTS)')
    add("schema_mode_wrapped.gltf", prim(mode=2 ** 32 + 4), "meshes[0].primitives[0].mode: 4294967300 is not one of 0 (POINTS)")
    add("schema_mode_unknown.gltf", prim(mode=7), "meshes[0].primitives[0].mode: 7 is not one of 0 (POINTS)")
    add("schema_attributes_empty.gltf", prim(attributes={}), "meshes[0].primitives[0].attributes: needs at least 1 property")
    add("schema_translation_strings.gltf", changed(lambda d: d["nodes"][0].update(translation=["a", "b", "c"])),
        'nodes[0].translation[0]: "a" is not a number')
    add("schema_translation_short.gltf", changed(lambda d: d["nodes"][0].update(translation=[1, 2])),
        "nodes[0].translation: has 2 items, needs at least 3")
    add("schema_matrix_and_trs.gltf",
        changed(lambda d: d["nodes"][0].update(matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], scale=[1, 1, 1])),
        'nodes[0]: must not have "matrix" and "translation" or "matrix" and "rotation" or "matrix" and "scale"')
    add("schema_children_duplicate.gltf", changed(lambda d: d.update(nodes=[{"children": [1, 1]}, {"mesh": 0}])),
        "nodes[0].children: 1 is listed twice")
    mat = lambda change: changed(lambda d: change(d["materials"][0]))
    add("schema_metallic_string.gltf", mat(lambda m: m.update(pbrMetallicRoughness={"metallicFactor": "abc"})),
        'materials[0].pbrMetallicRoughness.metallicFactor: "abc" is not a number')
    add("schema_metallic_above_one.gltf", mat(lambda m: m.update(pbrMetallicRoughness={"metallicFactor": 2})),
        "materials[0].pbrMetallicRoughness.metallicFactor: 2 is above the maximum 1")
    add("schema_double_sided_string.gltf", mat(lambda m: m.update(doubleSided="yes")),
        'materials[0].doubleSided: "yes" is not a boolean')
    add("schema_base_color_three.gltf", mat(lambda m: m.update(pbrMetallicRoughness={"baseColorFactor": [1, 1, 1]})),
        "materials[0].pbrMetallicRoughness.baseColorFactor: has 3 items, needs at least 4")
    add("schema_alpha_mode_unknown.gltf", mat(lambda m: m.update(alphaMode="CLIP")), 'materials[0].alphaMode: "CLIP" is not one of')
    add("schema_ior_between.gltf",
        mat(lambda m: m.update(extensions={"KHR_materials_ior": {"ior": 0.5}})),
        "materials[0].extensions.KHR_materials_ior.ior: 0.5 must be exactly one of")
    add("schema_emissive_strength_negative.gltf",
        mat(lambda m: m.update(extensions={"KHR_materials_emissive_strength": {"emissiveStrength": -1}})),
        "materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength: -1 is below the minimum 0")

    def sparse_count(count):
        def change(d):
            raw = struct.pack("<HH", 1, 0) + struct.pack("<3f", 5, 5, 5)
            d["buffers"].append({"byteLength": len(raw), "uri": data_uri(raw)})
            d["bufferViews"] += [{"buffer": 1, "byteLength": 4}, {"buffer": 1, "byteOffset": 4, "byteLength": 12}]
            d["accessors"][0]["sparse"] = {"count": count, "indices": {"bufferView": 1, "componentType": UINT16},
                                           "values": {"bufferView": 2}}
        return changed(change)
    add("schema_sparse_count_wrapped.gltf", sparse_count(2 ** 32 + 1),
        "accessors[0].sparse.count: 4294967297 is out of range")
    add("schema_sparse_count_zero.gltf", sparse_count(0), "accessors[0].sparse.count: 0 is below the minimum 1")
    add("schema_asset_version_pattern.gltf", changed(lambda d: d["asset"].update(version="2.0.1")), "asset.version")
    add("schema_buffer_length_string.gltf", changed(lambda d: d["buffers"][0].update(byteLength="36")),
        "buffers[0].byteLength")
    add("schema_image_uri_and_view.gltf",
        changed(lambda d: d.update(images=[{"uri": "a.png", "bufferView": 0, "mimeType": "image/png"}])),
        "images[0]: ")
    add("schema_sampler_filter_unknown.gltf", changed(lambda d: d.update(samplers=[{"magFilter": 1}])),
        "samplers[0].magFilter: 1 is not one of 9728 (NEAREST), 9729 (LINEAR)")
    add("schema_sampler_minfilter_unknown.gltf", changed(lambda d: d.update(samplers=[{"minFilter": 9730}])),
        "samplers[0].minFilter: 9730 is not one of 9728 (NEAREST)")
    add("nul_byte_then_text.gltf", json.dumps(triangle_doc()).encode() + b"\0" + b'{"nodes": [{"mesh": 9}]}',
        "the JSON text holds a NUL byte at byte")
    add("nul_byte_inside.gltf", json.dumps(triangle_doc()).replace('"2.0"', '"2.0\u0000"').encode().replace(b"\\u0000", b"\0"),
        "NUL byte")

    # Issue 18, cameras and lights: values the schema allows but the specification or the
    # renderer does not.
    def camera(projection, kind="perspective"):
        def change(d):
            d["cameras"] = [{"type": kind, kind: projection}]
            d["nodes"].append({"camera": 0, "translation": [0, 0, 3]})
            d["scenes"][0]["nodes"].append(1)
        return changed(change)
    add("camera_znear_zero.gltf", camera({"yfov": 0.8, "znear": 0}), "cameras[0].perspective.znear: 0 must be greater than 0")
    add("camera_znear_negative.gltf", camera({"yfov": 0.8, "znear": -1}), "cameras[0].perspective.znear: -1 must be greater than 0")
    add("camera_zfar_below_znear.gltf", camera({"yfov": 0.8, "znear": 1, "zfar": 0.5}),
        "cameras[0].perspective.zfar: 0.5 is not greater than znear 1")
    add("camera_yfov_zero_as_float.gltf", camera({"yfov": 1e-50, "znear": 0.1}),
        "cameras[0].perspective.yfov: 1e-50 must be greater than 0 (as a 32-bit float it is not)")
    add("camera_ortho_zero_mag.gltf", camera({"xmag": 0, "ymag": 1, "znear": 0, "zfar": 10}, "orthographic"),
        "cameras[0].orthographic.xmag: must not be zero")
    add("camera_type_without_object.gltf",
        changed(lambda d: d.update(cameras=[{"type": "perspective", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0, "zfar": 1}}])),
        'cameras[0]: type "perspective" but no "perspective" object')

    def light(props, node=None):
        def change(d):
            d["nodes"].append(dict(node or {}, extensions={"KHR_lights_punctual": {"light": 0}}))
            d["scenes"][0]["nodes"].append(1)
            d["extensions"] = {"KHR_lights_punctual": {"lights": [dict({"type": "point"}, **props)]}}
        return changed(change)
    add("light_range_negative.gltf", light({"range": -1}),
        "extensions.KHR_lights_punctual.lights[0].range: -1 must be greater than 0")
    add("light_type_unknown.gltf", light({"type": "area"}), 'extensions.KHR_lights_punctual.lights[0].type: "area" is not one of')
    add("light_color_above_one.gltf", light({"color": [1e35, 1, 1], "intensity": 1e10}),
        "extensions.KHR_lights_punctual.lights[0].color[0]: 1e+35 is above the maximum 1")
    add("light_intensity_beyond_float.gltf", light({"intensity": 1e300}),
        "extensions.KHR_lights_punctual.lights[0].intensity: 1e+300 is beyond the range of a 32-bit float")
    add("light_intensity_too_strong.gltf", light({"intensity": 1e30}),
        "extensions.KHR_lights_punctual.lights[0].intensity: 1e+30 makes")
    add("light_far_away.gltf", light({"intensity": 10}, {"translation": [1e30, 0, 0]}),
        "nodes[1]: the light lies at (1e+30, 0, 0)")
    add("light_beyond_float.gltf", light({"intensity": 10}, {"translation": [1e300, 0, 0]}),
        "nodes[1].translation[0]: 1e+300 is beyond the range of a 32-bit float")
    add("camera_far_away.gltf", camera({"yfov": 0.8, "znear": 0.1}) if False else
        changed(lambda d: (d.update(cameras=[{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]),
                           d["nodes"].append({"camera": 0, "translation": [0, 0, 1e20]}), d["scenes"][0]["nodes"].append(1))),
        "nodes[1]: the camera lies at (0, 0, 1e+20)")

    # Issue 18, references the loader did not check.
    add("skin_missing.gltf", changed(lambda d: d["nodes"][0].update(skin=3)), "nodes[0].skin: skins[3] does not exist")
    add("sampler_missing.gltf",
        changed(lambda d: (d.update(textures=[{"source": 0, "sampler": 2}],
                                    images=[{"uri": data_uri(png(1, 1, b"\0\xff\0\0\xff"), "image/png")}]))),
        "textures[0].sampler: samplers[2] does not exist")
    add("animation_sampler_missing.gltf",
        changed(lambda d: d.update(animations=[{"channels": [{"sampler": 1, "target": {"node": 0, "path": "translation"}}],
                                                "samplers": [{"input": 0, "output": 0}]}])),
        "animations[0].channels[0].sampler: animations[0].samplers[1] does not exist")
    add("morph_target_missing.gltf", prim(targets=[{"POSITION": 4}]),
        "meshes[0].primitives[0].targets[0].POSITION: accessors[4] does not exist")

    # Issue 18, scale: finite in double but not what single precision can render.
    def positions(*values):
        return changed(lambda d: d["buffers"][0].update(uri=data_uri(struct.pack("<9f", *values))))
    add("triangle_at_float_max.gltf", positions(-3e38, -3e38, 0, 3e38, -3e38, 0, 0, 3e38, 0),
        "meshes[0].primitives[0]: vertex 0 of nodes[0] lies at (-3e+38, -3e+38, 0) in world space")
    add("node_scale_huge.gltf", changed(lambda d: d["nodes"][0].update(scale=[1e20, 1e20, 1e20])),
        "meshes[0].primitives[0]: vertex 1 of nodes[0] lies at (1e+20, 0, 0)")
    add("matrix_scale_huge.gltf",
        changed(lambda d: d["nodes"][0].update(matrix=[1e20, 0, 0, 0, 0, 1e20, 0, 0, 0, 0, 1e20, 0, 0, 0, 0, 1])),
        "beyond the +-1e+08 units vkphoton handles")
    add("triangle_tiny.gltf", positions(0, 0, 0, 1e-30, 0, 0, 0, 1e-30, 0), "scenes[0]: the geometry spans only 1e-30 units")
    add("scene_tiny.gltf", changed(lambda d: d["nodes"][0].update(scale=[1e-6, 1e-6, 1e-6])),
        "scenes[0]: the geometry spans only 1e-06 units")
    add("scene_far_from_origin.gltf", changed(lambda d: d["nodes"][0].update(translation=[1e6, 0, 0])),
        "scenes[0]: the geometry spans 1 units but lies 1e+06 units from the origin")
    add("emission_too_strong.gltf",
        mat(lambda m: m.update(extensions={"KHR_materials_emissive_strength": {"emissiveStrength": 1e30}})),
        "materials[0]: emission 1e+30 W/m^2/sr")

    # Issue 18, memory before limits: one primitive of 4 M triangles (zeros: no bufferView, so no
    # file data) listed 17 times is refused from the counts, before anything is decoded.
    def repeated(d):
        d["accessors"].append({"componentType": FLOAT, "count": 3 * 2 ** 22, "type": "VEC3"})
        d["meshes"][0]["primitives"] = [{"attributes": {"POSITION": 1}, "material": 0}] * 17
    add("repeated_primitive.gltf", changed(repeated),
        "scenes[0]: 71303168 triangles (counting every mesh reference) exceed the limit of 67108864")
    def many_nodes(d):
        d["accessors"].append({"componentType": FLOAT, "count": 3 * 2 ** 20, "type": "VEC3"})
        d["meshes"].append({"primitives": [{"attributes": {"POSITION": 1}, "material": 0}]})
        d["nodes"] = [{"mesh": 1} for _ in range(70)]
        d["scenes"][0]["nodes"] = list(range(70))
    add("repeated_mesh_nodes.gltf", changed(many_nodes), "scenes[0]: 73400320 triangles")

    # Issue 18, images stb would decode although they are damaged.
    jpeg_sof = b"\xff\xc0" + struct.pack(">HBHHB", 11, 8, 1, 1, 1) + b"\x01\x11\x00"
    add("jpeg_without_scan.gltf", textured({"uri": data_uri(b"\xff\xd8" + jpeg_sof + b"\xff\xd9", "image/jpeg")}),
        "images[0]: the JPEG has no image data (no start-of-scan segment)")
    add("jpeg_truncated.gltf", textured({"uri": data_uri(b"\xff\xd8" + jpeg_sof[:7], "image/jpeg")}),
        "images[0]: the JPEG is truncated")
    good_png = png(1, 1, b"\0\xff\0\0\xff")
    add("png_truncated.gltf", textured({"uri": data_uri(good_png[:-12], "image/png")}),
        "images[0]: the PNG is truncated (no IEND chunk)")
    damaged = bytearray(good_png)
    damaged[42] ^= 0x55  # inside the IDAT data (the chunk starts at byte 33)
    add("png_bad_crc.gltf", textured({"uri": data_uri(bytes(damaged), "image/png")}), "chunk at byte 33 fails its CRC check")

    # Issue 13: texture sets, transforms, samplers, tangents and colours.
    one_texel = data_uri(png(1, 1, b"\0\xff\0\0\xff"), "image/png")

    def texture_ref(ref, sampler=None):
        def change(d):
            d["materials"][0]["pbrMetallicRoughness"] = {"baseColorTexture": dict(ref, index=0)}
            d["textures"] = [{"source": 0}]
            d["images"] = [{"uri": one_texel}]
            if sampler is not None:
                d["textures"][0]["sampler"] = 0
                d["samplers"] = [sampler]
        return changed(change)

    add("texcoord_set_missing.gltf", texture_ref({"texCoord": 1}),
        'meshes[0].primitives[0]: material "lamp" reads TEXCOORD_1, which the primitive does not have')
    add("texcoord_set_beyond.gltf", texture_ref({"texCoord": 7}),
        'meshes[0].primitives[0]: material "lamp" reads TEXCOORD_7, which the primitive does not have')
    add("texture_transform_texcoord_beyond.gltf",
        texture_ref({"extensions": {"KHR_texture_transform": {"texCoord": 2}}}),
        "reads TEXCOORD_2, which the primitive does not have")
    add("texture_transform_bad_offset.gltf",
        texture_ref({"extensions": {"KHR_texture_transform": {"offset": [1, "x"]}}}),
        "baseColorTexture.extensions.KHR_texture_transform.offset[1]: \"x\" is not a number")
    add("texture_transform_huge_scale.gltf",
        texture_ref({"extensions": {"KHR_texture_transform": {"scale": [1e30, 1]}}}),
        "KHR_texture_transform: offset, rotation and scale must be finite (within 1e6)")
    add("sampler_bad_wrap.gltf", texture_ref({}, {"wrapS": 1234}), "samplers[0].wrapS")
    add("sampler_bad_filter.gltf", texture_ref({}, {"magFilter": 9984}), "samplers[0].magFilter")

    def vertex_attribute(name, values, kind, material=None):
        def change(d):
            raw = struct.pack("<%df" % len(values), *values)
            d["buffers"].append({"byteLength": len(raw), "uri": data_uri(raw)})
            d["bufferViews"].append({"buffer": 1, "byteLength": len(raw)})
            d["accessors"].append({"bufferView": 1, "componentType": FLOAT, "count": 3, "type": kind})
            d["meshes"][0]["primitives"][0]["attributes"][name] = 1
            if material:
                material(d)
        return changed(change)

    def normal_mapped(d):
        d["materials"][0]["normalTexture"] = {"index": 0}
        d["textures"] = [{"source": 0}]
        d["images"] = [{"uri": one_texel}]
    nan = float("nan")
    add("tangent_nan.gltf", vertex_attribute("TANGENT", [1, 0, 0, 1, nan, 0, 0, 1, 1, 0, 0, 1], "VEC4", normal_mapped),
        "meshes[0].primitives[0]: TANGENT 1 is NaN or infinite (accessors[1])")
    add("color_nan.gltf", vertex_attribute("COLOR_0", [1, 1, 1, 1, 1, nan, 1, 1, 1], "VEC3"),
        "meshes[0].primitives[0]: COLOR_0 1 is NaN or infinite (accessors[1])")
    add("color_signed.gltf",
        changed(lambda d: (d["accessors"].append({"bufferView": 0, "componentType": 5120, "normalized": True,
                                                  "count": 3, "type": "VEC3"}),
                           d["meshes"][0]["primitives"][0]["attributes"].update(COLOR_0=1))),
        "accessors[1]: COLOR_0 must be float or normalized unsigned byte or short")
    add("alpha_mode_unknown.gltf", mat(lambda m: m.update(alphaMode="CUTOUT")), "materials[0].alphaMode")

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

    # Compressed streams that do not decode: a Draco header followed by garbage, and a meshopt
    # ATTRIBUTES stream of the right header byte (0xa0) and nothing decodable after it.
    draco = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
             "extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"],
             "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "extensions": {
                 "KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}}}]}],
             "accessors": [{"componentType": FLOAT, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                           {"componentType": UINT32, "count": 3, "type": "SCALAR"}],
             "buffers": [{"byteLength": 16, "uri": data_uri(b"DRACO\x02\x02\x01\x01\x00\x00\x00\xff\xff\xff\xff")}],
             "bufferViews": [{"buffer": 0, "byteLength": 16}]}
    add("draco_corrupt_stream.gltf", draco,
        "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression: the Draco stream does not decode")
    meshopt = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
               "extensionsUsed": ["EXT_meshopt_compression"], "extensionsRequired": ["EXT_meshopt_compression"],
               "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
               "accessors": [{"bufferView": 0, "componentType": FLOAT, "count": 3, "type": "VEC3",
                              "min": [0, 0, 0], "max": [1, 1, 0]}],
               "buffers": [{"byteLength": 12, "uri": data_uri(b"\xa0" + b"\x01" * 11)},
                           {"byteLength": 36, "extensions": {"EXT_meshopt_compression": {"fallback": True}}}],
               "bufferViews": [{"buffer": 1, "byteLength": 36, "byteStride": 12, "extensions": {
                   "EXT_meshopt_compression": {"buffer": 0, "byteLength": 12, "byteStride": 12, "count": 3,
                                               "mode": "ATTRIBUTES"}}}]}
    add("meshopt_corrupt_stream.gltf", meshopt,
        "bufferViews[0].extensions.EXT_meshopt_compression: the ATTRIBUTES stream does not decode")
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
