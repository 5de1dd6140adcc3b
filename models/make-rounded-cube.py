"""Writes rounded-cube.obj: a cube of side 2 whose edges and corners are rounded to radius 0.3,
each face a 14×14 grid (8 cells across its flat part, 3 over each rounded edge), texture (u,v)
laid out as a cross of six squares (one island a face, each a quarter of the texture
across), normals exact.
Run: python3 make-rounded-cube.py > rounded-cube.obj"""
import math

FLAT, ROUND = 8, 3  # cells across a face's flat part, and over each rounded edge
N, R, A = FLAT + 2 * ROUND, 0.3, 0.7  # cells a face side, rounding radius, flat half-side


def spacing(i):
    """Where grid line i of a face lies, -1..1: evenly over the flat part and each edge."""
    if i < ROUND:
        return -1 + (1 - A) * i / ROUND
    if i <= ROUND + FLAT:
        return -A + 2 * A * (i - ROUND) / FLAT
    return A + (1 - A) * (i - ROUND - FLAT) / ROUND
FACES = [  # (normal, u axis, v axis, cell of the cross: column, row from the bottom)
    ((0, 0, 1), (1, 0, 0), (0, 1, 0), (1, 1)),
    ((1, 0, 0), (0, 0, -1), (0, 1, 0), (2, 1)),
    ((0, 0, -1), (-1, 0, 0), (0, 1, 0), (3, 1)),
    ((-1, 0, 0), (0, 0, 1), (0, 1, 0), (0, 1)),
    ((0, 1, 0), (1, 0, 0), (0, 0, -1), (1, 2)),
    ((0, -1, 0), (1, 0, 0), (0, 0, 1), (1, 0)),
]


def rounded(p):
    inner = [max(-A, min(A, c)) for c in p]
    d = [c - i for c, i in zip(p, inner)]
    length = math.sqrt(sum(c * c for c in d)) or 1.0
    n = [c / length for c in d]
    return [i + R * c for i, c in zip(inner, n)], n


print("# A rounded cube, made by make-rounded-cube.py beside it (CC0).")
count = 0
for normal, u_axis, v_axis, (column, row) in FACES:
    for j in range(N + 1):
        for i in range(N + 1):
            s, t = spacing(i), spacing(j)
            p = [normal[k] + s * u_axis[k] + t * v_axis[k] for k in range(3)]
            point, n = rounded(p)
            print("v %.5f %.5f %.5f" % tuple(point))
            print("vn %.5f %.5f %.5f" % tuple(n))
            print("vt %.5f %.5f" % ((column + (s + 1) / 2) / 4, (row + (t + 1) / 2) / 4))
    for j in range(N):
        for i in range(N):
            a = count + j * (N + 1) + i + 1
            b, c, d = a + 1, a + N + 2, a + N + 1
            print("f %d/%d/%d %d/%d/%d %d/%d/%d %d/%d/%d" % (a, a, a, b, b, b, c, c, c, d, d, d))
    count += (N + 1) ** 2
