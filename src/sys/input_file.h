/* input_file.h — opening a file to read that a student may have made anything: a FIFO, a device,
 * a folder. input_file_open never blocks on a FIFO without a writer (it would hang a whole class's
 * grading); with regular_only, anything but a regular file is refused at once (errno EISDIR for a
 * folder, ENODEV for the rest). NULL with errno set. */
#ifndef PATHLAB_INPUT_FILE_H
#define PATHLAB_INPUT_FILE_H
#include <stdio.h>

FILE *input_file_open(const char *path, int regular_only);
/* The reason for errno after a failed input_file_open, for messages: "a folder, not a file",
 * "not a regular file (a FIFO or a device)", or strerror's. */
const char *input_file_why(int err);
#endif
