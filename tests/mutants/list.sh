#!/usr/bin/env bash
# tests/mutants/list.sh — the mutants of `make mutants` (sourced by tests/mutants/run.sh).
#
#   mutant NAME FILE SED TEST ENV 'WHAT IT BREAKS'
#
# NAME   short name (also used by tests/mutants/bug_images.sh);
# FILE   the file of the copied tree the mutation edits (src/...);
# SED    a sed script applied to FILE with sed -i; it must change the file (run.sh checks the
#        checksum), so a mutant whose code has since moved reports "did not apply" instead of passing;
# TEST   the tests/run.sh filter that must then print a FAIL line (the fastest test that catches it);
# ENV    environment for that test ("-" for none): PATHLAB_FAST=1 and PATHLAB_TEST_QUICK=1 make
#        test_direct, test_sampling and test_bvh 5-30 times faster with fewer samples;
# WHAT   the bug in a student's words.
#
# Patterns use sed's basic regular expressions: * . [ ] / are escaped; in a replacement & is the
# matched text (\& a literal &).

# ---- direct light: the estimator Le f cos(theta_p) cos(theta_s) / d^2 / pdf1_area ----
mutant no-cos-surface src/tracer/integrator.c \
    's/cos_p \/ pdf1_sa \* w_mis/1.0f \/ pdf1_sa * w_mis/' \
    test_direct PATHLAB_FAST=1 'forgot cos(theta) of the light direction at the surface point'
mutant no-cos-light src/tracer/light.h \
    's/pdf_area \* dist2 \/ cos_s : 0\.0f/pdf_area * dist2 : 0.0f/' \
    test_direct PATHLAB_FAST=1 'forgot cos(theta_s) at the light when turning the area pdf into solid angle'
mutant area-pdf src/tracer/integrator.c \
    's/pdf1_sa = pdf_area_to_solid_angle(s\.pdf_area, dist2, cos_s);/pdf1_sa = s.pdf_area;/' \
    test_direct PATHLAB_FAST=1 'divided by the area pdf 1/A instead of the solid-angle pdf (no d^2/cos)'
mutant light-choice src/tracer/light.c \
    's/return choice_prob(ls, strategy, i) \/ e->area;/return 1.0f \/ e->area;/' \
    test_direct PATHLAB_FAST=1 'picked a light triangle with probability P_i but never divided by P_i'
# ---- emission and MIS ----
mutant emission-twice src/tracer/integrator.c \
    's/w_mis = mis_weight(opt->direct, pdf2_sa, pdf1_sa);/w_mis = 1.0f;/' \
    test_direct PATHLAB_FAST=1 'light found by light sampling AND by the BRDF ray, no MIS weight: counted twice'
mutant le-every-vertex src/tracer/integrator.c \
    's/if (!bvh_intersect(sc->accel, &ray_pq, &q)) break;/&\n        add_Lk(\&sum, k, v3_mul(beta, emitted(sc, \&q, ray_pq.d)));/' \
    test_direct PATHLAB_FAST=1 'added Le at every hit on top of next-event estimation'
mutant mis-swapped src/tracer/integrator.c \
    's/w_mis = mis_weight(opt->direct, pdf2_sa, pdf1_sa);/w_mis = mis_weight(opt->direct, pdf1_sa, pdf2_sa);/' \
    test_direct PATHLAB_FAST=1 'MIS weights that do not sum to 1 (the pdfs swapped on the BRDF side)'
mutant two-sided-emission src/tracer/integrator.c \
    's/return v3_dot(sc->Ng\[h->tri\], dir) < 0\.0f ? Ke : v3(0, 0, 0);/(void)dir; return Ke;/' \
    test_direct PATHLAB_FAST=1 'lights emit from their back face too'
# ---- paths ----
mutant no-cos-throughput src/tracer/integrator.c \
    's/beta = v3_mul(beta, v3_scale(f, cos_p \/ pdf2_sa));/beta = v3_mul(beta, v3_scale(f, 1.0f \/ pdf2_sa));/' \
    test_direct PATHLAB_FAST=1 'forgot cos(theta) in the path throughput f cos / pdf'
