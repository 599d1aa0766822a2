/* commands.c — a command line dispatched to its command, and the helps (commands.h). */
#include "util/commands.h"
#include "sys/shown.h"
#include <string.h>
#include "util/cli.h"

/* Everything: the overview, then each command's own help. */
static void help_all(const command_table *t, FILE *f)
{
    const command *c;
    int k;
    t->print(f, t->header);
    for (c = t->list; c->name; c++) t->print(f, c->synopsis);
    t->print(f, t->footer);
    for (c = t->list; c->name; c++)
        for (k = 0; c->help[k]; k++) t->print(f, c->help[k]);
}

/* One command's help on stdout: its overview lines and its flags; 0. */
static int help_one(const command_table *t, const command *c)
{
    char *args[3];
    int k;
    if (c->own_help) {
        args[0] = (char *)c->name, args[1] = "--help", args[2] = NULL;
        return c->run(2, args);
    }
    t->print(stdout, "usage:\n");
    t->print(stdout, c->synopsis);
    for (k = 0; c->help[k]; k++) t->print(stdout, c->help[k]);
    return 0;
}

static const command *find_command(const command_table *t, const char *name)
{
    const command *c;
    for (c = t->list; c->name; c++)
        if (!strcmp(name, c->name)) return c;
    return NULL;
}

/* A short error for a name that is no command, with the closest command's name; 2. */
static int unknown_command(const command_table *t, const char *name)
{
    const command *c;
    const char *best = NULL;
    int d = 0;
    for (c = t->list; c->name; c++) cli_consider(name, c->name, &best, &d);
    cli_consider(name, "help", &best, &d);
    fprintf(stderr, "%s: unknown command '%.200s'", t->program, name);
    if (best) fprintf(stderr, "; did you mean '%s'?", shown(best));
    fprintf(stderr, " (%s help lists the commands)\n", t->program);
    return 2;
}

/* -h or --help among a command's arguments (a file named -h is written ./-h). */
static int asks_help(int argc, char **argv)
{
    int i;
    for (i = 1; i < argc; i++)
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return 1;
    return 0;
}

int commands_main(const command_table *t, int argc, char **argv)
{
    const command *c;
    if (argc < 2) { help_all(t, stderr); return 2; }
    if (!strcmp(argv[1], "--version") && (c = find_command(t, "version"))) return c->run(1, argv + 1);
    if (!strcmp(argv[1], "help") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        if (argc < 3 || !strcmp(argv[2], "help")) { help_all(t, stdout); return 0; }
        if (argc > 3) { fprintf(stderr, "%s help: one command at a time (%s help COMMAND)\n", t->program, t->program); return 2; }
        c = find_command(t, argv[2]);
        return c ? help_one(t, c) : unknown_command(t, argv[2]);
    }
    c = find_command(t, argv[1]);
    if (!c) return unknown_command(t, argv[1]);
    if (asks_help(argc - 1, argv + 1)) return help_one(t, c);
    return c->run(argc - 1, argv + 1);
}
