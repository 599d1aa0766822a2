"""Reference renders with Blender Cycles (Debian's blender 3.4 package), the peer renderer for efficiency.
../shared/tools/cycles/cycles_ref.py (its parts in tools/cycles_common.py) with a sky: --sky R,G,B (a constant world) or --sky FILE
(.pfm or .hdr: an Environment Texture, equirectangular, interpolation Closest, its image linear), the
lookup vector turned so that the OBJ's +Y is the sky's up as pathlab reads it (docs/sky.md): the world
direction (x, y, z) looks up Cycles' equirectangular map at (x, -z, y), a 90 degree turn about X.
blender -b --factory-startup --python cycles_ref.py -- OBJ --eye x,y,z --target x,y,z --up x,y,z
        --fov DEG(vertical) --size WxH --spp N --bounces MAX --out out.exr [--threads 2] [--seed S]
Materials: MTL Kd -> Lambert (Diffuse BSDF), Ke -> one-sided emission (radiance = Ke), flat shading.
Glossy (Ks/Ns) is NOT reproduced: use it only on diffuse scenes. Box pixel filter, no clamping,
no denoising, no adaptive sampling, black world. Coordinates kept as in the OBJ (no axis conversion)."""
import sys, os, math
# tools/cycles_common.py: Blender puts no script's folder on sys.path
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
import bpy
import cycles_common as cc

ap = cc.arg_parser()
ap.add_argument('--sky', default=None)
a = ap.parse_args(cc.blender_argv())

sc = cc.import_obj(a.obj)
mtl = cc.read_mtl(a.obj, default_kd=(0.8, 0.8, 0.8))
made = {}
for ob in cc.meshes(sc):
    cc.flat_shading(ob)
    cc.set_materials(ob, mtl, made)
cc.add_camera(sc, a)

world = cc.black_world(sc)
if a.sky:
    wt = world.node_tree; bg = wt.nodes['Background']; bg.inputs['Strength'].default_value = 1
    if os.path.exists(a.sky):
        env = wt.nodes.new('ShaderNodeTexEnvironment'); env.projection = 'EQUIRECTANGULAR'; env.interpolation = 'Closest'
        env.image = bpy.data.images.load(os.path.abspath(a.sky)); env.image.colorspace_settings.name = 'Non-Color'
        tc = wt.nodes.new('ShaderNodeTexCoord'); mp = wt.nodes.new('ShaderNodeMapping'); mp.vector_type = 'VECTOR'
        mp.inputs['Rotation'].default_value = (math.pi / 2, 0, 0)
        wt.links.new(tc.outputs['Generated'], mp.inputs['Vector']); wt.links.new(mp.outputs['Vector'], env.inputs['Vector'])
        wt.links.new(env.outputs['Color'], bg.inputs['Color'])
    else:
        bg.inputs['Color'].default_value = (*[float(x) for x in a.sky.split(',')], 1)
cc.render(sc, a)
