#!/usr/bin/env python3
"""Writes the bundled scenes in assets/ and the test scenes in tests/data/ (run from the
repository root; output is committed).

cornell/  The Cornell box from the published Cornell measurements (units: mm): the room, the
          two blocks, and the 130 x 105 mm ceiling light, lowered 0.8 mm so it does not share
          the ceiling's plane. Albedos are the usual RGB reductions of the measured spectral
          reflectances; the light's Ke is its radiance (17, 12, 4 in the common RGB reduction).
          Camera: the published pinhole (35 mm focal length, 25 mm film => fov_y 39.3077 deg).
cornell-glass/  The same box with the short block replaced by a glass sphere (illum 7, Ni 1.5,
          smooth; vertex normals) resting on the floor, and the tall block a mirror (illum 3,
          Ks 0.95, Pr 0) turned to 45 degrees.
furnace/  The camera inside a closed icosphere (subdivided icosahedron), every face Kd 0.5 and
          Ke 1 facing inward: the exact answer at depth K is (1 - 0.5^(K+1)) / 0.5.
glossy/   Three Cook-Torrance spheres (gold metal, red plastic, rough copper) on a glossy dark
          floor before a matte wall, under a tilted softbox and a warm strip light (units: m).
          Ks is the Fresnel F0, Pr the roughness (GGX alpha = Pr^2). The spheres are flat-faceted
          icospheres (the renderer uses geometric normals), fine enough for smooth highlights.
tests/data/cornell_point/  The Cornell box's room and blocks without the area light, lit by one
          point light just under the ceiling's centre (in its description, W/sr in mm units): the
          Cornell light's colour, about the irradiance that light gives the floor below it. A scene
          whose light has no radiance bound (K_eps) and that only next-event estimation lights.
many-lights/  A closed room (units: mm, 2400 wide, 600 high, 4000 deep) of Lambertian walls and
          floor with four boxes standing on it, lit by 300 small one-sided panels facing into the
          room (a 12 x 16 grid over the ceiling, two rows along each side wall's upper band, a row
          on the back and on the front wall), their radiance log-uniform over two orders of
          magnitude (0.2 to 20), one in five tinted warm or cool, and by three large dim panels
          low on the walls. Each panel is a light of its own (two triangles, its own material),
          drawn from a fixed seed: the scene for measuring how next-event estimation chooses
          among many lights. The camera stands inside, by the front wall.
sky/      sun-sky.exr: a latitude-longitude HDR sky (256 x 128, +y up, the image's centre along -z,
          as --env reads it): a blue gradient from the horizon to the zenith over a dark ground,
          and a sun 2.5 degrees in radius at 35 degrees elevation toward -z/+x, whose radiance
          gives a surface facing it about three times the sky's irradiance. Written as an
          uncompressed scanline EXR by the few lines of write_exr below.
Every polygon is written counter-clockwise as seen from the side it faces (its front).
"""
import json
import math
import os
import struct


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def facing(polygon, towards):
    """Returns the polygon ordered so that its counter-clockwise normal points along `towards`."""
    n = cross(sub(polygon[1], polygon[0]), sub(polygon[2], polygon[0]))
    return polygon if dot(n, towards) > 0 else list(reversed(polygon))


def centroid(points):
    return [sum(p[i] for p in points) / len(points) for i in range(3)]


def write_obj(path, header, groups):
    lines = [f"# {line}" for line in header] + [f"mtllib {os.path.basename(path)[:-4]}.mtl"]
    count = 0
    for name, material, polygons in groups:
        lines += [f"o {name}", f"usemtl {material}"]
        for polygon in polygons:
            for v in polygon:
                lines.append("v " + " ".join(f"{c:.6g}" for c in v))
            lines.append("f " + " ".join(str(count + i + 1) for i in range(len(polygon))))
            count += len(polygon)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_mtl(path, header, materials):
    lines = [f"# {line}" for line in header]
    for name, fields in materials:
        lines.append(f"newmtl {name}")
        lines += [f"{key} {' '.join(f'{c:.6g}' for c in value)}" for key, value in fields]
        lines.append("")
    with open(path, "w") as f:
        f.write("\n".join(lines))


