#!/usr/bin/env python3
"""polyroll --model dem3d: the experiment's 3D box simulated grain by grain in Yade.

polyroll runs it with the Python of Yade's launcher, importing Yade as a library from the folder the
launcher names (POLYROLL_YADE_PY), one thread (OMP_NUM_THREADS=1):
    POLYROLL_YADE_PY=/usr/lib/x86_64-linux-gnu/yade-double/py /usr/bin/python3 polyroll_dem3d.py IN.json OUTDIR
so none of the launcher's servers start (its XMLRPC info server listens on every network interface).
Through the launcher it runs as well: yade -j1 -n -x polyroll_dem3d.py IN.json OUTDIR.
IN.json is written by the C++ program (SI units, ramp frame: x down the slope, y along the ramp's
normal, z the roll axis; the shell's angle is counter-clockwise about +z, so rolling down lowers it).
OUTDIR receives states.csv, setup.json and, when frames_hz > 0, grains.csv (each written under a
temporary name, then renamed). stdout carries only `progress <time_s> <x_m>` lines from this script
(Yade may print its own lines first: a reader skips them). Errors: one line on stderr, exit 1; bad input: exit 2.

The model: the shell is ONE rigid clump of facets (inside walls and both lids, what the grains touch)
and small spheres at its outer vertices (what touches the ramp); the ramp is a Yade wall at y = 0.
All contacts are linear spring-dashpots set by a contact time and a restitution (ViscElMat).
Yade is imported inside functions only, so this module imports and lints without Yade.
"""
import json
import math
import os
import random
import sys
import time
from contextlib import nullcontext

EDGE_SPHERES_PER_VERTEX = 3  # along z at each outer vertex; the shell's out-of-plane DOFs are blocked anyway
# Yade turns en = 0 into a zero stiffness (log 0), and a tiny en makes the dashpot too stiff for the
# explicit step: restitutions are floored here (an impact at 0.05 keeps 0.25 % of the normal energy).
MIN_RESTITUTION = 0.05
RAMP_MASS_KG = 1e12  # the wall's mass for the contact's reduced mass: effectively immovable
POUR_GAP = 0.1       # pour lattice spacing = (1 + POUR_GAP) * largest grain diameter
MAX_SOLID_SHARE = 0.64  # random close packing: more solid than this in the inner prism cannot be poured
GROW_SHARE = 0.3     # share of settle_time_s spent growing grains that had to start shrunk (dense fills)
INSIDE_TOL = 0.1     # grains_inside tolerance, in nominal grain radii
PROGRESS_EVERY_S = 0.25
LID_LOAD_EVERY_ROWS = 10  # the lid load's means sample one row in ten (the formula's sum runs over every grain)
INSIDE_EVERY_ROWS = 10  # grains counted inside the shell one row in ten and on the last: a leak is seen 10 ms late at most
MASK_INSIDE, MASK_RAMP = 1, 2  # grains+facets share bit 1; edge spheres+ramp share bit 2
COLOR = (0.6, 0.6, 0.6)        # given explicitly: Yade's random colour reseeds Python's global random


class InputError(Exception):
    pass


# ---------------------------------------------------------------- input

def _field(cfg, path, kind=float, lo=None, hi=None, lo_open=False):
    """Return cfg[path] (dotted path) checked for type and range; InputError names the key."""
    node = cfg
    for part in path.split('.'):
        if not isinstance(node, dict) or part not in node:
            raise InputError('missing key %s' % path)
        node = node[part]
    if kind in (int, float):
        if isinstance(node, bool) or not isinstance(node, (int, float)) or (kind is int and node != int(node)):
            raise InputError('%s must be %s' % (path, 'an integer' if kind is int else 'a number'))
        node = kind(node)
        if not math.isfinite(node) or (lo is not None and (node <= lo if lo_open else node < lo)) \
                or (hi is not None and node > hi):
            raise InputError('%s = %r is out of range' % (path, node))
    elif not isinstance(node, kind):
        raise InputError('%s has the wrong type' % path)
    return node


def _points(cfg, path, count=None):
    """`count` [x, y] number pairs, or one pair when count is None."""
    pts = _field(cfg, path, list)
    pts = [pts] if count is None else pts
    if len(pts) != (count or 1) or not all(isinstance(p, list) and len(p) == 2 and all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in p) for p in pts):
        raise InputError('%s must hold %s' % (path, '[x, y]' if count is None else '%d [x, y] pairs' % count))
    return [(float(p[0]), float(p[1])) for p in pts]


