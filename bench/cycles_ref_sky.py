"""Reference renders with Blender Cycles (Debian's blender 3.4 package), the peer renderer for efficiency.
A copy of ../shared/tools/cycles/cycles_ref.py with a sky: --sky R,G,B (a constant world) or --sky FILE
(.pfm or .hdr: an Environment Texture, equirectangular, interpolation Closest, its image linear), the
lookup vector turned so that the OBJ's +Y is the sky's up as pathlab reads it (docs/sky.md): the world
direction (x, y, z) looks up Cycles' equirectangular map at (x, -z, y), a 90 degree turn about X.
blender -b --factory-startup --python cycles_ref.py -- OBJ --eye x,y,z --target x,y,z --up x,y,z
        --fov DEG(vertical) --size WxH --spp N --bounces MAX --out out.exr [--threads 2] [--seed S]
Materials: MTL Kd -> Lambert (Diffuse BSDF), Ke -> one-sided emission (radiance = Ke), flat shading.
Glossy (Ks/Ns) is NOT reproduced: use it only on diffuse scenes. Box pixel filter, no clamping,
no denoising, no adaptive sampling, black world. Coordinates kept as in the OBJ (no axis conversion)."""
import sys, os, math, argparse
import bpy
from mathutils import Vector

argv = sys.argv[sys.argv.index('--') + 1:]
ap = argparse.ArgumentParser()
ap.add_argument('obj'); ap.add_argument('--eye'); ap.add_argument('--target'); ap.add_argument('--up', default='0,1,0')
ap.add_argument('--fov', type=float); ap.add_argument('--size', default='256x256'); ap.add_argument('--spp', type=int, default=256)
ap.add_argument('--bounces', type=int, default=1024); ap.add_argument('--out'); ap.add_argument('--threads', type=int, default=2); ap.add_argument('--seed', type=int, default=1)
ap.add_argument('--sky', default=None)
a = ap.parse_args(argv)
vec = lambda s: Vector([float(x) for x in s.split(',')])
W, H = [int(x) for x in a.size.split('x')]

bpy.ops.wm.read_factory_settings(use_empty=True)
sc = bpy.context.scene
bpy.ops.wm.obj_import(filepath=a.obj, forward_axis='Y', up_axis='Z')

# materials from the MTL, parsed here so that nothing of the importer's Principled mapping leaks in
mtl = {}
cur = None
objdir = os.path.dirname(os.path.abspath(a.obj))
for line in open(a.obj, encoding='latin-1'):
    if line.startswith('mtllib'):
        for name in line.split()[1:]:
            for l in open(os.path.join(objdir, name), encoding='latin-1'):
                t = l.split('#')[0].split()
                if not t: continue
                if t[0] == 'newmtl': cur = ' '.join(t[1:]); mtl[cur] = {'Kd': (0.8, 0.8, 0.8), 'Ke': (0, 0, 0)}
                elif t[0] in ('Kd', 'Ke') and cur: mtl[cur][t[0]] = tuple(float(x) for x in t[1:4])
def make(name, kd, ke):
    m = bpy.data.materials.new('pl_' + name); m.use_nodes = True
    nt = m.node_tree; nt.nodes.clear()
    out = nt.nodes.new('ShaderNodeOutputMaterial')
    dif = nt.nodes.new('ShaderNodeBsdfDiffuse'); dif.inputs['Color'].default_value = (*kd, 1); dif.inputs['Roughness'].default_value = 0
    if max(ke) > 0:
        em = nt.nodes.new('ShaderNodeEmission'); em.inputs['Color'].default_value = (*ke, 1); em.inputs['Strength'].default_value = 1
        geo = nt.nodes.new('ShaderNodeNewGeometry')
        mix = nt.nodes.new('ShaderNodeMixShader')  # front face: emission; back face: black
        blk = nt.nodes.new('ShaderNodeEmission'); blk.inputs['Strength'].default_value = 0
        nt.links.new(geo.outputs['Backfacing'], mix.inputs['Fac'])
        nt.links.new(em.outputs['Emission'], mix.inputs[1]); nt.links.new(blk.outputs['Emission'], mix.inputs[2])
        add = nt.nodes.new('ShaderNodeAddShader')
        nt.links.new(dif.outputs['BSDF'], add.inputs[0]); nt.links.new(mix.outputs['Shader'], add.inputs[1])
        nt.links.new(add.outputs['Shader'], out.inputs['Surface'])
    else:
        nt.links.new(dif.outputs['BSDF'], out.inputs['Surface'])
    return m
