/* class_run.h — one grading run, as `pathlab grade` makes it: the reference read with what lies
 * beside it (reference.h), then each image graded in turn (grade.h), the likely mistake of those that
 * fail named (grade_diagnose.h), its verdict printed (grade_print.h), its heatmap and page written
 * (grade_page.h), and the class's summary and report (grade_class.h). */
#ifndef PATHLAB_GRADE_CLASS_RUN_H
#define PATHLAB_GRADE_CLASS_RUN_H
#include "grade/grade.h"

typedef struct {
    const char *ref, *var, *layers;        /* --ref; --var and --layers, or NULL: found beside the reference */
    const char *heatmap, *report, *pages;  /* the outputs asked for, or NULL */
    int heatmap_folder;                    /* 1: --heatmap is a folder (several images, or one that exists):
                                            * FOLDER/NAME.png; 0: the picture itself (cmd/grade.c decides) */
    int details;                           /* 1: each image's tests in full, even with several */
    grade_opts o;
    const char *const *images;             /* the images, folders expanded (folder.h) */
    int nimages;
} grade_job;

/* Runs the job; the outputs' names were checked (cmd/grade.c). Exit status: 0 all pass, 1 a fail,
 * 2 an input error (or an output that could not be written). */
int grade_run(const grade_job *job);
#endif
