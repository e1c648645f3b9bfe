/* tmpguard.c - see tmpguard.h. A slot's path is written before its kind
 * is set (and the kind cleared before the slot is reused), so the handler,
 * which reads only slots whose kind is set, never sees half a path; it
 * calls only unlink, rmdir, signal and raise. */
#define _POSIX_C_SOURCE 200809L
#include "tmpguard.h"

#include <signal.h>
#include <string.h>
#include <unistd.h>

#define SLOTS 32
#define PATH_CAP 4096

enum { FREE = 0, FILE_SLOT = 1, DIR_SLOT = 2 };

static char paths[SLOTS][PATH_CAP];
static volatile sig_atomic_t kind[SLOTS];

void tmpguard_clean(void)
{
    for (int i = 0; i < SLOTS; i++)
        if (kind[i] == FILE_SLOT) {
            unlink(paths[i]);
            kind[i] = FREE;
        }
    for (int i = SLOTS - 1; i >= 0; i--) /* after the files they may hold */
        if (kind[i] == DIR_SLOT) {
            rmdir(paths[i]);
            kind[i] = FREE;
        }
}

static void on_signal(int sig)
{
    tmpguard_clean();
    signal(sig, SIG_DFL);
    raise(sig);
}

void tmpguard_install(void)
{
    static int installed = 0;
    if (installed) return;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL);
    installed = 1;
}

static int add(const char *path, int k)
{
    if (!path) return 0;
    tmpguard_install();
    if (strlen(path) >= PATH_CAP) return -1;
    for (int i = 0; i < SLOTS; i++)
        if (kind[i] == FREE) {
            strcpy(paths[i], path);
            kind[i] = k;
            return 0;
        }
    return -1;
}

int tmpguard_file(const char *path) { return add(path, FILE_SLOT); }
int tmpguard_dir(const char *path) { return add(path, DIR_SLOT); }

void tmpguard_forget(const char *path)
{
    if (!path) return;
    for (int i = 0; i < SLOTS; i++)
        if (kind[i] != FREE && strcmp(paths[i], path) == 0) kind[i] = FREE;
}
