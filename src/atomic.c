/* atomic.c - see atomic.h. */
#include "atomic.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int atomic_create(const char *path, char **tmp, char *err, size_t errlen)
{
    *tmp = NULL;
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
        snprintf(err, errlen, "%s: is a directory", path);
        return -1;
    }
    const size_t len = strlen(path) + 16;
    char *t = malloc(len);
    if (!t) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    snprintf(t, len, "%s.tmp.XXXXXX", path);
    const int fd = mkstemp(t);
    if (fd < 0) {
        snprintf(err, errlen, "%s: cannot create file: %s", path, strerror(errno));
        free(t);
        return -1;
    }
    fchmod(fd, 0644); /* mkstemp makes 0600 */
    *tmp = t;
    return fd;
}

int atomic_replace(const char *tmp, const char *path)
{
    if (rename(tmp, path) == 0) return 0;
    const int e = errno ? errno : EIO;
    unlink(tmp);
    errno = e;
    return -1;
}

int atomic_open(atomic_file *a, const char *path, const char *mode, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    a->path = strdup(path);
    if (!a->path) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    const int fd = atomic_create(path, &a->tmp, err, errlen);
    if (fd >= 0) a->f = fdopen(fd, mode);
    if (fd >= 0 && !a->f) {
        snprintf(err, errlen, "%s: cannot open file: %s", path, strerror(errno));
        close(fd);
    }
    if (!a->f) {
        atomic_abort(a);
        return -1;
    }
    return 0;
}

int atomic_finish(atomic_file *a, char *err, size_t errlen)
{
    errno = 0;
    int bad = fflush(a->f) != 0 || ferror(a->f);
    if (fclose(a->f) != 0) bad = 1;
    a->f = NULL;
    if (bad) {
        snprintf(err, errlen, "%s: write failed: %s", a->path, strerror(errno ? errno : EIO));
        atomic_abort(a);
        return -1;
    }
    return 0;
}

int atomic_publish(atomic_file *a, char *err, size_t errlen)
{
    if (atomic_replace(a->tmp, a->path) != 0) {
        snprintf(err, errlen, "%s: write failed: %s", a->path, strerror(errno));
        atomic_abort(a);
        return -1;
    }
    free(a->path);
    free(a->tmp);
    memset(a, 0, sizeof *a);
    return 0;
}

int atomic_commit(atomic_file *a, char *err, size_t errlen)
{
    if (atomic_finish(a, err, errlen) != 0) return -1;
    return atomic_publish(a, err, errlen);
}

void atomic_abort(atomic_file *a)
{
    if (a->f) fclose(a->f);
    if (a->tmp) unlink(a->tmp);
    free(a->path);
    free(a->tmp);
    memset(a, 0, sizeof *a);
}
