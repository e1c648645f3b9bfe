/* safefile.c - see safefile.h. */
#include "safefile.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int safefile_create(const char *path, char **tmp, char *err, size_t errlen)
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

int safefile_replace(const char *tmp, const char *path)
{
    if (rename(tmp, path) == 0) return 0;
    const int e = errno ? errno : EIO;
    unlink(tmp);
    errno = e;
    return -1;
}

int safefile_open(safefile *a, const char *path, const char *mode, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    a->path = strdup(path);
    if (!a->path) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    const int fd = safefile_create(path, &a->tmp, err, errlen);
    if (fd >= 0) a->f = fdopen(fd, mode);
    if (fd >= 0 && !a->f) {
        snprintf(err, errlen, "%s: cannot open file: %s", path, strerror(errno));
        close(fd);
    }
    if (!a->f) {
        safefile_abort(a);
        return -1;
    }
    return 0;
}

int safefile_finish(safefile *a, char *err, size_t errlen)
{
    errno = 0;
    int bad = fflush(a->f) != 0 || ferror(a->f);
    if (fclose(a->f) != 0) bad = 1;
    a->f = NULL;
    if (bad) {
        snprintf(err, errlen, "%s: write failed: %s", a->path, strerror(errno ? errno : EIO));
        safefile_abort(a);
        return -1;
    }
    return 0;
}

int safefile_publish(safefile *a, char *err, size_t errlen)
{
    if (safefile_replace(a->tmp, a->path) != 0) {
        snprintf(err, errlen, "%s: write failed: %s", a->path, strerror(errno));
        safefile_abort(a);
        return -1;
    }
    free(a->path);
    free(a->tmp);
    memset(a, 0, sizeof *a);
    return 0;
}

int safefile_commit(safefile *a, char *err, size_t errlen)
{
    if (safefile_finish(a, err, errlen) != 0) return -1;
    return safefile_publish(a, err, errlen);
}

void safefile_abort(safefile *a)
{
    if (a->f) fclose(a->f);
    if (a->tmp) unlink(a->tmp);
    free(a->path);
    free(a->tmp);
    memset(a, 0, sizeof *a);
}
