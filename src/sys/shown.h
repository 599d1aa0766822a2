/* shown.h — a name as it may be printed on a terminal or in a message: every file name, folder,
 * material or text that came from outside goes through shown() before it is printed, so that no name
 * can move the cursor, recolour, hide (ESC[8m), erase or reorder what the teacher reads, and two
 * different names never print the same. Plain text is returned as it is; otherwise a copy in which
 * C0 and C1 control characters, DEL and bytes that are not UTF-8 are written \xNN, the bidirectional
 * controls (U+061C, U+200E, U+200F, U+202A..U+202E, U+2066..U+2069) \uXXXX, and the backslash \\.
 * The copies live in a ring of SHOWN_RING buffers: up to that many shown() in one message, from the
 * main thread; a name over SHOWN_MAX bytes is cut, its end replaced by "...". */
#ifndef PATHLAB_SHOWN_H
#define PATHLAB_SHOWN_H

#define SHOWN_RING 12
#define SHOWN_MAX 4352
#define SHOWN_CAP (4 * SHOWN_MAX + 4)   /* the room a shown() copy may take, its NUL included */

const char *shown(const char *name);
#endif
