/* test_readall.c - the one whole-file reader (src/files/readall.h) against
 * files written here: every byte back, in order, for sizes on both sides
 * of its first buffer (64 KiB) and of its doublings; the size limit at
 * exactly the file's size (read) and one byte under it (READALL_LARGE);
 * an empty file (a buffer, no bytes); a missing file (READALL_OPEN, errno
 * ENOENT); a folder (READALL_READ); nothing allocated on a failure (the
 * sanitizer build's leak check). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "readall.h"
#include "testutil.h"

static int passed_, failed_;

static unsigned char byte_at(size_t i) { return (unsigned char)((i * 2654435761u) >> 13); }

static int write_file(const char *path, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    for (size_t i = 0; i < n; i++) fputc(byte_at(i), f);
    return fclose(f);
}

int main(void)
{
    char dir[] = "/tmp/cfpo_readall_XXXXXX";
    if (!mkdtemp(dir)) { perror("mkdtemp"); return 1; }
    char path[256];
    snprintf(path, sizeof path, "%s/f.bin", dir);
    const size_t sizes[] = {0, 1, 65535, 65536, 65537, 131072, 131073, 1000003};
    for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        const size_t n = sizes[s];
        if (write_file(path, n) != 0) { perror(path); return 1; }
        unsigned char *buf = NULL;
        size_t len = 12345;
        CHECK(readall(path, 0, &buf, &len) == READALL_OK && buf != NULL, "%zu bytes, no limit: not read", n);
        CHECK(len == n, "%zu bytes: read %zu", n, len);
        size_t bad = 0;
        for (size_t i = 0; buf && i < len && i < n; i++) bad += buf[i] != byte_at(i);
        CHECK(bad == 0, "%zu bytes: %zu differ", n, bad);
        free(buf);
        if (n == 0) continue;
        buf = NULL;
        CHECK(readall(path, n, &buf, &len) == READALL_OK && len == n, "%zu bytes, limit %zu: not read", n, n);
        free(buf);
        if (n == 1) continue; /* a limit of 0 is none */
        buf = NULL;
        CHECK(readall(path, n - 1, &buf, &len) == READALL_LARGE && buf == NULL, "%zu bytes, limit %zu: not refused",
              n, n - 1);
    }
    unsigned char *buf = NULL;
    size_t len = 0;
    char missing[300];
    snprintf(missing, sizeof missing, "%s/none.bin", dir);
    errno = 0;
    CHECK(readall(missing, 0, &buf, &len) == READALL_OPEN && errno == ENOENT && buf == NULL,
          "a missing file: not READALL_OPEN with ENOENT");
    CHECK(readall(dir, 0, &buf, &len) == READALL_READ && buf == NULL, "a folder: not READALL_READ");
    unlink(path);
    rmdir(dir);
    return test_report(passed_, failed_);
}
