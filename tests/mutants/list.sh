#!/usr/bin/env bash
# tests/mutants/list.sh — the run list of `make mutants` (sourced by tests/mutants/lib.sh).
#
#   mutant NAME TEST ENV
#
# NAME   the mutant: tests/mutants/NAME.patch is the bug, a unified diff against the tree (paths
#        a/src/... b/src/..., applied with patch -p1); its first line says what it breaks in a
#        student's words, its lines "Test:" and "Env:" repeat TEST and ENV (run.sh fails if they
#        disagree with this list, if a patch is not listed here, or if a patch does not apply);
# TEST   the tests/run.sh filter that must then print a FAIL line (the fastest test that catches it);
# ENV    environment for that test ("-" for none): PATHLAB_FAST=1 and PATHLAB_TEST_QUICK=1 make
#        test_direct, test_sampling and test_bvh 5-30 times faster with fewer samples.
#
# A new mutant: edit a copy of the source file, then tests/mutants/remake.sh NAME COPY SRCFILE
# writes NAME.patch (add its header and its line here); a stale one: tests/mutants/remake.sh NAME.

#      NAME                     TEST           ENV
# ---- direct light: the estimator Le f cos(theta_p) cos(theta_s) / d^2 / pdf1_area ----
mutant no-cos-surface           test_direct    PATHLAB_FAST=1
mutant no-cos-light             test_direct    PATHLAB_FAST=1
mutant area-pdf                 test_direct    PATHLAB_FAST=1
mutant light-choice             test_direct    PATHLAB_FAST=1
# ---- emission and MIS ----
mutant emission-twice           test_direct    PATHLAB_FAST=1
mutant le-every-vertex          test_direct    PATHLAB_FAST=1
mutant mis-swapped              test_direct    PATHLAB_FAST=1
mutant two-sided-emission       test_direct    PATHLAB_FAST=1
# ---- paths ----
mutant no-cos-throughput        test_direct    PATHLAB_FAST=1
mutant rr-no-divide             test_rr        PATHLAB_FAST=1
# ---- BRDF and warps ----
mutant blinn-norm               test_sampling  PATHLAB_FAST=1
mutant half-vector-pdf          test_sampling  PATHLAB_FAST=1
mutant cos-pdf-const            test_sampling  PATHLAB_FAST=1
mutant triangle-no-sqrt         test_sampling  PATHLAB_FAST=1
# ---- ray tracing ----
mutant acne                     test_bvh       PATHLAB_TEST_QUICK=1
mutant bvh-first-hit            test_bvh       PATHLAB_TEST_QUICK=1
mutant bvh-child-slot           test_bvh       PATHLAB_TEST_QUICK=1
mutant bvh-tie-order            test_bvh       PATHLAB_TEST_QUICK=1
mutant visibility-one-side      test_visibility -
# ---- samples and merges (references for any view, docs/references.md) ----
mutant sample-stream-no-index   test_passes    -
mutant merge-unweighted         test_passes    -
mutant merge-var-within-only    test_passes    -
# ---- adaptive sampling (docs/adaptive.md) ----
mutant adaptive-pilot-kept      test_adaptive  -
mutant adaptive-count-as-done   test_adaptive  -
# ---- Sobol samplers (docs/sampler.md) ----
mutant sobol-light-remainder    test_sobol     -
