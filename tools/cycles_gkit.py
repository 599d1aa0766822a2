"""tools/cycles_gkit.py: ../shared/tools/cycles/cycles_ref.py (its parts in tools/cycles_common.py)
extended for gKit's scenes (docs/gkit.md):
--smooth keeps the OBJ's vn (smooth shading from them), and map_Kd becomes an Image Texture node with
Closest interpolation (nearest texel, as gKit), its bytes taken as Non-Color (raw /255, gKit's) or
sRGB with --srgb, multiplied by Kd. --pfm OUT.pfm also writes the image as a PFM (read back from the
EXR by Blender itself: no OpenImageIO needed).
Reference renders with Blender Cycles (Debian's blender 3.4 package), the peer renderer for efficiency.
blender -b --factory-startup --python cycles_ref.py -- OBJ --eye x,y,z --target x,y,z --up x,y,z
        --fov DEG(vertical) --size WxH --spp N --bounces MAX --out out.exr [--threads 2] [--seed S]
Materials: MTL Kd -> Lambert (Diffuse BSDF), Ke -> one-sided emission (radiance = Ke), flat shading;
a Kd or Ke the MTL does not give is 0, as pathlab reads it (an emitter without Kd reflects nothing).
Glossy (Ks/Ns) is NOT reproduced: use it only on diffuse scenes. Box pixel filter, no clamping,
no denoising, no adaptive sampling, black world. Coordinates kept as in the OBJ (no axis conversion)."""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))   # cycles_common: Blender puts no script's folder there
import bpy
import cycles_common as cc

ap = cc.arg_parser()
ap.add_argument('--smooth', action='store_true'); ap.add_argument('--srgb', action='store_true'); ap.add_argument('--pfm')
a = ap.parse_args(cc.blender_argv())

sc = cc.import_obj(a.obj)
mtl = cc.read_mtl(a.obj, default_kd=(0, 0, 0))   # a Kd not given is 0, as pathlab reads it
made = {}
for ob in cc.meshes(sc):
    if a.smooth:   # the importer's custom normals are the vn: smooth shading from them
        # Blender keeps custom normals as offsets in a per-corner space that depends on the faces'
        # smooth flags: turning a flat face (an OBJ without `s 1`) smooth after the import rotates
        # every vn (the sphere's equator vn (0,0,1) became (0.28,0.23,0.93)). So read the vn as
        # imported, turn the faces smooth, then set the same vn again.
        me = ob.data; me.calc_normals_split(); vn = [tuple(l.normal) for l in me.loops]
        for p in me.polygons: p.use_smooth = True
        if me.has_custom_normals: me.normals_split_custom_set(vn)
        # no shadow-terminator fix: Cycles would start shadow rays from a curved surface above the
        # facet, where gKit's (and pathlab's) start on the facet itself
        ob.cycles.shadow_terminator_geometry_offset = 0.0; ob.cycles.shadow_terminator_offset = 0.0
    else:
        cc.flat_shading(ob)
    cc.set_materials(ob, mtl, made, tex_colorspace='sRGB' if a.srgb else 'Non-Color')
cc.add_camera(sc, a)
cc.black_world(sc)
cc.render(sc, a)
if a.pfm:   # the EXR read back by Blender (bottom row first, as PFM), written as a little-endian PFM
    import struct
    img = bpy.data.images.load(os.path.abspath(a.out)); px = list(img.pixels); w, h = img.size
    with open(a.pfm, 'wb') as f:
        f.write(b'PF\n%d %d\n-1\n' % (w, h))
        f.write(struct.pack('<%df' % (3 * w * h), *[px[4 * i + c] for i in range(w * h) for c in range(3)]))
