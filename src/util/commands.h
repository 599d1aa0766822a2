/* commands.h — a program of several commands (pathlab render, pathlab grade ...): each command is
 * its name, its main, its lines of the overview (`pathlab help`) and the parts of its own help
 * (`pathlab NAME --help`, `pathlab help NAME`). commands_main dispatches argv to the one named, prints
 * the helps, and answers a name that is no command with the closest one ("did you mean"). */
#ifndef PATHLAB_COMMANDS_H
#define PATHLAB_COMMANDS_H
#include <stdio.h>

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);   /* argv[0] is the command's name */
    const char *synopsis;                /* its lines in the overview */
    const char *help[4];                 /* the parts of its own help after those lines, NULL-terminated */
    int own_help;                        /* 1: the command prints its help itself on --help */
} command;

typedef struct {
    const char *program;                 /* "pathlab" */
    const command *list;                 /* ends with a NULL name; --version runs the one named "version" */
    const char *header, *footer;         /* the overview's first and last lines */
    void (*print)(FILE *f, const char *text);   /* prints a help text (it may expand names in it) */
} command_table;

/* argv[1] is the command, or help [COMMAND], --help, -h, --version. Returns the exit status: the
 * command's, 0 for a help asked, 2 for no command or an unknown one. */
int commands_main(const command_table *t, int argc, char **argv);
#endif
