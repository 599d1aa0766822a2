/* fuzz_common.h — what the libFuzzer harnesses of tests/fuzz/ share. pathlab's readers take file
 * names, not memory, so each input is written into a private temporary folder (mkdtemp under
 * $TMPDIR, else /tmp), made on the first call and removed with its files when the process exits. */
#ifndef PATHLAB_FUZZ_COMMON_H
#define PATHLAB_FUZZ_COMMON_H
#include <stddef.h>
#include <stdint.h>

/* libFuzzer's entry point; each harness defines it (tests/fuzz/replay.c calls it without libFuzzer). */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Writes n bytes to the file name (no '/') of the private folder and returns its path (static
 * storage, one per name slot 0..5); aborts if the folder or the file cannot be written, since a
 * harness that silently tests nothing would look like a clean run. */
const char *fuzz_write(int slot, const char *name, const uint8_t *data, size_t n);
/* The path that name would have in the private folder (slot as above), without writing it;
 * removes any file of that name left by an earlier input. */
const char *fuzz_absent(int slot, const char *name);
#endif
