"""tests/student/box_scene.py OUT [LIGHT_MM]: writes OUT.obj and OUT.mtl, a Cornell-like box for the student
renderer's test (tests/test_student.sh): the five walls, a block that casts penumbrae, and the light
hung 100 mm under the ceiling facing down, so that the ceiling above it sees the light's back (an
unclamped cosine at the light gives negative light there). Every face is a quad, its front side by
the winding (normal u x v). LIGHT_MM: a square light of that side, centred where the default
130 x 105 mm one is (a small light: deep penumbrae, light found by chance by BSDF sampling)."""
import sys

out = sys.argv[1]
side = float(sys.argv[2]) if len(sys.argv) > 2 else None
V, F = [], []


def quad(mat, p, u, v):
    """the quad p, p + u, p + u + v, p + v (normal u x v)"""
    i = len(V) + 1
    V.extend([p, [p[k] + u[k] for k in range(3)], [p[k] + u[k] + v[k] for k in range(3)], [p[k] + v[k] for k in range(3)]])
    F.append((mat, [i, i + 1, i + 2, i + 3]))


W, H, D = 556.0, 548.8, 559.2
quad("white", [0, 0, 0], [0, 0, D], [W, 0, 0])      # floor, up
quad("white", [0, H, 0], [W, 0, 0], [0, 0, D])      # ceiling, down
quad("white", [0, 0, D], [0, H, 0], [W, 0, 0])      # back wall, towards the camera
quad("red", [W, 0, 0], [0, H, 0], [0, 0, D])        # x = W, towards -x
quad("green", [0, 0, 0], [0, 0, D], [0, H, 0])      # x = 0, towards +x
x0, x1, y1, z0, z1 = 130.0, 290.0, 165.0, 65.0, 272.0   # the block, its faces outward
quad("white", [x0, y1, z0], [0, 0, z1 - z0], [x1 - x0, 0, 0])
quad("white", [x0, 0, z0], [x1 - x0, 0, 0], [0, y1, 0])
quad("white", [x0, 0, z1], [0, y1, 0], [x1 - x0, 0, 0])
quad("white", [x0, 0, z0], [0, y1, 0], [0, 0, z1 - z0])
quad("white", [x1, 0, z0], [0, 0, z1 - z0], [0, y1, 0])
if side is None:
    quad("light", [213, 450, 227], [130, 0, 0], [0, 0, 105])   # facing down
else:
    quad("light", [278 - side / 2, 450, 279.5 - side / 2], [side, 0, 0], [0, 0, side])
with open(out + ".obj", "w") as f:
    f.write("mtllib %s.mtl\n" % out.split("/")[-1])
    for v in V:
        f.write("v %g %g %g\n" % tuple(v))
    for m, idx in F:
        f.write("usemtl %s\nf %s\n" % (m, " ".join(map(str, idx))))
with open(out + ".mtl", "w") as f:
    f.write("newmtl white\nKd 0.74 0.74 0.74\nnewmtl red\nKd 0.49 0.05 0.05\nnewmtl green\nKd 0.07 0.40 0.09\n"
            "newmtl light\nKd 0 0 0\nKe 17 12 4\n")