def write_json(path, data):
    with open(path, "w") as f:
        json.dump(data, f, indent=2)
        f.write("\n")


def block(top):
    """A block standing on the floor under its top face (4 corners at the same height)."""
    base = [[x, 0.0, z] for x, _, z in top]
    middle = centroid(top + base)
    faces = [top] + [[top[i], top[(i + 1) % 4], base[(i + 1) % 4], base[i]] for i in range(4)]
    return [facing(f, sub(centroid(f), middle)) for f in faces]  # outward


CORNELL_ALBEDOS = [("white", [("Kd", [0.725, 0.71, 0.68])]),
                   ("red", [("Kd", [0.63, 0.065, 0.05])]),
                   ("green", [("Kd", [0.14, 0.45, 0.091])])]
CORNELL_LIGHT = ("light", [("Kd", [0.78, 0.78, 0.78]), ("Ke", [17, 12, 4])])
CORNELL_CAMERA = {"position": [278, 273, -800], "look_at": [278, 273, 0], "up": [0, 1, 0],
                  "fov_y": 39.3077, "width": 512, "height": 512}
SHORT_BLOCK = [[130, 165, 65], [82, 165, 225], [240, 165, 272], [290, 165, 114]]
TALL_BLOCK = [[423, 330, 247], [265, 330, 296], [314, 330, 456], [472, 330, 406]]


def cornell_room():
    """The room's walls and its light, as (name, material, polygons) groups."""
    inside = [278.0, 274.4, 279.6]
    room = {
        "floor": [[552.8, 0, 0], [0, 0, 0], [0, 0, 559.2], [549.6, 0, 559.2]],
        "ceiling": [[556, 548.8, 0], [556, 548.8, 559.2], [0, 548.8, 559.2], [0, 548.8, 0]],
        "back_wall": [[549.6, 0, 559.2], [0, 0, 559.2], [0, 548.8, 559.2], [556, 548.8, 559.2]],
        "green_wall": [[0, 0, 559.2], [0, 0, 0], [0, 548.8, 0], [0, 548.8, 559.2]],
        "red_wall": [[552.8, 0, 0], [549.6, 0, 559.2], [556, 548.8, 559.2], [556, 548.8, 0]],
    }
    materials = {"floor": "white", "ceiling": "white", "back_wall": "white",
                 "green_wall": "green", "red_wall": "red"}
    groups = [(n, materials[n], [facing(p, sub(inside, centroid(p)))]) for n, p in room.items()]
    light = [[343, 548.0, 227], [343, 548.0, 332], [213, 548.0, 332], [213, 548.0, 227]]
    return groups, ("light", "light", [facing(light, [0, -1, 0])])


def cornell():
    groups, light = cornell_room()
    groups += cornell_blocks() + [light]
    write_obj("assets/cornell/cornell.obj",
              ["Cornell box after the published Cornell measurements (mm).",
               "Counter-clockwise = front. Kd: Lambertian albedo; Ke: radiance, front side only."],
              groups)
    write_mtl("assets/cornell/cornell.mtl",
              ["Albedos: RGB reductions of the measured reflectance spectra. Light: Ke = radiance."],
              CORNELL_ALBEDOS + [CORNELL_LIGHT])
    write_json("assets/cornell/cornell.json", CORNELL_CAMERA)


def cornell_blocks():
    """The short and the tall block, as (name, material, polygons) groups."""
    return [("short_block", "white", block(SHORT_BLOCK)), ("tall_block", "white", block(TALL_BLOCK))]


def cornell_point():
    # Irradiance under the area light, about Le A / d^2 = 17 * 130 * 105 / 548^2 = 0.77 in red;
    # the point light gives I / d^2 at d = 540 mm, so I = 13000 * (17, 12, 4) W/sr.
    os.makedirs("tests/data/cornell_point", exist_ok=True)
    groups, _ = cornell_room()
    write_obj("tests/data/cornell_point/cornell_point.obj",
              ["The Cornell box's room and blocks (mm) without the area light: the point light of",
               "cornell_point.json lights it. Counter-clockwise = front. Kd: Lambertian albedo."],
              groups + cornell_blocks())
    write_mtl("tests/data/cornell_point/cornell_point.mtl",
              ["Albedos: RGB reductions of the measured reflectance spectra."], CORNELL_ALBEDOS)
    write_json("tests/data/cornell_point/cornell_point.json",
               {**CORNELL_CAMERA, "width": 64, "height": 64,
                "lights": [{"type": "point", "position": [278, 540, 279.6],
                            "intensity": [221000, 156000, 52000]}]})


