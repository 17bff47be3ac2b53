#!/usr/bin/env python3
"""Writes glTF 2.0 test assets with known answers (Python standard library only).

Usage: make_gltf.py OUTPUT_DIR

Every asset's expected import result follows from the numbers written here;
tests/gltf/*_test.cpp check them. Most assets are written three ways:
NAME.gltf (external NAME.bin), NAME_embedded.gltf (data-URI buffer) and NAME.glb.
"""
import base64
import json
import math
import os
import struct
import sys
import zlib

FLOAT, UBYTE, USHORT, UINT = 5126, 5121, 5123, 5125
TYPE_COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}


class Asset:
    """Collects one binary buffer plus the JSON that points into it."""

    def __init__(self):
        self.blob = bytearray()
        self.gltf = {"asset": {"version": "2.0", "generator": "orb tests/gltf/make_gltf.py"},
                     "buffers": [], "bufferViews": [], "accessors": [], "meshes": [], "nodes": [],
                     "scenes": [{"nodes": []}], "scene": 0}

    def accessor(self, values, type_, component=FLOAT, normalized=False, minmax=False):
        """values: flat list of numbers. Returns the accessor index."""
        fmt = {FLOAT: "f", UBYTE: "B", USHORT: "H", UINT: "I"}[component]
        while len(self.blob) % 4:
            self.blob.append(0)
        offset = len(self.blob)
        self.blob += struct.pack("<%d%s" % (len(values), fmt), *values)
        self.gltf["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": len(self.blob) - offset})
        n = TYPE_COMPONENTS[type_]
        acc = {"bufferView": len(self.gltf["bufferViews"]) - 1, "componentType": component,
               "count": len(values) // n, "type": type_}
        if normalized:
            acc["normalized"] = True
        if minmax or type_ == "VEC3" and component == FLOAT:
            acc["min"] = [min(values[i::n]) for i in range(n)]
            acc["max"] = [max(values[i::n]) for i in range(n)]
        self.gltf["accessors"].append(acc)
        return len(self.gltf["accessors"]) - 1

    def mesh(self, name, positions, indices=None, mode=None, material=None, extra_attributes=None):
        prim = {"attributes": {"POSITION": self.accessor([c for p in positions for c in p], "VEC3")}}
        if indices is not None:
            prim["indices"] = self.accessor(indices, "SCALAR", UINT if len(positions) > 65535 else USHORT)
        if mode is not None:
            prim["mode"] = mode
        if material is not None:
            prim["material"] = material
        for key, index in (extra_attributes or {}).items():
            prim["attributes"][key] = index
        self.gltf["meshes"].append({"name": name, "primitives": [prim]})
        return len(self.gltf["meshes"]) - 1

    def node(self, root=True, **fields):
        self.gltf["nodes"].append({k: v for k, v in fields.items() if v is not None})
        index = len(self.gltf["nodes"]) - 1
        if root:
            self.gltf["scenes"][0]["nodes"].append(index)
        return index

    def image(self, data, name, mime="image/png"):
        """Encoded image bytes stored in a bufferView; returns the image index."""
        while len(self.blob) % 4:
            self.blob.append(0)
        offset = len(self.blob)
        self.blob += data
        self.gltf["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": len(data)})
        self.gltf.setdefault("images", []).append(
            {"name": name, "bufferView": len(self.gltf["bufferViews"]) - 1, "mimeType": mime})
        return len(self.gltf["images"]) - 1

    def texture(self, image, wrap=None):
        """A texture of `image`; `wrap` (a glTF wrap mode) for both axes, else the default sampler."""
        texture = {"source": image}
        if wrap is not None:
            self.gltf.setdefault("samplers", []).append({"wrapS": wrap, "wrapT": wrap})
            texture["sampler"] = len(self.gltf["samplers"]) - 1
        self.gltf.setdefault("textures", []).append(texture)
        return len(self.gltf["textures"]) - 1

    def write_images_apart(self, out_dir, name, as_files):
        """NAME.gltf (external .bin) whose bufferView images are instead data:
        URIs, or (as_files) PNG files beside it, NAME_image<i>.png."""
        doc = self._clean()
        for i, image in enumerate(doc.get("images", [])):
            if "bufferView" not in image:
                continue
            view = doc["bufferViews"][image.pop("bufferView")]
            data = bytes(self.blob[view["byteOffset"]:view["byteOffset"] + view["byteLength"]])
            if as_files:
                image["uri"] = "%s_image%d.png" % (name, i)
                with open(os.path.join(out_dir, image["uri"]), "wb") as f:
                    f.write(data)
            else:
                image["uri"] = "data:%s;base64,%s" % (image["mimeType"], base64.b64encode(data).decode())
            del image["mimeType"]
        doc["buffers"] = [{"byteLength": len(self.blob), "uri": name + ".bin"}]
        with open(os.path.join(out_dir, name + ".bin"), "wb") as f:
            f.write(self.blob)
        with open(os.path.join(out_dir, name + ".gltf"), "w") as f:
            json.dump(doc, f, indent=1)

    def extension_used(self, name):
        self.gltf.setdefault("extensionsUsed", [])
        if name not in self.gltf["extensionsUsed"]:
            self.gltf["extensionsUsed"].append(name)

    def _clean(self):
        doc = json.loads(json.dumps(self.gltf))
        for key in ("meshes", "nodes", "accessors", "bufferViews"):
            if not doc[key]:
                del doc[key]
        return doc

    def write_all(self, out_dir, name):
        self.write_gltf(out_dir, name)
        self.write_gltf(out_dir, name + "_embedded", embedded=True)
        self.write_glb(out_dir, name)

    def write_gltf(self, out_dir, name, embedded=False):
        doc = self._clean()
        if self.blob:
            if embedded:
                uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode()
            else:
                uri = name + ".bin"
                with open(os.path.join(out_dir, uri), "wb") as f:
                    f.write(self.blob)
            doc["buffers"] = [{"byteLength": len(self.blob), "uri": uri}]
        else:
            del doc["buffers"]
        with open(os.path.join(out_dir, name + ".gltf"), "w") as f:
            json.dump(doc, f, indent=1)

    def write_glb(self, out_dir, name):
        doc = self._clean()
        blob = bytes(self.blob)
        if blob:
            doc["buffers"] = [{"byteLength": len(blob)}]
        else:
            del doc["buffers"]
        text = json.dumps(doc).encode()
        text += b" " * (-len(text) % 4)
        blob += b"\0" * (-len(blob) % 4)
        chunks = struct.pack("<II", len(text), 0x4E4F534A) + text
        if blob:
            chunks += struct.pack("<II", len(blob), 0x004E4942) + blob
        with open(os.path.join(out_dir, name + ".glb"), "wb") as f:
            f.write(struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks)


