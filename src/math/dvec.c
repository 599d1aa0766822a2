/* dvec.c — frames in double precision (dvec.h). */
#include "math/dvec.h"

dframe dframe_about(dvec n)
{
    dframe f;
    double sign = n.z >= 0.0 ? 1.0 : -1.0, a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    f.t = dv(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.b = dv(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

dvec dframe_dir(const dframe *F, double t, double phi)
{
    double c = 1.0 - t, s = sqrt(fmax(0.0, t * (2.0 - t)));
    return dv_lin(F->n, c, dv_lin(F->t, cos(phi), F->b, sin(phi)), s);
}

/* t from sin^2 keeps its precision near the axis */
void dframe_coords(const dframe *F, dvec w, double *t, double *phi)
{
    double x = dv_dot(w, F->t), y = dv_dot(w, F->b), z = dv_dot(w, F->n), s2 = x * x + y * y;
    *t = z > 0.0 ? s2 / (1.0 + z) : 1.0 - z;
    *phi = atan2(y, x);
    if (*phi < 0.0) *phi += 2.0 * PI;
}
