#!/usr/bin/env bash
# The BVH as `make bench` builds it: tests/test_bvh compiled with -march=native (asserts on). On a CPU
# with AVX-512 that build tests nodes and triangle blocks with intrinsics (node_hits_v, block_hits_v
# in src/geometry/bvh_traverse.c) in the whole traversal, as NATIVE=1 builds it (the `make` build has
# them only in its AVX-512 copy, which test_bvh's isa checks compare with the SSE2 copy); the same
# hits are expected of it. Without -march=native support the file says SKIP.
. "$(dirname "$0")/lib.sh"
CC=${CC:-cc}
if ! echo 'int main(void) { return 0; }' | "$CC" -march=native -x c -o "$TMP/probe" - 2> /dev/null; then
    echo "SKIP test_bvh_native: $CC does not take -march=native"; exit 0
fi
if "$CC" -march=native -dM -E -x c /dev/null | grep -q '__AVX512VL__'; then path="AVX-512 intrinsics"; else path="portable loops (no AVX-512 here)"; fi
if ! "$CC" -std=c99 -Wall -Wextra -pedantic -Werror -D_POSIX_C_SOURCE=200809L -O2 -march=native -Isrc -Itests \
        -o "$TMP/test_bvh" tests/test_bvh.c src/geometry/bvh.c src/geometry/bvh_traverse.c src/geometry/ray.c src/sys/big_array.c src/sys/parallel.c \
        -lm -lpthread 2> "$TMP/cc"; then
    fail "test_bvh with -march=native: does not compile without warnings: $(head -c 400 "$TMP/cc")"; exit 0
fi
pass "test_bvh with -march=native compiles without warnings ($path)"
"$TMP/test_bvh" > "$TMP/out" 2>&1; rc=$?
sed 's/^\(PASS\|FAIL\) /\1 native: /' "$TMP/out"
[ $rc -eq 0 ] || grep -q '^FAIL' "$TMP/out" || fail "native test_bvh exited with status $rc without a FAIL line"
exit 0
