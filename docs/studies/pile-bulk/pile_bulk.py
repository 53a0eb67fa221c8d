"""How high the settled pile stands in the 3D box and in the 2D model, at the release.

For each 3D run folder (`polyroll run --model dem3d ... --sample-hz 1000` with POLYROLL_DEM3D_WORKDIR=RUN/wd,
its JSON summary in RUN/run.json) and each 2D scene (`import polyroll`, the same polygon, fill, angle and
seed): the grains at t = 0 in the shell's frame, the pile's level along the pour's "up" (the ramp's
normal tilted by the slope, turned into the shell's frame at the pose the grains were poured in), and

  bulk_share_of_com  the share of the inside (area in 2D, volume in 3D) below the level of a pile of
               uniform density whose centre of mass stands as high as the measured pile's: how high
               the pile stands, robust to a rough top (the number the closure uses);
  bulk_share   the share below the mean height of the top twelfth of the grains' centres plus a mean
               radius (biased upwards where the top is rough: a 3D top ten grains deep has its peaks);
  solid        the solid fraction below that level minus 3 grain diameters (spheres: volume over the
               bulk volume; discs: area over the bulk area), the grains counted by their centres;
  com_across_mm, level_pile_across_mm
               how far downhill (across the pour's "up") the pile's centre of mass lies, and where a
               level pile's with the same height of centre of mass would;
  surface_tilt_deg
               a line through the highest grain of each grain-wide column (noisy in 3D).

The 3D box's grain count is r x inside volume x 0.60 (materials.json's packing_fraction) over a
grain's volume; the 2D plan fills exactly r of the inside area. So the 3D over the 2D bulk_share_of_com,
scene by scene, is how much higher the 3D pile stands at the same fill mass: the value
closure.bulk_factor stands for (docs/studies/pile-bulk.md).

Usage (Debian's python3):
  PYTHONPATH=build/python python3 docs/studies/pile-bulk/pile_bulk.py OUT.csv RUN_FOLDER...
"""
import csv
import json
import math
import os
import sys


def rot(x, y, a):
    return x * math.cos(a) - y * math.sin(a), x * math.sin(a) + y * math.cos(a)