# ---- shapes ----

def uv_sphere(radius=1.0, center=(0.0, 0.0, 0.0), segments=32, rings=16):
    """Blender-style UV sphere: poles plus rings x segments vertices."""
    pts = [(center[0], center[1] + radius, center[2])]
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(segments):
            phi = 2 * math.pi * s / segments
            pts.append((center[0] + radius * math.sin(theta) * math.cos(phi), center[1] + radius * math.cos(theta),
                        center[2] + radius * math.sin(theta) * math.sin(phi)))
    pts.append((center[0], center[1] - radius, center[2]))
    south = len(pts) - 1
    idx = []
    ring = lambda r, s: 1 + (r - 1) * segments + s % segments
    for s in range(segments):
        idx += [0, ring(1, s + 1), ring(1, s)]
        idx += [south, ring(rings - 1, s), ring(rings - 1, s + 1)]
    for r in range(1, rings - 1):
        for s in range(segments):
            a, b, c, d = ring(r, s), ring(r, s + 1), ring(r + 1, s), ring(r + 1, s + 1)
            idx += [a, b, d, a, d, c]
    return pts, idx


def sphere_zone(theta_from, theta_to, radius=1.0, segments=32, rings=16):
    """Part of a UV sphere between polar angles theta_from and theta_to
    (radians from +y), open along its cut edges; a pole is included when
    the zone reaches it."""
    pts, idx = [], []
    first_ring = 0
    if theta_from == 0:
        pts.append((0.0, radius, 0.0))
        first_ring = 1
    ring_thetas = [theta_from + (theta_to - theta_from) * r / rings for r in range(first_ring, rings + 1)]
    base = len(pts)
    for theta in ring_thetas:
        for s in range(segments):
            phi = 2 * math.pi * s / segments
            pts.append((radius * math.sin(theta) * math.cos(phi), radius * math.cos(theta),
                        radius * math.sin(theta) * math.sin(phi)))
    ring = lambda r, s: base + r * segments + s % segments
    if first_ring:
        for s in range(segments):
            idx += [0, ring(0, s + 1), ring(0, s)]
    for r in range(len(ring_thetas) - 1):
        for s in range(segments):
            a, b, c, d = ring(r, s), ring(r, s + 1), ring(r + 1, s), ring(r + 1, s + 1)
            idx += [a, b, d, a, d, c]
    return pts, idx


