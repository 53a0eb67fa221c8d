"""What the first impact hands over: angular momentum about the vertex that lands, shell and pile apart.

For the small hexagon of BBs at its first landing, in the 2D grain model (Box2D, through `import
polyroll`) and in the 3D reference (Yade's grains.csv at 1 kHz, from `polyroll run --model dem3d
--sample-hz 1000` with POLYROLL_DEM3D_WORKDIR kept). Everything in the ramp's frame: x down the slope,
y away from it, angular quantities positive rolling down (clockwise).

The landing vertex B: at the tracker's first impact the face under the shell lies on the ramp, B its
front vertex, c + (s/2, -a) with s the outer side and a the outer apothem. Velocities are central
differences of positions 1 ms apart (the shell's and every grain's); a grain's own spin is left out
(a BB's is 2/5 m r^2 w, under 2% of its share at the pile's radius). Grain masses: the fill's mass shared
in proportion to r^2 (2D discs) or r^3 (3D spheres).

The rigid handover: the shell and the pile turned as one block about B with the angular momentum
about B they had 2 ms before the landing (plus gravity's moment over the 5 ms): what the shell's
angular velocity would be 3 ms after it if the pile took part as a rigid body. The measured one over
that says how much of the rigid block's turn the shell keeps; the pile's share of the angular
momentum says where the rest is.

Usage (Debian's python3):
  PYTHONPATH=build/python python3 docs/studies/first-impact-handover/handover.py 2d OUT.csv   (2D: 20 runs)
  PYTHONPATH=build/python python3 docs/studies/first-impact-handover/handover.py fields OUT.csv FIELD=VALUE...
  PYTHONPATH=build/python python3 docs/studies/first-impact-handover/handover.py scenes OUT.csv SCENE_FILE...
  PYTHONPATH=build/python python3 docs/studies/first-impact-handover/handover.py grid OUT.csv POLYGON FILL A1,A2,.. [FIELD=VALUE...]
  python3 docs/studies/first-impact-handover/handover.py 3d OUT.csv RUN_FOLDER...   (each with out/ and wd/)
"""
import csv
import json
import math
import os
import sys

OFFSETS_MS = (-2, 3, 10, 30, 60)
G = 9.81
T_END_S = 1.2  # sampled as long as the 3D runs (their --time-limit): an octagon at 10 deg lands near 0.5 s


def cross_cw(rx, ry, px, py):
    """z of r x p, positive clockwise (rolling down with x down the slope and y up from it)."""
    return ry * px - rx * py


