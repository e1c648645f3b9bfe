/* runsignal.c - see runsignal.h. The handler only stores the signal's
 * number (async-signal-safe). */
#include "runsignal.h"

#include <signal.h>
#include <string.h>

static volatile sig_atomic_t caught;
static int installed;
static struct sigaction old_term, old_usr1;

static void on_signal(int sig)
{
    caught = sig;
}

void runsignal_install(void)
{
    if (installed) return;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGTERM, &sa, &old_term);
    sigaction(SIGUSR1, &sa, &old_usr1);
    installed = 1;
}

int runsignal_caught(void)
{
    return (int)caught;
}

void runsignal_restore(void)
{
    if (!installed) return;
    sigaction(SIGTERM, &old_term, NULL);
    sigaction(SIGUSR1, &old_usr1, NULL);
    installed = 0;
}