def cornell_glass():
    groups, light = cornell_room()
    # The tall block's footprint turned to 45 degrees from the camera's axis, so that its two
    # visible faces mirror the red and the green wall rather than the open front.
    centre = centroid(TALL_BLOCK)
    half = math.dist(TALL_BLOCK[0], TALL_BLOCK[1]) / 2
    mirror_top = [[centre[0] + half * math.sqrt(2) * math.cos(a), 330, centre[2] + half * math.sqrt(2) * math.sin(a)]
                  for a in (0, math.pi / 2, math.pi, 3 * math.pi / 2)]
    groups.append(("mirror_block", "mirror", block(mirror_top)))
    groups.append(light)
    path = "assets/cornell-glass/cornell-glass.obj"
    write_obj(path, ["The Cornell box with a glass sphere and a mirror block (mm).",
                     "Counter-clockwise = front; the sphere's vn are its exact normals."], groups)
    # The sphere where the short block stood, resting on the floor; vertex normals make it smooth.
    radius = 90.0
    centre = centroid(SHORT_BLOCK)
    centre[1] = radius
    vertices, faces = icosphere(4)
    first = sum(len(polygon) for _, _, polygons in groups for polygon in polygons)
    lines = ["o glass_sphere", "usemtl glass"]
    lines += ["v " + " ".join(f"{centre[i] + radius * v[i]:.6g}" for i in range(3)) for v in vertices]
    lines += ["vn " + " ".join(f"{c:.6g}" for c in v) for v in vertices]
    # The icosahedron's faces are counter-clockwise seen from outside: they face out.
    lines += [f"f {first + a + 1}//{a + 1} {first + b + 1}//{b + 1} {first + c + 1}//{c + 1}"
              for a, b, c in faces]
    with open(path, "a") as f:
        f.write("\n".join(lines) + "\n")
    write_mtl("assets/cornell-glass/cornell-glass.mtl",
              ["The Cornell box's albedos and light; glass: a smooth dielectric (illum 7) of index",
               "Ni, filter Tf; mirror: a perfect mirror (illum 3, Pr 0) of Fresnel F0 = Ks."],
              CORNELL_ALBEDOS + [CORNELL_LIGHT, ("glass", [("illum", [7]), ("Ni", [1.5]), ("Tf", [1, 1, 1])]),
                                 ("mirror", [("illum", [3]), ("Ks", [0.95, 0.95, 0.95]), ("Pr", [0])])])
    write_json("assets/cornell-glass/cornell-glass.json", CORNELL_CAMERA)