def clipped(poly, up, level):
    """The polygon's part with dot(p, up) <= level."""
    out = []
    for i in range(len(poly)):
        p, q = poly[i], poly[(i + 1) % len(poly)]
        hp, hq = p[0] * up[0] + p[1] * up[1] - level, q[0] * up[0] + q[1] * up[1] - level
        if hp <= 0:
            out.append(p)
        if (hp < 0) != (hq < 0) and hp != hq:
            t = hp / (hp - hq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def area_below(poly, up, level):
    """Area of the polygon's part with dot(p, up) <= level."""
    pts = clipped(poly, up, level)
    return abs(sum(pts[i][0] * pts[(i + 1) % len(pts)][1] - pts[(i + 1) % len(pts)][0] * pts[i][1]
                   for i in range(len(pts)))) / 2


def centroid_below(poly, up, level):
    """Centroid (x, y) of the polygon's part with dot(p, up) <= level."""
    pts = clipped(poly, up, level)
    a = cx = cy = 0.0
    for i in range(len(pts)):
        (x0, y0), (x1, y1) = pts[i], pts[(i + 1) % len(pts)]
        c = x0 * y1 - x1 * y0
        a += c
        cx += (x0 + x1) * c
        cy += (y0 + y1) * c
    return cx / (3 * a), cy / (3 * a)


def centroid_height(poly, up, level):
    """Height along up of the centroid of the part below level."""
    cx, cy = centroid_below(poly, up, level)
    return cx * up[0] + cy * up[1]


def centroid_across(poly, up, level):
    """Position across up (along (up_y, -up_x), downhill for a pile poured on the ramp) of the centroid
    of the part below level."""
    cx, cy = centroid_below(poly, up, level)
    return cx * up[1] - cy * up[0]


def level_of_com(poly, up, com_height):
    """The level of a pile of uniform density whose centre of mass stands at com_height (bisection: the
    centroid rises with the level)."""
    hs = [p[0] * up[0] + p[1] * up[1] for p in poly]
    lo, hi = min(hs) + 1e-9, max(hs)
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if centroid_height(poly, up, mid) < com_height else (lo, mid)
    return (lo + hi) / 2


def measure(pts, radii, poly, up, depth):
    """depth: the box's inside depth (spheres), or None (discs)."""
    h = [p[0] * up[0] + p[1] * up[1] for p in pts]
    r_mean = sum(radii) / len(radii)
    top = sorted(h)[-max(3, len(h) // 12):]
    level = sum(top) / len(top) + r_mean
    deep = level - 3 * 2 * r_mean
    if depth:
        solid = sum(4 / 3 * math.pi * r ** 3 for hh, r in zip(h, radii) if hh <= deep)
        bulk = area_below(poly, up, deep) * depth
    else:
        solid = sum(math.pi * r * r for hh, r in zip(h, radii) if hh <= deep)
        bulk = area_below(poly, up, deep)
    com = [sum(p[k] * (r ** (3 if depth else 2)) for p, r in zip(pts, radii)) /
           sum(r ** (3 if depth else 2) for r in radii) for k in (0, 1)]
    # The free surface's tilt: a straight line through the highest grain of each grain-wide column
    # across the pile (least squares; positive: higher downhill), the outermost columns left out (they
    # hold a grain or two against the walls).
    across = [p[0] * up[1] - p[1] * up[0] for p in pts]
    cols = {}
    for a, hh in zip(across, h):
        k = math.floor(a / (2 * r_mean))
        cols[k] = max(cols.get(k, -1.0), hh)
    ks = sorted(cols)[1:-1]
    tilt = float('nan')
    if len(ks) >= 3:
        xs, ys = [(k + 0.5) * 2 * r_mean for k in ks], [cols[k] for k in ks]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        tilt = math.degrees(math.atan(sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)))
    com_h = com[0] * up[0] + com[1] * up[1]
    equal = level_of_com(poly, up, com_h)
    return {'bulk_share': area_below(poly, up, level) / area_below(poly, up, 1.0), 'solid': solid / bulk if bulk else float('nan'),
            'bulk_share_of_com': area_below(poly, up, equal) / area_below(poly, up, 1.0),
            # how far downhill the pile's centre of mass lies, against a pile of uniform density with a
            # level top at the same height of centre of mass (negative: the pile holds a slope uphill)
            'com_across_mm': (com[0] * up[1] - com[1] * up[0]) * 1e3, 'surface_tilt_deg': tilt,
            'level_pile_across_mm': centroid_across(poly, up, equal) * 1e3,
            'pile_com_x_mm': com[0] * 1e3, 'pile_com_y_mm': com[1] * 1e3, 'grains': len(pts)}


def run_3d(folder):
    summ = json.load(open(os.path.join(folder, 'run.json')))
    wd = os.path.join(folder, 'wd')
    IN = json.load(open(os.path.join(wd, 'IN.json')))
    th, a0 = math.radians(IN['angle_deg']), IN['release']['angle_rad']
    up = rot(-math.sin(th), math.cos(th), -a0)  # the pour's up, in the shell's frame at the pour's pose
    st = next(csv.DictReader(open(os.path.join(wd, 'states.csv'))))
    cx, cy, ang = float(st['x_m']), float(st['y_m']), float(st['angle_rad'])
    pts, radii = [], []
    for r in csv.DictReader(open(os.path.join(wd, 'grains.csv'))):
        if r['time_s'] != st['time_s']:
            break
        pts.append(rot(float(r['x_m']) - cx, float(r['y_m']) - cy, -ang))
        radii.append(float(r['radius_m']))
    out = measure(pts, radii, [tuple(v) for v in IN['shell']['inner_vertices_m']], up, IN['shell']['inner_depth_m'])
    out.update(model='dem3d', polygon=summ['scene']['shell']['preset'], fill_ratio=summ['scene']['fill']['ratio'],
               angle_deg=IN['angle_deg'], seed=IN['seed'], inner=IN['shell']['inner_vertices_m'])
    return out


def run_2d(polygon, fill, angle, seed, inner, fields=None):
    import polyroll
    sim = polyroll.Simulation(polygon=polygon, fill=fill, angle=angle, seed=seed, model='grains', fields=fields)
    sh, g = sim.shell(), sim.grains()
    a0 = sh['angle_rad'] - math.radians(sim.measured()['results']['release_balance_correction_deg'])
    th = math.radians(angle)
    up = rot(-math.sin(th), math.cos(th), -a0)
    pts = [rot(x - sh['x_m'], y - sh['y_m'], -sh['angle_rad']) for x, y in zip(g['x_m'].tolist(), g['y_m'].tolist())]
    out = measure(pts, g['radius_m'].tolist(), [tuple(v) for v in inner], up, None)
    out.update(model='grains' + (', ' + ' '.join('%s=%g' % kv for kv in fields.items()) if fields else ''),
               polygon=polygon, fill_ratio=fill, angle_deg=angle, seed=seed)
    return out


def main(argv):
    rows = []
    for folder in argv[2:]:
        d3 = run_3d(folder)
        inner = d3.pop('inner')
        rows.append(d3)
        rows.append(run_2d(d3['polygon'], d3['fill_ratio'], d3['angle_deg'], d3['seed'], inner))
        for r in rows[-2:]:
            print('%-8s %-14s r %.3f %5.1f deg s%d: bulk share of CoM %.3f (x %.2f of r), of the top %.3f (x %.2f of r), solid %.3f, pile CoM %.2f, %.2f mm, %d grains; downhill %.2f mm, a level pile %.2f; surface tilt %.1f deg' % (
                r['model'], r['polygon'], r['fill_ratio'], r['angle_deg'], r['seed'], r['bulk_share_of_com'],
                r['bulk_share_of_com'] / r['fill_ratio'], r['bulk_share'],
                r['bulk_share'] / r['fill_ratio'], r['solid'], r['pile_com_x_mm'], r['pile_com_y_mm'], r['grains'], r['com_across_mm'], r['level_pile_across_mm'], r['surface_tilt_deg']), flush=True)
    keys = ['model', 'polygon', 'fill_ratio', 'angle_deg', 'seed', 'grains', 'bulk_share_of_com', 'bulk_share', 'solid', 'pile_com_x_mm', 'pile_com_y_mm', 'com_across_mm', 'level_pile_across_mm', 'surface_tilt_deg']
    with open(argv[1], 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction='ignore')
        w.writeheader()
        w.writerows({k: ('%.5g' % v if isinstance(v, float) else v) for k, v in r.items()} for r in rows)


if __name__ == '__main__':
    main(sys.argv)
