/* chi2_triangle.c — sub-triangle cells of the barycentric triangle (chi2_triangle.h). Square (a, b)
 * of the n x n grid over [0, 1]^2 holds the sub-triangle nearer the origin, index a n + b, and when
 * a + b < n - 1 also the far one, index (n-1-a) n + (n-1-b): an index no near one uses. */
#include "check/chi2_triangle.h"
#include "stats/quadrature.h"
#include <math.h>

int tri_cell(double b1, double b2, int n)
{
    double x = b1 * n, y = b2 * n;
    int a = x < 0.0 ? 0 : (int)x, b = y < 0.0 ? 0 : (int)y;
    if (a > n - 1) a = n - 1;
    if (b > n - 1 - a) b = n - 1 - a;
    return (x - a) + (y - b) < 1.0 || a + b == n - 1 ? a * n + b : (n - 1 - a) * n + (n - 1 - b);
}

/* The corners (b1[i], b2[i]) of sub-triangle k. */
static void tri_cell_corners(int k, int n, double b1[3], double b2[3])
{
    int i = k / n, j = k % n;
    if (i + j <= n - 1) {   /* near sub-triangle of square (i, j) */
        b1[0] = i, b2[0] = j, b1[1] = i + 1, b2[1] = j, b1[2] = i, b2[2] = j + 1;
    } else {                /* far sub-triangle of square (n-1-i, n-1-j) */
        int a = n - 1 - i, b = n - 1 - j;
        b1[0] = a + 1, b2[0] = b + 1, b1[1] = a, b2[1] = b + 1, b1[2] = a + 1, b2[2] = b;
    }
    for (i = 0; i < 3; i++) b1[i] /= n, b2[i] /= n;
}

/* The square [0,1]^2 maps onto the triangle P0 P1 P2 by (u, v) -> P0 + u (P1 - P0) + u v (P2 - P1),
 * with Jacobian u |det(P1 - P0, P2 - P1)|. */
double tri_cell_integral(double (*f)(const void *ctx, double b1, double b2), const void *ctx, int k, int n)
{
    double x[3], y[3], det, sum = 0.0;
    int i, j;
    tri_cell_corners(k, n, x, y);
    det = fabs((x[1] - x[0]) * (y[2] - y[1]) - (y[1] - y[0]) * (x[2] - x[1]));
    for (i = 0; i < GL_N; i++)
        for (j = 0; j < GL_N; j++) {
            double u = gl_node(0.0, 1.0, 0, i), v = gl_node(0.0, 1.0, 0, j);
            double px = x[0] + u * (x[1] - x[0]) + u * v * (x[2] - x[1]), py = y[0] + u * (y[1] - y[0]) + u * v * (y[2] - y[1]);
            sum += gl_weight(1.0, i) * gl_weight(1.0, j) * u * det * f(ctx, px, py);
        }
    return sum;
}
