/* help.h — pathlab's help texts, printed with the strategy names read from the tables beside their
 * enums (tracer/light.h, tracer/integrator.h), so that the help never lists a name the parser
 * would refuse. In a text, {light|} {dir|} {direct|} expand to the names joined by '|', and
 * {light } {dir } {direct } to the names joined by spaces. */
#ifndef PATHLAB_HELP_H
#define PATHLAB_HELP_H
#include <stdio.h>

void help_print(FILE *f, const char *text);
#endif