# IN.json key -> (name used here, lowest, highest, lowest excluded); every key is required.
NUMBERS = {
    'gravity_m_s2': ('gravity_m_s2', 0, None, True),
    'angle_deg': ('angle_deg', -89, 89, False),
    'ramp.length_m': ('ramp_length_m', 0, None, True),
    'ramp.curvature_deg_per_m': ('curvature_deg_per_m', -90, 90, False),
    'ramp.friction': ('ramp_friction', 0, None, False),
    'ramp.restitution': ('ramp_restitution', 0, 1, False),
    'shell.inner_depth_m': ('inner_depth_m', 0, None, True),
    'shell.lid_thickness_m': ('lid_thickness_m', 0, None, False),
    'shell.mass_kg': ('mass_kg', 0, None, True),
    'shell.inertia_roll_kg_m2': ('inertia_roll_kg_m2', 0, None, True),
    'shell.inertia_cross_kg_m2': ('inertia_cross_kg_m2', 0, None, True),
    'release.angle_rad': ('angle_rad', None, None, False),
    'release.tip_rad': ('tip_rad', -2 * math.pi, 2 * math.pi, False),
    'release.tilt_deg': ('tilt_deg', -90, 90, False),
    'end_centre_x_m': ('end_centre_x_m', None, None, False),
    'fill.grain_diameter_m': ('grain_diameter_m', 0, None, True),
    'fill.diameter_spread': ('diameter_spread', 0, 0.5, False),
    'fill.grain_density_kg_m3': ('grain_density_kg_m3', 0, None, True),
    'fill.friction': ('grain_friction', 0, None, False),
    'fill.wall_friction': ('wall_friction', 0, None, False),
    'fill.restitution': ('grain_restitution', 0, 1, False),
    'dem3d.contact_time_s': ('contact_time_s', 0, None, True),
    'dem3d.time_step_share': ('time_step_share', 0, 1, True),
    'dem3d.edge_radius_m': ('edge_radius_m', 0, None, True),
    'dem3d.channel_width_m': ('channel_width_m', 0, None, False),
    'step_hz': ('step_hz', 0, None, True),
    'time_limit_s': ('time_limit_s', 0, None, True),
    'settle_time_s': ('settle_time_s', 0, None, False),
    'rest_speed_m_s': ('rest_speed_m_s', 0, None, True),
    'rest_time_s': ('rest_time_s', 0, None, False),
    'frames_hz': ('frames_hz', 0, None, False)}


def load_config(path):
    """Read and validate IN.json into a flat dict of the values the model uses."""
    try:
        with open(path) as f:
            cfg = json.load(f)
    except (OSError, ValueError) as e:
        raise InputError('cannot read %s: %s' % (path, e))
    if not isinstance(cfg, dict):
        raise InputError('%s does not hold a JSON object' % path)
    c = {name: _field(cfg, key, float, lo, hi, lo_open) for key, (name, lo, hi, lo_open) in NUMBERS.items()}
    c['seed'] = _field(cfg, 'seed', int)
    n = c['sides'] = _field(cfg, 'shell.sides', int, 3, 1000)
    c['grain_count'] = _field(cfg, 'fill.grain_count', int, 0, 10 ** 6)
    c['pivot_vertex'] = _field(cfg, 'pivot_vertex', int, 0, n - 1)
    c['outer'] = _points(cfg, 'shell.outer_vertices_m', n)
    c['inner'] = _points(cfg, 'shell.inner_vertices_m', n)
    c['centre'] = _points(cfg, 'release.centre_m')[0]
    c['pose'] = _field(cfg, 'release.pose', str)
    if c['pose'] not in ('vertex', 'face', 'tipped'):
        raise InputError('release.pose must be "vertex", "face" or "tipped"')
    length = c['inner_depth_m'] + 2 * c['lid_thickness_m']
    if 0 < c['channel_width_m'] <= length:
        raise InputError('dem3d.channel_width_m = %r m: no wider than the box (%r m long)' % (c['channel_width_m'], length))
    return c


# ---------------------------------------------------------------- the track's profile

def slope_deg(c, x):
    """The track's local slope x metres down it: it falls by curvature_deg_per_m per metre about the
    chord's angle at the middle (polyroll's ramp_profile.h); the angle itself on a straight track."""
    if c['curvature_deg_per_m'] == 0:
        return c['angle_deg']
    return c['angle_deg'] + c['curvature_deg_per_m'] * (c['ramp_length_m'] / 2 - x)


def gravity_at(c, x):
    """Gravity in the frame of the straight ramp the engine keeps, at the local slope x metres down:
    the track unrolled, as polyroll's 2D engine does."""
    th = math.radians(slope_deg(c, x))
    return (c['gravity_m_s2'] * math.sin(th), -c['gravity_m_s2'] * math.cos(th))


def height(c, x, y):
    """Height of the point x down the track and y above it, relative to the top: gravity's potential
    per unit mass and g."""
    th = math.radians(slope_deg(c, x))
    if c['curvature_deg_per_m'] == 0:
        return -x * math.sin(th) + y * math.cos(th)
    k, top = math.radians(c['curvature_deg_per_m']), math.radians(slope_deg(c, 0.0))
    return -(math.cos(th) - math.cos(top)) / k + y * math.cos(th)


def release_slope_deg(c):
    """The slope under the pivot vertex at release: the pile settles and balances against it."""
    piv = rot(c['outer'][c['pivot_vertex']], c['angle_rad'])
    return slope_deg(c, c['centre'][0] + piv[0])


# ---------------------------------------------------------------- plane geometry (shell frame)

def rot(p, a):
    ca, sa = math.cos(a), math.sin(a)
    return (ca * p[0] - sa * p[1], sa * p[0] + ca * p[1])


