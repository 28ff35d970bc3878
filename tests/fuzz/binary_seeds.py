#!/usr/bin/env python3
"""Writes the loader fuzzer's seeds that hold binary files (loader_input.h): a binary glTF, glTF
1.0 files (text and binary), EXR textures and an EXR environment map, and the binary glTF finding whose BIN chunk claims 8 bytes
more than the file holds. Run from the repository's root: python3 tests/fuzz/binary_seeds.py"""
import base64
import json
import math
import struct
import zlib

SEPARATOR = b"\n%%strata-part%%\n"


def container(obj=b"", mtl=b"", description=b"", gltf=b"", texture=b"", environment=b""):
    parts = [obj, mtl, description, gltf, texture, environment]
    while parts and not parts[-1]:
        parts.pop()
    return SEPARATOR.join(parts)


def exr(width, height, pixels, half=False):
    """An uncompressed scanline OpenEXR of RGB `pixels` (rows top first, (r, g, b) each)."""
    def attribute(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value

    pixel_type, size, pack = (1, 2, "<e") if half else (2, 4, "<f")
    channels = b"".join(name + b"\0" + struct.pack("<iB3xii", pixel_type, 0, 1, 1) for name in (b"B", b"G", b"R"))
    header = b"".join([
        attribute("channels", "chlist", channels + b"\0"),
        attribute("compression", "compression", b"\0"),
        attribute("dataWindow", "box2i", struct.pack("<4i", 0, 0, width - 1, height - 1)),
        attribute("displayWindow", "box2i", struct.pack("<4i", 0, 0, width - 1, height - 1)),
        attribute("lineOrder", "lineOrder", b"\0"),
        attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0)),
        attribute("screenWindowCenter", "v2f", struct.pack("<2f", 0.0, 0.0)),
        attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)),
    ]) + b"\0"
    start = 8 + len(header) + 8 * height
    lines, offsets = [], []
    for y in range(height):
        row = pixels[y * width:(y + 1) * width]
        data = b"".join(struct.pack(pack, p[c]) for c in (2, 1, 0) for p in row)  # B, G, R planes
        offsets.append(start + sum(len(line) for line in lines))
        lines.append(struct.pack("<ii", y, len(data)) + data)
    return b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + header + struct.pack(f"<{height}Q", *offsets) + b"".join(lines)


def png(width, height, rgba):
    """An 8-bit RGBA PNG."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    raw = b"".join(b"\0" + bytes(rgba[y * width * 4:(y + 1) * width * 4]) for y in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def glb(document, binary, bin_length=None):
    """A binary glTF: its JSON chunk, then its BIN chunk of `bin_length` claimed bytes."""
    text = json.dumps(document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text
    chunks += struct.pack("<II", len(binary) if bin_length is None else bin_length, 0x004E4942) + binary
    return b"glTF" + struct.pack("<II", 2, 12 + len(chunks)) + chunks


def over_read_glb(total=376):
    """The binary glTF of `total` bytes whose BIN chunk claims its own 8 header bytes as data too,
    and whose buffer takes all it claims: tinygltf 2.7 copied 8 bytes from past the end of the
    file (AddressSanitizer: heap-buffer-overflow in ParseBuffer)."""
    for claimed in range(total):
        document = {"asset": {"version": "2.0"}, "buffers": [{"byteLength": claimed}]}
        payload = total - (len(glb(document, b"")))
        if payload >= 0 and payload + 8 == claimed:
            return glb(document, b"\0" * payload, bin_length=claimed)
    raise ValueError("no such file of that size")


def triangle_model():
    """A textured triangle's glTF document and buffer: positions, UVs, indices."""
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    uvs = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
    indices = struct.pack("<3H2x", 0, 1, 2)
    binary = positions + uvs + indices
    document = {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_materials_emissive_strength", "KHR_lights_punctual"],
        "buffers": [{"byteLength": len(binary)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 24},
                        {"buffer": 0, "byteOffset": 60, "byteLength": 6}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"},
                      {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"}],
        "images": [{"uri": "fuzz.png"}],
        "textures": [{"source": 0}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}},
                       "emissiveTexture": {"index": 0}, "emissiveFactor": [1, 1, 1],
                       "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 5}}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "point", "color": [1, 0.5, 0.25], "intensity": 20},
            {"type": "spot", "intensity": 3, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}},
            {"type": "directional", "intensity": 2}]}},
        "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.3, 0.3, 3]},
                  {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 0, 1]},
                  {"extensions": {"KHR_lights_punctual": {"light": 1}}, "rotation": [0, 0, 0, 1]},
                  {"extensions": {"KHR_lights_punctual": {"light": 2}}, "scale": [1, 1, 1]}],
        "scenes": [{"nodes": [0, 1, 2, 3, 4]}],
    }
    return document, binary