def ico_sphere(radius=1.0, subdivisions=2):
    t = (1 + math.sqrt(5)) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
             (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    verts = [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in verts]
    for _ in range(subdivisions):
        cache, new_faces = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                m = [(verts[a][i] + verts[b][i]) / 2 for i in range(3)]
                n = math.sqrt(sum(x * x for x in m))
                verts.append(tuple(x / n for x in m))
                cache[key] = len(verts) - 1
            return cache[key]

        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new_faces
    return [tuple(radius * c for c in v) for v in verts], [i for f in faces for i in f]


def png(rows):
    """An 8-bit RGB PNG of rows (top first) of (r, g, b) texels."""
    raw = b"".join(b"\0" + bytes(c for texel in row for c in texel) for row in rows)

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", len(rows[0]), len(rows), 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def projected_uvs(pts, u_range, v_range):
    """Texture coordinates by projecting a unit sphere's points along z onto
    the rectangle u_range x v_range (x -> u, -y -> v)."""
    uvs = []
    for x, y, _ in pts:
        uvs += [u_range[0] + (x + 1) / 2 * (u_range[1] - u_range[0]),
                v_range[0] + (1 - y) / 2 * (v_range[1] - v_range[0])]
    return uvs


def cube(half=1.0):
    pts = [(x * half, y * half, z * half) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return pts, [i for a, b, c, d in quads for i in (a, b, c, a, c, d)]


def quat_axis_angle(axis, degrees):
    h = math.radians(degrees) / 2
    return [axis[0] * math.sin(h), axis[1] * math.sin(h), axis[2] * math.sin(h), math.cos(h)]


# ---- assets ----

def nested(out):
    """UV sphere (radius 1, centred at (0.5,0,0) in mesh space) under two
    nested nodes; the same mesh again under a matrix node; an ico sphere."""
    a = Asset()
    uv = a.mesh("UVSphere", *uv_sphere(1.0, (0.5, 0.0, 0.0)))
    ico = a.mesh("IcoSphere", *ico_sphere(1.5, 2))
    child = a.node(root=False, name="Child", translation=[0, 1, 0], mesh=uv)
    a.node(name="Root", translation=[1, 2, 3], rotation=quat_axis_angle((0, 0, 1), 90), scale=[2, 2, 2],
           children=[child])
    a.node(name="Matrix", matrix=[0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 10, 0, 0, 1], mesh=uv)
    a.node(name="Ico", translation=[0, -5, 0], mesh=ico)
    a.write_all(out, "nested")


def instanced(out):
    a = Asset()
    a.extension_used("EXT_mesh_gpu_instancing")
    uv = a.mesh("Ball", *uv_sphere(1.0))
    t = a.accessor([0, 0, 0, 3, 0, 0, 0, 3, 0], "VEC3")
    r = a.accessor([0, 0, 0, 1] * 3, "VEC4")
    s = a.accessor([1, 1, 1, 2, 2, 2, 0.5, 0.5, 0.5], "VEC3")
    a.node(name="Balls", translation=[0, 0, -1], mesh=uv,
           extensions={"EXT_mesh_gpu_instancing": {"attributes": {"TRANSLATION": t, "ROTATION": r, "SCALE": s}}})
    a.write_all(out, "instanced")


def points(out):
    a = Asset()
    pos = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]
    radius = a.accessor([0.1, 0.2, 0.3, 0.4], "SCALAR")
    color = a.accessor([1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5, 0.5, 0.5], "VEC3")
    m1 = a.mesh("Cloud", [tuple(pos[i:i + 3]) for i in range(0, 12, 3)], mode=0,
                extra_attributes={"_RADIUS": radius, "COLOR_0": color})
    m2 = a.mesh("Plain", [(0, 0, 0), (4, 0, 0), (0, 3, 0)], mode=0)
    a.node(name="Cloud", translation=[0, 0, 1], scale=[2, 2, 2], mesh=m1)
    a.node(name="Plain", translation=[10, 0, 0], mesh=m2)
    a.write_all(out, "points")


def parts(out):
    """Spheres sharing one primitive, and open surfaces that lie on a sphere.
    Row: 3 UV spheres of radius 1 at x = 0, 3, 6 in one indexed primitive.
    Soup: the same row with every triangle's corners written out separately
    (as an exporter splitting every seam does), so only welding joins them.
    Band (+-45 degrees of latitude), Hemisphere and Cap (the sphere without
    a 36-degree polar cap) lie on a sphere of radius 1 but are open."""
    a = Asset()
    pts, idx = [], []
    for k in range(3):
        p, i = uv_sphere(1.0, (3.0 * k, 0.0, 0.0))
        idx += [j + len(pts) for j in i]
        pts += p
    row = a.mesh("Row", pts, idx)
    soup = a.mesh("Soup", [pts[j] for j in idx])
    band = a.mesh("Band", *sphere_zone(math.pi / 4, 3 * math.pi / 4))
    hemisphere = a.mesh("Hemisphere", *sphere_zone(0, math.pi / 2))
    cap = a.mesh("Cap", *sphere_zone(0, 0.8 * math.pi))
    a.node(name="Row", mesh=row)
    a.node(name="Soup", translation=[0, 5, 0], mesh=soup)
    a.node(name="Band", translation=[0, -5, 0], mesh=band)
    a.node(name="Hemisphere", translation=[5, -5, 0], mesh=hemisphere)
    a.node(name="Cap", translation=[10, -5, 0], mesh=cap)
    a.write_all(out, "parts")

    # One sphere as two hemispheres in two primitives (two materials), each
    # with its own copy of the equator's vertices: welding joins them. The
    # southern zone's last ring (at the pole) welds into one vertex.
    h = Asset()
    h.gltf["materials"] = [{"name": "North"}, {"name": "South"}]
    h.mesh("Halves", *sphere_zone(0, math.pi / 2), material=0)
    south_pts, south_idx = sphere_zone(math.pi / 2, math.pi)
    prim = {"attributes": {"POSITION": h.accessor([c for p in south_pts for c in p], "VEC3")},
            "indices": h.accessor(south_idx, "SCALAR", USHORT), "material": 1}
    h.gltf["meshes"][0]["primitives"].append(prim)
    h.node(name="Halves", translation=[0, 0, 2], mesh=0)
    h.write_gltf(out, "halves")


def non_sphere(out):
    a = Asset()
    a.mesh("Ball", *uv_sphere(1.0))
    a.mesh("Cube", *cube(1.0))
    a.node(name="Ball", mesh=0)
    a.node(name="Box", translation=[5, 0, 0], mesh=1)
    a.write_all(out, "non_sphere")


def materials(out):
    """One sphere per material case, at x = 0, 3, 6, ..."""
    a = Asset()
    pts, idx = uv_sphere(1.0, segments=16, rings=8)
    volume = {"KHR_materials_volume": {"thicknessFactor": 1.0}}
    a.gltf["materials"] = [
        {"name": "Diffuse", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1], "metallicFactor": 0}},
        {"name": "VertexColour", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 1, 1, 1], "metallicFactor": 0}},
        {"name": "Metal", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.7, 1], "metallicFactor": 1,
                                                   "roughnessFactor": 0.25}},
        {"name": "Glass", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 0.9, 1], "metallicFactor": 0,
                                                   "roughnessFactor": 0},
         "extensions": dict(volume, KHR_materials_transmission={"transmissionFactor": 1.0},
                            KHR_materials_ior={"ior": 1.33})},
        {"name": "Lamp", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0},
         "emissiveFactor": [1, 0.5, 0.25], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}},
        {"name": "Textured", "pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.3, 0.3, 1], "metallicFactor": 0,
                                                      "baseColorTexture": {"index": 0}}},
        {"name": "RoughGlass", "pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0.3},
         "extensions": dict(volume, KHR_materials_transmission={"transmissionFactor": 0.9})},
        # Only the dielectric part transmits: (1 - 0.6) * 1 < 0.5, so this stays opaque.
        {"name": "MostlyMetalGlass", "pbrMetallicRoughness": {"metallicFactor": 0.6, "roughnessFactor": 0.5},
         "extensions": dict(volume, KHR_materials_transmission={"transmissionFactor": 1.0})},
        {"name": "Plastic", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1], "metallicFactor": 0,
                                                     "roughnessFactor": 0.5}},
    ]
    for ext in ("KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume",
                "KHR_materials_emissive_strength"):
        a.extension_used(ext)
    # A 1x1 PNG as a data URI: never decoded, only reported.
    a.gltf["images"] = [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg=="}]
    a.gltf["textures"] = [{"source": 0}]
    # Vertex colours: half the vertices (0.5, 0.25, 1), half (0.3, 0.15, 0.6); mean (0.4, 0.2, 0.8).
    colors = []
    for i in range(len(pts)):
        colors += [0.5, 0.25, 1.0] if i % 2 == 0 else [0.3, 0.15, 0.6]
    assert len(pts) % 2 == 0
    color = a.accessor(colors, "VEC3")
    count = len(a.gltf["materials"])
    for m in range(count):
        mesh = a.mesh("Ball%d" % m, pts, idx, material=m, extra_attributes={"COLOR_0": color} if m == 1 else None)
        a.node(name=a.gltf["materials"][m]["name"], translation=[3 * m, 0, 0], mesh=mesh)
    mesh = a.mesh("NoMaterial", pts, idx)
    a.node(name="NoMaterial", translation=[3 * count, 0, 0], mesh=mesh)
    a.write_all(out, "materials")


def glass_volumes(out):
    """Transmissive materials whose volume Orb cannot render: a thin wall (no
    KHR_materials_volume) and an absorbing volume (attenuationDistance)."""
    a = Asset()
    pts, idx = uv_sphere(1.0, segments=16, rings=8)
    a.gltf["materials"] = [
        {"name": "ThinWall", "pbrMetallicRoughness": {"metallicFactor": 0},
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0}}},
        {"name": "Tinted", "pbrMetallicRoughness": {"metallicFactor": 0},
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                        "KHR_materials_volume": {"thicknessFactor": 2.0, "attenuationDistance": 0.5,
                                                 "attenuationColor": [1, 0.5, 0.5]}}},
    ]
    for ext in ("KHR_materials_transmission", "KHR_materials_volume"):
        a.extension_used(ext)
    for m in range(2):
        mesh = a.mesh("Ball%d" % m, pts, idx, material=m)
        a.node(name=a.gltf["materials"][m]["name"], translation=[3 * m, 0, 0], mesh=mesh)
    # A second sphere of the same material: still one message per material.
    a.node(name="ThinWall2", translation=[6, 0, 0], mesh=0)
    a.write_all(out, "glass_volumes")