def edge_planes(poly):
    """Inward unit normals and offsets of a convex polygon's edges: inside iff n.p + off >= 0."""
    area2 = sum(poly[i - 1][0] * poly[i][1] - poly[i][0] * poly[i - 1][1] for i in range(len(poly)))
    sign = 1.0 if area2 > 0 else -1.0
    planes = []
    for i in range(len(poly)):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % len(poly)]
        ln = math.hypot(x1 - x0, y1 - y0)
        nx, ny = -sign * (y1 - y0) / ln, sign * (x1 - x0) / ln
        planes.append((nx, ny, -(nx * x0 + ny * y0)))
    return planes


def depth_inside(planes, p):
    """Distance from p to the nearest edge (negative outside)."""
    return min(nx * p[0] + ny * p[1] + off for nx, ny, off in planes)


def pour_sites(c, radii, down, rng):
    """Grain centres for the pour, in the shell frame: the lowest len(radii) sites of a randomly offset,
    jittered cubic lattice in the inner prism, no two grains overlapping. Returns (sites, shrink): when the
    loose lattice (spacing (1 + POUR_GAP) * largest diameter) holds too few sites the spacing shrinks and
    the grains start at shrink * radius, to grow while they settle."""
    n = len(radii)
    if n == 0:
        return [], 1.0
    planes, half = edge_planes(c['inner']), c['inner_depth_m'] / 2
    area = 0.5 * abs(sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(c['inner'], c['inner'][1:] + c['inner'][:1])))
    if sum(4 / 3 * math.pi * r ** 3 for r in radii) > MAX_SOLID_SHARE * area * 2 * half:
        raise InputError('fill.grain_count = %d: more solid than random close packing holds in the shell' % n)
    xs, ys = [p[0] for p in c['inner']], [p[1] for p in c['inner']]
    d_max = 2 * max(radii)
    loose = (1 + POUR_GAP) * d_max
    offset = (rng.random(), rng.random(), rng.random())
    s = loose
    while True:
        sites = []
        for i in range(int((max(xs) - min(xs)) / s) + 2):
            x = min(xs) + (i + offset[0]) * s
            for j in range(int((max(ys) - min(ys)) / s) + 2):
                y = min(ys) + (j + offset[1]) * s
                if depth_inside(planes, (x, y)) < s / 2:
                    continue
                for k in range(int(2 * half / s) + 2):
                    z = -half + (k + offset[2]) * s
                    if abs(z) <= half - s / 2:
                        sites.append((-(x * down[0] + y * down[1]), len(sites), (x, y, z)))
        if len(sites) >= n:
            break
        s *= 0.97
        if s < 0.5 * d_max:
            raise RuntimeError('fill.grain_count = %d grains do not fit in the shell' % n)
    sites.sort()
    jitter = 0.999 * s * POUR_GAP / (2 * (1 + POUR_GAP))  # keeps neighbours apart at full (shrunk) size
    return [tuple(v + rng.uniform(-jitter, jitter) for v in p) for _, _, p in sites[:n]], s / loose


# ---------------------------------------------------------------- the Yade scene

