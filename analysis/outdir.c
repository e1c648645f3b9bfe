/* outdir.c - see outdir.h. The temporary folder and every name it may
 * hold are registered with the suite's one signal handler (src/files/tmpguard.h),
 * which unlinks the files and then removes the folder. */
#define _POSIX_C_SOURCE 200809L
#include "outdir.h"

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tmpguard.h"

static const char *names[AN_OUT_COUNT] = AN_OUT_NAMES;

#define PATHMAX 4096

/* Registers (on = 1) or forgets (0) the temporary folder and the names it
 * may hold with the signal handler. */
static void guard(const an_outdir *o, int on)
{
    char p[PATHMAX + 32];
    for (int i = 0; i < AN_OUT_COUNT; i++)
        if (snprintf(p, sizeof p, "%s/%s", o->tmp, names[i]) < (int)sizeof p) {
            if (on) tmpguard_file(p);
            else tmpguard_forget(p);
        }
    if (on) tmpguard_dir(o->tmp);
    else tmpguard_forget(o->tmp);
}

static int known_name(const char *s)
{
    for (int i = 0; i < AN_OUT_COUNT; i++)
        if (strcmp(s, names[i]) == 0) return 1;
    return 0;
}

/* An earlier output of this tool: a folder with stats.json and nothing but
 * known names. */
static int is_our_folder(const char *path)
{
    DIR *d = opendir(path);
    if (!d) return 0;
    int ok = 1, has_stats = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
        if (!known_name(e->d_name)) ok = 0;
        if (strcmp(e->d_name, "stats.json") == 0) has_stats = 1;
    }
    closedir(d);
    return ok && has_stats;
}

static void remove_folder(const char *dir)
{
    char p[PATHMAX + 32];
    for (int i = 0; i < AN_OUT_COUNT; i++)
        if (snprintf(p, sizeof p, "%s/%s", dir, names[i]) < (int)sizeof p) unlink(p);
    rmdir(dir);
}

int an_outdir_begin(an_outdir *o, const char *path, char *err, size_t errlen)
{
    memset(o, 0, sizeof *o);
    size_t len = strlen(path);
    while (len > 1 && path[len - 1] == '/') len--;
    if (len == 0 || len + 64 > PATHMAX) {
        snprintf(err, errlen, "%s: bad output folder name", path);
        return -1;
    }
    o->final = strndup(path, len);
    o->tmp = malloc(len + 32);
    if (!o->final || !o->tmp) {
        snprintf(err, errlen, "out of memory");
        an_outdir_abort(o);
        return -1;
    }
    struct stat st;
    if (stat(o->final, &st) == 0 && !(S_ISDIR(st.st_mode) && is_our_folder(o->final))) {
        snprintf(err, errlen, "%s: exists and is not an earlier cfpo-analyze output folder; "
                 "remove it or choose another with -o", o->final);
        an_outdir_abort(o);
        return -1;
    }
    snprintf(o->tmp, len + 32, "%s.tmp.%ld", o->final, (long)getpid());
    tmpguard_install();
    if (mkdir(o->tmp, 0777) != 0) {
        snprintf(err, errlen, "%s: cannot create the output folder: %s", o->final, strerror(errno));
        an_outdir_abort(o);
        return -1;
    }
    o->created = 1;
    guard(o, 1);
    return 0;
}

char *an_outdir_file(const an_outdir *o, const char *name)
{
    int ok = 0;
    for (int i = 0; i < AN_OUT_WRITTEN; i++) ok |= strcmp(name, names[i]) == 0;
    if (!ok) return NULL;
    size_t len = strlen(o->tmp) + strlen(name) + 2;
    char *p = malloc(len);
    if (p) snprintf(p, len, "%s/%s", o->tmp, name);
    return p;
}

void an_outdir_message(const an_outdir *o, char *msg, size_t cap)
{
    if (!o->tmp || !o->final) return;
    char *at = strstr(msg, o->tmp);
    if (!at) return;
    char out[2048];
    snprintf(out, sizeof out, "%.*s%s%s", (int)(at - msg), msg, o->final, at + strlen(o->tmp));
    snprintf(msg, cap, "%s", out);
}

int an_outdir_commit(an_outdir *o, char *err, size_t errlen)
{
    char old[PATHMAX + 32];
    snprintf(old, sizeof old, "%s.old.%ld", o->final, (long)getpid()); /* final < PATHMAX - 64 */
    struct stat st;
    int replacing = stat(o->final, &st) == 0;
    errno = 0;
    if (replacing && (!is_our_folder(o->final) || rename(o->final, old) != 0)) {
        snprintf(err, errlen, "%s: cannot replace the earlier output folder: %s", o->final,
                 errno ? strerror(errno) : "unexpected contents");
        an_outdir_abort(o);
        return -1;
    }
    if (rename(o->tmp, o->final) != 0) {
        snprintf(err, errlen, "%s: cannot rename the output folder into place: %s", o->final,
                 strerror(errno));
        if (replacing) rename(old, o->final);
        an_outdir_abort(o);
        return -1;
    }
    guard(o, 0);
    o->created = 0;
    if (replacing) remove_folder(old);
    free(o->tmp);
    free(o->final);
    o->tmp = o->final = NULL;
    return 0;
}

void an_outdir_abort(an_outdir *o)
{
    if (o->created) {
        guard(o, 0);
        remove_folder(o->tmp);
        o->created = 0;
    }
    free(o->tmp);
    free(o->final);
    o->tmp = o->final = NULL;
}
