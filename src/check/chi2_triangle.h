/* chi2_triangle.h — cells on a triangle for the chi-square tests of point samplers: the barycentric
 * triangle {b1, b2 >= 0, b1 + b2 <= 1} cut into n^2 equal sub-triangles by n - 1 lines parallel to
 * each side, and the integral of a density over one of them. */
#ifndef PATHLAB_CHI2_TRIANGLE_H
#define PATHLAB_CHI2_TRIANGLE_H

/* Index in [0, n^2) of the sub-triangle holding the barycentrics (b1, b2) of the 2nd and 3rd corners
 * (a point slightly outside goes to the nearest cell). */
int tri_cell(double b1, double b2, int n);
/* Integral of f(b1, b2) db1 db2 over sub-triangle k (the whole triangle has area 1/2 in (b1, b2)):
 * Gauss-Legendre on the square collapsed onto the triangle, exact for polynomials of degree 14. */
double tri_cell_integral(double (*f)(const void *ctx, double b1, double b2), const void *ctx, int k, int n);
#endif
