/* commands.c — a command line dispatched to its command, and the helps (commands.h). */
#include "util/commands.h"
#include "sys/shown.h"
#include <fcntl.h>
#include <string.h>
#include <unistd.h>
#include "util/cli.h"

/* The overview: the header, each command's lines, the footer. */
static void overview(const command_table *t, FILE *f)
{
    const command *c;
    t->print(f, t->header);
    for (c = t->list; c->name; c++) t->print(f, c->synopsis);
    t->print(f, t->footer);
}

/* One command's help on stdout: its overview lines and its flags (the same for `help NAME` and
 * `NAME --help`, and in `help`, under the heading "pathlab NAME"); 0. */
static int help_one(const command_table *t, const command *c)
{
    char *args[3];
    int k;
    fflush(stdout);
    if (c->own_help) {
        args[0] = (char *)c->name, args[1] = "--help", args[2] = NULL;
        return c->run(2, args);
    }
    t->print(stdout, "usage:\n");
    t->print(stdout, c->synopsis);
    for (k = 0; c->help[k]; k++) t->print(stdout, c->help[k]);
    return 0;
}

/* Everything on stdout: the overview, then each command's help under its heading. */
static void help_all(const command_table *t)
{
    const command *c;
    overview(t, stdout);
    for (c = t->list; c->name; c++) {
        printf("\n==== %s %s ====\n", t->program, c->name);
        help_one(t, c);
        fflush(stdout);
    }
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

/* ---- the shell's completion, from the commands' flag tables ---- */

/* The flags of command c into f, one a line (util/cli.h, cli_list_flags): c's main is run with the
 * listing on, which makes its cli_parse list the tables instead of parsing; c's own output is
 * silenced (fd 1 and 2 on /dev/null). 0, or 1 if /dev/null cannot be opened. */
static int list_flags(const command *c, FILE *f)
{
    char *args[2];
    int out, err, null = open("/dev/null", O_WRONLY);
    if (null < 0) return 1;
    args[0] = (char *)c->name, args[1] = NULL;
    fflush(stdout), fflush(stderr);
    out = dup(1), err = dup(2);
    dup2(null, 1), dup2(null, 2);
    cli_list_flags(f);
    c->run(1, args);
    cli_list_flags(NULL);
    fflush(stdout), fflush(stderr);
    dup2(out, 1), dup2(err, 2);
    close(out), close(err), close(null);
    return 0;
}

/* One command's arm of the bash function: its flags, and after a flag of a list, the list. */
static void bash_arm(const command *c, FILE *list)
{
    char line[1024];
    int first = 1;
    printf("    %s)\n        flags='", c->name);
    rewind(list);
    while (fgets(line, sizeof line, list)) {
        line[strcspn(line, " \n")] = '\0';
        printf("%s%s", first ? "" : " ", line), first = 0;
    }
    printf("'\n        case $prev in\n");
    rewind(list);
    while (fgets(line, sizeof line, list)) {
        char *sp = strchr(line, ' ');
        line[strcspn(line, "\n")] = '\0';
        if (sp) *sp = '\0', printf("        %s) values='%s' ;;\n", line, sp + 1);
    }
    printf("        esac ;;\n");
}

static void bash_script(const command_table *t, FILE *const *lists)
{
    const command *c;
    int k;
    printf("# bash completion for %s, generated from its flag tables by `%s completion bash`\n", t->program, t->program);
    printf("_%s() {\n    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]} flags= values=\n", t->program);
    printf("    local commands='");
    for (c = t->list; c->name; c++) printf("%s ", c->name);
    printf("help completion'\n");
    printf("    if [ \"$COMP_CWORD\" -eq 1 ]; then COMPREPLY=($(compgen -W \"$commands --help --version\" -- \"$cur\")); return; fi\n");
    printf("    case ${COMP_WORDS[1]} in\n    help) [ \"$COMP_CWORD\" -eq 2 ] && COMPREPLY=($(compgen -W \"$commands\" -- \"$cur\")); return ;;\n");
    printf("    completion) [ \"$COMP_CWORD\" -eq 2 ] && COMPREPLY=($(compgen -W 'bash flags' -- \"$cur\")); return ;;\n");
    for (c = t->list, k = 0; c->name; c++, k++) bash_arm(c, lists[k]);
    printf("    esac\n");
    printf("    if [ -n \"$values\" ]; then COMPREPLY=($(compgen -W \"$values\" -- \"$cur\"))\n");
    printf("    elif [[ $cur == -* ]]; then COMPREPLY=($(compgen -W \"$flags --help --isa\" -- \"$cur\"))\n");
    printf("    fi   # else the shell completes file names (-o default)\n}\n");
    printf("complete -o default -F _%s %s\n", t->program, t->program);
}

/* `completion bash`: the script; `completion flags NAME`: NAME's flags, one a line. */
static int completion_main(const command_table *t, int argc, char **argv)
{
    FILE *lists[64];
    const command *c;
    int n = 0, k, rc = 0;
    if (argc == 3 && !strcmp(argv[1], "flags") && (c = find_command(t, argv[2]))) {
        char line[1024];
        if (!(lists[0] = tmpfile()) || list_flags(c, lists[0])) rc = 1;
        for (rewind(lists[0]); !rc && fgets(line, sizeof line, lists[0]);) fputs(line, stdout);
        if (lists[0]) fclose(lists[0]);
        return rc;
    }
    if (argc != 2 || strcmp(argv[1], "bash")) {
        fprintf(stderr, "%s completion: bash (the bash completion script) or flags COMMAND (its flags, one a line)\n", t->program);
        return 2;
    }
    for (c = t->list; c->name && n < 64; c++, n++)
        if (!(lists[n] = tmpfile()) || list_flags(c, lists[n])) { rc = 1; break; }
    if (!rc) bash_script(t, lists);
    for (k = 0; k < n && lists[k]; k++) fclose(lists[k]);
    if (rc) fprintf(stderr, "%s completion: cannot make a temporary file or open /dev/null\n", t->program);
    return rc;
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
    if (argc < 2) {
        overview(t, stderr);
        fprintf(stderr, "(%s help: every command's flags)\n", t->program);
        return 2;
    }
    if (!strcmp(argv[1], "completion")) return completion_main(t, argc - 1, argv + 1);
    if (!strcmp(argv[1], "--version") && (c = find_command(t, "version"))) return c->run(1, argv + 1);
    if (!strcmp(argv[1], "help") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        if (argc < 3 || !strcmp(argv[2], "help")) { help_all(t); return 0; }
        if (argc > 3) { fprintf(stderr, "%s help: one command at a time (%s help COMMAND)\n", t->program, t->program); return 2; }
        c = find_command(t, argv[2]);
        return c ? help_one(t, c) : unknown_command(t, argv[2]);
    }
    c = find_command(t, argv[1]);
    if (!c) return unknown_command(t, argv[1]);
    if (asks_help(argc - 1, argv + 1)) return help_one(t, c);
    return c->run(argc - 1, argv + 1);
}
