"""tools/cycles_glossy.py: ../shared/tools/cycles/cycles_ref.py (its parts in tools/cycles_common.py) with
the MTL's glossy term: each material is Diffuse(Kd) + Glossy(Ks) (+ one-sided emission of Ke), the
Glossy BSDF Beckmann with alpha = sqrt(2 / (Ns + 2)) (Walter et al. 2007's match of a Blinn-Phong
exponent; Cycles squares its Roughness input, so Roughness = sqrt(alpha)), flat shading, black world.
NOT the course's BRDF (Ks (Ns+8)/(8 pi) cos^Ns theta_h has no shadowing-masking and no 1/(4 cos cos)):
the images differ from pathlab's, so only each renderer's error against its own reference compares
(bench/cycles.sh's P ratio for pathlab against C for Cycles, docs/performance.md).
blender -b --factory-startup --python tools/cycles_glossy.py -- OBJ --eye ... (cycles_ref.py's options)"""
import sys, os, math
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bpy
import cycles_common as cc

a = cc.arg_parser().parse_args(cc.blender_argv())
sc = cc.import_obj(a.obj)
mtl = cc.read_mtl(a.obj, default_kd=(0, 0, 0))
gloss, cur = {}, None   # name -> (Ks, Ns): read_mtl keeps Kd, Ke and map_Kd only
objdir = os.path.dirname(os.path.abspath(a.obj))
for line in open(a.obj, encoding='latin-1'):
    if line.startswith('mtllib'):
        for name in line.split()[1:]:
            for l in open(os.path.join(objdir, name), encoding='latin-1'):
                t = l.split('#')[0].split()
                if not t: continue
                if t[0] == 'newmtl': cur = ' '.join(t[1:]); gloss[cur] = [(0, 0, 0), 1.0]
                elif t[0] == 'Ks' and cur: v = [float(x) for x in t[1:4]]; gloss[cur][0] = tuple(v * 3 if len(v) == 1 else v)
                elif t[0] == 'Ns' and cur: gloss[cur][1] = float(t[1])
made = {}
for ob in cc.meshes(sc):
    cc.flat_shading(ob)
    cc.set_materials(ob, mtl, made)
for key, m in made.items():
    ks, ns = gloss.get(key, [(0, 0, 0), 1.0])
    if max(ks) <= 0: continue
    nt = m.node_tree
    dif = next(n for n in nt.nodes if n.type == 'BSDF_DIFFUSE')
    link = next(l for l in nt.links if l.from_node == dif)
    g = nt.nodes.new('ShaderNodeBsdfGlossy'); g.distribution = 'BECKMANN'
    g.inputs['Color'].default_value = (*ks, 1)
    g.inputs['Roughness'].default_value = math.sqrt(math.sqrt(2.0 / (ns + 2.0)))
    add = nt.nodes.new('ShaderNodeAddShader')
    to = link.to_socket
    nt.links.remove(link)
    nt.links.new(dif.outputs['BSDF'], add.inputs[0]); nt.links.new(g.outputs['BSDF'], add.inputs[1])
    nt.links.new(add.outputs['Shader'], to)
cc.add_camera(sc, a)
cc.black_world(sc)
cc.render(sc, a)
