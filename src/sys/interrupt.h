/* interrupt.h — Ctrl-C (SIGINT) and SIGTERM during a render: the first asks the render to stop
 * after its current pass, so that the image reached is written; the second stops at once,
 * removing any temporary file being written, and writes nothing. Outside interrupt_install the
 * signals keep their default action (the program dies, and it has no temporary file then). */
#ifndef PATHLAB_INTERRUPT_H
#define PATHLAB_INTERRUPT_H

/* Installs the two-step handlers for SIGINT and SIGTERM. */
void interrupt_install(void);
/* 0, or the first signal received since interrupt_install (SIGINT or SIGTERM). */
int interrupt_signal(void);
/* The name of a signal for messages: "SIGINT", "SIGTERM". */
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