def version1_model(binary_body):
    """triangle_model's triangle in glTF 1.0's form: lists keyed by name, positions read with a
    stride, a node of two meshes, a technique's Blinn-Phong values and KHR_materials_common's;
    `binary_body` puts the buffer and the texture's image in a KHR_binary_glTF body."""
    _, binary = triangle_model()
    uri = "data:," if binary_body else "data:application/octet-stream;base64," + base64.b64encode(binary).decode()
    buffer = {"byteLength": len(binary), "uri": uri}
    image = ({"uri": "data:,", "extensions": {"KHR_binary_glTF": {"bufferView": "image", "mimeType": "image/png"}}}
             if binary_body else {"uri": "fuzz.png"})
    name = "binary_glTF" if binary_body else "buf"
    return {
        "asset": {"version": "1.0"},
        "extensionsUsed": ["KHR_binary_glTF", "KHR_materials_common"],
        "buffers": {name: buffer},
        "bufferViews": {"vertices": {"buffer": name, "byteOffset": 0, "byteLength": 60, "target": 34962},
                        "indices": {"buffer": name, "byteOffset": 60, "byteLength": 6, "target": 34963},
                        "image": {"buffer": name, "byteOffset": 68, "byteLength": 0}},
        "accessors": {"position": {"bufferView": "vertices", "byteOffset": 0, "byteStride": 12,
                                   "componentType": 5126, "count": 3, "type": "VEC3"},
                      "strided": {"bufferView": "vertices", "byteOffset": 0, "byteStride": 24,
                                  "componentType": 5126, "count": 2, "type": "VEC2"},
                      "uv": {"bufferView": "vertices", "byteOffset": 36, "componentType": 5126, "count": 3,
                             "type": "VEC2"},
                      "index": {"bufferView": "indices", "byteOffset": 0, "componentType": 5123, "count": 3,
                                "type": "SCALAR"}},
        "images": {"img": image},
        "samplers": {"s": {"magFilter": 9728, "wrapS": 33071}},
        "textures": {"tex": {"source": "img", "sampler": "s"}},
        "techniques": {"t": {"parameters": {"diffuse": {"type": 35666, "value": [0.5, 0.5, 0.5, 1]}}}},
        "materials": {"phong": {"technique": "t", "values": {"specular": [0.04, 0.04, 0.04, 1], "shininess": 50,
                                                              "emission": [2, 1, 0, 1]}},
                      "common": {"extensions": {"KHR_materials_common": {
                          "technique": "BLINN", "values": {"diffuse": "tex", "emission": "tex"}}}}},
        "meshes": {"a": {"primitives": [{"attributes": {"POSITION": "position", "TEXCOORD_0": "uv",
                                                         "JOINT": "strided"},
                                          "indices": "index", "material": "phong"}]},
                   "b": {"primitives": [{"attributes": {"POSITION": "position", "TEXCOORD_0": "uv"},
                                         "material": "common", "mode": 4}]}},
        "cameras": {"c": {"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1, "aspectRatio": 1}}},
        "nodes": {"root": {"meshes": ["a", "b"], "children": ["eye"], "translation": [0, 0, 1]},
                  "eye": {"camera": "c", "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.3, 0.3, 3, 1]}},
        "scenes": {"s": {"nodes": ["root"]}},
        "scene": "s",
    }, binary


def binary_version1(document, body):
    """A KHR_binary_glTF file: "glTF", version 1, the length, the content's length and format 0."""
    text = json.dumps(document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    return b"glTF" + struct.pack("<IIII", 1, 20 + len(text) + len(body), len(text), 0) + text + body


QUAD_OBJ = (b"mtllib fuzz.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
            b"vn 0 0 1\nusemtl glow\nf 1/1/1 2/2/1 3/3/1 4/4/1\n")
GLOW_MTL = b"newmtl glow\nKd 0.5 0.5 0.5\nKe 1 1 1\nmap_Ke fuzz.png\nmap_Kd fuzz.png\n"
SKY_DESCRIPTION = json.dumps({
    "position": [0.5, 0.5, 2], "look_at": [0.5, 0.5, 0], "up": [0, 1, 0], "fov_y": 40, "width": 8, "height": 8,
    "lights": [{"type": "point", "position": [0, 0, 1], "intensity": [1, 1, 1]}],
    "environment": {"file": "sky.exr", "rotate": 90}}).encode()
# An emission texture holding what an EXR can and a texture must not: NaN, infinities, negatives.
ODD_TEXELS = [(1.0, 0.5, 0.25), (math.nan, 1.0, 1.0), (math.inf, -math.inf, 0.0), (-5.0, 2.0, 3.0)]
SKY = [(0.2 + 0.1 * x, 0.3, 0.5 + 0.05 * y) for y in range(2) for x in range(4)]


def main():
    document, binary = triangle_model()
    texture = png(2, 2, [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 128, 255, 255, 255, 0])
    seeds = {
        "tests/fuzz/corpus/glb": container(gltf=glb(document, binary), texture=texture),
        "tests/fuzz/corpus/glb-exr-half": container(gltf=glb(document, binary),
                                                    texture=exr(2, 2, ODD_TEXELS[:1] * 4, half=True)),
        "tests/fuzz/corpus/exr-emission-and-sky": container(QUAD_OBJ, GLOW_MTL, SKY_DESCRIPTION,
                                                            texture=exr(2, 2, ODD_TEXELS),
                                                            environment=exr(4, 2, SKY)),
    }
    version1, body = version1_model(binary_body=True)
    body += b"\0" * (-len(body) % 4)
    version1["bufferViews"]["image"].update(byteOffset=len(body), byteLength=len(texture))
    body += texture
    version1["buffers"]["binary_glTF"]["byteLength"] = len(body)
    seeds["tests/fuzz/corpus/gltf-version1-binary"] = container(gltf=binary_version1(version1, body))
    seeds["tests/fuzz/corpus/gltf-version1"] = container(
        gltf=json.dumps(version1_model(binary_body=False)[0]).encode(), texture=texture)
    seeds["tests/fuzz/findings/crash-glb-bin-chunk-over-read"] = container(gltf=over_read_glb())
    for path, data in seeds.items():
        with open(path, "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
