/* quadrature.h — the 8-point Gauss-Legendre rule, exact for polynomials of degree 15 on [-1, 1]:
 *   integral of f over [a, b] ~ (b - a)/2 sum_k GL_W[k] f(a + (b - a)(GL_X[k] + 1)/2).
 * The sampling checks (chi2_sphere.c, chi2_triangle.c, arvo.c's users) integrate pdfs with it,
 * cut into panels where the integrand needs them. */
#ifndef PATHLAB_QUADRATURE_H
#define PATHLAB_QUADRATURE_H

#define GL_N 8
static const double GL_X[GL_N] = {0.96028985649753629,  0.79666647741362684,  0.52553240991632899,
                                  0.18343464249564978,  -0.18343464249564978, -0.52553240991632899,
                                  -0.79666647741362684, -0.96028985649753629};
static const double GL_W[GL_N] = {0.10122853629037679, 0.22238103445337445, 0.31370664587788738,
                                  0.36268378337836199, 0.36268378337836199, 0.31370664587788738,
                                  0.22238103445337445, 0.10122853629037679};

/* The k-th node of panel j of [a, a + panels h], and its weight h/2 GL_W[k]. */
static inline double gl_node(double a, double h, int j, int k) { return a + h * (j + 0.5 * (GL_X[k] + 1.0)); }
static inline double gl_weight(double h, int k) { return 0.5 * h * GL_W[k]; }
#endif