def build_scene(c, rng):
    """Materials, engines, ramp, shell clump and grains at the release pose; returns the scene's handles."""
    import yade
    from yade import O, utils
    g, th = c['gravity_m_s2'], math.radians(release_slope_deg(c))
    tc = c['contact_time_s']

    def mat(en, mu, density):
        en = max(en, MIN_RESTITUTION)  # et = en: tangential contacts are damped like normal ones
        return O.materials.append(
            yade.ViscElMat(tc=tc, en=en, et=en, frictionAngle=math.atan(mu), density=density))
    r_edge, k = c['edge_radius_m'], EDGE_SPHERES_PER_VERTEX
    m_grain = mat(c['grain_restitution'], c['grain_friction'], c['grain_density_kg_m3'])
    m_wall = mat(c['grain_restitution'], c['wall_friction'], 0.0)
    # One vertex's edge spheres together weigh the shell: the ramp contact's stiffness refers to its mass.
    m_edge = mat(c['ramp_restitution'], c['ramp_friction'], c['mass_kg'] / k / (4 / 3 * math.pi * r_edge ** 3))
    m_ramp = mat(c['ramp_restitution'], c['ramp_friction'], 0.0)
    # ViscElMat combines friction angles by min, which would give grain-wall pairs the grain's friction:
    # every pair is set explicitly instead (pairs the masks keep apart get the min).
    mu = {(m_grain, m_grain): c['grain_friction'], (m_grain, m_wall): c['wall_friction'],
          (m_edge, m_ramp): c['ramp_friction']}
    ids = [m_grain, m_wall, m_edge, m_ramp]
    matches = [(a, b, math.atan(mu.get((a, b), min(math.tan(O.materials[a].frictionAngle),
                                                     math.tan(O.materials[b].frictionAngle)))))
               for i, a in enumerate(ids) for b in ids[i:]]
    ip2 = yade.Ip2_ViscElMat_ViscElMat_ViscElPhys(frictAngle=yade.MatchMaker(matches=matches, algo='min'))
    collider = yade.InsertionSortCollider([yade.Bo1_Sphere_Aabb(), yade.Bo1_Facet_Aabb(), yade.Bo1_Wall_Aabb()])
    O.engines = [
        yade.ForceResetter(), collider,
        yade.InteractionLoop([yade.Ig2_Sphere_Sphere_ScGeom(), yade.Ig2_Facet_Sphere_ScGeom(),
                              yade.Ig2_Wall_Sphere_ScGeom()], [ip2], [yade.Law2_ScGeom_ViscElPhys_Basic()]),
        yade.NewtonIntegrator(gravity=(g * math.sin(th), -g * math.cos(th), 0.0), damping=0.0)]
    # Output rows fall on whole steps: dt is the largest step <= share * tc that divides 1/step_hz.
    steps_per_row = max(1, math.ceil(1.0 / (c['step_hz'] * c['time_step_share'] * tc)))
    O.dt = 1.0 / (c['step_hz'] * steps_per_row)

    # The ramp: an infinite plane y = 0 (the run ends at end_centre_x_m, before the ramp's real end).
    ramp = O.bodies.append(utils.wall(0.0, axis=1, sense=1, material=m_ramp, mask=MASK_RAMP, color=COLOR))
    O.bodies[ramp].state.mass = RAMP_MASS_KG
    # The track's channel (channel_width_m > 0): its two sides, planes across the roll axis at
    # z = +-width / 2, of the ramp's material (the experiment's channel is covered with the same
    # sandpaper). Only the edge spheres at the box's ends reach them. 0: no sides, and the box is held
    # in its plane instead (release()).
    channel = []
    if c['channel_width_m'] > 0:
        for sense, z in ((1, -c['channel_width_m'] / 2), (-1, c['channel_width_m'] / 2)):
            side = O.bodies.append(utils.wall(z, axis=2, sense=sense, material=m_ramp, mask=MASK_RAMP, color=COLOR))
            O.bodies[side].state.mass = RAMP_MASS_KG
            channel.append(side)

    # The shell, built in the global frame at the release pose.
    a0, c0 = c['angle_rad'], c['centre']

    def world(p, z):
        q = rot(p, a0)
        return (c0[0] + q[0], c0[1] + q[1], z)
    n, half, inner = c['sides'], c['inner_depth_m'] / 2, c['inner']
    tris = []
    for j in range(n):
        p, q = inner[j], inner[(j + 1) % n]
        tris += [(world(p, -half), world(q, -half), world(q, half)),
                 (world(p, -half), world(q, half), world(p, half))]
    for z in (-half, half):
        tris += [(world(inner[0], z), world(inner[j], z), world(inner[j + 1], z)) for j in range(1, n - 1)]
    members = [utils.facet(t, fixed=False, material=m_wall, mask=MASK_INSIDE, color=COLOR) for t in tris]
    n_facets = len(members)
    inset = r_edge / math.cos(math.pi / n)  # the sphere touches both faces meeting at the vertex
    z_edge = c['inner_depth_m'] / 2 + c['lid_thickness_m'] - r_edge
    for v in c['outer']:
        ln = math.hypot(*v)
        p = (v[0] * (1 - inset / ln), v[1] * (1 - inset / ln))
        for i in range(k):
            z = 0.0 if k == 1 else -z_edge + 2 * z_edge * i / (k - 1)
            members.append(utils.sphere(world(p, z), r_edge, material=m_edge, mask=MASK_RAMP, color=COLOR))
    clump, member_ids = O.bodies.appendClumped(members)
    for i in member_ids[:n_facets]:
        O.bodies[i].state.mass = c['mass_kg']  # the grain-wall contact's reduced mass sees the shell
    st = O.bodies[clump].state
    st.mass = c['mass_kg']
    # appendClumped puts the clump's local axes along its principal axes in whatever order: give the
    # roll inertia to the local axis that lies along global z.
    rm = st.ori.toRotationMatrix()
    st.inertia = yade.Vector3(*[c['inertia_roll_kg_m2'] if abs(rm[2, i]) > 0.5 else c['inertia_cross_kg_m2']
                                for i in range(3)])
    st.blockedDOFs = 'xyzXYZ'

    # Grains, at their full size (mass, inertia), possibly shrunk for the pour.
    d, spread = c['grain_diameter_m'], c['diameter_spread']
    radii = [d / 2 * (1 + spread * rng.uniform(-1, 1)) for _ in range(c['grain_count'])]
    down = rot((math.sin(th), -math.cos(th)), -a0)
    sites, shrink = pour_sites(c, radii, down, rng)
    grains = []
    for r, p in zip(radii, sites):
        b = utils.sphere(world(p[:2], p[2]), r, material=m_grain, mask=MASK_INSIDE, color=COLOR)
        b.shape.radius = r * shrink
        grains.append(O.bodies.append(b))
    return {'clump': clump, 'members': member_ids, 'grains': grains, 'radii': radii, 'shrink': shrink,
            'edges': member_ids[n_facets:], 'lids': member_ids[2 * n:n_facets], 'collider': collider,
            'steps_per_row': steps_per_row, 'channel': channel}


