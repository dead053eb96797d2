"""Blender check of issue 42: the OBJ + MTL and the GLB of one model show the same colours in Blender.

Run inside Blender (3.4 is Debian 12's), headless:

    blender -b --factory-startup --python-exit-code 1 -P tests/blender/compare_colours.py -- MODEL.obj MODEL.glb [--keep DIR]

`tests/blender/blender_colours.sh` writes the two files with the CLI and runs this. Each file is imported into an
empty scene the way a user does (File > Import > Wavefront (.obj) at scale 0.001 for millimetres; File > Import >
glTF 2.0 with Shading set to Flat, since the default fails with Debian's numpy, issue 42) and rendered with the
Workbench engine (what the viewport's Solid mode shows) with flat lighting, material colours, no shadow, cavity,
outline, specular or anti-aliasing, and the Standard view transform, so that a pixel is the material's colour as
the screen shows it. Every part class (balls, blue, yellow and red struts) is rendered alone from the same
orthographic camera, and its pixel colour is the per-channel median over the pixels it covers.

Checks (each within TOLERANCE = 0.05 of full scale per channel, i.e. 5%):
  - the rendered pixel colour of each class, OBJ against GLB (the acceptance of issue 42);
  - the Principled BSDF base colour of each class's material (what Material Preview, EEVEE and Cycles use),
    OBJ against GLB, compared as display (sRGB-encoded) values;
and the two imports' bounding boxes agree within 1% (same size, axes and place, so the same camera sees the same
model). Prints one JSON object, then "blender colours: PASS" or "blender colours: FAIL"; exits 1 on failure.
"""

import json
import math
import os
import statistics
import sys
import tempfile

import bpy
from mathutils import Vector

TOLERANCE = 0.05
CLASSES = ("ball", "blue", "yellow", "red")
SIZE = 256  # render width and height in pixels


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1 :] if "--" in sys.argv else []
    keep = None
    if "--keep" in argv:
        i = argv.index("--keep")
        keep = argv[i + 1]
        del argv[i : i + 2]
    if len(argv) != 2:
        print("usage: blender -b -P compare_colours.py -- MODEL.obj MODEL.glb [--keep DIR]", file=sys.stderr)
        sys.exit(2)
    return argv[0], argv[1], keep


def class_of(material_name):
    """Part class of a material: OBJ names them ball_white, strut_blue, ...; GLB 'ball white', 'blue', ..."""
    name = material_name.lower()
    for colour in ("yellow", "blue", "red"):
        if colour in name:
            return colour
    if "ball" in name or "white" in name:
        return "ball"
    return None


def obj_scale(path):
    """0.001 for an OBJ whose header says millimetres (the default export), 1 for metres."""
    with open(path, encoding="utf-8", errors="replace") as f:
        for _ in range(10):
            line = f.readline()
            if line.startswith("# units:"):
                return 0.001 if "millimetres" in line else 1.0
    return 0.001