def handover(times, shell_xy, shell_angle, grains_xy, masses, t_land, shell, angle_deg):
    """times: step times (s, 1 ms apart); shell_xy[k] = (x, y); shell_angle[k] (rad, counterclockwise);
    grains_xy[k] = list of (x, y); masses: per grain (kg). Returns a dict of the readings."""
    dt = times[1] - times[0]
    k_land = min(range(len(times)), key=lambda k: abs(times[k] - t_land))
    n, R, m_s, I_s = shell['sides'], shell['outer_circumradius_m'], shell['mass_kg'], shell['inertia_kg_m2']
    s, a = 2 * R * math.sin(math.pi / n), R * math.cos(math.pi / n)
    cx, cy = shell_xy[k_land]
    bx, by = cx + s / 2, cy - a
    th = math.radians(angle_deg)
    gx, gy = G * math.sin(th), -G * math.cos(th)
    M = sum(masses)

    def at(k):
        w = -(shell_angle[k + 1] - shell_angle[k - 1]) / (2 * dt)
        (x0, y0), (x1, y1), (x, y) = shell_xy[k - 1], shell_xy[k + 1], shell_xy[k]
        vx, vy = (x1 - x0) / (2 * dt), (y1 - y0) / (2 * dt)
        L_shell = I_s * w + m_s * cross_cw(x - bx, y - by, vx, vy)
        L_pile = 0.0
        Px = Py = 0.0
        I_pile = 0.0
        tau = m_s * cross_cw(x - bx, y - by, gx, gy)
        for m, (gx0, gy0), (gx1, gy1), (qx, qy) in zip(masses, grains_xy[k - 1], grains_xy[k + 1], grains_xy[k]):
            ux, uy = (gx1 - gx0) / (2 * dt), (gy1 - gy0) / (2 * dt)
            L_pile += m * cross_cw(qx - bx, qy - by, ux, uy)
            Px += m * ux
            Py += m * uy
            I_pile += m * ((qx - bx) ** 2 + (qy - by) ** 2)
            tau += m * cross_cw(qx - bx, qy - by, gx, gy)
        return {'w': w, 'L_shell': L_shell, 'L_pile': L_pile, 'I_pile_B': I_pile, 'tau': tau,
                'v_pile_ahead': Px / M, 'v_pile_up': Py / M, 'v_shell': (vx, vy)}

    out = {}
    before = at(k_land - 2)
    I_B = I_s + m_s * (s * s / 4 + a * a) + before['I_pile_B']
    L0 = before['L_shell'] + before['L_pile']
    # gravity's moment about B over the 5 ms from -2 to +3 ms
    w_rigid = (L0 + before['tau'] * 0.005) / I_B
    out['w_before'] = before['w']
    out['L_before'] = L0
    out['pile_share_before'] = before['L_pile'] / L0
    out['pile_share_rigid'] = before['I_pile_B'] / I_B  # the pile's share if it turned with the shell
    out['w_rigid_3ms'] = w_rigid
    for ms in OFFSETS_MS[1:]:
        r = at(k_land + round(ms * 1e-3 / dt))
        L = r['L_shell'] + r['L_pile']
        out['w_%dms' % ms] = r['w']
        out['L_%dms' % ms] = L
        out['pile_share_%dms' % ms] = r['L_pile'] / L if L else float('nan')
        out['v_pile_ahead_%dms' % ms] = r['v_pile_ahead']
    out['shell_keeps_of_rigid'] = out['w_3ms'] / w_rigid
    out['L_kept_3ms'] = out['L_3ms'] / (L0 + before['tau'] * 0.005)
    return out


def run_2d(angle, fill, seed, variant, scene_file=None, polygon='hexagon-small'):
    import polyroll
    fields = {'fill.material.grains_per_disc': 1.0} if variant == 'one-disc-per-bb' else None
    if '=' in variant:  # FIELD=VALUE: one scene field moved (the 'fields' mode); several joined by '&'
        fields = {name: float(value) for name, value in (part.split('=') for part in variant.split('&'))}
    closure = variant if variant in ('none', 'pile-disorder') else 'none'
    if scene_file:  # a scene file as it stands (its fill), at this angle and seed
        sim = polyroll.Simulation(scene_file, angle=angle, seed=seed, model='grains', fields=fields)
    else:
        # a variant that sets fill.ratio itself (with the bulk density, to keep the fill's mass) names no fill
        named = {} if fields and 'fill.ratio' in fields else {'fill': fill}
        sim = polyroll.Simulation(polygon=polygon, angle=angle, seed=seed, model='grains', closure=closure,
                                  fields=fields, **named)
    shell = sim.measured()['shell']
    shell['sides'] = sim.measured()['scene']['shell']['sides']
    fill_mass = sim.measured()['results'].get('fill_mass_kg')
    times, sxy, sang, gxy = [], [], [], []
    radii = None
    while sim.time_s < T_END_S and not sim.finished:
        sim.step(1)
        sh, g = sim.shell(), sim.grains()
        times.append(sim.time_s)
        sxy.append((sh['x_m'], sh['y_m']))
        sang.append(sh['angle_rad'])
        gxy.append(list(zip(g['x_m'].tolist(), g['y_m'].tolist())))
        radii = g['radius_m'].tolist()
    impacts = sim.result().impacts
    t_land = float(impacts.time_s[0]) if len(impacts) else None
    summ = sim.run_to_end().summary
    fill_mass = summ['results']['fill_mass_kg']
    w2 = sum(r * r for r in radii)
    masses = [fill_mass * r * r / w2 for r in radii]
    out = handover(times, sxy, sang, gxy, masses, t_land, shell, angle)
    if scene_file:
        fill, variant = summ['scene']['fill']['ratio'], os.path.basename(scene_file)
    out.update(model='grains' if variant == 'none' else 'grains, ' + variant, polygon=summ['scene']['shell']['preset'],
               angle_deg=angle, fill_ratio=fill,
               seed=seed, landing_s=t_land,
               behaviour=summ['results']['behaviour'], faces=summ['results'].get('impacts'))
    return out


