/* interrupt.c — two-step signal handling. The handler only sets a flag or, the second time,
 * unlinks the registered temporary files and _exits: both async-signal-safe. */
#include "sys/interrupt.h"
#include <pthread.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>

#define MAX_TEMPS 4096

static volatile sig_atomic_t first_signal;
static const char *volatile temp_name[MAX_TEMPS];   /* the caller's strings, valid until removed */

static void on_signal(int sig)
{
    int k;
    if (!first_signal) {
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

void interrupt_install(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);   /* one handler at a time: the second waits for the first */
    sigaddset(&sa.sa_mask, SIGTERM);
    sa.sa_flags = SA_RESTART;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

int interrupt_signal(void) { return first_signal; }

const char *interrupt_name(int sig) { return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal"; }

static sigset_t held;

void interrupt_hold(void)
{
    sigset_t s;
    sigemptyset(&s);
    sigaddset(&s, SIGINT);
    sigaddset(&s, SIGTERM);
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
