"""tools/cycles_common.py: what tools/cycles_gkit.py and bench/cycles_ref_sky.py share, both grown from
../shared/tools/cycles/cycles_ref.py and run by Blender (blender -b --python SCRIPT -- ARGS): the
command line, the MTL read here, the materials (Lambert, one-sided emission), flat shading, the camera,
the black world and Cycles' settings (box filter 1 pixel, no clamping, no denoising, no adaptive
sampling, an EXR of 32-bit floats). Blender does not put a script's folder on sys.path: each script
adds this folder itself before `import cycles_common`."""
import sys, os, math, argparse, time
import bpy
from mathutils import Vector, Matrix


def arg_parser():
    """The options both scripts take; a script adds its own, then parses blender_argv()."""
    ap = argparse.ArgumentParser()
    ap.add_argument('obj'); ap.add_argument('--eye'); ap.add_argument('--target'); ap.add_argument('--up', default='0,1,0')
    ap.add_argument('--fov', type=float); ap.add_argument('--size', default='256x256'); ap.add_argument('--spp', type=int, default=256)
    ap.add_argument('--bounces', type=int, default=1024); ap.add_argument('--out'); ap.add_argument('--threads', type=int, default=2); ap.add_argument('--seed', type=int, default=1)
    return ap


def blender_argv():
    """The script's arguments: those after '--' (Blender's own come before)."""
    return sys.argv[sys.argv.index('--') + 1:]


