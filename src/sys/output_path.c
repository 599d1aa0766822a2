/* output_path.c — outputs checked before the work (output_path.h). access(W_OK) asks the kernel
 * with the real uid, which is what a student runs with; a read-only file system answers EROFS. */
#include "sys/output_path.h"
#include "sys/shown.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

static int say(const char *cmd, const char *flag, const char *path, const char *why)
{
    fprintf(stderr, "pathlab %s: %s %.1000s: %s\n", cmd, shown(flag), shown(path), why);
    return 1;
}

/* The folder of path into dir ("." for a bare name); 1 if it does not fit. */
static int folder_of(char *dir, size_t cap, const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 0;
    if (!slash) return snprintf(dir, cap, ".") >= (int)cap;
    if (n == 0) n = 1;   /* "/x.pfm": the root */
    if (n >= cap) return 1;
    memcpy(dir, path, n);
    dir[n] = '\0';
    return 0;
}

/* 0 if dir is a folder this process can create files in, else 1 after saying why. */
static int writable_folder(const char *cmd, const char *flag, const char *path, const char *dir)
{
    struct stat st;
    char why[1200];
    if (stat(dir, &st) != 0) {
        snprintf(why, sizeof why, "the folder %.1000s does not exist (create it first)", dir);
        return say(cmd, flag, path, why);
    }
    if (!S_ISDIR(st.st_mode)) {
        snprintf(why, sizeof why, "%.1000s is not a folder", dir);
        return say(cmd, flag, path, why);
    }
    if (access(dir, W_OK | X_OK) != 0) {
        snprintf(why, sizeof why, "cannot write in the folder %.1000s: %s", dir, strerror(errno));
        return say(cmd, flag, path, why);
    }
    return 0;
}

/* 0 if path's extension is one of exts (or exts is NULL), else 1 after naming them. */
static int known_extension(const char *cmd, const char *flag, const char *path, const char *const *exts)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    char why[256];
    int k;
    if (!exts) return 0;
    if (dot && (!slash || dot > slash))
        for (k = 0; exts[k]; k++)
            if (!strcasecmp(dot, exts[k])) return 0;
    snprintf(why, sizeof why, "unknown %sformat (use", !strcmp(exts[0], ".pfm") ? "image " : "");
    for (k = 0; exts[k] && strlen(why) + strlen(exts[k]) + 8 < sizeof why; k++)
        snprintf(why + strlen(why), sizeof why - strlen(why), "%s %s", k == 0 ? "" : exts[k + 1] ? "," : " or", exts[k]);
    snprintf(why + strlen(why), sizeof why - strlen(why), ")");
    return say(cmd, flag, path, why);
}

int output_path_check(const char *cmd, const char *flag, const char *path, const char *const *exts)
{
    struct stat st;
    char dir[PATH_CAP];
    if (!path[0]) return say(cmd, flag, "''", "an empty file name");
    if (path[strlen(path) - 1] == '/' || (stat(path, &st) == 0 && S_ISDIR(st.st_mode)))
        return say(cmd, flag, path, "is a folder: give a file name");
    if (known_extension(cmd, flag, path, exts)) return 1;
    if (folder_of(dir, sizeof dir, path)) return say(cmd, flag, path, "the name is too long");
    if (writable_folder(cmd, flag, path, dir)) return 1;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) return say(cmd, flag, path, "exists and is not a regular file");
    /* a file its owner made read-only (a teacher's reference) is not replaced, even by root */
    if (lstat(path, &st) == 0 && S_ISREG(st.st_mode) && !(st.st_mode & S_IWUSR))
        return say(cmd, flag, path, "is read-only: not replaced (chmod u+w it, or write elsewhere)");
    return 0;
}

int output_dir_check(const char *cmd, const char *flag, const char *dir)
{
    struct stat st;
    char name[PATH_CAP], parent[PATH_CAP];
    size_t n = strlen(dir);
    if (!n) return say(cmd, flag, "''", "an empty folder name");
    if (stat(dir, &st) == 0) {
        if (!S_ISDIR(st.st_mode)) return say(cmd, flag, dir, "exists and is not a folder");
        return writable_folder(cmd, flag, dir, dir);
    }
    while (n > 1 && dir[n - 1] == '/') n--;   /* "out/" is the folder out */
    if (n >= sizeof name) return say(cmd, flag, dir, "the name is too long");
    memcpy(name, dir, n);
    name[n] = '\0';
    if (folder_of(parent, sizeof parent, name)) return say(cmd, flag, dir, "the name is too long");
    return writable_folder(cmd, flag, dir, parent);
}