mutant rr-no-divide src/tracer/integrator.c \
    's/\*beta = v3_scale(before, 1\.0f \/ p_survive);/(void)p_survive;/' \
    test_rr PATHLAB_FAST=1 'Russian roulette kills paths but survivors are not divided by p_survive'
# ---- BRDF and warps ----
mutant blinn-norm src/tracer/brdf.c \
    's/(m->Ns + 8\.0f) \/ (8\.0f \* PI_F)/(m->Ns + 2.0f) \/ (8.0f * PI_F)/' \
    test_sampling PATHLAB_FAST=1 'Blinn lobe normalised with (Ns+2) instead of (Ns+8)'
mutant half-vector-pdf src/tracer/brdf.c \
    's/pdf_cos_power(h, Ns) \/ (4\.0f \* wo_h)/pdf_cos_power(h, Ns)/' \
    test_sampling PATHLAB_FAST=1 'used the pdf of the half vector as the pdf of wi (no 1/(4 wo.h))'
mutant cos-pdf-const src/tracer/sampling.c \
    's/return w\.z > 0\.0f ? w\.z \* INV_PI_F : 0\.0f;/return w.z > 0.0f ? INV_PI_F : 0.0f;/' \
    test_sampling PATHLAB_FAST=1 'cosine-hemisphere pdf returned as 1/pi instead of cos(theta)/pi'
mutant triangle-no-sqrt src/tracer/sampling.c \
    's/float s = sqrtf(u1);/float s = u1;/' \
    test_sampling PATHLAB_FAST=1 'point on a triangle with b = u1 instead of sqrt(u1): not uniform'
# ---- ray tracing ----
mutant acne src/geometry/ray.c \
    's/return v3_madd(p, n, d);/(void)n; (void)d; return p;/' \
    test_bvh PATHLAB_TEST_QUICK=1 'no ray-origin offset: rays hit the surface they leave (acne)'
mutant bvh-first-hit src/geometry/bvh.c \
    's/^\( *\)tcull = tmax \* BVH_T_WIDEN;$/&\n\1if (best) goto done;/' \
    test_bvh PATHLAB_TEST_QUICK=1 'BVH traversal stops at the first leaf hit, not the closest hit'
mutant bvh-child-slot src/geometry/bvh.c \
    '/^static inline unsigned node_hits/,/^}/s/i < BVH_WIDTH; i++/i < BVH_WIDTH - 1; i++/' \
    test_bvh PATHLAB_TEST_QUICK=1 'box test loop off by one: the last child of each node is never entered'
# ---- samples and merges (references for any view, docs/references.md) ----
mutant sample-stream-no-index src/math/rng.h \
    's/splitmix64_mix(seed) ^ pixel) ^ i)/splitmix64_mix(seed) ^ pixel))/' \
    test_passes - 'every sample of a pixel draws the same numbers: the stream ignores the sample index'
mutant merge-unweighted src/stats/combine.c \
    's/c->mean\[i\] += delta \* (n \/ total);/c->mean[i] += delta * 0.5;/' \
    test_passes - 'pieces averaged with equal weights, whatever their numbers of samples'
mutant merge-var-within-only src/stats/combine.c \
    's/c->m2\[i\] += m2b + delta \* delta \* (c->n \* n \/ total);/c->m2[i] += m2b;/' \
    test_passes - 'merged variance adds the spread inside each piece but forgets the spread between their means'
# ---- adaptive sampling (docs/adaptive.md) ----
mutant adaptive-pilot-kept src/render/adaptive.c \
    's/return splitmix64_mix(seed ^ 0x70696c6f74ULL) + SPLITMIX64_GAMMA;/return seed;/' \
    test_adaptive - 'the pilot that chose n(x) is the first samples kept in the image: counts depend on the kept samples (biased)'
mutant adaptive-count-as-done src/render/render.c \
    's/int n = pixel_spp \&\& pixel_spp\[p\] < done ? pixel_spp\[p\] : done;/int n = done;/' \
    test_adaptive - 'each pixel sum divided by the passes done instead of its own sample count'
# ---- Sobol samplers (docs/sampler.md) ----
mutant sobol-light-remainder src/tracer/light.c \
    's/    u1 = (float)r;/    u1 = (float)u0; (void)r;/' \
    test_sobol - 'the joint light sample takes the raw choice number as its first coordinate, not its remainder in the chosen emitter'