def ignored(out):
    """Everything Orb drops, once each kind, for the one "ignored: ..." warning.
    Material 3 is used by nothing, so its occlusion texture is not counted."""
    a = Asset()
    pts, idx = uv_sphere(1.0, segments=16, rings=8)
    a.gltf["images"] = [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg=="}]
    a.gltf["textures"] = [{"source": 0}]
    a.gltf["materials"] = [
        {"name": "Velvet", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}, "normalTexture": {"index": 0},
         "extensions": {"KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1]}}},
        {"name": "Car", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}},
         "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1}}},
        {"name": "Glass", "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1},
                                         "KHR_materials_transmission": {"transmissionFactor": 1,
                                                                        "transmissionTexture": {"index": 0}}}},
        {"name": "Unused", "occlusionTexture": {"index": 0}},
    ]
    for ext in ("KHR_materials_sheen", "KHR_materials_clearcoat", "KHR_materials_transmission", "KHR_lights_punctual",
                "KHR_texture_transform", "EXT_lights_image_based"):
        a.extension_used(ext)
    a.gltf["extensionsRequired"] = ["EXT_lights_image_based"]
    for m in range(3):
        mesh = a.mesh("Ball%d" % m, pts, idx, material=m)
        a.node(name=a.gltf["materials"][m]["name"], translation=[3 * m, 0, 0], mesh=mesh)
    a.node(name="Velvet2", translation=[9, 0, 0], mesh=0)
    a.gltf["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "SpotA", "type": "spot", "intensity": 5, "range": 10, "spot": {"outerConeAngle": 0.5}},
        {"name": "SpotB", "type": "spot", "intensity": 5, "spot": {}},
    ]}}
    a.node(name="SpotNodeA", translation=[0, 5, 0], extensions={"KHR_lights_punctual": {"light": 0}})
    a.node(name="SpotNodeB", translation=[0, -5, 0], extensions={"KHR_lights_punctual": {"light": 1}})
    a.write_all(out, "ignored")