def import_file(path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if path.lower().endswith(".obj"):
        # Blender 3.4's File > Import > Wavefront (.obj): the C++ importer (the legacy one reads Kd the same way).
        bpy.ops.wm.obj_import(filepath=path, global_scale=obj_scale(path))
    else:
        # The default import_shading='NORMALS' raises "module 'numpy' has no attribute 'bool'" with Debian's numpy.
        bpy.ops.import_scene.gltf(filepath=path, import_shading="FLAT")
    bpy.context.view_layer.update()


def srgb_encode(c):
    c = max(0.0, min(1.0, c))
    return c * 12.92 if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055


def base_colours():
    """Per class: (diffuse_color, Principled BSDF base colour), both linear RGB as Blender holds them."""
    out = {}
    for m in bpy.data.materials:
        cls = class_of(m.name)
        if cls is None or m.users == 0:
            continue
        base = None
        if m.use_nodes and m.node_tree:
            for node in m.node_tree.nodes:
                if node.type == "BSDF_PRINCIPLED":
                    base = list(node.inputs["Base Color"].default_value)[:3]
        out[cls] = {"material": m.name, "diffuse_color": list(m.diffuse_color)[:3], "base_color": base}
    return out


def mesh_objects():
    return [o for o in bpy.context.scene.objects if o.type == "MESH"]


def bounding_box(objects):
    lo = [math.inf] * 3
    hi = [-math.inf] * 3
    for o in objects:
        for corner in o.bound_box:
            p = o.matrix_world @ Vector(corner)
            for k in range(3):
                lo[k] = min(lo[k], p[k])
                hi[k] = max(hi[k], p[k])
    return lo, hi


def setup_render(lo, hi):
    sc = bpy.context.scene
    sc.render.engine = "BLENDER_WORKBENCH"
    sh = sc.display.shading
    sh.light = "FLAT"
    sh.color_type = "MATERIAL"
    sh.show_cavity = False
    sh.show_shadows = False
    sh.show_object_outline = False
    sh.show_specular_highlight = False
    sh.show_xray = False
    sh.use_dof = False
    sc.display.render_aa = "OFF"
    sc.render.film_transparent = True
    sc.render.dither_intensity = 0.0
    sc.render.resolution_x = SIZE
    sc.render.resolution_y = SIZE
    sc.render.resolution_percentage = 100
    sc.render.image_settings.file_format = "PNG"
    sc.render.image_settings.color_mode = "RGBA"
    sc.render.image_settings.color_depth = "8"
    sc.display_settings.display_device = "sRGB"
    sc.view_settings.view_transform = "Standard"
    sc.view_settings.look = "None"
    sc.view_settings.exposure = 0.0
    sc.view_settings.gamma = 1.0
    sc.view_settings.use_curve_mapping = False

    centre = Vector([(a + b) / 2 for a, b in zip(lo, hi)])
    diagonal = (Vector(hi) - Vector(lo)).length
    cam_data = bpy.data.cameras.new("check camera")
    cam_data.type = "ORTHO"
    cam_data.ortho_scale = 1.1 * diagonal
    cam_data.clip_start = 0.001 * diagonal
    cam_data.clip_end = 10 * diagonal
    cam = bpy.data.objects.new("check camera", cam_data)
    sc.collection.objects.link(cam)
    direction = Vector((1.0, -1.6, 0.9)).normalized()  # Blender's z is up after either import
    cam.location = centre + 3 * diagonal * direction
    cam.rotation_euler = (-direction).to_track_quat("-Z", "Y").to_euler()
    sc.camera = cam


def render_class(cls, objects_by_class, path):
    for c, objs in objects_by_class.items():
        for o in objs:
            o.hide_render = cls is not None and c != cls
    sc = bpy.context.scene
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(path)
    img.colorspace_settings.name = "Non-Color"  # the PNG's bytes as they are: display values
    px = img.pixels[:]
    bpy.data.images.remove(img)
    channels = ([], [], [])
    for i in range(0, len(px), 4):
        if px[i + 3] > 0.99:
            for k in range(3):
                channels[k].append(px[i + k])
    if not channels[0]:
        return None, 0
    return [statistics.median(ch) for ch in channels], len(channels[0])


def measure(path, workdir, tag, keep):
    import_file(path)
    objects = mesh_objects()
    by_class = {}
    for o in objects:
        cls = None
        for slot in o.material_slots:
            if slot.material is not None:
                cls = class_of(slot.material.name) or cls
        by_class.setdefault(cls, []).append(o)
    lo, hi = bounding_box(objects)
    setup_render(lo, hi)
    result = {"file": path, "objects": len(objects), "bbox": [lo, hi], "materials": base_colours(), "pixels": {}}
    for cls in CLASSES:
        if cls not in by_class:
            continue
        png = os.path.join(workdir, f"{tag}_{cls}.png")
        colour, count = render_class(cls, by_class, png)
        result["pixels"][cls] = {"rgb": colour, "rgb255": [round(c * 255) for c in colour] if colour else None,
                                 "pixels": count}
    if keep:
        render_class(None, by_class, os.path.join(workdir, f"{tag}_all.png"))
    return result


def main():
    obj_path, glb_path, keep = parse_args()
    workdir = keep or tempfile.mkdtemp(prefix="zome_blender_")
    os.makedirs(workdir, exist_ok=True)
    obj = measure(os.path.abspath(obj_path), workdir, "obj", keep)
    glb = measure(os.path.abspath(glb_path), workdir, "glb", keep)

    failures = []
    compared = {}
    for cls in CLASSES:
        a = obj["pixels"].get(cls)
        b = glb["pixels"].get(cls)
        if not a or not b or a["rgb"] is None or b["rgb"] is None or min(a["pixels"], b["pixels"]) < 50:
            failures.append(f"{cls}: not rendered in both files (obj {a}, glb {b})")
            continue
        diff = max(abs(x - y) for x, y in zip(a["rgb"], b["rgb"]))
        entry = {"obj_pixel": a["rgb255"], "glb_pixel": b["rgb255"], "max_channel_difference": round(diff, 4),
                 "pixels_counted": [a["pixels"], b["pixels"]]}
        if diff > TOLERANCE:
            failures.append(f"{cls}: rendered colour OBJ {a['rgb255']} against GLB {b['rgb255']}"
                            f" differs by {diff:.3f} > {TOLERANCE}")
        ma = obj["materials"].get(cls, {}).get("base_color")
        mb = glb["materials"].get(cls, {}).get("base_color")
        if ma and mb:
            da = [srgb_encode(c) for c in ma]
            db = [srgb_encode(c) for c in mb]
            bdiff = max(abs(x - y) for x, y in zip(da, db))
            entry["obj_base_color_linear"] = [round(c, 4) for c in ma]
            entry["glb_base_color_linear"] = [round(c, 4) for c in mb]
            entry["base_color_difference_srgb"] = round(bdiff, 4)
            if bdiff > TOLERANCE:
                failures.append(f"{cls}: base colour OBJ {[round(c, 4) for c in ma]} against GLB {[round(c, 4) for c in mb]}"
                                f" (linear) differs by {bdiff:.3f}"
                                f" in sRGB > {TOLERANCE}")
        compared[cls] = entry

    (olo, ohi), (glo, ghi) = obj["bbox"], glb["bbox"]
    size = max(b - a for a, b in zip(glo, ghi))
    bbox_diff = max(max(abs(x - y) for x, y in zip(olo, glo)), max(abs(x - y) for x, y in zip(ohi, ghi)))
    if not size > 0 or bbox_diff > 0.01 * size:
        failures.append(f"bounding boxes differ: OBJ {olo}..{ohi}, GLB {glo}..{ghi} (m)")

    summary = {
        "blender": bpy.app.version_string,
        "tolerance": TOLERANCE,
        "renders": workdir,
        "colours": compared,
        "bbox_m": {"obj": [[round(v, 4) for v in olo], [round(v, 4) for v in ohi]],
                   "glb": [[round(v, 4) for v in glo], [round(v, 4) for v in ghi]]},
        "objects": {"obj": obj["objects"], "glb": glb["objects"]},
        "failures": failures,
    }
    # One key a line, and one part class a line under "colours".
    lines = []
    for key, value in summary.items():
        if key == "colours":
            inner = [f'  "{cls}": {json.dumps(entry)}' for cls, entry in value.items()]
            lines.append(f' "{key}": {{\n' + ",\n".join(inner) + "\n }")
        else:
            lines.append(f' "{key}": {json.dumps(value)}')
    print("{\n" + ",\n".join(lines) + "\n}")
    print("blender colours: " + ("FAIL" if failures else "PASS"))
    sys.stdout.flush()
    sys.exit(1 if failures else 0)


main()