def icosphere(subdivisions):
    t = (1 + math.sqrt(5)) / 2
    vertices = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
                [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    faces = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4],
             [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8],
             [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    unit = lambda v: [c / math.sqrt(dot(v, v)) for c in v]
    vertices = [unit(v) for v in vertices]
    for _ in range(subdivisions):
        midpoints = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoints:
                vertices.append(unit([(vertices[a][i] + vertices[b][i]) / 2 for i in range(3)]))
                midpoints[key] = len(vertices) - 1
            return midpoints[key]

        refined = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            refined += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
        faces = refined
    return vertices, faces


def furnace():
    radius = 1.0
    vertices, faces = icosphere(3)
    lines = ["# Furnace: a closed icosphere (1280 faces, radius 1), every face Kd 0.5, Ke 1 1 1,",
             "# facing inward. Exact radiance at depth K: (1 - 0.5^(K+1)) / 0.5; 2 as K grows.",
             "mtllib furnace.mtl", "o sphere", "usemtl furnace"]
    lines += ["v " + " ".join(f"{radius * c:.9g}" for c in v) for v in vertices]
    for a, b, c in faces:
        # The icosahedron's faces are counter-clockwise seen from outside; reverse them to face in.
        lines.append(f"f {a + 1} {c + 1} {b + 1}")
    with open("assets/furnace/furnace.obj", "w") as f:
        f.write("\n".join(lines) + "\n")
    write_mtl("assets/furnace/furnace.mtl", ["Uniform albedo 0.5 and emission 1 everywhere."],
              [("furnace", [("Kd", [0.5, 0.5, 0.5]), ("Ke", [1, 1, 1])])])
    write_json("assets/furnace/furnace.json",
               {"position": [0.1, -0.05, 0.02], "look_at": [0.1, -0.05, 1.0], "up": [0, 1, 0],
                "fov_y": 90, "width": 64, "height": 64})


def glossy():
    lines = ["# Glossy studio: three Cook-Torrance spheres on a glossy floor (units: m).",
             "# Counter-clockwise = front. Ks: Fresnel F0; Pr: roughness (GGX alpha = Pr^2).",
             "mtllib glossy.mtl"]
    count = 0

    def polygons(name, material, polys):
        nonlocal count
        lines.extend([f"o {name}", f"usemtl {material}"])
        for poly in polys:
            lines.extend("v " + " ".join(f"{c:.6g}" for c in v) for v in poly)
            lines.append("f " + " ".join(str(count + i + 1) for i in range(len(poly))))
            count += len(poly)

    polygons("floor", "floor", [facing([[-5, 0, -2], [5, 0, -2], [5, 0, 5], [-5, 0, 5]], [0, 1, 0])])
    polygons("wall", "wall", [facing([[-5, 0, -2], [5, 0, -2], [5, 5, -2], [-5, 5, -2]], [0, 0, 1])])
    # Softbox above and in front, tilted 30 degrees toward the spheres.
    c, s30 = math.cos(math.radians(30)), math.sin(math.radians(30))
    box = [[x, 3.2 + dz * s30, 2.0 + dz * c] for x, dz in [(-1.2, -0.5), (1.2, -0.5), (1.2, 0.5), (-1.2, 0.5)]]
    polygons("softbox", "softbox", [facing(box, [0, -c, -s30])])
    # A warm vertical strip at the back left, lighting the spheres' rims.
    strip = [[-3.2, 0.2, -1.0], [-3.2, 0.2, -0.4], [-3.2, 2.4, -0.4], [-3.2, 2.4, -1.0]]
    polygons("strip", "strip", [facing(strip, [1, 0, 0.3])])

    vertices, faces = icosphere(4)
    radius = 0.55
    for name, x in [("gold", -1.3), ("plastic", 0.0), ("copper", 1.3)]:
        lines.extend([f"o {name}", f"usemtl {name}"])
        lines.extend("v " + " ".join(f"{c:.6g}" for c in [x + radius * v[0], radius + radius * v[1],
                                                              radius * v[2]]) for v in vertices)
        # The icosahedron's faces are counter-clockwise seen from outside: they face out.
        lines.extend(f"f {count + a + 1} {count + b + 1} {count + c + 1}" for a, b, c in faces)
        count += len(vertices)
    with open("assets/glossy/glossy.obj", "w") as f:
        f.write("\n".join(lines) + "\n")
    write_mtl("assets/glossy/glossy.mtl",
              ["Cook-Torrance materials: Kd Lambertian base, Ks Schlick F0, Pr roughness; Ke radiance."],
              [("floor", [("Kd", [0.16, 0.16, 0.18]), ("Ks", [0.04, 0.04, 0.04]), ("Pr", [0.3])]),
               ("wall", [("Kd", [0.55, 0.55, 0.55])]),
               ("gold", [("Kd", [0, 0, 0]), ("Ks", [1.0, 0.71, 0.29]), ("Pr", [0.3])]),
               ("plastic", [("Kd", [0.6, 0.05, 0.04]), ("Ks", [0.04, 0.04, 0.04]), ("Pr", [0.2])]),
               ("copper", [("Kd", [0, 0, 0]), ("Ks", [0.95, 0.64, 0.54]), ("Pr", [0.55])]),
               ("softbox", [("Ke", [12, 12, 12])]),
               ("strip", [("Ke", [10, 6, 3])])])
    write_json("assets/glossy/glossy.json",
               {"position": [0, 1.3, 4.6], "look_at": [0, 0.5, 0], "up": [0, 1, 0],
                "fov_y": 32, "width": 480, "height": 270})


def many_lights():
    import random
    rng = random.Random(20261204)
    width, height, depth = 2400.0, 600.0, 4000.0
    sx, sy, sz = width / 1000, height / 500, depth / 1400  # the boxes' layout, drawn for 1000 x 500 x 1400
    inside = [width / 2, height / 2, depth / 2]
    room = {
        "floor": ("floor", [[0, 0, 0], [width, 0, 0], [width, 0, depth], [0, 0, depth]]),
        "ceiling": ("wall", [[0, height, 0], [width, height, 0], [width, height, depth], [0, height, depth]]),
        "back_wall": ("wall", [[0, 0, depth], [width, 0, depth], [width, height, depth], [0, height, depth]]),
        "front_wall": ("wall", [[0, 0, 0], [width, 0, 0], [width, height, 0], [0, height, 0]]),
        "left_wall": ("blue", [[0, 0, 0], [0, 0, depth], [0, height, depth], [0, height, 0]]),
        "right_wall": ("ochre", [[width, 0, 0], [width, 0, depth], [width, height, depth], [width, height, 0]]),
    }
    groups = [(n, m, [facing(p, sub(inside, centroid(p)))]) for n, (m, p) in room.items()]
    boxes = [[[150, 260, 300], [380, 260, 300], [380, 260, 520], [150, 260, 520]],
             [[620, 140, 420], [840, 140, 380], [880, 140, 600], [660, 140, 640]],
             [[300, 380, 900], [520, 380, 900], [520, 380, 1080], [300, 380, 1080]],
             [[700, 200, 1000], [900, 200, 1000], [900, 200, 1250], [700, 200, 1250]]]
    boxes = [[[x * sx, y * sy, z * sz] for x, y, z in top] for top in boxes]
    groups += [(f"box_{i}", "box", block(top)) for i, top in enumerate(boxes)]
    inset = 0.8  # off the surface behind, as the Cornell light is
    panels = []  # (corners, facing direction)
    for i in range(12):
        for k in range(16):
            x, z = (i + 0.5) * width / 12, (k + 0.5) * depth / 16
            y = height - inset
            panels.append(([[x - 40, y, z - 40], [x + 40, y, z - 40], [x + 40, y, z + 40], [x - 40, y, z + 40]],
                           [0, -1, 0]))
    for wall_x, inward in [(inset, 1), (width - inset, -1)]:
        for y in (height - 120, height - 50):
            for k in range(20):
                z = (k + 0.5) * depth / 20
                panels.append(([[wall_x, y - 15, z - 20], [wall_x, y - 15, z + 20], [wall_x, y + 15, z + 20],
                                [wall_x, y + 15, z - 20]], [inward, 0, 0]))
    for wall_z, inward in [(depth - inset, -1), (inset, 1)]:
        for i in range(14):
            x = (i + 0.5) * width / 14
            panels.append(([[x - 30, height - 80, wall_z], [x + 30, height - 80, wall_z],
                            [x + 30, height - 40, wall_z], [x - 30, height - 40, wall_z]], [0, 0, inward]))
    tints = [[1.0, 0.55, 0.2], [0.35, 0.6, 1.0], [1.0, 0.3, 0.6], [0.4, 1.0, 0.45]]
    materials = [("floor", [("Kd", [0.55, 0.52, 0.48])]), ("wall", [("Kd", [0.75, 0.75, 0.73])]),
                 ("blue", [("Kd", [0.35, 0.45, 0.65])]), ("ochre", [("Kd", [0.7, 0.55, 0.3])]),
                 ("box", [("Kd", [0.7, 0.7, 0.7])])]
    for n, (corners, towards) in enumerate(panels):
        radiance = 0.2 * 100.0 ** rng.random()
        colour = rng.choice(tints) if rng.random() < 0.2 else [1.0, 0.95, 0.85]
        name = f"panel_{n:03d}"
        groups.append((name, name, [facing(corners, towards)]))
        materials.append((name, [("Kd", [0.8, 0.8, 0.8]), ("Ke", [radiance * c for c in colour])]))
    large = [("glow_left", [[inset, 60, 800], [inset, 60, 2000], [inset, 300, 2000], [inset, 300, 800]], [1, 0, 0]),
             ("glow_right", [[width - inset, 60, 2000], [width - inset, 60, 3400], [width - inset, 300, 3400],
                             [width - inset, 300, 2000]], [-1, 0, 0]),
             ("glow_back", [[700, 80, depth - inset], [1700, 80, depth - inset], [1700, 300, depth - inset],
                            [700, 300, depth - inset]], [0, 0, -1])]
    for name, corners, towards in large:
        groups.append((name, "glow", [facing(corners, towards)]))
    materials.append(("glow", [("Kd", [0.8, 0.8, 0.8]), ("Ke", [0.3, 0.32, 0.36])]))
    os.makedirs("assets/many-lights", exist_ok=True)
    write_obj("assets/many-lights/many-lights.obj",
              ["A room lit by 300 small emissive panels and 3 large dim ones (mm); make_assets.py.",
               "Counter-clockwise = front. Kd: Lambertian albedo; Ke: radiance, front side only."],
              groups)
    write_mtl("assets/many-lights/many-lights.mtl",
              ["Panels: Ke = radiance, log-uniform in 0.2..20, some tinted; the glow panels are dim."],
              materials)
    write_json("assets/many-lights/many-lights.json",
               {"position": [width / 2, 0.55 * height, 40], "look_at": [width / 2, 0.3 * height, depth], "up": [0, 1, 0],
                "fov_y": 62, "width": 480, "height": 320})


def write_exr(path, width, height, pixel):
    """An uncompressed scanline OpenEXR of 32-bit float B, G, R channels (OpenEXR's file layout:
    the magic number and version, the header's attributes, a scanline offset table, then each
    scanline as its y, its byte count and each channel's row in the channels' order)."""
    def attribute(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value

    channels = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in "BGR") + b"\0"
    window = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", 20000630, 2) +
              attribute("channels", "chlist", channels) +
              attribute("compression", "compression", b"\0") +
              attribute("dataWindow", "box2i", window) +
              attribute("displayWindow", "box2i", window) +
              attribute("lineOrder", "lineOrder", b"\0") +
              attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
              attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0)) +
              attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    row_bytes = 3 * 4 * width
    first = len(header) + 8 * height
    offsets = b"".join(struct.pack("<Q", first + y * (8 + row_bytes)) for y in range(height))
    rows = []
    for y in range(height):
        texels = [pixel(x, y) for x in range(width)]
        data = b"".join(struct.pack(f"<{width}f", *(t[c] for t in texels)) for c in (2, 1, 0))
        rows.append(struct.pack("<ii", y, row_bytes) + data)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(header + offsets + b"".join(rows))


def sky():
    width, height = 256, 128
    elevation, azimuth, radius = math.radians(35.0), math.radians(20.0), math.radians(2.5)
    # The map's convention: theta from +y, phi from -z toward +x.
    sun = [math.cos(elevation) * math.sin(azimuth), math.sin(elevation), -math.cos(elevation) * math.cos(azimuth)]
    zenith, horizon, ground = [0.25, 0.45, 1.0], [0.95, 0.97, 1.0], [0.18, 0.16, 0.14]
    sun_radiance = [2000.0, 1900.0, 1700.0]

    def pixel(x, y):
        theta = math.pi * (y + 0.5) / height
        phi = 2.0 * math.pi * ((x + 0.5) / width - 0.5)
        d = [math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi)]
        if dot(d, sun) > math.cos(radius):
            return sun_radiance
        if d[1] < 0.0:
            return ground
        t = d[1] ** 0.5  # the blue deepens quickly above the horizon
        return [horizon[i] + (zenith[i] - horizon[i]) * t for i in range(3)]

    write_exr("assets/sky/sun-sky.exr", width, height, pixel)


if __name__ == "__main__":
    cornell()
    cornell_point()
    cornell_glass()
    furnace()
    glossy()
    many_lights()
    sky()
