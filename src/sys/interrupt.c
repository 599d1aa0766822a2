/* interrupt.c — signal handling in two modes. From interrupt_quit_on_signal (main, before any
 * command) a signal unlinks the registered temporary files and _exits; from interrupt_install (a
 * render) the first signal only sets a flag and the second does the same as a quit. Both are
 * async-signal-safe: write, unlink, _exit. */
#include "sys/interrupt.h"
#include <pthread.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>

#define MAX_TEMPS 4096

static volatile sig_atomic_t first_signal, two_step;
static const char *volatile temp_name[MAX_TEMPS];   /* the caller's strings, valid until removed */

static void on_signal(int sig)
{
    int k;
    if (two_step && !first_signal) {
        static const char msg[] = "\npathlab: interrupted: finishing the current pass to write the image reached "
                                  "(press Ctrl-C again to stop at once and write nothing)\n";
        first_signal = sig;
        if (write(2, msg, sizeof msg - 1) < 0) first_signal = sig;   /* nothing to do if stderr is gone */
        return;
    }
    for (k = 0; k < MAX_TEMPS; k++)
        if (temp_name[k]) unlink(temp_name[k]);
    _exit(128 + sig);
}

/* The signals that end pathlab: Ctrl-C, kill, a closed terminal (SIGHUP), Ctrl-\ (SIGQUIT) and a
 * reader gone from a pipe (SIGPIPE). Each left temporary files behind before; all take the same
 * handler. */
static const int ENDING_SIGNALS[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE};
#define NSIGNALS ((int)(sizeof ENDING_SIGNALS / sizeof ENDING_SIGNALS[0]))

static void ending_set(sigset_t *s)
{
    int i;
    sigemptyset(s);
    for (i = 0; i < NSIGNALS; i++) sigaddset(s, ENDING_SIGNALS[i]);
}

/* The handler for all of them (also when the shell started pathlab with SIGINT ignored, as a
 * script's background job: the tests interrupt such renders). */
static void set_handler(void)
{
    struct sigaction sa;
    int i;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    ending_set(&sa.sa_mask);   /* one handler at a time: a second signal waits for the first */
    sa.sa_flags = SA_RESTART;
    for (i = 0; i < NSIGNALS; i++) sigaction(ENDING_SIGNALS[i], &sa, NULL);
}

void interrupt_quit_on_signal(void)
{
    two_step = 0;
    set_handler();
}

void interrupt_install(void)
{
    two_step = 1;
    set_handler();
}

int interrupt_signal(void) { return first_signal; }

const char *interrupt_name(int sig)
{
    switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    case SIGQUIT: return "SIGQUIT";
    case SIGPIPE: return "SIGPIPE";
    default: return "a signal";
    }
}

static sigset_t held;

void interrupt_hold(void)
{
    sigset_t s;
    ending_set(&s);
    pthread_sigmask(SIG_BLOCK, &s, &held);
}

void interrupt_release(void) { pthread_sigmask(SIG_SETMASK, &held, NULL); }

void interrupt_temp_add(const char *name)
{
    int k;
    for (k = 0; k < MAX_TEMPS; k++)
        if (!temp_name[k]) {
            temp_name[k] = name;
            return;
        }
}

void interrupt_temp_remove(const char *name)
{
    int k;
    for (k = 0; k < MAX_TEMPS; k++)
        if (temp_name[k] == name) temp_name[k] = NULL;
}
