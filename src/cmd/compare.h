/* compare.h — `pathlab compare SCENE.obj --estimators "light,brdf,mis-power" -o DIR`: renders the
 * same scene with several estimators at equal samples per pixel or equal time, measures each
 * against a reference (given, or rendered with the best estimator at many more samples), and
 * writes the images, their error heatmaps, a labelled mosaic, a table of RMSE, relMSE, MAE and
 * efficiency 1/(MSE x time), and DIR/index.html (compare_page.h). See the comment at the top of compare.c for the choices made. */
#ifndef PATHLAB_COMPARE_H
#define PATHLAB_COMPARE_H

/* Its lines in pathlab help: the usage, then what an estimator is. */
#define COMPARE_USAGE \
    "  pathlab compare SCENE.obj --estimators \"light,brdf,mis-power\" -o DIR [--spp N | --time SEC]\n" \
    "                [--ref REF.pfm [--ref-var VAR.pfm] | --ref-spp M] [--scale S] [render flags]   (below)\n"
#define COMPARE_HELP \
    "compare: renders each estimator at equal spp (default 16) or equal time, and writes into DIR each image\n" \
    "(LABEL.pfm and its variance LABEL_var.pfm, each with its sidecar as render writes them, LABEL.png), its error heatmap (heat-LABEL.png), a labelled mosaic (mosaic.ppm, .png) and the table\n" \
    "(table.md, .csv: RMSE, relMSE, MAE, efficiency 1/(MSE*time)) and a page, index.html: the images in the viewer,\n" \
    "the table, the error against time. Estimators are comma-separated, each a list of\n" \
    "render flags and names: {direct } = --direct X; {light } = --light X;\n" \
    "{dir } = --dir X, brdf written dir-brdf (brdf alone is --direct brdf); {sampler } = --sampler X;\n" \
    "join names with + or spaces: \"light+solid-angle\", \"mis-power --rr off\", \"mis-power+sobol\"; LABEL=FLAGS names one:\n" \
    "\"solid angle=--direct light --light solid-angle\". Flags outside --estimators apply to all; an estimator's\n" \
    "own flags win. Without --ref the reference is rendered with --direct mis-power --light solid-angle\n" \
    "--dir brdf at 16x the largest spp (--ref-spp M) into DIR/reference.pfm; the reference's variance (its own,\n" \
    "--ref-var, or the one its sidecar names; REF_var.pfm beside a REF.pfm without a sidecar) is taken off each MSE\n" \
    "(an MSE below it is nan: use a reference of more samples). --ref must not be in DIR. --scale S: the heatmaps'\n" \
    "white (default 3x the largest RMSE).\n"
/* argv[0] is "compare". Exit status: 0 done, 1 a render or a write failed, 2 bad input. */
int compare_main(int argc, char **argv);
#endif
