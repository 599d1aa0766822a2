/* check_sampling.h — `pathlab check-sampling`: every sampling routine of pathlab against its pdf, one row
 * per case. Its parts are in src/check/, from the bottom: case.h (what a case and its result are), warp_check.h,
 * brdf_check.h, light_check.h (running a case of each kind, on chi2_sphere.h, chi2_triangle.h,
 * arvo.h and light_scene.h), cases.h (the list), run.h (the cases on threads), verdict.h (pass or
 * fail), sampling_table.h (the table and its legend), and this command here (flags, main). */
#ifndef PATHLAB_CMD_CHECK_SAMPLING_H
#define PATHLAB_CMD_CHECK_SAMPLING_H

/* argv[0] = "check-sampling". Prints the table; 0 when every case passes, 1 if one fails, 2 on a usage error. */
int check_sampling_main(int argc, char **argv);
#endif