def advance(steps):
    """Step synchronously: O.run(n, True) waits by polling and loses ~40 ms of wall time per call."""
    from yade import O
    for _ in range(steps):
        O.step()


def settle(c, sc):
    """Pour: the shell held at the release pose, the grains fall and settle (growing first if shrunk).
    Returns (time used, settled)."""
    from yade import O
    grains, shrink = sc['grains'], sc['shrink']
    if not grains:
        return 0.0, True
    t_grow = GROW_SHARE * c['settle_time_s'] if shrink < 1 else 0.0
    r_in = max(math.hypot(*p) for p in c['inner'])
    t_min = t_grow + math.sqrt(4 * r_in / c['gravity_m_s2'])  # a fall across the shell, at least
    steps, t, mass = sc['steps_per_row'], 0.0, sum(O.bodies[i].state.mass for i in grains)
    settled = False
    while t < c['settle_time_s'] and not settled:
        advance(steps)
        t += steps * O.dt
        if t_grow > 0:
            grow(sc, min(1.0, t / t_grow))
        ke = sum(O.bodies[i].state.mass * O.bodies[i].state.vel.squaredNorm() for i in grains)
        if not math.isfinite(ke):
            raise RuntimeError('the pour blew up (non-finite grain velocity)')
        settled = t >= t_min and ke < mass * c['rest_speed_m_s'] ** 2  # rms grain speed below rest speed
    grow(sc, 1.0)  # full size whatever happened (settle_time_s = 0 leaves no time to grow)
    return t, settled


def grow(sc, share):
    """Grains from their pour size (share 0) to their full size (share 1)."""
    from yade import O
    f = sc['shrink'] + (1 - sc['shrink']) * share
    for i, r in zip(sc['grains'], sc['radii']):
        O.bodies[i].shape.radius = r * f
    sc['collider']()  # the bounds follow the new radii


class LidLoad:
    """The normal force the grains put on the two lids (N, both together), measured from the contacts,
    against what polyroll's 2D lid friction assumes for the same pile (src/sim/grains/lid_friction.cpp):
    each grain m g (2 K h / depth), h its depth below the pile's top along gravity,
    K = 1 - sin(atan(grain friction)). Summed over sampled rows for their means."""

    def __init__(self, c, sc):
        from yade import O
        self.with_body, self.lids = O.interactions.withBody, sc['lids']
        self.grains = [O.bodies[i] for i in sc['grains']]
        self.k = 1 - math.sin(math.atan(c['grain_friction']))
        self.depth = c['inner_depth_m']
        self.sum_measured = self.sum_formula = 0.0
        self.rows = 0

    def measured(self):
        # The lids lie across z: a contact's z-component is its push on the lid.
        return sum(abs(i.phys.normalForce[2]) for f in self.lids for i in self.with_body(f) if i.isReal)

    def formula(self, gravity):
        g = math.sqrt(sum(v * v for v in gravity))
        if g == 0 or not self.grains:
            return 0.0
        up = [-v / g for v in gravity]
        hs = [sum(u * p for u, p in zip(up, b.state.pos)) for b in self.grains]
        top = max(h + b.shape.radius for h, b in zip(hs, self.grains))
        return sum(b.state.mass * g * 2 * self.k * (top - h) / self.depth for h, b in zip(hs, self.grains))

    def now(self, gravity):
        return self.measured(), self.formula(gravity)

    def add_row(self, gravity):
        m, f = self.now(gravity)
        self.sum_measured += m
        self.sum_formula += f
        self.rows += 1

    def means(self):
        return (self.sum_measured / self.rows, self.sum_formula / self.rows) if self.rows else (0.0, 0.0)


def balance_turn(c, sc):
    """The turn (rad, counter-clockwise) about the pivot vertex that puts the combined centre of mass
    tilt_deg past balance downhill, measured against the true vertical, clamped so that neither
    neighbouring face reaches the ramp."""
    from yade import O
    th = math.radians(release_slope_deg(c))
    piv = pivot_point(c)
    bodies = [(c['mass_kg'], O.bodies[sc['clump']].state.pos)] + \
        [(O.bodies[i].state.mass, O.bodies[i].state.pos) for i in sc['grains']]
    m = sum(b[0] for b in bodies)
    v = [sum(b[0] * b[1][k] for b in bodies) / m - piv[k] for k in range(2)]
    up, downhill = (-math.sin(th), math.cos(th)), (math.cos(th), math.sin(th))
    lean = math.atan2(v[0] * downhill[0] + v[1] * downhill[1], v[0] * up[0] + v[1] * up[1])
    step = 2 * math.pi / c['sides']
    turned = (-c['angle_rad']) % step  # rotation from face (0, 1) flat
    delta = lean - math.radians(c['tilt_deg'])  # a counter-clockwise turn lowers the lean
    return min(max(delta, -0.9 * (step - turned)), 0.9 * turned), piv


