/* interrupt.h — Ctrl-C (SIGINT) and SIGTERM, and SIGHUP, SIGQUIT and SIGPIPE alike. Before a render (interrupt_quit_on_signal, set by
 * main for every command): pathlab stops at once, removing any temporary file being written. During
 * a render (interrupt_install): the first asks the render to stop after its current pass, so that
 * the image reached is written; the second stops at once like the first mode, writing nothing.
 * Either way a file is the old one or the whole new one (renamed into place), and no *.tmp.* or
 * *.pending file is left. SIGKILL cannot be caught: it leaves the temporary files being written
 * (NAME.pending, NAME.tmp.XXXXXX beside the output), never a half-written output. */
#ifndef PATHLAB_INTERRUPT_H
#define PATHLAB_INTERRUPT_H

/* Installs the handlers: quit at once (removing the temporary files), or the render's two steps. */
void interrupt_quit_on_signal(void);
void interrupt_install(void);
/* 0, or the first signal received since interrupt_install. */
int interrupt_signal(void);
/* The name of a signal for messages: "SIGINT", "SIGTERM", "SIGHUP", ... */
const char *interrupt_name(int sig);

/* A temporary file that a second signal must remove. Call interrupt_hold() before creating it,
 * then interrupt_temp_add(name), then interrupt_release(); and the same around its rename or removal
 * with interrupt_temp_remove(name) (the same pointer): no signal can fall between the file and its
 * registration. The string is not copied: it must stay valid until removed. Holds nest one deep only. */
void interrupt_hold(void);
void interrupt_release(void);
void interrupt_temp_add(const char *name);
void interrupt_temp_remove(const char *name);
#endif
