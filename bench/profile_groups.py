#!/usr/bin/env python3
"""Where a render's time goes, by group (docs/performance.md, "Where a render's time goes").

    perf record -F 999 --call-graph dwarf,8192 -o cornell.data \
        build-native/pathlab render scenes/cornell.obj --size 256x256 --spp 64 --threads 1 -o /tmp/c.pfm
    perf script -i cornell.data --inline -F tid,ip,sym,srcline > cornell.script
    python3 bench/profile_groups.py cornell.script

Each sample's frames (inlined ones included) are walked from the leaf up; helpers that belong to
their caller (vec.h, libm, pcg32_next, anything unknown) are skipped, and the first frame that names
a function of the table below decides the group. The own lines of bvh_intersect, bvh_occluded and
integrate are split by line number: the ranges in by_line() are those of the sources at the commit
that added this script; update them if bvh.c or integrator.c move."""
import re, sys, collections

GROUPS = {}
def g(name, *funcs):
    for f in funcs: GROUPS[f] = name
g('BVH traversal', 'node_hits', 'push_near_first', 'lowest_bit', 'ray_prepare', 'ray_is_valid', 'row')
g('triangle intersection', 'block_hits_float', 'block_hits', 'redo_edge_lanes', 'lane_hit_exact')
g('shading (BRDF eval/sample/pdf, vertex setup, MIS)', 'make_vertex', 'brdf_eval', 'brdf_sample', 'brdf_pdf', 'blinn_pdf',
  'brdf_glossy_prob', 'half_vector', 'reflect', 'sample_dir', 'dir_pdf2_sa', 'sample_cosine_hemisphere', 'sample_cos_power',
  'sample_uniform_hemisphere', 'pdf_cos_power', 'pdf_cosine_hemisphere', 'mis_weight', 'power_heuristic',
  'balance_heuristic', 'emitted', 'direct_from_dir', 'scene_hit_point', 'frame_to_world')
g('light sampling', 'light_sample_point', 'pick', 'light_pdf_area', 'choice_prob', 'sample_uniform_triangle',
  'direct_from_light', 'light_pdf1_sa', 'pdf_area_to_solid_angle', 'pdf_solid_angle_to_area')
g('ray origins (offset_ray_origin, triangle_scale)', 'offset_ray_origin', 'triangle_scale', 'scene_triangle_scale',
  'visible', 'continuation_ray')
g('random numbers (pcg32_float/double)', 'pcg32_float', 'pcg32_double')
g('bookkeeping: per-sample stream setup (pcg32_for_sample)', 'pcg32_for_sample', 'pcg32_init', 'splitmix64_mix')
g('camera rays', 'camera_ray')
g('bookkeeping: accumulation, tiles, threads, progress', 'accumulate', 'add_sample', 'render_pixel', 'render_tiles',
  'run_chunks', 'parallel_for', 'worker_main', 'progress_update', 'describe', 'fraction', 'add_Lk', 'radiance_start',
  'pthread_mutex_lock', 'pthread_mutex_unlock', '__pthread_mutex_lock', '__pthread_mutex_unlock_usercnt',
  'lll_lock_wait', '__lll_lock_wait', 'futex_wait')
g('other: Russian roulette', 'survives_roulette')
g('bookkeeping: accumulation, tiles, threads, progress', 'progress_duration', 'progress_end', 'store_images')
g('light sampling', 'choice_of')
# skipped: helpers that take their caller's group
SKIP = re.compile(r'^(v3_\w+|frame_\w+|pcg32_next|__?\w*fmaxf\w*|\w*fminf\w*|__wrap_scalbnf|__scalbnf|\w*ilogbf\w*|'
                  r'\w*ldexpf\w*|\w*sincosf\w*|\w*sqrtf\w*|\w*powf\w*|\w*expf\w*|\w*logf\w*|copysignf|luminance|'
                  r'fmaxf@plt|fminf@plt|ilogbf@plt|ldexpf@plt|\[unknown\])$')

def by_line(sym, src):
    """Own lines of the traversal loops and of integrate."""
    m = re.match(r'(\w+\.c):(\d+)', src or '')
    line = int(m.group(2)) if m else 0
    if sym == 'bvh_intersect':
        return 'triangle intersection' if 768 <= line <= 776 else 'BVH traversal'
    if sym == 'bvh_occluded':
        return 'triangle intersection' if 807 <= line <= 810 else 'BVH traversal'
    if sym == 'integrate':
        if 236 <= line <= 239: return 'shading (BRDF eval/sample/pdf, vertex setup, MIS)'
        return 'other: integrate\'s own loop (counters, branches, L sum)'
    return None

def frames(block):
    lines = [l for l in block.split('\n') if l.strip()]
    out, i = [], 0
    tid = None
    if lines and re.match(r'^\s*\d+\s*$', lines[0]): tid = lines[0].strip(); lines = lines[1:]
    while i < len(lines):
        m = re.match(r'^\s+([0-9a-f]+)\s+(\S+)', lines[i])
        if not m:
            i += 1; continue
        sym = m.group(2); src = lines[i + 1].strip() if i + 1 < len(lines) else ''
        out.append((re.sub(r'\+0x[0-9a-f]+$', '', sym), src, m.group(1).startswith('ffffffff')))
        i += 2
    return tid, out

def classify(fr):
    names = [x[0] for x in fr]
    if fr[0][2] and ('render_tiles' in names or 'integrate' in names):
        return 'kernel, during the render loop (timer interrupts, page faults)', fr[0][0]
    if fr[0][2]: return 'outside the render loop (load, BVH build, output)', fr[0][0]
    for sym, src, _k in fr:
        if sym in GROUPS: return GROUPS[sym], sym
        r = by_line(sym, src)
        if r: return r, sym
        continue   # libm, libc and vec.h helpers: their caller decides
    return 'outside the render loop (load, BVH build, output)', fr[0][0]

text = open(sys.argv[1]).read()
blocks = [b for b in re.split(r'\n\s*\n', text) if b.strip()]
cnt, funcs, ray = collections.Counter(), collections.defaultdict(collections.Counter), collections.Counter()
kernel_in_render = 0
for b in blocks:
    tid, fr = frames(b)
    if not fr: continue
    grp, sym = classify(fr)
    # kernel frames on top of a render-loop sample: count where in the render loop it happened
    cnt[grp] += 1; funcs[grp][sym] += 1
    names = [x[0] for x in fr]
    if 'bvh_occluded' in names: ray['shadow rays (bvh_occluded)'] += 1
    elif 'bvh_intersect' in names:
        # camera ray: intersect called from integrate line 215
        k = names.index('bvh_intersect')
        src = fr[k + 1][1] if k + 1 < len(fr) else ''
        ray['camera rays (bvh_intersect, integrator.c:217)' if 'integrator.c:217' in src else
            'continuation rays (bvh_intersect, integrator.c:242)' if 'integrator.c:242' in src else
            'bvh_intersect from ' + src] += 1
n = sum(cnt.values())
print('samples', n)
for grp, c in cnt.most_common():
    top = ', '.join('%s %.1f%%' % (s, 100.0 * k / n) for s, k in funcs[grp].most_common(8))
    print('%-60s %5.1f%%  %s' % (grp, 100.0 * c / n, top))
print()
for k, c in ray.most_common(): print('%-52s %5.1f%%' % (k, 100.0 * c / n))