def move_rigidly(body_ids, pivot, delta, dy):
    """Rotate bodies by delta about the z-line through pivot, then lift them by dy; zero their motion."""
    import yade
    from yade import O
    qz = yade.Quaternion(yade.Vector3(0, 0, 1), delta)
    for i in body_ids:
        st = O.bodies[i].state
        p = rot((st.pos[0] - pivot[0], st.pos[1] - pivot[1]), delta)
        st.pos = yade.Vector3(pivot[0] + p[0], pivot[1] + p[1] + dy, st.pos[2])
        st.ori = qz * st.ori
        st.vel = st.angVel = st.angMom = yade.Vector3(0, 0, 0)


def pivot_point(c):
    """The pivot vertex's position (x, y) in the global frame with the shell at c's pose."""
    piv = rot(c['outer'][c['pivot_vertex']], c['angle_rad'])
    return (piv[0] + c['centre'][0], piv[1] + c['centre'][1])


def tip_onto_vertex(c, everything):
    """The tipped release: shell and settled pile turn together about the pivot vertex from the face
    they were filled on into the vertex pose (tip_rad); c's pose follows them."""
    piv = pivot_point(c)
    move_rigidly(everything, piv, c['tip_rad'], 0.0)
    q = rot((c['centre'][0] - piv[0], c['centre'][1] - piv[1]), c['tip_rad'])
    c['centre'] = (piv[0] + q[0], piv[1] + q[1])
    c['angle_rad'] += c['tip_rad']


def release(c, sc):
    """Tip (tipped release), turn to balance (vertex and tipped), set the shell down on the ramp, zero
    all motion, free the in-plane DOFs. Returns the balance correction (deg) and the shell's angle at t = 0."""
    import yade
    from yade import O
    everything = [sc['clump']] + list(sc['members']) + list(sc['grains'])
    if c['pose'] == 'tipped':
        tip_onto_vertex(c, everything)
    delta, pivot = balance_turn(c, sc) if c['pose'] != 'face' else (0.0, (0.0, 0.0))
    move_rigidly(everything, pivot, delta, 0.0)
    # The edge spheres round the vertices off: close the gap (or overlap) left to the ramp.
    gap = min(O.bodies[i].state.pos[1] - O.bodies[i].shape.radius for i in sc['edges'])
    move_rigidly(everything, (0.0, 0.0), 0.0, -gap)
    sc['collider']()
    # In a channel the box is free in all six directions, kept in the track by the channel's sides;
    # without one it turns and moves only in its plane, as the 2D cross-section does.
    st = O.bodies[sc['clump']].state
    if sc['channel']:
        st.blockedDOFs = ''
    else:
        st.blockedDOFs = 'zXY'
        # With any rotation blocked Yade integrates the body by its spherical rule, which divides each
        # global torque component by the principal moment of the same index, whichever local axis that
        # is (here the roll moment lies on local x, global z's torque would be divided by a cross
        # moment, 27% less for the small hexagon). Turning about global z alone, the box needs the roll
        # moment on every index.
        roll = c['inertia_roll_kg_m2']
        st.inertia = yade.Vector3(roll, roll, roll)
    return math.degrees(delta), c['angle_rad'] + delta


# ---------------------------------------------------------------- the run

