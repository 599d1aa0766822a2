/* folder.h — the images of a grading: those named, and a class's folder expanded into its .pfm
 * files, sorted by name, leaving out variances (_var.pfm), layers (_split_L) and the reference
 * with the files made beside it (REF-64x64.pfm, REF_split.pfm ...). */
#ifndef PATHLAB_GRADE_FOLDER_H
#define PATHLAB_GRADE_FOLDER_H

typedef struct {
    const char **images;   /* the images, folders expanded */
    int n, cap;
    char **owned;          /* the paths made for a folder's images, freed by grade_list_free */
    int nowned;
} grade_list;

/* Room for cap images; 0, or 1 when out of memory. */
int grade_list_init(grade_list *l, int cap);
/* Appends one image (left out beyond cap: grade_list_add_folder says so). */
void grade_list_add(grade_list *l, const char *image);
/* Appends the .pfm files of a folder, but not ref and its files; 0, or 1 after saying why. Warns
 * when the folder holds none. */
int grade_list_add_folder(grade_list *l, const char *dir, const char *ref);
void grade_list_free(grade_list *l);
#endif