def cameras(out):
    a = Asset()
    a.mesh("Ball", *uv_sphere(1.0))
    a.node(name="Ball", mesh=0)
    a.gltf["cameras"] = [
        {"name": "Main", "type": "perspective", "perspective": {"yfov": 0.5, "aspectRatio": 2.0, "znear": 0.1}},
        {"name": "Side", "type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}},
    ]
    a.node(name="MainCam", translation=[0, 0, 10], camera=0)
    a.node(name="SideCam", translation=[10, 0, 0], rotation=quat_axis_angle((0, 1, 0), 90), camera=1)
    a.write_all(out, "cameras")

    o = Asset()
    o.mesh("Ball", *uv_sphere(1.0))
    o.node(name="Ball", mesh=0)
    # xmag/ymag 4/3 is Orb's default 640x480; 1000 is wider than any image Orb makes.
    o.gltf["cameras"] = [
        {"name": "Ortho", "type": "orthographic", "orthographic": {"xmag": 2, "ymag": 1.5, "znear": 0.1, "zfar": 100}},
        {"name": "Wide", "type": "orthographic", "orthographic": {"xmag": 1000, "ymag": 1, "znear": 0.1, "zfar": 100}},
        {"name": "Mirrored", "type": "orthographic", "orthographic": {"xmag": 1, "ymag": -1, "znear": 0.1, "zfar": 100}},
    ]
    o.node(name="OrthoCam", translation=[0, 0, 10], camera=0)
    o.node(name="WideCam", translation=[10, 0, 0], rotation=quat_axis_angle((0, 1, 0), 90), camera=1)
    o.node(name="MirroredCam", translation=[0, 0, 10], camera=2)
    o.write_all(out, "ortho")

    n = Asset()
    n.mesh("Ball", *uv_sphere(1.0))
    n.node(name="A", mesh=0)
    n.node(name="B", translation=[4, 0, 0], mesh=0)
    n.write_all(out, "no_camera")


def lights(out):
    a = Asset()
    a.extension_used("KHR_lights_punctual")
    a.mesh("Ball", *uv_sphere(1.0))
    a.node(name="Ball", mesh=0)
    a.gltf["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "Bulb", "type": "point", "color": [1, 0.5, 0.25], "intensity": 100},
        {"name": "Spot", "type": "spot", "intensity": 50, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.4}},
        {"name": "Sun", "type": "directional", "intensity": 3},
    ]}}
    a.node(name="BulbNode", translation=[0, 5, 0], extensions={"KHR_lights_punctual": {"light": 0}})
    a.write_all(out, "point_light")
    a.node(name="SpotNode", translation=[0, -5, 0], extensions={"KHR_lights_punctual": {"light": 1}})
    # The sun shines down -y: its node's -z is turned to -y by -90 degrees about x... +90 turns -z into -y.
    a.node(name="SunNode", rotation=quat_axis_angle((1, 0, 0), -90), extensions={"KHR_lights_punctual": {"light": 2}})
    a.write_all(out, "all_lights")


