"""The paper's voxel-sum wall force computed here on its own, from the voxel geometry and the
coefficients alone (Jaeger et al., section II.B, Eq. 6: F_pw = sum_k (F_n,k + F_a,k) n_k +
F_f,k t_k), for the checks of fix wall/voxel model voxel_sum in wall_check.py. It follows
the reference sums of tests/contact/test_voxel_sum_wall.cpp (not the library's code): each
solid voxel is the cube [i +- 1/2] x [j +- 1/2] x [k +- 1/2] (unit spacing, origin 0), its
gap h_k is the distance from the particle's surface to the cube, and

    F_n,k = k_w delta_k            overlapping (Eq. 1, conservative part)
    F_a,k = -h_k k_a R             for 0 <= h_k <= 0.03 R (Eq. 4)
    |F_f,k| <= mu |F_n,k + F_a,k|  (Eq. 5, the friction capacity of the voxel)

Geometries are lists of disjoint solid boxes ((i0, i1), (j0, j1), (k0, k1)), bounds inclusive.
"""
import math

RANGE = 0.03  # adhesion range / R (Eq. 4)


class Coefficients:
    def __init__(self, name, k_w, k_a, mu, radius, density):
        self.name, self.k_w, self.k_a, self.mu, self.radius = name, k_w, k_a, mu, radius
        self.mass = density * 4.0 / 3.0 * math.pi * radius ** 3

    def reach(self):
        return (1.0 + RANGE) * self.radius

    def resting_stiffness(self):
        """The voxel under a resting particle plus the 8 around it adhering (k_a R each)."""
        return self.k_w + 8.0 * self.k_a * self.radius

    def time_step(self):
        """1/100 of the period of the stiffest normal oscillation, as the unit test takes."""
        return 2.0 * math.pi * math.sqrt(self.mass / self.resting_stiffness()) / 100.0


def solid_near(boxes, c, margin, margin_z=None):
    """The solid voxels (i, j, k) of `boxes` within `margin` cells of `c` along x and y and
    `margin_z` (default `margin`) along z."""
    margins = (margin, margin, margin if margin_z is None else margin_z)
    out = []
    for (i0, i1), (j0, j1), (k0, k1) in boxes:
        lo = [max(b0, math.ceil(c[a] - margins[a])) for a, b0 in enumerate((i0, j0, k0))]
        hi = [min(b1, math.floor(c[a] + margins[a])) for a, b1 in enumerate((i1, j1, k1))]
        for k in range(lo[2], hi[2] + 1):
            for j in range(lo[1], hi[1] + 1):
                for i in range(lo[0], hi[0] + 1):
                    out.append((i, j, k))
    return out


def cube_offset(c, voxel):
    """From the cube's closest point to c."""
    return [math.copysign(max(abs(c[a] - voxel[a]) - 0.5, 0.0), c[a] - voxel[a]) for a in range(3)]


def normal_force(coef, gap):
    """Conservative normal force of one voxel, repulsive positive (Eqs. 1 and 4)."""
    if gap < 0.0:
        return -coef.k_w * gap
    if gap <= RANGE * coef.radius:
        return -gap * coef.k_a * coef.radius
    return 0.0


class Sum:
    def __init__(self):
        self.normal = [0.0, 0.0, 0.0]    # sum of the voxels' normal forces
        self.friction = [0.0, 0.0, 0.0]  # every contact at its Coulomb limit against `slide`
        self.capacity = 0.0              # sum of mu |F_n,k + F_a,k|
        self.contacts = 0


def voxel_sum(boxes, coef, c, slide=(0.0, 0.0, 0.0), voxels=None):
    """The sum over the voxels within reach of a particle centred at c; `voxels` may give the
    candidates (solid_near) to save the search when called many times near one place."""
    s = Sum()
    candidates = voxels if voxels is not None else solid_near(boxes, c, coef.reach() + 0.5)
    for voxel in candidates:
        d = cube_offset(c, voxel)
        length = math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
        gap = length - coef.radius
        if gap > RANGE * coef.radius:
            continue
        f = normal_force(coef, gap)
        n = [x / length for x in d]
        for a in range(3):
            s.normal[a] += f * n[a]
        s.capacity += coef.mu * abs(f)
        s.contacts += 1
        along = sum(slide[a] * n[a] for a in range(3))
        t = [slide[a] - along * n[a] for a in range(3)]
        t_norm = math.sqrt(sum(x * x for x in t))
        if t_norm > 0.0:
            for a in range(3):
                s.friction[a] -= coef.mu * abs(f) / t_norm * t[a]
    return s