def run_3d(folder):
    summ = json.load(open(os.path.join(folder, 'run.json')))
    wd = os.path.join(folder, 'wd')
    setup = json.load(open(os.path.join(wd, 'setup.json')))
    IN = json.load(open(os.path.join(wd, 'IN.json')))
    with open(os.path.join(folder, 'out', 'impacts.csv')) as f:
        t_land = float(next(csv.DictReader(f))['time_s'])
    states = list(csv.DictReader(open(os.path.join(wd, 'states.csv'))))
    rows = {}
    radii = {}
    with open(os.path.join(wd, 'grains.csv')) as f:
        for r in csv.DictReader(f):
            t = round(float(r['time_s']) * 1000)
            rows.setdefault(t, []).append((float(r['x_m']), float(r['y_m'])))
            radii[int(r['grain'])] = float(r['radius_m'])
    st = {round(float(r['time_s']) * 1000): r for r in states}
    keys = sorted(k for k in rows if k in st)
    times = [k / 1000 for k in keys]
    sxy = [(float(st[k]['x_m']), float(st[k]['y_m'])) for k in keys]
    sang = [float(st[k]['angle_rad']) for k in keys]
    gxy = [rows[k] for k in keys]
    order = sorted(radii)
    w3 = sum(radii[i] ** 3 for i in order)
    masses = [setup['fill_mass_kg'] * radii[i] ** 3 / w3 for i in order]
    shell = dict(summ['shell'])
    shell['sides'] = summ['scene']['shell']['sides']
    out = handover(times, sxy, sang, gxy, masses, t_land, shell, IN['angle_deg'])
    out.update(model='dem3d', polygon=summ['scene']['shell']['preset'], angle_deg=IN['angle_deg'], fill_ratio=summ['scene']['fill']['ratio'],
               seed=IN['seed'], landing_s=t_land, behaviour=summ['results']['behaviour'], faces=summ['results'].get('impacts'))
    return out


def main(argv):
    rows = []
    if argv[1] == '2d':
        for fill in (0.25, 0.5):
            for angle in (17, 18, 19):
                for seed in (1, 2):
                    rows.append(run_2d(angle, fill, seed, 'none'))
                    print(rows[-1], flush=True)
        # Two 2D variants at 18 deg: the pile-disorder closure (closure-from-3d.md) and one disc a BB.
        for variant in ('pile-disorder', 'one-disc-per-bb'):
            for fill in (0.25, 0.5):
                for seed in (1, 2):
                    rows.append(run_2d(18, fill, seed, variant))
                    print(rows[-1], flush=True)
    elif argv[1] == 'fields':  # each FIELD=VALUE alone, the half-full and quarter-full hexagon at 18 deg
        for variant in argv[3:]:
            for fill in (0.25, 0.5):
                for seed in (1, 2):
                    rows.append(run_2d(18, fill, seed, variant))
                    print(rows[-1], flush=True)
    elif argv[1] == 'grid':  # grid OUT.csv POLYGON FILL ANGLES [FIELD=VALUE ...]: each variant (none first) at
        # each angle (comma-separated), seeds 1-2
        polygon, fill, angles = argv[3], float(argv[4]), [float(a) for a in argv[5].split(',')]
        for variant in ['none'] + argv[6:]:
            for angle in angles:
                for seed in (1, 2):
                    rows.append(run_2d(angle, fill, seed, variant, polygon=polygon))
                    print(rows[-1], flush=True)
    elif argv[1] == 'scenes':  # each scene file at 18 deg, seeds 1-2
        for scene_file in argv[3:]:
            for seed in (1, 2):
                rows.append(run_2d(18, None, seed, 'none', scene_file))
                print(rows[-1], flush=True)
    else:
        for folder in argv[3:]:
            rows.append(run_3d(folder))
            print(rows[-1], flush=True)
    keys = list(rows[0].keys())
    with open(argv[2], 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)


if __name__ == '__main__':
    main(sys.argv)
