/* grade.h — the `pathlab grade` command (its engine is grade/). */
#ifndef PATHLAB_CMD_GRADE_H
#define PATHLAB_CMD_GRADE_H
/* The command; exit status 0 all pass, 1 a fail, 2 bad input. */
int grade_main(int argc, char **argv);
#endif