made = {}
for ob in [o for o in sc.objects if o.type == 'MESH']:
    # flat shading from the geometric normal, as pathlab: drop the importer's custom (vn) normals
    if ob.data.has_custom_normals: ob.data.free_normals_split(); bpy.context.view_layer.objects.active = ob; bpy.ops.mesh.customdata_custom_splitnormals_clear()
    ob.data.use_auto_smooth = False
    for p in ob.data.polygons: p.use_smooth = False
    for i, slot in enumerate(ob.material_slots):
        nm = slot.material.name if slot.material else None
        key = nm if nm in mtl else (nm.rsplit('.', 1)[0] if nm and nm.rsplit('.', 1)[0] in mtl else None)
        kd, ke = (mtl[key]['Kd'], mtl[key]['Ke']) if key else ((0.8, 0.8, 0.8), (0, 0, 0))
        if key not in made: made[key] = make(str(key), kd, ke)
        slot.material = made[key]

cam = bpy.data.cameras.new('cam'); co = bpy.data.objects.new('cam', cam); sc.collection.objects.link(co); sc.camera = co
eye, tgt, up = vec(a.eye), vec(a.target), vec(a.up)
co.location = eye
co.rotation_euler = (tgt - eye).to_track_quat('-Z', 'Y').to_euler()
# respect the given up vector: build the rotation from an orthonormal frame
w = (eye - tgt).normalized(); u = up.cross(w).normalized(); v = w.cross(u)
from mathutils import Matrix
co.matrix_world = Matrix(((u.x, v.x, w.x, eye.x), (u.y, v.y, w.y, eye.y), (u.z, v.z, w.z, eye.z), (0, 0, 0, 1)))
cam.sensor_fit = 'VERTICAL'; cam.angle_y = math.radians(a.fov); cam.clip_start = 1e-4; cam.clip_end = 1e6

world = bpy.data.worlds.new('w'); sc.world = world; world.use_nodes = True
world.node_tree.nodes['Background'].inputs['Strength'].default_value = 0
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
sc.render.engine = 'CYCLES'; c = sc.cycles
c.device = 'CPU'; c.samples = a.spp; c.use_adaptive_sampling = False; c.use_denoising = False
c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = a.bounces
c.transparent_max_bounces = 8; c.sample_clamp_direct = 0; c.sample_clamp_indirect = 0
c.caustics_reflective = c.caustics_refractive = True; c.blur_glossy = 0
c.pixel_filter_type = 'BOX'; c.filter_width = 1.0
c.seed = a.seed
sc.render.threads_mode = 'FIXED'; sc.render.threads = a.threads
sc.render.resolution_x, sc.render.resolution_y, sc.render.resolution_percentage = W, H, 100
sc.view_settings.view_transform = 'Standard'; sc.view_settings.look = 'None'; sc.view_settings.exposure = 0; sc.view_settings.gamma = 1
sc.render.image_settings.file_format = 'OPEN_EXR'; sc.render.image_settings.color_depth = '32'
sc.render.image_settings.color_mode = 'RGB'; sc.render.image_settings.exr_codec = 'ZIP'
sc.render.filepath = os.path.abspath(a.out)
import time; t0 = time.time()
bpy.ops.render.render(write_still=True)
print('CYCLES_DONE %.2f s' % (time.time() - t0))