def balanced_height(boxes, coef, x, y, load, slide, z_from):
    """Height of the centre above (x, y) where the voxels carry the load (pushing down) with
    every contact sliding against `slide`, reached from z_from as a slowly moved particle gets
    there: up while the net force pushes up, down while it pulls down, to the first balance."""
    voxels = solid_near(boxes, (x, y, z_from), coef.reach() + 0.5, coef.reach() + 2.5)

    def pushed_up(z):
        s = voxel_sum(boxes, coef, (x, y, z), slide, voxels)
        return s.normal[2] + s.friction[2] - load > 0.0

    up = pushed_up(z_from)
    step = 2e-4 if up else -2e-4
    z = z_from
    while abs(z - z_from) < 2.0:
        if pushed_up(z + step) != up:
            pushed, pulled = z, z + step
            for _ in range(40):
                mid = 0.5 * (pushed + pulled)
                if pushed_up(mid) == up:
                    pushed = mid
                else:
                    pulled = mid
            return pulled if up else pushed
        z += step
    return math.nan


def slide_threshold(boxes, coef, x0, y0, z_rest, load=0.0, cells=2, per_cell=500):
    """Quasi-static sliding along +x from the rest above (x0, y0): the resistance at the start
    (friction alone, the normal forces cancel there) and the largest one met over `cells`
    cells, every contact at its Coulomb limit and the height balanced at each position."""
    at_rest, largest, z = 0.0, 0.0, z_rest
    for s in range(cells * per_cell + 1):
        x = x0 + s / per_cell
        z = balanced_height(boxes, coef, x, y0, load, (1.0, 0.0, 0.0), z)
        total = voxel_sum(boxes, coef, (x, y0, z), (1.0, 0.0, 0.0))
        resistance = -(total.normal[0] + total.friction[0])
        if s == 0:
            at_rest = resistance
        largest = max(largest, resistance)
    return at_rest, largest


def pull_off_force(boxes, coef, x, y, z_rest, floor_top):
    """Largest net normal pull a flat floor resists above (x, y) from the rest height up: the
    net attraction grows with z between the heights where a voxel leaves the adhesion range,
    so its maximum is just below one of those."""
    best = -voxel_sum(boxes, coef, (x, y, z_rest)).normal[2]
    reach = coef.reach()
    for j in range(int(y) - 6, int(y) + 7):
        for i in range(int(x) - 6, int(x) + 7):
            sx = max(abs(i - x) - 0.5, 0.0)
            sy = max(abs(j - y) - 0.5, 0.0)
            s2 = sx * sx + sy * sy
            if s2 >= reach * reach:
                continue
            z_drop = floor_top + math.sqrt(reach * reach - s2)
            if z_drop < z_rest:
                continue
            best = max(best, -voxel_sum(boxes, coef, (x, y, z_drop - 1e-9)).normal[2])
    return best


def write_voxel_file(path, dims, boxes, spacing=1):
    """A raw lbm-pore voxel file (doc/fluid.md, "Voxel geometry files"), origin 0."""
    nx, ny, nz = dims
    data = bytearray(nx * ny * nz)
    for (i0, i1), (j0, j1), (k0, k1) in boxes:
        for k in range(k0, k1 + 1):
            for j in range(j0, j1 + 1):
                row = (k * ny + j) * nx
                data[row + i0:row + i1 + 1] = b"\x01" * (i1 - i0 + 1)
    with open(path, "wb") as f:
        f.write(f"LBMPORE_VOXELS 1\n{nx} {ny} {nz}\n{spacing} 0 0 0\n".encode())
        f.write(bytes(data))
