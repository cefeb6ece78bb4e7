#!/usr/bin/env python3
"""Helpers of in.dimers.lammps (trapdem's clump benchmark, bench/clumps.cpp --shape dimer, in LAMMPS).

  dimer_bed.py sites W DEPTH HEIGHT R SEED OUT
      Writes OUT, a LAMMPS include file of one "create_atoms 0 single x y z mol dimer 1 rotate
      theta Rx Ry Rz units box" per dimer: clumps.cpp's lattice (lattice_sites: spacing 2.1 x the
      reach 1.5 R, sites (i + 1/2) spacing with x + spacing/2 <= W, y + spacing/2 <= DEPTH,
      z < 0.9 HEIGHT, z outermost, x innermost) and its orientations: per site three draws u1, u2,
      u3 of std::uniform_real_distribution<double>(0, 1) on std::mt19937_64(SEED) (SEED 2026 is
      clumps.cpp's), turned into a quaternion by trapdem's uniform_orientation (Shoemake's uniform
      rotation). The dimer of dimer.mol lies along x, as trapdem's template (its least moment
      first), so the members land where trapdem puts them (up to the template's radius: trapdem
      integrates the union on a grid, r 8e-6 smaller than the exact one, see in.dimers.lammps).

  dimer_bed.py infile DUMP OUT MASS I_AXIAL I_PERP
      Writes OUT, fix rigid/small's infile: "N", then per body "mol mass xcm ycm zcm ixx iyy izz
      ixy ixz iyz vx vy vz lx ly lz ix iy iz" (the fix rigid doc's format) with the union's mass
      and inertia, not the sums over the two overlapping spheres LAMMPS would compute. DUMP is a
      write_dump custom file with the columns id mol x y z (two atoms per molecule). The inertia
      tensor of an axisymmetric body with unit axis u is I_perp 1 + (I_axial - I_perp) u u^T; its
      off-diagonal entries are the tensor's (-sum m x y), the sign of LAMMPS's own sum. The bodies
      start at rest with image flags 0.
"""
import math
import sys
from collections import defaultdict

MASK64 = (1 << 64) - 1


class MT19937_64:
    """std::mt19937_64 (the C++ standard's parameters)."""

    def __init__(self, seed):
        self.mt = [seed & MASK64]
        for i in range(1, 312):
            prev = self.mt[-1]
            self.mt.append((6364136223846793005 * (prev ^ (prev >> 62)) + i) & MASK64)
        self.index = 312

    def _twist(self):
        mt = self.mt
        for i in range(312):
            x = (mt[i] & 0xFFFFFFFF80000000) | (mt[(i + 1) % 312] & 0x7FFFFFFF)
            xa = x >> 1
            if x & 1:
                xa ^= 0xB5026F5AA96619E9
            mt[i] = mt[(i + 156) % 312] ^ xa
        self.index = 0

    def __call__(self):
        if self.index >= 312:
            self._twist()
        y = self.mt[self.index]
        self.index += 1
        y ^= (y >> 29) & 0x5555555555555555
        y ^= (y << 17) & 0x71D67FFFEDA60000
        y ^= (y << 37) & 0xFFF7EEE000000000
        y ^= y >> 43
        return y & MASK64


def unit(rng):
    """libstdc++'s uniform_real_distribution<double>(0, 1) on a 64-bit engine: one draw / 2^64."""
    u = float(rng()) / 18446744073709551616.0
    return u if u < 1.0 else math.nextafter(1.0, 0.0)


def uniform_orientation(u1, u2, u3):
    """trapdem's (src/dem/rigid/quaternion.hpp): (w, x, y, z)."""
    a, b = math.sqrt(1.0 - u1), math.sqrt(u1)
    return (b * math.cos(2 * math.pi * u3), a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2),
            b * math.sin(2 * math.pi * u3))


def lattice_sites(width, depth, height, spacing):
    """clumps.cpp's lattice_sites, with its accumulated additions."""
    sites = []
    z = 0.5 * spacing
    while z < 0.9 * height:
        y = 0.5 * spacing
        while y + 0.5 * spacing <= depth:
            x = 0.5 * spacing
            while x + 0.5 * spacing <= width:
                sites.append((x, y, z))
                x += spacing
            y += spacing
        z += spacing
    return sites


def sites(width, depth, height, r, seed, out):
    rng = MT19937_64(seed)
    spacing = 2.1 * 1.5 * r
    lines = []
    for x, y, z in lattice_sites(width, depth, height, spacing):
        u1, u2, u3 = unit(rng), unit(rng), unit(rng)
        w, qx, qy, qz = uniform_orientation(u1, u2, u3)
        if w < 0:  # the same rotation, with an angle in [0, 180] degrees
            w, qx, qy, qz = -w, -qx, -qy, -qz
        s = math.sqrt(qx * qx + qy * qy + qz * qz)
        theta = math.degrees(2.0 * math.atan2(s, w))
        axis = (qx / s, qy / s, qz / s) if s > 0 else (1.0, 0.0, 0.0)
        lines.append(f"create_atoms 0 single {x:.17g} {y:.17g} {z:.17g} mol dimer 1 rotate {theta:.17g} "
                     f"{axis[0]:.17g} {axis[1]:.17g} {axis[2]:.17g} units box")
    with open(out, "w") as f:
        f.write(f"# {len(lines)} dimers: clumps.cpp's lattice (spacing {spacing:.17g} m) and orientations "
                f"(mt19937_64 seed {seed})\n")
        f.write("\n".join(lines) + "\n")


def infile(dump, out, mass, i_axial, i_perp):
    lines = open(dump).read().splitlines()
    head = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[head].split()[2:]
    ci, cm, cx, cy, cz = (cols.index(c) for c in ("id", "mol", "x", "y", "z"))
    atoms = defaultdict(list)
    for l in lines[head + 1:]:
        f = l.split()
        if len(f) == len(cols):
            atoms[int(f[cm])].append((int(f[ci]), float(f[cx]), float(f[cy]), float(f[cz])))
    rows = []
    for mol in sorted(atoms):
        a = sorted(atoms[mol])
        if len(a) != 2:
            sys.exit(f"dimer_bed.py: molecule {mol} has {len(a)} atoms, expected 2")
        p, q = a[0][1:], a[1][1:]
        com = [(p[k] + q[k]) / 2 for k in range(3)]
        d = [q[k] - p[k] for k in range(3)]
        n = math.sqrt(sum(c * c for c in d))
        u = [c / n for c in d]
        t = lambda i, j: (i_perp if i == j else 0.0) + (i_axial - i_perp) * u[i] * u[j]
        vals = [mass, *com, t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(0, 2), t(1, 2)] + [0.0] * 6
        rows.append(f"{mol} " + " ".join(f"{v:.17g}" for v in vals) + " 0 0 0")
    with open(out, "w") as f:
        f.write(f"# fix rigid/small infile: {len(rows)} dimers, union mass {mass:g} kg, "
                f"moments {i_axial:g} (axis), {i_perp:g} (across) kg m^2\n{len(rows)}\n")
        f.write("\n".join(rows) + "\n")


def main(argv):
    if len(argv) == 8 and argv[1] == "sites":
        sites(*(float(a) for a in argv[2:6]), int(argv[6]), argv[7])
    elif len(argv) == 7 and argv[1] == "infile":
        infile(argv[2], argv[3], *(float(a) for a in argv[4:7]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