def import_obj(path):
    """An empty scene with the OBJ in it, coordinates as in the file (no axis conversion)."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    bpy.ops.wm.obj_import(filepath=path, forward_axis='Y', up_axis='Z')
    return sc


def read_mtl(obj, default_kd):
    """The materials of the OBJ's mtllib files, parsed here so that nothing of the importer's
    Principled mapping leaks in: name -> {'Kd', 'Ke', 'map' (map_Kd's path or None)}. A Kd the MTL
    does not give is default_kd, a Ke 0; one number is a grey."""
    mtl = {}
    cur = None
    objdir = os.path.dirname(os.path.abspath(obj))
    for line in open(obj, encoding='latin-1'):
        if line.startswith('mtllib'):
            for name in line.split()[1:]:
                for l in open(os.path.join(objdir, name), encoding='latin-1'):
                    t = l.split('#')[0].split()
                    if not t: continue
                    if t[0] == 'newmtl': cur = ' '.join(t[1:]); mtl[cur] = {'Kd': default_kd, 'Ke': (0, 0, 0), 'map': None}
                    elif t[0] in ('Kd', 'Ke') and cur: mtl[cur][t[0]] = tuple(float(x) for x in (t[1:4] if len(t) > 2 else t[1:2] * 3))
                    elif t[0] == 'map_Kd' and cur: mtl[cur]['map'] = os.path.join(objdir, ' '.join(t[1:]))
    return mtl


def make_material(name, kd, ke, tex=None, colorspace='Non-Color'):
    """Lambert of albedo kd (times the image tex, nearest texel, read in colorspace) plus, where ke
    is not black, an emission of radiance ke on the front face only."""
    m = bpy.data.materials.new('pl_' + name); m.use_nodes = True
    nt = m.node_tree; nt.nodes.clear()
    out = nt.nodes.new('ShaderNodeOutputMaterial')
    dif = nt.nodes.new('ShaderNodeBsdfDiffuse'); dif.inputs['Color'].default_value = (*kd, 1); dif.inputs['Roughness'].default_value = 0
    if tex:   # Kd x the texture at the hit's uv, nearest texel
        im = nt.nodes.new('ShaderNodeTexImage'); im.image = bpy.data.images.load(tex)
        im.image.colorspace_settings.name = colorspace
        im.interpolation = 'Closest'; im.extension = 'REPEAT'
        mul = nt.nodes.new('ShaderNodeMixRGB'); mul.blend_type = 'MULTIPLY'; mul.inputs['Fac'].default_value = 1
        mul.inputs['Color1'].default_value = (*kd, 1)
        nt.links.new(im.outputs['Color'], mul.inputs['Color2']); nt.links.new(mul.outputs['Color'], dif.inputs['Color'])
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


def meshes(sc):
    return [o for o in sc.objects if o.type == 'MESH']


def flat_shading(ob):
    """Flat shading from the geometric normal, as pathlab: drop the importer's custom (vn) normals."""
    if ob.data.has_custom_normals: ob.data.free_normals_split(); bpy.context.view_layer.objects.active = ob; bpy.ops.mesh.customdata_custom_splitnormals_clear()
    ob.data.use_auto_smooth = False
    for p in ob.data.polygons: p.use_smooth = False


def set_materials(ob, mtl, made, tex_colorspace=None):
    """Each material slot of ob gets its MTL material (made once per name: made keeps them; a name
    the MTL lacks, Blender's 'name.001' included, is a grey 0.8). With tex_colorspace ('sRGB' or
    'Non-Color'), map_Kd multiplies Kd; without, map_Kd is ignored."""
    for i, slot in enumerate(ob.material_slots):
        nm = slot.material.name if slot.material else None
        key = nm if nm in mtl else (nm.rsplit('.', 1)[0] if nm and nm.rsplit('.', 1)[0] in mtl else None)
        kd, ke = (mtl[key]['Kd'], mtl[key]['Ke']) if key else ((0.8, 0.8, 0.8), (0, 0, 0))
        if key not in made:
            tex = mtl[key]['map'] if key and tex_colorspace else None
            made[key] = make_material(str(key), kd, ke, tex, tex_colorspace)
        slot.material = made[key]


def add_camera(sc, a):
    """The camera of --eye, --target, --up and --fov (vertical, degrees)."""
    vec = lambda s: Vector([float(x) for x in s.split(',')])
    cam = bpy.data.cameras.new('cam'); co = bpy.data.objects.new('cam', cam); sc.collection.objects.link(co); sc.camera = co
    eye, tgt, up = vec(a.eye), vec(a.target), vec(a.up)
    co.location = eye
    co.rotation_euler = (tgt - eye).to_track_quat('-Z', 'Y').to_euler()
    # respect the given up vector: build the rotation from an orthonormal frame
    w = (eye - tgt).normalized(); u = up.cross(w).normalized(); v = w.cross(u)
    co.matrix_world = Matrix(((u.x, v.x, w.x, eye.x), (u.y, v.y, w.y, eye.y), (u.z, v.z, w.z, eye.z), (0, 0, 0, 1)))
    cam.sensor_fit = 'VERTICAL'; cam.angle_y = math.radians(a.fov); cam.clip_start = 1e-4; cam.clip_end = 1e6


def black_world(sc):
    """A world that gives no light (its Background node's strength 0); returned for a script's sky."""
    world = bpy.data.worlds.new('w'); sc.world = world; world.use_nodes = True
    world.node_tree.nodes['Background'].inputs['Strength'].default_value = 0
    return world


def render(sc, a):
    """Cycles on the CPU with --spp, --bounces, --seed, --threads, --size, written as the EXR --out;
    prints CYCLES_DONE and the render's seconds."""
    W, H = [int(x) for x in a.size.split('x')]
    sc.render.engine = 'CYCLES'; c = sc.cycles
    c.device = 'CPU'; c.samples = a.spp; c.use_adaptive_sampling = False; c.use_denoising = False
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = a.bounces
    c.transparent_max_bounces = 8; c.sample_clamp_direct = 0; c.sample_clamp_indirect = 0
    c.caustics_reflective = c.caustics_refractive = True; c.blur_glossy = 0
    c.pixel_filter_type = 'BOX'; c.filter_width = 1.0
    c.seed = a.seed
    if os.environ.get('CYCLES_PATTERN'):   # as tools/cycles_pattern.py does for cycles_ref.py
        c.sampling_pattern = os.environ['CYCLES_PATTERN']
    print('CYCLES_PATTERN', c.sampling_pattern, flush=True)
    sc.render.threads_mode = 'FIXED'; sc.render.threads = a.threads
    sc.render.resolution_x, sc.render.resolution_y, sc.render.resolution_percentage = W, H, 100
    sc.view_settings.view_transform = 'Standard'; sc.view_settings.look = 'None'; sc.view_settings.exposure = 0; sc.view_settings.gamma = 1
    sc.render.image_settings.file_format = 'OPEN_EXR'; sc.render.image_settings.color_depth = '32'
    sc.render.image_settings.color_mode = 'RGB'; sc.render.image_settings.exr_codec = 'ZIP'
    sc.render.filepath = os.path.abspath(a.out)
    t0 = time.time()
    bpy.ops.render.render(write_still=True)
    print('CYCLES_DONE %.2f s' % (time.time() - t0))
