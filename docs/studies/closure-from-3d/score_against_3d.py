#!/usr/bin/env python3
"""How far a model's thresholds are from the 3D reference's, from the scorecard of
`polyroll validate --observations assets/reference-3d.json [--half H] --out DIR`:

    python3 docs/studies/closure-from-3d/score_against_3d.py DIR [DIR ...]
    python3 docs/studies/closure-from-3d/score_against_3d.py --calibration CAL_DIR REFERENCE.json

The second form reads a `polyroll calibrate` folder's results.csv and gives the same table for each
candidate value it ran (the thresholds read from its runs by the same rule), against REFERENCE.json.

For each scene: the 3D first-impact threshold (the last angle where both seeds stop at the first
impact) and the model's, the 3D sustained-rolling threshold (the first angle where both roll to the
end) and the model's, their differences (model minus 3D), and whether the model's terminal velocity
and distance lie inside the 3D seeds' spread. Then the mean and the worst of the absolute differences
over the scenes, for each threshold: the closure study's bar is 0.5 deg on average and 1 deg at worst.
A band the model never shows at the simulated angles counts as the simulated angles' far end.
"""
import json
import os
import sys


def band_end(score, which):
    band = score.get('details', {}).get('band_deg')
    return None if not band else band[which]


def summarise(folder):
    with open(os.path.join(folder, 'scorecard.json')) as f:
        card = json.load(f)
    scenes = {}
    for s in card['observations']:
        sid, kind = s['id'].rsplit('-', 1)
        if kind == 'impact':  # "-first-impact"
            sid, kind = s['id'][:-len('-first-impact')], 'first'
        e = scenes.setdefault(sid, {})
        if kind == 'first':
            e['t1_3d'] = s['experiment']['angle_range_deg'][1]
            e['t1'] = band_end(s, 1)
            angles = [a['angle_deg'] for a in s['details']['per_angle']]
            e['lo'], e['hi'] = min(angles), max(angles)
        elif kind == 'rolls':
            e['t2_3d'] = s['experiment']['angle_range_deg'][0]
            e['t2'] = band_end(s, 0)
        else:  # vt, d: the measured number's check
            for c in s['checks']:
                if c['check'] in ('terminal velocity', 'distance'):
                    e[kind] = (c['agree'], c.get('simulation', ''), c.get('experiment', ''))
    return scenes


def scene_key(shell, fill, material, ramp):
    return (shell, float(fill), material, ramp)


def reference_scenes(path):
    """{scene key: (id, 3D first-impact threshold, 3D rolling threshold)} of a reference file."""
    with open(path) as f:
        doc = json.load(f)
    out = {}
    for ob in doc['observations']:
        if 'angle_range_deg' not in ob:
            continue
        sc = ob['scene']
        key = scene_key(sc['shell']['preset'], sc['fill']['ratio'], sc['fill'].get('material', 'bb'),
                        sc.get('ramp', {}).get('preset', 'air-track'))
        sid, t = ob['id'].rsplit('-first-impact', 1)[0].rsplit('-rolls', 1)[0], ob['angle_range_deg']
        e = out.setdefault(key, [sid, None, None])
        if ob['id'].endswith('-first-impact'):
            e[1] = t[1]
        else:
            e[2] = t[0]
    return out


def calibration_tables(folder, reference):
    import csv
    import collections
    ref = reference_scenes(reference)
    with open(os.path.join(folder, 'results.csv')) as f:
        rows = list(csv.DictReader(f))
    params = [c for c in rows[0] if c.startswith(('closure.', 'fill.material.'))]
    runs = collections.defaultdict(lambda: collections.defaultdict(list))
    for r in rows:
        if r['status'] != 'ok':
            continue
        value = tuple(r[p] for p in params)
        key = scene_key(r['polygon'], r['fill_ratio'], r['material'], r['ramp'])
        runs[(value, key)][float(r['angle_deg'])].append(r['behaviour'])
    for value in sorted({v for v, _ in runs}):
        print('## %s = %s\n' % (', '.join(params), ', '.join(value)))
        print('| scene | first impact 3D | model | diff | rolling 3D | model | diff |')
        print('| --- | --- | --- | --- | --- | --- | --- |')
        d1, d2 = [], []
        for key, (sid, t1_3d, t2_3d) in ref.items():
            at = runs.get((value, key))
            if not at:
                continue
            most = lambda a, b: 2 * sum(1 for x in at[a] if x == b) > len(at[a])
            angles = sorted(at)
            fi = [a for a in angles if most(a, 'stopped_at_first_impact')]
            roll = [a for a in angles if most(a, 'rolled_to_end')]
            t1 = max(fi) if fi else angles[0] - 0.5
            t2 = min(roll) if roll else angles[-1] + 0.5
            d1.append(abs(t1 - t1_3d))
            d2.append(abs(t2 - t2_3d))
            print('| %s | %g | %g | %+g | %g | %g | %+g |' % (sid, t1_3d, t1, t1 - t1_3d, t2_3d, t2, t2 - t2_3d))
        if d1:
            print('\nfirst impact: mean |diff| %.2f deg, worst %.2f; sustained rolling: mean %.2f, worst %.2f '
                  '(%d scenes)\n' % (sum(d1) / len(d1), max(d1), sum(d2) / len(d2), max(d2), len(d1)))


def main(argv):
    if len(argv) >= 2 and argv[1] == '--calibration':
        calibration_tables(argv[2], argv[3])
        return 0
    if len(argv) < 2:
        sys.stderr.write(__doc__)
        return 2
    for folder in argv[1:]:
        scenes = summarise(folder)
        print('## %s\n' % folder)
        print('| scene | first impact 3D | model | diff | rolling 3D | model | diff | Vt inside 3D spread | D inside |')
        print('| --- | --- | --- | --- | --- | --- | --- | --- | --- |')
        d1, d2 = [], []
        for sid, e in scenes.items():
            # No band: the model never stops at the first impact (t1 below the angles) or never rolls.
            t1 = e.get('t1') if e.get('t1') is not None else e['lo'] - 0.5
            t2 = e.get('t2') if e.get('t2') is not None else e['hi'] + 0.5
            a, b = t1 - e['t1_3d'], t2 - e['t2_3d']
            d1.append(abs(a))
            d2.append(abs(b))
            cell = lambda k: ('yes' if e[k][0] else 'no (%s)' % e[k][1]) if k in e else '-'
            print('| %s | %g | %s | %+g | %g | %s | %+g | %s | %s |' % (
                sid, e['t1_3d'], '%g' % t1 if e.get('t1') is not None else 'none (<%g)' % e['lo'], a,
                e['t2_3d'], '%g' % t2 if e.get('t2') is not None else 'none (>%g)' % e['hi'], b, cell('vt'), cell('d')))
        n = len(d1)
        print('\nfirst impact: mean |diff| %.2f deg, worst %.2f; sustained rolling: mean %.2f, worst %.2f (%d scenes)\n'
              % (sum(d1) / n, max(d1), sum(d2) / n, max(d2), n))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
