/* test_tmpguard.c - the one signal handler for temporaries (src/files/tmpguard.h).
 *
 * Properties: a process that registers nothing keeps the default action
 * of SIGINT, SIGTERM and SIGHUP; in a process that holds both kinds at
 * once (a command's temporary file, and a temporary folder with files in
 * it, as cfpo-analyze's output folder), each of the three signals removes
 * every registered file and then the folder, and still ends the process by
 * that signal; a file registered and then forgotten, and one never
 * registered, survive; tmpguard_clean (an error exit) removes what is
 * registered and forgets it, so a second clean touches nothing. */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "testutil.h"
#include "tmpguard.h"

static int passed_, failed_;
static char root[64];

static void path_of(char *p, size_t cap, const char *name) { snprintf(p, cap, "%s/%s", root, name); }

static void touch(const char *name)
{
    char p[256];
    path_of(p, sizeof p, name);
    FILE *f = fopen(p, "w");
    if (f) {
        fputs("x\n", f);
        fclose(f);
    }
}

static int exists(const char *name)
{
    char p[256];
    struct stat st;
    path_of(p, sizeof p, name);
    return stat(p, &st) == 0;
}

/* In the child: the files and the folder, registered as the commands do. */
static void make_and_register(void)
{
    char p[256];
    touch("out.npy.tmp.1");
    touch("kept.txt");
    touch("forgotten.tmp");
    path_of(p, sizeof p, "out.tmp.1");
    mkdir(p, 0777);
    touch("out.tmp.1/stats.json");
    touch("out.tmp.1/spectrum.txt");
    path_of(p, sizeof p, "out.npy.tmp.1");
    tmpguard_file(p);
    path_of(p, sizeof p, "forgotten.tmp");
    tmpguard_file(p);
    tmpguard_forget(p);
    const char *names[3] = {"out.tmp.1/stats.json", "out.tmp.1/spectrum.txt", "out.tmp.1/raps.txt"};
    for (int i = 0; i < 3; i++) { /* raps.txt: registered, not written yet */
        path_of(p, sizeof p, names[i]);
        tmpguard_file(p);
    }
    path_of(p, sizeof p, "out.tmp.1");
    tmpguard_dir(p);
}

static void cleanup(void)
{
    const char *names[] = {"out.tmp.1/stats.json", "out.tmp.1/spectrum.txt", "out.tmp.1", "out.npy.tmp.1",
                           "kept.txt", "forgotten.tmp"};
    char p[256];
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        path_of(p, sizeof p, names[i]);
        remove(p);
    }
}

static void test_signal(int sig, const char *name)
{
    int ready[2];
    if (pipe(ready) != 0) return;
    const pid_t pid = fork();
    if (pid == 0) {
        close(ready[0]);
        make_and_register();
        if (write(ready[1], "r", 1) != 1) _exit(3);
        for (;;) pause();
    }
    close(ready[1]);
    char c;
    const int got = (int)read(ready[0], &c, 1);
    close(ready[0]);
    kill(pid, sig);
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(got == 1 && WIFSIGNALED(status) && WTERMSIG(status) == sig, "%s: the process did not end by %s", name,
          name);
    CHECK(!exists("out.npy.tmp.1") && !exists("out.tmp.1"), "%s: left%s%s", name,
          exists("out.npy.tmp.1") ? " the temporary file" : "", exists("out.tmp.1") ? " the temporary folder" : "");
    CHECK(exists("kept.txt") && exists("forgotten.tmp"), "%s: removed a file it was not (or no longer) given",
          name);
    cleanup();
}

static void test_default_action(void)
{
    const pid_t pid = fork();
    if (pid == 0) {
        int bad = 0;
        const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
        for (int i = 0; i < 3; i++) {
            struct sigaction sa;
            sigaction(sigs[i], NULL, &sa);
            bad += sa.sa_handler != SIG_DFL;
        }
        tmpguard_forget("nothing"); /* forgetting registers nothing */
        struct sigaction sa;
        sigaction(SIGTERM, NULL, &sa);
        bad += sa.sa_handler != SIG_DFL;
        char p[256];
        path_of(p, sizeof p, "x.tmp");
        tmpguard_file(p); /* the first registration installs it */
        sigaction(SIGTERM, NULL, &sa);
        bad += sa.sa_handler == SIG_DFL;
        _exit(bad);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0,
          "the handler is installed by the first registration, and only then");
}

static void test_clean(void)
{
    const pid_t pid = fork();
    if (pid == 0) {
        make_and_register();
        tmpguard_clean();
        int bad = exists("out.npy.tmp.1") + exists("out.tmp.1") + !exists("kept.txt");
        touch("out.npy.tmp.1"); /* the same name again, after the clean: not touched */
        tmpguard_clean();
        bad += !exists("out.npy.tmp.1");
        _exit(bad);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0, "tmpguard_clean: %d wrong",
          WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    cleanup();
}

int main(void)
{
    snprintf(root, sizeof root, "/tmp/test_tmpguard.XXXXXX");
    if (!mkdtemp(root)) {
        perror("mkdtemp");
        return 1;
    }
    test_default_action();
    test_signal(SIGTERM, "SIGTERM");
    test_signal(SIGINT, "SIGINT");
    test_signal(SIGHUP, "SIGHUP");
    test_clean();
    rmdir(root);
    return test_report(passed_, failed_);
}