class Tracker:
    """Shell pose (unwrapped angle), energies and grains inside, read from the scene at each row.

    A row runs at step_hz (1 kHz) and was a third of a run's time when it walked every grain in Python
    (docs/studies/dem3d-cost.md); it now asks Yade's C++ for the kinetic energy, takes the grains'
    first moments from their positions (the potential energy on a straight track is linear in them),
    and counts the grains inside every INSIDE_EVERY_ROWS rows and on the last row."""

    def __init__(self, c, sc, angle0):
        from yade import O
        self.c = c
        self.g = c['gravity_m_s2']
        self.q0 = O.bodies[sc['clump']].state.ori.conjugate()
        self.angle0, self.turn = angle0, 0.0
        self.planes = edge_planes(c['inner'])
        self.tol = INSIDE_TOL * c['grain_diameter_m'] / 2
        self.pe0 = None
        self.shell = O.bodies[sc['clump']].state
        self.grains = [O.bodies[i].state for i in sc['grains']]  # cached: a lookup per grain per row is slow
        self.masses = [b.mass for b in self.grains]
        self.fill_mass = sum(self.masses)
        self.free = bool(sc['channel'])  # all six directions free (a channel), or only the plane's three
        self.straight = c['curvature_deg_per_m'] == 0
        th = math.radians(c['angle_deg'])
        self.sin_th, self.cos_th = math.sin(th), math.cos(th)
        self.inside, self.rows = len(self.grains), 0

    def roll_since_release(self, q):
        """The turn about the roll axis since t = 0 (rad, in (-pi, pi])."""
        if not self.free:
            return 2 * math.atan2(q[2], q[3])  # a turn about z alone
        # Free in a channel: the direction of the box's own x axis in the ramp's plane, so that a
        # small yaw or tilt does not count as roll.
        import yade
        a = q * yade.Vector3(1, 0, 0)
        return math.atan2(a[1], a[0])

    def count_inside(self, x, y, angle, positions):
        half = self.c['inner_depth_m'] / 2 + self.tol
        return sum(1 for p in positions if abs(p[2]) <= half and
                   depth_inside(self.planes, rot((p[0] - x, p[1] - y), -angle)) >= -self.tol)

    def count_now(self, row):
        """The grains inside now, counted whatever the row (the run's last row); row: this row's values."""
        self.inside = self.count_inside(row[0], row[1], row[2], [b.pos for b in self.grains])
        return self.inside

    def row(self):
        """The row's values: the shell's pose and motion, the energies, the fill's centre, the grains inside."""
        from yade import utils
        c, st = self.c, self.shell
        q = st.ori * self.q0  # rotation since t = 0
        rel = self.roll_since_release(q)
        self.turn += (rel - self.turn + math.pi) % (2 * math.pi) - math.pi  # unwrap
        angle = self.angle0 + self.turn
        x, y, vx, vy, w = st.pos[0], st.pos[1], st.vel[0], st.vel[1], st.angVel[2]
        # Every dynamic body's 1/2 (m v^2 + w.I w): the shell's clump (its blocked directions do not
        # move) and the grains; the clump's members and the fixed walls are not dynamic bodies.
        ke = utils.kineticEnergy()
        positions = [b.pos for b in self.grains]
        xs, ys = [p[0] for p in positions], [p[1] for p in positions]
        mx, my = math.fsum(map(float.__mul__, self.masses, xs)), math.fsum(map(float.__mul__, self.masses, ys))
        g, m_shell = self.g, c['mass_kg']
        if self.straight:  # height = -x sin(theta) + y cos(theta): linear, so summed over the moments
            pe = g * ((m_shell * -x + -mx) * self.sin_th + (m_shell * y + my) * self.cos_th)
        else:
            pe = g * (m_shell * height(c, x, y) + math.fsum(m * height(c, px, py)
                                                            for m, px, py in zip(self.masses, xs, ys)))
        if self.rows % INSIDE_EVERY_ROWS == 0:
            self.inside = self.count_inside(x, y, angle, positions)
        self.rows += 1
        if self.pe0 is None:
            self.pe0 = pe
        vals = (x, y, angle, vx, vy, w, ke, pe - self.pe0)
        if not all(math.isfinite(v) for v in vals):
            raise RuntimeError('the simulation blew up (non-finite shell state)')
        # The fill's centre of mass from the shell's centre, down the ramp and away from it (0, 0 empty).
        fill = (mx / self.fill_mass - x, my / self.fill_mass - y) if self.fill_mass > 0 else (0.0, 0.0)
        return vals + fill + (self.inside,)


class ChannelLog:
    """How the box moved in the track's channel: its largest offset across the track, yaw and tilt,
    and how often and how hard its ends touched the channel's sides (one reading a row)."""

    def __init__(self, sc):
        from yade import O
        self.sides, self.shell = sc['channel'], O.bodies[sc['clump']].state
        self.z0, self.q0 = self.shell.pos[2], self.shell.ori.conjugate()
        self.rows = self.touching = 0
        self.max_offset = self.max_yaw = self.max_tilt = self.max_force = 0.0
        self.impulse = 0.0  # sum of the sides' normal force over the rows, times the row's time

    def add_row(self, dt_row):
        import yade
        from yade import O
        st = self.shell
        self.rows += 1
        self.max_offset = max(self.max_offset, abs(st.pos[2] - self.z0))
        # The box's roll axis (its own z) against the track's: yaw is its turn about the ramp's normal
        # (y), tilt about the direction down the ramp (x).
        axis = (st.ori * self.q0) * yade.Vector3(0, 0, 1)
        self.max_yaw = max(self.max_yaw, abs(math.degrees(math.atan2(axis[0], axis[2]))))
        self.max_tilt = max(self.max_tilt, abs(math.degrees(math.atan2(axis[1], axis[2]))))
        force = sum(abs(i.phys.normalForce[2]) for s in self.sides for i in O.interactions.withBody(s) if i.isReal)
        if force > 0:
            self.touching += 1
        self.max_force = max(self.max_force, force)
        self.impulse += force * dt_row

    def summary(self):
        return {'rows': self.rows, 'rows_touching': self.touching, 'max_offset_m': self.max_offset,
                'max_yaw_deg': self.max_yaw, 'max_tilt_deg': self.max_tilt,
                'max_side_force_N': self.max_force, 'side_impulse_N_s': self.impulse}