def animation(out):
    a = Asset()
    ball = a.mesh("Ball", *uv_sphere(0.5))
    nodes = {}
    nodes["Linear"] = a.node(name="Linear", mesh=ball)
    arm_child = a.node(root=False, name="ArmBall", translation=[2, 0, 0], mesh=ball)
    nodes["Arm"] = a.node(name="Arm", children=[arm_child])
    nodes["Step"] = a.node(name="Step", translation=[0, 10, 0], mesh=ball)
    nodes["Cubic"] = a.node(name="Cubic", translation=[0, -10, 0], mesh=ball)
    a.node(name="Static", translation=[0, 0, -10], mesh=ball)
    a.gltf["cameras"] = [{"name": "Cam", "type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}]
    nodes["Cam"] = a.node(name="CamNode", translation=[0, 0, 10], camera=0)
    samplers, channels = [], []

    def channel(node, path, interpolation, times, values, type_):
        samplers.append({"input": a.accessor(times, "SCALAR", minmax=True),
                         "output": a.accessor([c for v in values for c in v], type_),
                         "interpolation": interpolation})
        channels.append({"sampler": len(samplers) - 1, "target": {"node": node, "path": path}})

    channel(nodes["Linear"], "translation", "LINEAR", [0, 1, 2], [(0, 0, 0), (1, 0, 0), (1, 2, 0)], "VEC3")
    channel(nodes["Arm"], "rotation", "LINEAR", [0, 1], [(0, 0, 0, 1), quat_axis_angle((0, 1, 0), 90)], "VEC4")
    channel(nodes["Step"], "scale", "STEP", [0, 1, 2], [(1, 1, 1), (2, 2, 2), (3, 3, 3)], "VEC3")
    channel(nodes["Cubic"], "translation", "CUBICSPLINE", [0, 2],
            [(0, 0, 0), (0, -10, 0), (1, 0, 0), (3, 0, 0), (4, -10, 0), (0, 0, 0)], "VEC3")
    channel(nodes["Cam"], "translation", "LINEAR", [0, 1], [(0, 0, 10), (0, 0, 20)], "VEC3")
    a.gltf["animations"] = [{"name": "Everything", "samplers": samplers, "channels": channels}]
    a.write_all(out, "animation")


def clips(out):
    """Two clips moving the same node: "Rise" to (0, 1, 0) and "Slide" to
    (2, 0, 0), both over one second. Only one may play."""
    a = Asset()
    ball = a.mesh("Ball", *uv_sphere(0.5))
    node = a.node(name="Ball", mesh=ball)
    a.gltf["animations"] = []
    for name, end in (("Rise", (0, 1, 0)), ("Slide", (2, 0, 0))):
        sampler = {"input": a.accessor([0, 1], "SCALAR", minmax=True),
                   "output": a.accessor([0, 0, 0] + list(end), "VEC3"), "interpolation": "LINEAR"}
        a.gltf["animations"].append({"name": name, "samplers": [sampler],
                                     "channels": [{"sampler": 0, "target": {"node": node, "path": "translation"}}]})
    a.write_all(out, "clips")


def compressed(out):
    """Draco- and meshopt-compressed assets, as far as Orb sees them: the
    accessors have no bufferView (Draco) or the buffer views point into a
    compressed stream, and the extension is required."""
    d = Asset()
    d.blob += bytes(16)  # stands for the Draco bit stream
    d.gltf["bufferViews"].append({"buffer": 0, "byteOffset": 0, "byteLength": 16})
    d.gltf["accessors"] = [{"componentType": FLOAT, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                           {"componentType": USHORT, "count": 3, "type": "SCALAR"}]
    d.gltf["meshes"].append({"name": "Squashed", "primitives": [{
        "attributes": {"POSITION": 0}, "indices": 1,
        "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}}}]})
    d.node(name="Squashed", mesh=0)
    d.extension_used("KHR_draco_mesh_compression")
    d.gltf["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    d.write_gltf(out, "draco")
    d.write_glb(out, "draco")

    m = Asset()
    m.blob += bytes(16)
    m.gltf["buffers"] = [{"byteLength": 16}, {"byteLength": 36, "extensions": {"EXT_meshopt_compression": {"fallback": True}}}]
    m.gltf["bufferViews"].append({"buffer": 1, "byteOffset": 0, "byteLength": 36, "byteStride": 12,
                                  "extensions": {"EXT_meshopt_compression": {
                                      "buffer": 0, "byteOffset": 0, "byteLength": 16, "byteStride": 12,
                                      "mode": "ATTRIBUTES", "count": 3}}})
    m.gltf["accessors"] = [{"bufferView": 0, "componentType": FLOAT, "count": 3, "type": "VEC3",
                            "min": [0, 0, 0], "max": [1, 1, 0]}]
    m.gltf["meshes"].append({"name": "Packed", "primitives": [{"attributes": {"POSITION": 0}}]})
    m.node(name="Packed", mesh=0)
    m.extension_used("KHR_mesh_quantization")
    m.extension_used("EXT_meshopt_compression")
    m.gltf["extensionsRequired"] = ["KHR_mesh_quantization", "EXT_meshopt_compression"]
    m.write_glb(out, "meshopt")


def implicit_shapes(out):
    a = Asset()
    a.extension_used("KHR_implicit_shapes")
    a.extension_used("KHR_physics_rigid_bodies")
    a.gltf["extensions"] = {"KHR_implicit_shapes": {"shapes": [
        {"type": "sphere", "sphere": {"radius": 0.75}}, {"type": "box", "box": {"size": [1, 1, 1]}}]}}
    a.node(name="Direct", translation=[1, 1, 1], extensions={"KHR_implicit_shapes": {"shape": 0}})
    a.node(name="Collider", translation=[-2, 0, 0], scale=[2, 2, 2],
           extensions={"KHR_physics_rigid_bodies": {"collider": {"geometry": {"shape": 0}}}})
    a.node(name="Crate", extensions={"KHR_implicit_shapes": {"shape": 1}})
    a.write_gltf(out, "implicit_shapes")


def non_uniform(out):
    a = Asset()
    a.mesh("Ball", *uv_sphere(1.0))
    a.node(name="Squashed", scale=[1, 2, 1], mesh=0)
    a.write_gltf(out, "non_uniform")


def scenes(out):
    a = Asset()
    a.mesh("Ball", *uv_sphere(1.0))
    a.node(name="First", mesh=0)
    a.node(root=False, name="Second", translation=[10, 0, 0], mesh=0)
    a.gltf["scenes"] = [{"name": "one", "nodes": [0]}, {"name": "two", "nodes": [1]}]
    a.write_gltf(out, "scenes")


def sandbox(out):
    """External buffers outside the asset's folder, or missing, are errors."""
    a = Asset()
    a.mesh("Ball", *uv_sphere(1.0))
    a.node(name="Ball", mesh=0)
    a.write_gltf(out, "escape")
    doc = json.load(open(os.path.join(out, "escape.gltf")))
    os.makedirs(os.path.join(out, "sub"), exist_ok=True)
    with open(os.path.join(out, "outside.bin"), "wb") as f:
        f.write(a.blob)
    doc["buffers"][0]["uri"] = "../outside.bin"
    json.dump(doc, open(os.path.join(out, "sub", "escape.gltf"), "w"))
    doc["buffers"][0]["uri"] = "missing.bin"
    json.dump(doc, open(os.path.join(out, "missing_buffer.gltf"), "w"))
    doc["buffers"][0]["uri"] = os.path.abspath(os.path.join(out, "outside.bin"))
    json.dump(doc, open(os.path.join(out, "sub", "absolute.gltf"), "w"))


def textures(out):
    """Spheres whose materials come from textures (tests/gltf/gltf_texture_test.cpp).

    "Atlas" (baseColorFactor (1, 0.5, 1), metallicFactor 0.5) reads two 2 x 2
    atlases, one texel per cell, [row][column], rows top (v < 0.5) first:
      metallic-roughness (R, G, B): [[(0, 51, 255), (0, 102, 0)], [(0, 153, 128), (0, 204, 64)]]
        through TEXCOORD_0, KHR_texture_transform offset (0.5, 0), REPEAT;
      base colour (sRGB): [[(255, 255, 255), (188, 0, 0)], [(0, 0, 0), (0, 188, 0)]]
        through TEXCOORD_1 (= TEXCOORD_0 + (0.5, 0)), CLAMP_TO_EDGE.
    Each sphere's TEXCOORD_0 covers [u0, u0 + 0.3] x [v0, v0 + 0.3]:
      A0, A1: (0.1, 0.1)  MR cell [0][1] (G 102, B 0)   base [0][1] (188, 0, 0)
      A2:     (0.6, 0.1)  MR cell [0][0] (G 51, B 255)  base [0][1] (clamped)
      A3:     (1.6, 0.6)  MR cell [1][0] (G 153, B 128) base [1][1] (0, 188, 0)
    so A0 and A1 share one material and there are three in all.
    "Gradient" spans a whole 2 x 2 metallic-roughness texture, columns (0, 0, 0)
    and (0, 255, 255), by projecting x -> u: the sphere's halves x < 0 and
    x > 0 have equal areas, so its averages are roughness 0.5 and metallic 0.5.
    It also has a normal texture (not read).
    "Glow" (emissiveFactor (1, 0.5, 0.25)) has a 1 x 1 emissive texture (188, 94, 255)."""
    a = Asset()
    pts, idx = uv_sphere(1.0, segments=32, rings=16)
    mr = a.texture(a.image(png([[(0, 51, 255), (0, 102, 0)], [(0, 153, 128), (0, 204, 64)]]), "atlas_mr"), 10497)
    base = a.texture(a.image(png([[(255, 255, 255), (188, 0, 0)], [(0, 0, 0), (0, 188, 0)]]), "atlas_base"), 33071)
    gradient = a.texture(a.image(png([[(0, 0, 0), (0, 255, 255)], [(0, 0, 0), (0, 255, 255)]]), "gradient"))
    glow = a.texture(a.image(png([[(188, 94, 255)]]), "glow"))
    a.extension_used("KHR_texture_transform")
    a.gltf["materials"] = [
        {"name": "Atlas", "pbrMetallicRoughness": {
            "baseColorFactor": [1, 0.5, 1, 1], "metallicFactor": 0.5, "roughnessFactor": 1,
            "baseColorTexture": {"index": base, "texCoord": 1},
            "metallicRoughnessTexture": {"index": mr, "extensions": {
                "KHR_texture_transform": {"offset": [0.5, 0]}}}}},
        {"name": "Gradient", "pbrMetallicRoughness": {"metallicRoughnessTexture": {"index": gradient}},
         "normalTexture": {"index": gradient}},
        {"name": "Glow", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1]},
         "emissiveFactor": [1, 0.5, 0.25], "emissiveTexture": {"index": glow}},
    ]
    # One mesh, one primitive, four spheres (connected parts) at x = 0, 3, 6, 9.
    positions, indices, uv0, uv1 = [], [], [], []
    for k, (u0, v0) in enumerate([(0.1, 0.1), (0.1, 0.1), (0.6, 0.1), (1.6, 0.6)]):
        indices += [i + len(positions) for i in idx]
        positions += [(x + 3 * k, y, z) for x, y, z in pts]
        uv0 += projected_uvs(pts, (u0, u0 + 0.3), (v0, v0 + 0.3))
        uv1 += projected_uvs(pts, (u0 + 0.5, u0 + 0.8), (v0, v0 + 0.3))
    texcoords = {"TEXCOORD_0": a.accessor(uv0, "VEC2"), "TEXCOORD_1": a.accessor(uv1, "VEC2")}
    a.node(name="A", mesh=a.mesh("Atlas", positions, indices, material=0, extra_attributes=texcoords))
    gradient_uvs = {"TEXCOORD_0": a.accessor(projected_uvs(pts, (0, 1), (0, 1)), "VEC2")}
    a.node(name="Gradient", translation=[0, -3, 0],
           mesh=a.mesh("Gradient", pts, idx, material=1, extra_attributes=gradient_uvs))
    a.node(name="Glow", translation=[0, -6, 0],
           mesh=a.mesh("Glow", pts, idx, material=2, extra_attributes=gradient_uvs))
    a.write_all(out, "textures")
    a.write_images_apart(out, "textures_data_uri", as_files=False)
    a.write_images_apart(out, "textures_files", as_files=True)


def bad_images(out):
    """Four spheres whose base-colour textures cannot be used, each a way an
    image can be broken: bytes that are no image (data: URI), a PNG cut
    short, a PNG whose header claims 100000 x 100000 texels, and a file that
    does not exist. Each material keeps its factor: colours (0.1 k, 0.5, 0.5)."""
    a = Asset()
    pts, idx = uv_sphere(1.0, segments=16, rings=8)
    good = png([[(255, 0, 0)]])
    a.image(good[:40], "truncated")
    header = struct.pack(">IIBBBBB", 100000, 100000, 8, 2, 0, 0, 0)
    huge = good[:8] + struct.pack(">I", 13) + b"IHDR" + header + struct.pack(">I", zlib.crc32(b"IHDR" + header))
    a.image(huge + good[33:], "huge")
    a.gltf["images"].insert(0, {"name": "garbage", "uri": "data:image/png;base64," +
                                base64.b64encode(b"this is not an image").decode()})
    a.gltf["images"].append({"name": "missing", "uri": "missing.png"})
    uv = {"TEXCOORD_0": a.accessor(projected_uvs(pts, (0, 1), (0, 1)), "VEC2")}
    a.gltf["materials"] = []
    for k in range(4):
        a.gltf["textures"] = a.gltf.get("textures", []) + [{"source": k}]
        a.gltf["materials"].append({"name": a.gltf["images"][k]["name"], "pbrMetallicRoughness": {
            "baseColorFactor": [0.1 * (k + 1), 0.5, 0.5, 1], "baseColorTexture": {"index": k}}})
        a.node(name="Ball%d" % k, translation=[3 * k, 0, 0],
               mesh=a.mesh("Ball%d" % k, pts, idx, material=k, extra_attributes=uv))
    a.write_gltf(out, "bad_images")


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for make in (nested, instanced, points, parts, non_sphere, materials, glass_volumes, ignored, cameras, lights, animation, clips,
                 compressed, implicit_shapes, non_uniform, scenes, sandbox, textures, bad_images):
        make(out)
    with open(os.path.join(out, "stamp"), "w") as f:
        f.write("ok\n")


if __name__ == "__main__":
    main()