def simulate(c, sc, angle0, states, frames, lids, channel=None):
    """Step from the release to the end, writing one row per 1/step_hz; returns how the run ended.
    lids (LidLoad) adds the lid load of every LID_LOAD_EVERY_ROWS-th row to its means."""
    import yade
    from yade import O
    tr, steps = Tracker(c, sc, angle0), sc['steps_per_row']
    curved, newton = c['curvature_deg_per_m'] != 0, O.engines[-1]
    r_out = max(math.hypot(*p) for p in c['outer'])
    k, rest_since, next_frame, next_progress, x0 = 0, None, 0.0, 0.0, None
    while True:
        t = k / c['step_hz']
        row = tr.row()
        speed = math.hypot(row[3], row[4])
        if speed < c['rest_speed_m_s'] and abs(row[5]) * r_out < c['rest_speed_m_s']:
            rest_since = t if rest_since is None else rest_since
        else:
            rest_since = None
        end = None
        if row[0] > c['end_centre_x_m']:
            end = 'rolled_to_end'
        elif rest_since is not None and t - rest_since >= c['rest_time_s'] - 1e-9:
            end = 'rest'
        elif t >= c['time_limit_s'] - 1e-9:
            end = 'time_limit'
        if end:
            row = row[:-1] + (tr.count_now(row),)  # the last row's count is always fresh
        if k % LID_LOAD_EVERY_ROWS == 0:
            lids.add_row(newton.gravity)
        if channel:
            channel.add_row(1.0 / c['step_hz'])
        states.write(','.join(map(repr, (t,) + row)) + '\n')
        if x0 is None:
            x0 = row[0]
        if frames and t >= next_frame - 1e-9:
            frames.writelines('%r,%d,%r,%r,%r,%r\n' % ((t, j) + tuple(b.state.pos) + (b.shape.radius,))
                              for j, b in enumerate(O.bodies[i] for i in sc['grains']))
            next_frame += 1.0 / c['frames_hz']
        if t >= next_progress - 1e-9:
            print('progress %r %r' % (t, row[0] - x0), flush=True)
            next_progress += PROGRESS_EVERY_S
        if end:
            return end
        if curved:
            # A curved track: gravity turned to the slope under the shell, once a row (1/step_hz), a
            # few hundredths of a degree between turns.
            newton.gravity = yade.Vector3(*gravity_at(c, row[0]), 0.0)
        advance(steps)
        k += 1


class AtomicFile:
    """A file written under a temporary name in its folder: renamed into place if the block succeeds,
    removed if it raises."""

    def __init__(self, path):
        self.path, self.tmp = path, '%s.tmp-%d' % (path, os.getpid())

    def __enter__(self):
        self.f = open(self.tmp, 'w')
        return self.f

    def __exit__(self, kind, *_):
        self.f.close()
        if kind is None:
            os.replace(self.tmp, self.path)
        else:
            os.remove(self.tmp)


def run(in_path, out_dir):
    c = load_config(in_path)
    os.makedirs(out_dir, exist_ok=True)
    import yade.config
    from yade import O
    sc = build_scene(c, random.Random(c['seed']))  # private generator: Yade reseeds the global one
    settle_time, settled = settle(c, sc)
    lids = LidLoad(c, sc)
    poured = lids.now(O.engines[-1].gravity)  # the pile at rest in the held shell, before the release
    correction_deg, angle0 = release(c, sc)
    with AtomicFile(os.path.join(out_dir, 'states.csv')) as states, \
            (AtomicFile(os.path.join(out_dir, 'grains.csv')) if c['frames_hz'] > 0 else nullcontext()) as frames:
        states.write('time_s,x_m,y_m,angle_rad,vx_m_s,vy_m_s,omega_rad_s,kinetic_J,potential_J,'
                     'fill_ahead_m,fill_up_m,grains_inside\n')
        if frames:
            frames.write('time_s,grain,x_m,y_m,z_m,radius_m\n')
        channel = ChannelLog(sc) if sc['channel'] else None
        end = simulate(c, sc, angle0, states, frames, lids, channel)
    (run_mean, run_mean_formula), (end_load, end_formula) = lids.means(), lids.now(O.engines[-1].gravity)
    setup = {'grains': len(sc['grains']), 'fill_mass_kg': sum(O.bodies[i].state.mass for i in sc['grains']),
             'settle_time_s': settle_time, 'settled': settled, 'balance_correction_deg': correction_deg,
             'time_step_s': O.dt, 'yade_version': str(yade.config.version),
             'cpu_time_s': time.process_time(), 'end': end,
             # Normal force of the grains on both lids (N): measured from the contacts, and what the 2D
             # lid friction's formula gives for the same pile; after the pour, over the run, at its end.
             'lid_load_N': {'poured': poured[0], 'poured_formula': poured[1],
                            'run_mean': run_mean, 'run_mean_formula': run_mean_formula,
                            'end': end_load, 'end_formula': end_formula}}
    if channel:
        setup['channel'] = channel.summary()
    with AtomicFile(os.path.join(out_dir, 'setup.json')) as f:
        f.write(json.dumps(setup, indent=2) + '\n')


def main(argv):
    if len(argv) != 3:
        sys.stderr.write('usage: POLYROLL_YADE_PY=DIR python3 %s IN.json OUTDIR\n' % os.path.basename(argv[0]))
        return 2
    if os.environ.get('POLYROLL_YADE_PY'):
        sys.path.insert(0, os.environ['POLYROLL_YADE_PY'])
    try:
        run(argv[1], argv[2])
    except InputError as e:
        sys.stderr.write('dem3d input: %s\n' % e)
        return 2
    except Exception as e:  # one line for the caller, whatever went wrong
        sys.stderr.write('dem3d: %s\n' % (' '.join(str(e).split()) or type(e).__name__))
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
